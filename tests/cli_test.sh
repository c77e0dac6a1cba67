#!/usr/bin/env bash
# The command line as a user meets it: exit codes, messages that name the
# offending part, output files, determinism.
set -u
source "$(dirname "$0")/shell_test_lib.sh"

expect_exit() {  # expected-code description command...
    local want=$1 what=$2
    shift 2
    "$@" >"$tmp/out" 2>"$tmp/err"
    local got=$?
    [ "$got" -eq "$want" ] || fail "$what: exit $got, expected $want ($(head -c 300 "$tmp/err"))"
}

# Every bundled task is valid.
for t in "$root"/tasks/*.json "$root"/tasks/*/*.task.json; do
    [ -f "$t" ] || continue
    expect_exit 0 "validate $t" "$bin" validate "$t"
done

# Every bad fixture is rejected with exit 2 and a message naming its file
# and its part (a fault of the whole document by the file alone).
while IFS=$'\t' read -r file part; do
    expect_exit 2 "validate $file" "$bin" validate "$root/tests/fixtures/invalid/$file"
    where="error: $root/tests/fixtures/invalid/$file: "
    [ "$part" = "(document)" ] || where="$where$part: "
    grep -qF -- "$where" "$tmp/err" || fail "validate $file: message does not start '$where': $(cat "$tmp/err")"
