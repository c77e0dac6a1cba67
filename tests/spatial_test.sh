#!/usr/bin/env bash
# Spatial tasks (docs/formats.md "Spatial tasks") on the command line:
# `validate` reads them (exit 0) and refuses bad ones naming the part
# (exit 2); `certify` certifies the planted solutions of the shared
# planter and refuses their mutations exactly where the shared grader does;
# `solve` and `batch` design robots for them, `explain` says why not,
# `regress` judges them against recorded figures (planted tasks solved and graded,
# the unreachable one proved infeasible with its core); export writes every
# output of a spatial solution; every command that does not take spatial
# tasks yet refuses them by name.
# Arguments: modsynth binary, source root, folder of the shared contract
# (default: beside the source root); without the shared grader the
# comparison with it is skipped and said so.
set -u
source "$(dirname "$0")/shell_test_lib.sh"
shared=${3:-$root/../shared}
grader=$shared/grader/check_solution.py
[ -f "$grader" ] || echo "note: no $grader; the comparison with the shared grader is skipped"
fixtures=$root/tests/fixtures/spatial

expect_exit() {  # expected-code description command...
    local want=$1 what=$2
    shift 2
    "$@" >"$tmp/out" 2>"$tmp/err"
    local got=$?
    [ "$got" -eq "$want" ] || fail "$what: exit $got, expected $want ($(head -c 300 "$tmp/err"))"
}

# The shared grader's verdict: 0 pass, 1 fail.
grade() {  # task solution
    [ -f "$grader" ] || return 0
    python3 "$grader" "$1" "$2" >"$tmp/grade" 2>&1
}

