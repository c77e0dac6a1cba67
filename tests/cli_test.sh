#!/usr/bin/env bash
# The command line as a user meets it: exit codes, messages that name the
# offending part, output files, determinism.
set -u
bin=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

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

# Every bad fixture is rejected with exit 2 and a message naming its part.
while IFS=$'\t' read -r file part; do
    expect_exit 2 "validate $file" "$bin" validate "$root/tests/fixtures/invalid/$file"
    grep -qF -- "$part" "$tmp/err" || fail "validate $file: message does not name '$part': $(cat "$tmp/err")"
done < <(python3 -c '
import json, sys
for f, e in sorted(json.load(open(sys.argv[1])).items()):
    print(f + "\t" + e["part"])' "$root/tests/fixtures/invalid/expected.json")

# Usage errors and informational flags.
expect_exit 2 "no subcommand" "$bin"
expect_exit 2 "unknown subcommand" "$bin" frobnicate
expect_exit 2 "solve without -o" "$bin" solve "$root/tasks/rose.json"
expect_exit 2 "negative time limit" "$bin" solve "$root/tasks/rose.json" -o "$tmp/x.json" --time-limit -1
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

# Unwritable output is an internal error, reported, not a crash.
expect_exit 1 "unwritable output" "$bin" solve "$root/tasks/rose.json" -o "$tmp/no/such/dir/x.json" --quiet

echo "$(( failures == 0 ? 1 : 0 )) passed, $(( failures == 0 ? 0 : 1 )) failed: cli"
[ "$failures" -eq 0 ]
