#!/usr/bin/env bash
# The shipped drawings (the outline of tasks/drawings/bracket.dxf, all of
# tasks/drawings/sketch.svg) and a text placed on a wall (and an easel) in
# front of a base on the floor and wrapped round an upright cylinder: each import is solved
# (exit 0) and, when the shared grader is beside the source, its solution
# passes it.
# Arguments: modsynth binary, source root, folder of the shared contract
# (default: beside the source root).
set -u
source "$(dirname "$0")/shell_test_lib.sh"
shared=${3:-$root/../shared}
grader=$shared/grader/check_solution.py
[ -f "$grader" ] || echo "note: no $grader; the solutions are not graded"
base=-0.05,-0.05,0.02,0.05,0.05,0.02

solve_and_grade() {  # name import-args...
    local name=$1
    shift
    "$bin" import "$@" -o "$tmp/$name.json" --base "$base" \
        >"$tmp/out" 2>"$tmp/err" || { fail "$name: import: exit $?: $(cat "$tmp/err")"; return; }
    "$bin" solve "$tmp/$name.json" -o "$tmp/$name.solution.json" --time-limit 120 \
        >"$tmp/out" 2>"$tmp/err"
    local code=$?
    [ "$code" -eq 0 ] || { fail "$name: solve: exit $code: $(head -c 300 "$tmp/out")"; return; }
    echo "$name: $(head -n 1 "$tmp/out")"
    if [ -f "$grader" ]; then
        python3 "$grader" "$tmp/$name.json" "$tmp/$name.solution.json" >"$tmp/grade" 2>&1 ||
            fail "$name: the grader fails the solution: $(tail -1 "$tmp/grade")"
    fi
}
bracket=("$root/tasks/drawings/bracket.dxf" --layers outline)
sketch=("$root/tasks/drawings/sketch.svg" --width 0.2)
# The wall x = 0.4 faces the base (its normal U x V is -x).
wall=(--plane 0.4,0,0.25,0,-1,0,0,0,1)
# An upright cylinder of radius 0.08 whose near side is 0.32 m from the base.
cylinder=(--cylinder 0.4,0,0.25,0,0,1,0.08)
solve_and_grade bracket-wall "${bracket[@]}" "${wall[@]}"
solve_and_grade bracket-cylinder "${bracket[@]}" "${cylinder[@]}"
# An easel leaning back by 30 degrees (V typed to four digits: 0.866).
solve_and_grade bracket-easel "${bracket[@]}" --plane 0.4,0,0.3,0,-1,0,0.5,0,0.866
solve_and_grade sketch-wall "${sketch[@]}" "${wall[@]}"
solve_and_grade sketch-cylinder "${sketch[@]}" "${cylinder[@]}"
# A label round a bottle of radius 6 cm: lines round it and across it.
solve_and_grade label --text modsynth --height 0.03 --cylinder 0.4,0,0.25,0,0,1,0.06
finish surface_examples