done < <(python3 -c '
import json, sys
for f, e in sorted(json.load(open(sys.argv[1])).items()):
    print(f + "\t" + e["part"])' "$root/tests/fixtures/invalid/expected.json")

# Usage errors and informational flags.
expect_exit 2 "no subcommand" "$bin"
expect_exit 2 "unknown subcommand" "$bin" frobnicate
# A module the catalog does not have is named before any work is done.
printf '%s' '{"format": "modsynth-task/1", "trajectory": [{"type": "line", "start": [0.4, 0.1], "end": [0.5, 0.1]}], "robot": {"modules": ["X8-9", "X9-9"]}}' >"$tmp/unknown_module.json"
expect_exit 2 "solve with an unknown module" "$bin" solve "$tmp/unknown_module.json" -o "$tmp/unknown_module.out.json"
grep -q 'robot.modules\[1\]: the module catalog has no "X9-9"' "$tmp/err" || fail "the unknown module is not named: $(cat "$tmp/err")"
expect_exit 2 "validate with an unknown module" "$bin" validate "$tmp/unknown_module.json"
# A certified motion no allowed module carries is still "solved" (the
# contract's guarantees are about the motion, and hold): the status line,
# a warning, the solution's `modules` and the build sheet name the joint,
# the module, the time and the (negative) margin.
python3 - "$root/tasks/rose.json" "$tmp/heavy.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t["robot"].update({"modules": ["X5-1"], "payload": 5.0, "gravity": [0.0, -9.81]})
json.dump(t, open(sys.argv[2], "w"))
PY
expect_exit 0 "solve with a payload no allowed module carries" "$bin" solve "$tmp/heavy.json" -o "$tmp/heavy.out.json" --quiet --build-sheet "$tmp/heavy.md"
grep -q "^rose: solved in [0-9.]* s (front stage [0-9.]* s, refinement [0-9.]* s, verification [0-9.]* s), but joint 1 is overloaded$" "$tmp/out" || fail "the status line does not name the overloaded joint after the times: $(head -3 "$tmp/out")"
grep -Eq "^warning: the certified robot overloads its modules: .*joint 1.*X5-1.*margin -[0-9.]+ N m.*robot.payload" "$tmp/err" ||
    fail "no warning naming the joint, module and margin: $(cat "$tmp/err")"
grep -q "^\*\*Warning:\*\* .*joint 1" "$tmp/heavy.md" || fail "the build sheet carries no warning: $(head -5 "$tmp/heavy.md")"
python3 - "$tmp/heavy.out.json" <<'PY' || fail "the overload is not recorded: $(head -c 600 "$tmp/heavy.out.json")"
import json, re, sys
d = json.load(open(sys.argv[1]))
m = d["modules"]
assert d["status"] == "solved" and d["samples"], d["status"]
assert m["overloaded_joint"] == 1, m["overloaded_joint"]
assert re.search(r"joint 1 is overloaded", m["message"]), m["message"]
assert "X5-1" in m["message"] and re.search(r"margin -[0-9.]+ N m", m["message"]), m["message"]
assert re.search(r"at t = [0-9.]+ s", m["message"]), m["message"]
assert not m["joints"][0]["carries"]
PY
# export chooses again from the task and warns the same way.
expect_exit 0 "export of the overloaded solution" "$bin" export "$tmp/heavy.json" "$tmp/heavy.out.json" --build-sheet "$tmp/heavy2.md"
grep -q "^warning: the certified robot overloads its modules" "$tmp/err" || fail "export does not warn of the overload: $(cat "$tmp/err")"
cmp -s "$tmp/heavy.md" "$tmp/heavy2.md" || fail "export's build sheet differs from solve's"
expect_exit 2 "solve without -o" "$bin" solve "$root/tasks/rose.json"
expect_exit 2 "negative time limit" "$bin" solve "$root/tasks/rose.json" -o "$tmp/x.json" --time-limit -1
expect_exit 2 "unknown swept model" "$bin" solve "$root/tasks/rose.json" -o "$tmp/x.json" --swept sampled
expect_exit 2 "a negative shortening gap" "$bin" solve "$root/tasks/rose.json" -o "$tmp/x.json" --shorten-gap -0.001
expect_exit 2 "batch with an unknown swept model" "$bin" batch "$root/tasks" --out "$tmp/x.jsonl" --swept SV-app
expect_exit 2 "missing file" "$bin" validate "$tmp/does-not-exist.json"
expect_exit 0 "--help" "$bin" --help
expect_exit 0 "--version" "$bin" --version
grep -q "modsynth" "$tmp/out" || fail "--version prints no name"

# Solve the rose: exit 0, a solution that says solved, byte-identical twice.
expect_exit 0 "solve rose" "$bin" solve "$root/tasks/rose.json" -o "$tmp/a.json" --quiet
expect_exit 0 "solve rose again" "$bin" solve "$root/tasks/rose.json" -o "$tmp/b.json" --quiet
cmp -s "$tmp/a.json" "$tmp/b.json" || fail "same task and seed gave different solutions"
grep -q '"status": "solved"' "$tmp/a.json" || fail "rose solution is not solved"
if [ -f "$root/../shared/grader/check_solution.py" ]; then
    python3 "$root/../shared/grader/check_solution.py" "$root/tasks/rose.json" "$tmp/a.json" >"$tmp/grade" ||
        fail "shared grader rejects the rose solution: $(tail -1 "$tmp/grade")"
fi

# A task out of reach: exit 3 with a solution file that explains it.
for t in "$root"/tasks/infeasible/*.task.json; do
    [ -f "$t" ] || continue
    expect_exit 3 "solve $t" "$bin" solve "$t" -o "$tmp/inf.json" --quiet
    grep -q '"status": "infeasible"' "$tmp/inf.json" || fail "$t: status is not infeasible"
done

# Outputs people use: report, URDF, CSV and build sheet, from solve and
# again from the saved solution with export.
outputs() {  # prefix
    echo --report "$tmp/$1.html" --urdf "$tmp/$1.urdf" --csv "$tmp/$1.csv" --build-sheet "$tmp/$1.md" \
        --joint-trajectory "$tmp/$1.yaml"
}
expect_exit 0 "solve rose with outputs" "$bin" solve "$root/tasks/rose.json" -o "$tmp/s.json" --quiet $(outputs s)
for f in s.html s.urdf s.csv s.md s.yaml; do
    [ -s "$tmp/$f" ] || fail "solve rose did not write $f"
done
# Every solved motion is timed: velocities and accelerations follow.
head -1 "$tmp/s.csv" | grep -qE '^t,q1,q2(,q3)?,phase,primitive,qd1,qd2(,qd3)?,qdd1,qdd2(,qdd3)?$' ||
    fail "CSV header: $(head -1 "$tmp/s.csv")"
[ "$(($(wc -l <"$tmp/s.csv") - 1))" -eq "$(grep -c '"phase"' "$tmp/s.json")" ] ||
    fail "CSV rows do not match the solution's samples"
grep -q '<svg id="plot"' "$tmp/s.html" || fail "report has no plot"
if command -v check_urdf >/dev/null 2>&1; then
    check_urdf "$tmp/s.urdf" >"$tmp/check_urdf" 2>&1 || fail "check_urdf rejects the rose URDF: $(tail -3 "$tmp/check_urdf")"
fi
expect_exit 0 "export rose" "$bin" export "$root/tasks/rose.json" "$tmp/s.json" $(outputs e)
for ext in urdf csv md yaml; do
    cmp -s "$tmp/s.$ext" "$tmp/e.$ext" || fail "export gives a different .$ext than solve"
done
# The reports differ only in the stage timings, which a saved solution does not record.
cmp -s <(grep -v 'id="stage-times"' "$tmp/s.html") <(grep -v 'id="stage-times"' "$tmp/e.html") ||
    fail "export gives a different report than solve"
grep 'id="stage-times"' "$tmp/e.html" | grep -q 'n/a' || fail "export report claims stage timings"

# Export rejects bad solutions with exit 2 and names the part.
printf '{"format": "modsynth-solution/1", "task": "rose", "status": "solved"}' >"$tmp/bad.json"
expect_exit 2 "export a solution without robot" "$bin" export "$root/tasks/rose.json" "$tmp/bad.json" --csv "$tmp/bad.csv"
grep -q "robot" "$tmp/err" || fail "export of a bad solution does not name the robot: $(cat "$tmp/err")"
python3 -c '
import json, sys
d = json.load(open(sys.argv[1])); d["samples"][3]["q"] = [0.1]
json.dump(d, open(sys.argv[2], "w"))' "$tmp/s.json" "$tmp/bad_q.json"
expect_exit 2 "export a solution with a short q" "$bin" export "$root/tasks/rose.json" "$tmp/bad_q.json" --urdf "$tmp/bad.urdf"
grep -qF "samples[3].q" "$tmp/err" || fail "export does not name samples[3].q: $(cat "$tmp/err")"
expect_exit 2 "export with no output" "$bin" export "$root/tasks/rose.json" "$tmp/s.json"
expect_exit 2 "export a missing solution" "$bin" export "$root/tasks/rose.json" "$tmp/none.json" --csv "$tmp/x.csv"
if [ -f "$tmp/inf.json" ]; then
    expect_exit 2 "export a URDF of an infeasible solution" "$bin" export "$(ls "$root"/tasks/infeasible/*.task.json | tail -1)" "$tmp/inf.json" --urdf "$tmp/inf.urdf"
fi
# An output that cannot be written is refused before any work, naming it.
expect_exit 2 "export to an unwritable file" "$bin" export "$root/tasks/rose.json" "$tmp/s.json" --csv "$tmp/no/such/dir/x.csv"

# A stored certificate is never trusted: export verifies the motion again,
# and an edited one is reported as not certified wherever it would claim it.
python3 -c '
import json, sys
d = json.load(open(sys.argv[1])); d["samples"][40]["q"][0] += 0.05
json.dump(d, open(sys.argv[2], "w"))' "$tmp/s.json" "$tmp/edited.json"
expect_exit 0 "export an edited solution" "$bin" export "$root/tasks/rose.json" "$tmp/edited.json" \
    --report "$tmp/edited.html" --build-sheet "$tmp/edited.md"
grep -qF "warning: $tmp/edited.json: not certified: samples[40]" "$tmp/err" ||
    fail "no warning for an edited solution: $(cat "$tmp/err")"
grep -qF "<strong>not certified</strong>: samples[40]" "$tmp/edited.html" ||
    fail "the report of an edited solution does not say it is not certified"
! grep -q ">Certified " "$tmp/edited.html" || fail "the report of an edited solution claims a certificate"
grep -qF "**Warning:** not certified: samples\[40\]" "$tmp/edited.md" ||
    fail "the build sheet of an edited solution does not say it is not certified"

# A hostile task name is text in every output.
python3 -c '
import json, sys
name = "<script>alert(1)</script> `x` | y\n]]> \"q\""
t = json.load(open(sys.argv[1])); t["name"] = name; json.dump(t, open(sys.argv[3], "w"))
s = json.load(open(sys.argv[2])); s["task"] = name; json.dump(s, open(sys.argv[4], "w"))' \
    "$root/tasks/rose.json" "$tmp/s.json" "$tmp/hostile.task.json" "$tmp/hostile.json"
expect_exit 0 "export with a hostile task name" "$bin" export "$tmp/hostile.task.json" "$tmp/hostile.json" \
    --report "$tmp/h.html" --urdf "$tmp/h.urdf" --build-sheet "$tmp/h.md"
! grep -q "<script>alert" "$tmp/h.html" "$tmp/h.urdf" "$tmp/h.md" || fail "a hostile task name is markup"
head -1 "$tmp/h.md" | grep -qF '# Build sheet: &lt;script&gt;alert\(1\)&lt;\/script&gt; \`x\` \| y' ||
    fail "build sheet title: $(head -1 "$tmp/h.md")"
[ "$(sed -n 2p "$tmp/h.md")" = "" ] || fail "a line break in the task name ends the build sheet's title"

# explain: the proof in words, the parts, and checked relaxations.
far="$root/tasks/infeasible/table-too-far.task.json"
expect_exit 3 "explain $far" "$bin" explain "$far" --solve-seconds 3
grep -q "Proved infeasible" "$tmp/out" || fail "explain does not say it is proved"
grep -q "robot.max_link_length >= 1.3" "$tmp/out" || fail "explain suggests no longer links: $(cat "$tmp/out")"
expect_exit 3 "explain --json" "$bin" explain "$far" --solve-seconds 3 --json
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["status"]=="infeasible" and d["suggestions"]' "$tmp/out" ||
    fail "explain --json is not the expected JSON"
expect_exit 0 "explain a feasible task" "$bin" explain "$root/tasks/rose.json"
# A wall: the witness in the JSON, and the moves that break the proof.
ring="$root/tasks/infeasible/ring-around-path.task.json"
expect_exit 3 "explain --json a walled task" "$bin" explain "$ring" --solve-seconds 1 --json
python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
assert d["status"] == "infeasible" and "form a closed wall" in d["message"], d["message"]
walls = d["separation"]["walls"]
assert walls and len(walls[0]["cycle"]) == len(walls[0]["overlaps"]) >= 3, walls
changes = [s["change"] for s in d["suggestions"]]
for kind in ("remove obstacles[", "widen the gap between", "move base_regions["):
    assert any(c.startswith(kind) for c in changes), (kind, changes)' "$tmp/out" ||
    fail "explain --json of a walled task: $(cat "$tmp/out")"

# The discretized baseline and the comparison with it.
expect_exit 0 "baseline rose" "$bin" baseline "$root/tasks/rose.json" --points 25 -o "$tmp/base.json" --quiet
grep -q "executed EE strays up to" "$tmp/out" || fail "baseline prints no deviation: $(cat "$tmp/out")"
python3 - "$tmp/base.json" <<'PY' || fail "baseline JSON is not as documented"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "modsynth-baseline/1" and d["status"] == "executed", d.get("status")
assert len(d["points"]) == 25 and len(d["poses"]) == 25 and len(d["waypoints"]) >= 25
assert d["robot"]["dof"] == 2 and d["figures"]["max_ee_deviation"] > 0.005
PY
expect_exit 2 "baseline with one point" "$bin" baseline "$root/tasks/rose.json" --points 1
# Every stage option the command line exposes: a bad value exits 2 naming it.
while read -r cmd option value; do
    expect_exit 2 "$cmd $option $value" "$bin" $cmd "$root/tasks/rose.json" -o "$tmp/bad.json" "$option" "$value"
    grep -qF -- "$option" "$tmp/err" || fail "$cmd $option $value: message does not name it: $(cat "$tmp/err")"
done <<'OPTIONS'
solve --time-limit 0
solve --ee-speed 0
solve --joint-speed nan
solve --seed -1
baseline --points 1
baseline --baseline-time-limit inf
baseline --rrt-iterations 0
baseline --goal-bias 2
baseline --baseline-seed x
OPTIONS
expect_exit 4 "baseline out of reach" "$bin" baseline "$root/tasks/infeasible/out-of-reach.task.json" --quiet
grep -q "no design" "$tmp/out" || fail "baseline out of reach does not say 'no design': $(cat "$tmp/out")"
expect_exit 0 "compare rose" "$bin" compare "$root/tasks/rose.json" --quiet --report "$tmp/cmp.html"
for row in "max EE deviation" "path in reachable space" "total length"; do
    grep -q "$row" "$tmp/out" || fail "compare table lacks '$row'"
done
grep -q 'id="comparison"' "$tmp/cmp.html" || fail "compare report lacks the comparison table"
expect_exit 0 "compare rose --json" "$bin" compare "$root/tasks/rose.json" --quiet --json
python3 - "$tmp/out" <<'PY' || fail "compare --json is not as documented"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "modsynth-comparison/1"
assert d["modsynth"]["status"] == "solved" and d["discretized"]["status"] == "executed"
assert d["modsynth"]["figures"]["max_ee_deviation"] < 0.001
assert d["baseline_over_modsynth"]["max_ee_deviation"] > 5
PY

# Unwritable output is refused before the solve, naming it, not a crash.
expect_exit 2 "unwritable output" "$bin" solve "$root/tasks/rose.json" -o "$tmp/no/such/dir/x.json" --quiet

finish cli
