#!/usr/bin/env bash
# The scripts that grade with the shared grader say so in one line when it
# is not at hand (a clone without ../shared beside it), rather than ending
# in a Python traceback.
#
# usage: scripts_test.sh SOURCE_DIR
set -u
root=$1
failures=0
passes=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passes=$((passes + 1)); }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for script in bench certify-planted drawing-suite; do
  MODSYNTH_GRADER=$tmp/nowhere "$root/scripts/$script" >"$tmp/out" 2>"$tmp/err"
  code=$?
  lines=$(wc -l <"$tmp/err")
  if [ "$code" -ne 0 ] && [ "$lines" -eq 1 ] && grep -q "^$script: needs the shared grader, not found at $tmp/nowhere" "$tmp/err" &&
     ! grep -q Traceback "$tmp/err" && [ ! -s "$tmp/out" ]; then
    pass
  else
    fail "$script without the grader: exit $code, $lines line(s): $(head -c 300 "$tmp/err")"
  fi
done

echo "$passes passed, $failures failed: scripts"
[ "$failures" -eq 0 ]