for t in "$fixtures"/*.task.json; do
    expect_exit 0 "validate $t" "$bin" validate "$t"
    grep -q "valid spatial task" "$tmp/out" || fail "validate $t: $(cat "$tmp/out")"
done

while IFS=$'\t' read -r file part; do
    expect_exit 2 "validate $file" "$bin" validate "$root/tests/fixtures/invalid-spatial/$file"
    grep -qF -- "$part: " "$tmp/err" || fail "validate $file: does not name '$part': $(cat "$tmp/err")"
done < <(python3 -c '
import json, sys
for f, e in sorted(json.load(open(sys.argv[1])).items()):
    print(f + "\t" + e["part"])' "$root/tests/fixtures/invalid-spatial/expected.json")

# Every planted solution is certified, and the grader passes it.
for sol in "$fixtures"/*.planted.json; do
    task=${sol%.planted.json}.task.json
    expect_exit 0 "certify $sol" "$bin" certify "$task" "$sol"
    grep -q ": certified:" "$tmp/out" || fail "certify $sol: $(cat "$tmp/out")"
    grade "$task" "$sol" || fail "the grader fails $sol: $(tail -1 "$tmp/grade")"
done
expect_exit 0 "certify --json" "$bin" certify "$fixtures/s4-0010.task.json" \
    "$fixtures/s4-0010.planted.json" --json
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert d["certified"] and d["space"] == "3d" and d["max_ee_deviation"] < 1e-3, d' \
    "$tmp/out" || fail "certify --json: $(cat "$tmp/out")"

# Mutations: certify refuses (exit 5) each, and so does the grader.
mutate() {  # name python-statement-on-(task, sol)
    python3 - "$fixtures/s3-0004.task.json" "$fixtures/s3-0004.planted.json" \
        "$tmp/$1.task.json" "$tmp/$1.solution.json" "$2" <<'PY'
import json, math, sys
task, sol = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
exec(sys.argv[5])
json.dump(task, open(sys.argv[3], "w"))
json.dump(sol, open(sys.argv[4], "w"))
PY
    expect_exit 5 "certify the mutation '$1'" "$bin" certify "$tmp/$1.task.json" "$tmp/$1.solution.json"
    grep -q "not certified" "$tmp/out" || fail "$1: $(cat "$tmp/out")"
    if [ -f "$grader" ] && grade "$tmp/$1.task.json" "$tmp/$1.solution.json"; then
        fail "the grader passes the mutation '$1' that certify refuses"
    fi
}
mutate link-shortened 'sol["robot"]["dh"][2]["a"] *= 0.99'
mutate sample-moved 's = sol["samples"][len(sol["samples"]) // 2]; s["q"][1] += 0.005'
mutate twist-refused 'task["robot"]["twists"] = [0.0, -math.pi / 2]'
mutate base-moved 'sol["robot"]["base"][2] += 0.5'
mutate tool-too-long 'task["robot"]["tool_length"] = sol["robot"]["dh"][2]["a"] + 0.01'
mutate dof-refused 'task["robot"]["dof"] = [4]'
mutate link-too-long 'task["robot"]["max_link_length"] = 0.3'
mutate obstacle-on-chain '
import math
q = sol["samples"][10]["q"]
d1 = sol["robot"]["dh"][0]["d"]; a2 = sol["robot"]["dh"][1]["a"]
b = sol["robot"]["base"]
mid = [b[0] + 0.5 * a2 * math.cos(q[1]) * math.cos(q[0]), b[1] + 0.5 * a2 * math.cos(q[1]) * math.sin(q[0]),
       b[2] + d1 + 0.5 * a2 * math.sin(q[1])]
task["obstacles"].append({"type": "sphere", "center": [mid[0], mid[1], mid[2] + 0.02], "radius": 0.01})'

# A solution for the other kind of task is refused by name.
planter=$shared/grader/plant.py
if [ -f "$planter" ] && python3 "$planter" --kind 2dof --seed 1 --out "$tmp/p2" >/dev/null; then
    # Without its task's name, so that only the robot's kind is wrong.
    python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d.pop("task"); json.dump(d, open(sys.argv[2], "w"))' \
        "$tmp/p2/p2-0001.planted.json" "$tmp/planar.json"
    expect_exit 2 "a planar solution for a spatial task" "$bin" certify \
        "$fixtures/s3-0001.task.json" "$tmp/planar.json"
    grep -q "robot: a planar robot" "$tmp/err" || fail "the planar robot is not named: $(cat "$tmp/err")"
fi
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d.pop("task"); json.dump(d, open(sys.argv[2], "w"))' \
    "$fixtures/s3-0001.planted.json" "$tmp/spatial.json"
expect_exit 2 "a spatial solution for a planar task" "$bin" certify "$root/tasks/rose.json" \
    "$tmp/spatial.json"
grep -q "robot.dh" "$tmp/err" || fail "the spatial robot is not named: $(cat "$tmp/err")"

# solve designs a certified robot for planted tasks (exit 0, a solution the
# grader passes, its chain as DH rows) and proves the planted unreachable
# task infeasible (exit 3) with the planted core.
for t in s3-0001 s3-0004 s4-0030; do
    expect_exit 0 "solve $t" "$bin" solve "$fixtures/$t.task.json" -o "$tmp/$t.solution.json" \
        --time-limit 60
    grep -q "^$t: solved in " "$tmp/out" || fail "solve $t: $(head -c 300 "$tmp/out")"
    grep -q "joints: front stage" "$tmp/err" || fail "solve $t: no progress on stderr"
    grade "$fixtures/$t.task.json" "$tmp/$t.solution.json" ||
        fail "the grader fails the solution of $t: $(tail -1 "$tmp/grade")"
    python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))["robot"]; assert len(r["dh"]) == r["dof"] >= 3, r' \
        "$tmp/$t.solution.json" || fail "solve $t: no DH chain in the solution"
done
# solve writes the outputs of a spatial solution beside it, modules chosen.
expect_exit 0 "solve s3-0001 with outputs" "$bin" solve "$fixtures/s3-0001.task.json" \
    -o "$tmp/s3-out.json" --report "$tmp/s3-out.html" --urdf "$tmp/s3-out.urdf" \
    --build-sheet "$tmp/s3-out.md" --time-limit 60 --events "$tmp/s3-out.events"
# Its progress as typed events, one JSON object a line, as in the plane.
python3 - "$tmp/s3-out.events" <<'PY' || fail "solve --events of a spatial task: $(head -c 300 "$tmp/s3-out.events")"
import json, sys
events = [json.loads(l) for l in open(sys.argv[1])]
stages = {e["stage"] for e in events}
assert {"front stage", "search", "refinement", "verification", "timing"} <= stages, stages
assert all(not e["message"].startswith("[") for e in events), events
PY
for ext in html urdf md; do
    [ -s "$tmp/s3-out.$ext" ] || fail "solve --$ext of a spatial task wrote nothing"
done
grep -q 'id="scene-data"' "$tmp/s3-out.html" || fail "solve --report: no 3-D scene"
grep -q "A spatial arm" "$tmp/s3-out.md" || fail "solve --build-sheet: not a spatial build sheet"
grep -q "^  modules " "$tmp/out" || fail "solve s3-0001: no modules in the summary: $(cat "$tmp/out")"
python3 -c 'import json, sys; assert json.load(open(sys.argv[1]))["modules"]["joints"]' "$tmp/s3-out.json" ||
    fail "solve s3-0001: no modules in the solution"
expect_exit 3 "solve sir-0001" "$bin" solve "$fixtures/sir-0001.task.json" -o "$tmp/sir.json"
python3 - "$fixtures/sir-0001.expect.json" "$tmp/sir.json" <<'PY' || fail "solve sir-0001: the core is not the planted one"
import json, sys
want, got = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
core = set(got["explanation"]["core"])
assert got["status"] == "infeasible", got["status"]
assert {"base_regions", "robot.max_link_length"} <= core, core
assert core & set(want["core_should_include_one_of"]), core
PY
if [ -f "$grader" ]; then
    python3 "$grader" "$fixtures/sir-0001.task.json" "$tmp/sir.json" --expect infeasible >"$tmp/grade" 2>&1 ||
        fail "the grader fails the infeasibility of sir-0001: $(tail -1 "$tmp/grade")"
fi
# batch reads a spatial solution's chain back.
mkdir -p "$tmp/batch"
cp "$fixtures/s3-0001.task.json" "$fixtures/sir-0001.task.json" "$tmp/batch/"
"$bin" batch "$tmp/batch" --out "$tmp/batch.jsonl" --time-limit 60 >"$tmp/out" 2>&1 ||
    fail "batch on spatial tasks: $(head -c 300 "$tmp/out")"
python3 - "$tmp/batch.jsonl" <<'PY' || fail "batch: spatial rows wrong: $(cat "$tmp/batch.jsonl")"
import json, sys
rows = {r["name"]: r for r in map(json.loads, open(sys.argv[1]))}
assert rows["s3-0001"]["status"] == "solved" and rows["s3-0001"]["dof"] >= 3, rows["s3-0001"]
assert rows["s3-0001"]["total_link_length"] > 0.05, rows["s3-0001"]
assert rows["sir-0001"]["status"] == "infeasible" and "base_regions" in rows["sir-0001"]["core"], rows["sir-0001"]
PY


# export writes every output of a spatial solution: the planter's
# solutions carry no timing, so export times them (CSV and joint trajectory
# with rates within the default limits); check_urdf accepts the URDF.
for name in s3-0001 s4-0030; do
    expect_exit 0 "export $name" "$bin" export "$fixtures/$name.task.json" "$fixtures/$name.planted.json" \
        --report "$tmp/$name.html" --urdf "$tmp/$name.urdf" --csv "$tmp/$name.csv" \
        --joint-trajectory "$tmp/$name.yaml" --build-sheet "$tmp/$name.md"
    for ext in html urdf csv yaml md; do
        [ -s "$tmp/$name.$ext" ] || fail "export $name: no .$ext"
    done
    grep -q 'id="scene-data"' "$tmp/$name.html" || fail "export $name: the report has no 3-D scene"
    if command -v check_urdf >/dev/null; then
        check_urdf "$tmp/$name.urdf" >"$tmp/check_urdf" 2>&1 || fail "check_urdf refuses $name.urdf: $(tail -3 "$tmp/check_urdf")"
    fi
    python3 - "$tmp/$name.csv" "$fixtures/$name.planted.json" <<'PY' || fail "export $name: bad CSV"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
sol = json.load(open(sys.argv[2]))
n = sol["robot"]["dof"]
assert len(rows) == len(sol["samples"]), (len(rows), len(sol["samples"]))
for k in range(1, n + 1):
    assert max(abs(float(r["qd%d" % k])) for r in rows) <= 3.142 * (1 + 1e-6)
    assert max(abs(float(r["qdd%d" % k])) for r in rows) <= 10 * (1 + 1e-6)
assert all(float(b["t"]) > float(a["t"]) for a, b in zip(rows, rows[1:]))
for r, s in zip(rows, sol["samples"]):
    assert all(abs(float(r["q%d" % (k + 1)]) - s["q"][k]) < 1e-8 for k in range(n))
PY
    grep -q "joint_names: \[joint_1" "$tmp/$name.yaml" || fail "export $name: no joint names in the joint trajectory"
    grep -q "A spatial arm" "$tmp/$name.md" || fail "export $name: not a spatial build sheet"
done
# An edited motion is verified again: the report and the sheet say so.
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d["samples"][20]["q"][1] += 0.1; json.dump(d, open(sys.argv[2], "w"))' \
    "$fixtures/s3-0001.planted.json" "$tmp/edited.json"
expect_exit 0 "export an edited spatial solution" "$bin" export "$fixtures/s3-0001.task.json" "$tmp/edited.json" \
    --report "$tmp/edited.html" --build-sheet "$tmp/edited.md"
grep -q "not certified" "$tmp/err" || fail "export of an edited solution does not warn: $(cat "$tmp/err")"
grep -q "<strong>not certified</strong>" "$tmp/edited.html" || fail "the report of an edited solution claims a certificate"
grep -q "Warning:\*\* not certified" "$tmp/edited.md" || fail "the build sheet of an edited solution claims a certificate"
# A controller gets no uncertified motion unless asked for it.
expect_exit 2 "export the CSV of an edited spatial solution" "$bin" export "$fixtures/s3-0001.task.json" \
    "$tmp/edited.json" --csv "$tmp/edited.csv" --joint-trajectory "$tmp/edited.yaml"
[ ! -e "$tmp/edited.csv" ] && [ ! -e "$tmp/edited.yaml" ] || fail "an uncertified spatial motion was written for a controller"
grep -q -- "--write-uncertified" "$tmp/err" || fail "export does not say how to write it anyway: $(cat "$tmp/err")"
expect_exit 0 "export the CSV of an edited spatial solution when asked" "$bin" export "$fixtures/s3-0001.task.json" \
    "$tmp/edited.json" --csv "$tmp/edited.csv" --write-uncertified
[ -s "$tmp/edited.csv" ] || fail "--write-uncertified wrote no CSV"
# A module the catalog lacks is named; an overloaded joint is a warning.
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d["robot"]["modules"] = ["X5-1", "X9-99"]; json.dump(d, open(sys.argv[2], "w"))' \
    "$fixtures/s3-0001.task.json" "$tmp/modules.task.json"
expect_exit 2 "export with an unknown module" "$bin" export "$tmp/modules.task.json" "$fixtures/s3-0001.planted.json" --csv "$tmp/x.csv"
grep -qF "robot.modules[1]" "$tmp/err" || fail "export does not name robot.modules[1]: $(cat "$tmp/err")"
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); d["robot"]["modules"] = ["X5-1"]; d["robot"]["payload"] = 3.0; json.dump(d, open(sys.argv[2], "w"))' \
    "$fixtures/s3-0001.task.json" "$tmp/heavy.task.json"
expect_exit 0 "export an overloaded arm" "$bin" export "$tmp/heavy.task.json" "$fixtures/s3-0001.planted.json" --build-sheet "$tmp/heavy.md"
grep -q "overloads its modules: joint [12] is overloaded" "$tmp/err" || fail "export does not warn of the overload: $(cat "$tmp/err")"
grep -q "Warning:\*\* joint [12] is overloaded" "$tmp/heavy.md" || fail "the build sheet does not warn of the overload"
# An infeasible answer has a report but no robot to export.
python3 -c 'import json, sys; json.dump({"format": "modsynth-solution/1", "task": "s3-0001", "status": "infeasible", "explanation": {"message": "no", "core": ["trajectory[0]"]}}, open(sys.argv[1], "w"))' \
    "$tmp/infeasible.json"
expect_exit 2 "export a URDF of an infeasible spatial solution" "$bin" export "$fixtures/s3-0001.task.json" \
    "$tmp/infeasible.json" --report "$tmp/inf.html" --urdf "$tmp/inf.urdf"
[ -s "$tmp/inf.html" ] && [ ! -e "$tmp/inf.urdf" ] || fail "export of an infeasible solution: report and no URDF expected"

# explain: the planted unreachable task proved with its planted parts and
# changes that remove the conflict (--json as in the plane); a feasible one
# solved instead (exit 0).
expect_exit 3 "explain sir-0001" "$bin" explain "$fixtures/sir-0001.task.json" --solve-seconds 1
grep -q "^Proved infeasible: trajectory\[0\] is out of reach" "$tmp/out" ||
    fail "explain sir-0001: $(head -c 300 "$tmp/out")"
grep -q "  - robot.max_link_length >= " "$tmp/out" || fail "explain sir-0001 suggests no longer links: $(cat "$tmp/out")"
expect_exit 3 "explain --json sir-0001" "$bin" explain "$fixtures/sir-0001.task.json" --solve-seconds 1 --json
python3 - "$fixtures/sir-0001.expect.json" "$tmp/out" <<'PY' || fail "explain --json sir-0001: $(head -c 400 "$tmp/out")"
import json, sys
expect, got = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert got["status"] == "infeasible", got
core = set(got["core"])
assert {p for p in expect["core_should_include"] if not p.startswith("trajectory")} <= core, core
assert core & set(expect["core_should_include_one_of"]), core
assert {s["part"] for s in got["suggestions"]} == {"robot.max_link_length", "base_regions"}, got
PY
expect_exit 0 "explain a feasible spatial task" "$bin" explain "$fixtures/s3-0001.task.json"
grep -q "No conflict: a 3-joint robot" "$tmp/out" || fail "explain s3-0001: $(cat "$tmp/out")"

# Every other command refuses a spatial task by name, before any work.
task=$fixtures/s3-0001.task.json
for cmd in "baseline $task" "compare $task" "export-svg $task -o $tmp/x.svg"; do
    name=${cmd%% *}
    # shellcheck disable=SC2086
    expect_exit 2 "$name on a spatial task" "$bin" $cmd
    grep -qF "space: spatial tasks are not supported by $name yet" "$tmp/err" ||
        fail "$name does not refuse the spatial task by name: $(cat "$tmp/err")"
done
# A 100-primitive spatial task (lines chained round a climbing circle):
# solved and certified with time to spare, and under a tiny time limit
# answered "unknown" (exit 4, as in the plane) with a valid solution file.
python3 - "$tmp/chain100.json" <<'PY'
import json, math, sys
n = 100
pts = [[0.3 + 0.08 * math.cos(3 * math.pi * i / n), 0.08 * math.sin(3 * math.pi * i / n),
        0.25 + 0.1 * i / n] for i in range(n + 1)]
json.dump({"format": "modsynth-task/1", "name": "chain100", "space": "3d",
           "trajectory": [{"type": "line", "start": pts[i], "end": pts[i + 1]} for i in range(n)],
           "base_regions": [{"min": [-0.05, -0.05, 0.0], "max": [0.05, 0.05, 0.05]}],
           "robot": {"dof": [3, 4]}}, open(sys.argv[1], "w"))
PY
expect_exit 0 "solve a 100-primitive spatial task" "$bin" solve "$tmp/chain100.json" -o "$tmp/chain100.sol.json"
grade "$tmp/chain100.json" "$tmp/chain100.sol.json" || fail "the grader fails chain100: $(tail -1 "$tmp/grade")"
expect_exit 4 "solve a 100-primitive spatial task in 0.01 s" "$bin" solve "$tmp/chain100.json" \
    -o "$tmp/chain100.unknown.json" --time-limit 0.01
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert d["status"] == "unknown" and "time limit" in d["explanation"]["message"], d' \
    "$tmp/chain100.unknown.json" || fail "chain100 in 0.01 s: $(head -c 300 "$tmp/chain100.unknown.json")"
"$bin" certify "$tmp/chain100.json" "$tmp/chain100.unknown.json" >"$tmp/out" 2>&1
[ $? -ne 2 ] || fail "the unknown answer of chain100 is not a valid solution file: $(cat "$tmp/out")"

# regress judges spatial tasks as planar ones: recorded, then unchanged;
# another front-stage core or a longer chain than recorded is a regression.
mkdir -p "$tmp/regress/tasks"
cp "$task" "$fixtures/sir-0001.task.json" "$tmp/regress/tasks/"
expect_exit 0 "regress --regenerate of spatial tasks" "$bin" regress encodings \
    --tasks "$tmp/regress/tasks" --dir "$tmp/regress/encodings" --regenerate
[ -s "$tmp/regress/encodings/s3-0001.dof3.smt2" ] || fail "regress wrote no spatial encoding"
expect_exit 0 "regress of spatial tasks" "$bin" regress encodings \
    --tasks "$tmp/regress/tasks" --dir "$tmp/regress/encodings"
python3 - "$tmp/regress/encodings" <<'PY'
import json, sys
for name, edit in [("sir-0001", lambda d: d["front_stage"][0].update(core=["robot.twists"])),
                   ("s3-0001", lambda d: d["solve"].update(total_link_length=d["solve"]["total_link_length"] * 0.5))]:
    path = "%s/%s.expect.json" % (sys.argv[1], name)
    doc = json.load(open(path))
    edit(doc)
    json.dump(doc, open(path, "w"), indent=1)
PY
expect_exit 1 "regress of tampered spatial expectations" "$bin" regress encodings \
    --tasks "$tmp/regress/tasks" --dir "$tmp/regress/encodings"
grep -q "^REGRESSED sir-0001" "$tmp/out" || fail "regress misses another spatial core: $(head -c 600 "$tmp/out")"
grep -q "^REGRESSED s3-0001" "$tmp/out" || fail "regress misses a longer spatial chain: $(head -c 600 "$tmp/out")"

finish spatial
