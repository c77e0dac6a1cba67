#!/usr/bin/env bash
# Spatial tasks (docs/formats.md "Spatial tasks") on the command line:
# `validate` reads them (exit 0) and refuses bad ones naming the part
# (exit 2); `certify` certifies the planted solutions of the shared
# planter and refuses their mutations exactly where the shared grader does;
# every command that does not take spatial tasks yet refuses them by name.
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

# Every other command refuses a spatial task by name, before any work.
task=$fixtures/s3-0001.task.json
for cmd in "solve $task -o $tmp/x.json" "explain $task" "export $task $fixtures/s3-0001.planted.json --csv $tmp/x.csv" \
           "baseline $task" "compare $task" "export-svg $task -o $tmp/x.svg"; do
    name=${cmd%% *}
    # shellcheck disable=SC2086
    expect_exit 2 "$name on a spatial task" "$bin" $cmd
    grep -qF "space: spatial tasks are not supported by $name yet" "$tmp/err" ||
        fail "$name does not refuse the spatial task by name: $(cat "$tmp/err")"
done
mkdir -p "$tmp/regress/tasks" "$tmp/regress/encodings"
cp "$task" "$tmp/regress/tasks/"
"$bin" regress encodings --tasks "$tmp/regress/tasks" --dir "$tmp/regress/encodings" >"$tmp/out" 2>&1
grep -qF "spatial tasks are not supported by regress yet" "$tmp/out" ||
    fail "regress does not refuse the spatial task by name: $(head -c 400 "$tmp/out")"

finish spatial
