#!/usr/bin/env bash
# The hand-made spatial examples (tasks/spatial/): each is solved (exit 0)
# and, when the shared grader is beside the source, its solution passes it.
# Arguments: modsynth binary, source root, folder of the shared contract
# (default: beside the source root).
set -u
source "$(dirname "$0")/shell_test_lib.sh"
shared=${3:-$root/../shared}
grader=$shared/grader/check_solution.py
[ -f "$grader" ] || echo "note: no $grader; the solutions are not graded"
count=0
for task in "$root"/tasks/spatial/*.json; do
    name=$(basename "$task" .json)
    count=$((count + 1))
    "$bin" solve "$task" -o "$tmp/$name.solution.json" --time-limit 120 >"$tmp/out" 2>"$tmp/err"
    code=$?
    [ "$code" -eq 0 ] || { fail "$name: exit $code: $(head -c 300 "$tmp/out")"; continue; }
    if [ -f "$grader" ]; then
        python3 "$grader" "$task" "$tmp/$name.solution.json" >"$tmp/grade" 2>&1 ||
            fail "$name: the grader fails the solution: $(tail -1 "$tmp/grade")"
    fi
done
[ "$count" -ge 4 ] || fail "only $count examples in tasks/spatial/"
finish spatial_examples
