#!/usr/bin/env bash
# A drawing task built from hobby servos: tasks/rose-dynamixel.json solved
# with robot.modules ["dynamixel-x"] and, rewritten, with ["STS3215"]. Each
# solution is certified by modsynth and passes the shared grader (where it
# is at hand), and the summary, the build sheet and the
# solution's modules name the servos chosen, their family and the cost.
# An unknown family is refused naming robot.modules[i] and the families.
# Arguments: modsynth, source root, shared folder (default:
# MODSYNTH_SHARED_DIR, else beside the source root).
set -u
source "$(dirname "$0")/shell_test_lib.sh"
shared=${3:-${MODSYNTH_SHARED_DIR:-$root/../shared}}
grader=$shared/grader/check_solution.py

expect_exit() {  # expected-code description command...
    local want=$1 what=$2
    shift 2
    "$@" >"$tmp/out" 2>"$tmp/err"
    local got=$?
    [ "$got" -eq "$want" ] || fail "$what: exit $got, expected $want ($(head -c 300 "$tmp/err"))"
}

task=$root/tasks/rose-dynamixel.json
python3 - "$task" "$tmp" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t["robot"]["modules"] = ["STS3215"]
json.dump(t, open(sys.argv[2] + "/sts.json", "w"))
t["robot"]["modules"] = ["dynamixel"]
json.dump(t, open(sys.argv[2] + "/typo.json", "w"))
PY

check() {  # name task family model-pattern (the family and models as the sheet escapes them)
    local name=$1 t=$2 family=$3 model=$4
    local md_family=${family//-/\\\\-}
    expect_exit 0 "solve $name" "$bin" solve "$t" -o "$tmp/$name.out.json" --build-sheet "$tmp/$name.md"
    cp "$tmp/out" "$tmp/$name.summary"
    expect_exit 0 "certify $name" "$bin" certify "$t" "$tmp/$name.out.json"
    if [ -f "$grader" ]; then
        python3 "$grader" "$t" "$tmp/$name.out.json" --expect solved >"$tmp/$name.grade" 2>&1 ||
            fail "$name: the shared grader fails the solution: $(tail -1 "$tmp/$name.grade")"
    else
        echo "note: no shared grader at $grader; its check is skipped"
    fi
    grep -Eq "^  modules ($model)(, ($model))* \($family; [0-9.]+ kg\), every joint carried .*; cost: .* = \\\$[0-9.]+.*; total \\\$[0-9.]+$" "$tmp/$name.summary" ||
        fail "$name: the summary does not name the servos and the cost: $(grep modules "$tmp/$name.summary")"
    grep -Eq "^\| 1 \| ($model) \| $md_family \| [0-9.]+ \| " "$tmp/$name.md" ||
        fail "$name: the build sheet's modules table lacks family and cost: $(grep -A4 '^## Modules' "$tmp/$name.md")"
    grep -q "^Modules to order:" "$tmp/$name.md" || fail "$name: the build sheet lists no modules to order"
    grep -Eq "kg in all; total cost \\\$[0-9.]+\.$" "$tmp/$name.md" ||
        fail "$name: the build sheet has no cost total: $(grep 'kg in all' "$tmp/$name.md")"
    python3 - "$tmp/$name.out.json" "$family" <<'PY' || fail "$name: the solution's modules lack family or cost: $(tail -3 "$tmp/err")"
import json, sys
m = json.load(open(sys.argv[1]))["modules"]
assert m["overloaded_joint"] is None, m["message"]
assert all(j["family"] == sys.argv[2] and j["carries"] for j in m["joints"]), m["joints"]
assert abs(sum(j["cost"] for j in m["joints"]) - m["total_cost"]) < 1e-9, m
assert m["cost"].startswith("cost: ") and m["cost"] in m["message"], m
PY
}

check dynamixel "$task" dynamixel-x 'X[LCMH][0-9]{3}\\?-[MW][0-9]{3}'
check sts "$tmp/sts.json" 'feetech' 'STS3215'
expect_exit 2 "an unknown family" "$bin" solve "$tmp/typo.json" -o "$tmp/typo.out.json"
grep -q 'robot.modules\[0\]: the module catalog has no "dynamixel"; its families are dynamixel-x, feetech, hebi-x' "$tmp/err" ||
    fail "the unknown family is not named with the families: $(cat "$tmp/err")"

finish servos
