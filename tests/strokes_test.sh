#!/usr/bin/env bash
# Tasks of several strokes end to end (formats.md "Several strokes"): the
# hand-made tasks/strokes-*.json are solved, the solutions pass the shared
# grader with their number of strokes and certify again on export; an
# infeasible one names the stroke out of reach; bad documents exit 2 naming
# the part.
set -u
source "$(dirname "$0")/shell_test_lib.sh"
# The shared grader beside the source tree, or where MODSYNTH_GRADER says.
grader=${MODSYNTH_GRADER:-"$root/../shared/grader/check_solution.py"}

for spec in strokes-two-circles:3 strokes-around-post:2; do
    name=${spec%%:*} strokes=${spec##*:}
    task="$root/tasks/$name.json" sol="$tmp/$name.sol.json"
    "$bin" solve "$task" -o "$sol" --time-limit 60 >"$tmp/out" 2>&1
    code=$?
    [ "$code" -eq 0 ] || { fail "$name: solve exit $code: $(tail -3 "$tmp/out")"; continue; }
    grep -q '"phase": "travel"' "$sol" || fail "$name: no travel samples"
    if [ -f "$grader" ]; then
        python3 "$grader" "$task" "$sol" --expect solved >"$tmp/grade" 2>&1 ||
            fail "$name: grader: $(tail -1 "$tmp/grade")"
        tail -1 "$tmp/grade" | grep -q "^PASS .*strokes=$strokes\$" ||
            fail "$name: grader did not PASS with strokes=$strokes: $(tail -1 "$tmp/grade")"
    else
        echo "note: no shared grader at $grader; its check is skipped"
    fi
    # Export re-certifies the solution read back, and draws every output.
    "$bin" export "$task" "$sol" --report "$tmp/$name.html" --csv "$tmp/$name.csv" \
        --build-sheet "$tmp/$name.md" --urdf "$tmp/$name.urdf" >"$tmp/out" 2>&1 ||
        fail "$name: export exit $?: $(tail -3 "$tmp/out")"
    grep -q "not certified" "$tmp/out" && fail "$name: export does not certify it: $(cat "$tmp/out")"
    grep -q 'class="travel"' "$tmp/$name.html" || fail "$name: the report draws no travel"
    grep -q 'strokes\[1\]\[0\]' "$tmp/$name.html" || fail "$name: the report does not name strokes[1][0]"
    head -1 "$tmp/$name.csv" | grep -q ',phase,primitive,.*,stroke$' || fail "$name: CSV has no stroke column"
    grep -q ',travel,' "$tmp/$name.csv" || fail "$name: CSV has no travel rows"
done

# A stroke beyond reach: the core names it as strokes[1][0].
far="$root/tasks/infeasible/strokes-far-stroke.task.json"
"$bin" solve "$far" -o "$tmp/far.sol.json" >"$tmp/out" 2>&1
code=$?
[ "$code" -eq 3 ] || fail "far stroke: solve exit $code, expected 3 (infeasible)"
grep -q '"strokes\[1\]\[0\]"' "$tmp/far.sol.json" || fail "far stroke: core does not name strokes[1][0]: $(cat "$tmp/far.sol.json")"
[ -f "$grader" ] && { python3 "$grader" "$far" "$tmp/far.sol.json" --expect infeasible >"$tmp/grade" 2>&1 ||
    fail "far stroke: grader: $(tail -1 "$tmp/grade")"; }
"$bin" explain "$far" --time-limit 30 --solve-seconds 2 --json >"$tmp/explain.json" 2>"$tmp/err"
code=$?
[ "$code" -eq 3 ] || fail "far stroke: explain exit $code, expected 3: $(cat "$tmp/err")"
python3 - "$tmp/explain.json" <<'PY' || fail "far stroke: explain core does not name strokes[1][0]: $(cat "$tmp/explain.json")"
import json, sys
core = json.load(open(sys.argv[1]))["core"]
sys.exit(0 if "strokes[1][0]" in core and not any(p.startswith("trajectory") for p in core) else 1)
PY

# Bad documents: exit 2, naming the part.
bad() {  # what expected-part python-edit
    local what=$1 part=$2 edit=$3
    python3 - "$root/tasks/strokes-two-circles.json" "$tmp/bad.json" "$edit" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(doc, open(sys.argv[2], "w"))
PY
    "$bin" validate "$tmp/bad.json" >"$tmp/out" 2>&1
    local code=$?
    [ "$code" -eq 2 ] || fail "$what: validate exit $code, expected 2"
    grep -qF "$part" "$tmp/out" || fail "$what: message does not name $part: $(cat "$tmp/out")"
    "$bin" solve "$tmp/bad.json" -o "$tmp/bad.sol.json" >"$tmp/out" 2>&1
    code=$?
    [ "$code" -eq 2 ] || fail "$what: solve exit $code, expected 2"
}
bad "both keys" "strokes" 'doc["trajectory"] = doc["strokes"][0]'
bad "empty stroke" "strokes[1]" 'doc["strokes"][1] = []'
bad "no strokes" "strokes" 'doc["strokes"] = []'
bad "discontinuous stroke" "strokes[2][1]" 'doc["strokes"][2][1]["start"] = [0.46, 0.30]'

"$bin" validate "$root/tasks/strokes-two-circles.json" >"$tmp/out" 2>&1 ||
    fail "valid strokes task: validate exit $?: $(cat "$tmp/out")"

finish strokes
