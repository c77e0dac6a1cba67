#!/usr/bin/env bash
# scripts/loop-tasks: a closed polygon of 128 segments round a post (the
# issue's loop), a square of 256 drawn by a seed and the loop as one circle
# primitive are solved with 3 joints (2 are proved impossible by the loop
# round the post), each well within its time limit, and the shared grader
# passes the solutions.
# Arguments: modsynth, source root, shared folder (default:
# MODSYNTH_SHARED_DIR, else beside the source root).
set -u
source "$(dirname "$0")/shell_test_lib.sh"
shared=${3:-${MODSYNTH_SHARED_DIR:-$root/../shared}}
grader=$shared/grader/check_solution.py
gen=$root/scripts/loop-tasks

python3 "$gen" --out "$tmp/a" --shape polygon --segments 128 >"$tmp/gen" 2>&1 ||
    fail "generator exit $?: $(tail -3 "$tmp/gen")"
python3 "$gen" --out "$tmp/a" --shape square --segments 256 --seed 5 >>"$tmp/gen" 2>&1 ||
    fail "generator exit $?: $(tail -3 "$tmp/gen")"
python3 "$gen" --out "$tmp/a" --shape circle >>"$tmp/gen" 2>&1 ||
    fail "generator exit $?: $(tail -3 "$tmp/gen")"
for task in "$tmp/a/polygon-128.task.json" "$tmp/a/square-256-s5-0.task.json" \
    "$tmp/a/circle-1.task.json"; do
    name=$(basename "$task" .task.json)
    # A few seconds on one loaded core; the limit leaves room.
    "$bin" solve "$task" -o "$tmp/sol.json" --time-limit 60 >"$tmp/out" 2>&1
    code=$?
    [ $code -eq 0 ] || fail "$name: solve exit $code, expected 0 (solved): $(tail -3 "$tmp/out")"
    grep -q "2 joints: proved infeasible" "$tmp/out" || fail "$name: 2 joints not proved infeasible"
    python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(d["robot"]["dof"] != 3)' \
        "$tmp/sol.json" || fail "$name: solved with other than 3 joints"
    if [ -f "$grader" ]; then
        python3 "$grader" "$task" "$tmp/sol.json" --expect solved >"$tmp/grade" 2>&1 ||
            fail "$name: grader rejects modsynth's solution: $(tail -1 "$tmp/grade")"
    else
        echo "note: no shared grader at $grader; its check is skipped"
    fi
done
finish loop_tasks
