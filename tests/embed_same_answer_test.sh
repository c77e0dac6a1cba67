#!/usr/bin/env bash
# The library and the command line answer alike: modsynth::solve (through
# the embed example, built on the public headers alone) and `modsynth
# solve` write byte-identical solution files for every bundled task,
# modules included (the infeasible ones are explained too, which takes
# long: one stands for them); the spatial examples too.
set -u
source "$(dirname "$0")/shell_test_lib.sh"
example=$3

for t in "$root"/tasks/*.json "$root"/tasks/infeasible/out-of-reach.task.json \
    "$root"/tasks/spatial/*.json "$root"/tests/fixtures/spatial/s3-0001.task.json \
    "$root"/tests/fixtures/spatial/sir-0001.task.json; do
    name=$(basename "$t" .json)
    "$example" "$t" "$tmp/$name.library.json" >"$tmp/$name.library.out" 2>&1
    "$bin" solve "$t" -o "$tmp/$name.cli.json" --quiet --time-limit 30 >/dev/null 2>&1
    if [ ! -s "$tmp/$name.library.json" ]; then
        fail "$name: the library wrote no solution ($(head -c 300 "$tmp/$name.library.out"))"
    elif ! cmp -s "$tmp/$name.library.json" "$tmp/$name.cli.json"; then
        fail "$name: modsynth::solve and modsynth solve answer differently"
    fi
done
# The solved answers carry their modules, and the example says so.
grep -q '"modules"' "$tmp/rose.library.json" || fail "rose: no modules in the library's answer"
grep -q 'modules X' "$tmp/rose.library.out" || fail "rose: the example does not print the modules"
grep -q '"dh"' "$tmp/helix-pipe.library.json" || fail "helix-pipe: no DH chain in the library's answer"
grep -q 're-certified: yes' "$tmp/helix-pipe.library.out" ||
    fail "helix-pipe: the library's spatial answer is not re-certified"
finish embed_same_answer
