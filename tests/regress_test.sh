#!/usr/bin/env bash
# `modsynth regress encodings` fails on tampered expectations and names the
# task, passes an improvement, and refuses missing or stale expectations.
# (The committed encodings themselves are checked by the regress_encodings
# test.)
set -u
source "$(dirname "$0")/shell_test_lib.sh"

# Copies the committed encodings, applies a Python edit to one expectation,
# runs the regression against the copy.
tampered() {  # name expectation-file python-statement-on-doc
    local name=$1 file=$2 edit=$3
    rm -rf "$tmp/$name"
    cp -r "$root/encodings" "$tmp/$name"
    python3 - "$tmp/$name/$file" "$edit" <<'EOF'
import json, sys
path, edit = sys.argv[1], sys.argv[2]
doc = json.load(open(path))
exec(edit)
json.dump(doc, open(path, "w"), indent=1)
EOF
    timeout 300 "$bin" regress encodings --dir "$tmp/$name" --tasks "$root/tasks" >"$tmp/out" 2>"$tmp/err"
}

expect_regression() {  # what task-key
    local what=$1 key=$2 code=$3
    [ "$code" -eq 1 ] || fail "$what: exit $code, expected 1"
    grep -q "^REGRESSED $key" "$tmp/out" || fail "$what: no REGRESSED line naming $key: $(cat "$tmp/out")"
}

tampered shorter rose.expect.json 'doc["solve"]["total_link_length"] *= 0.5'
expect_regression "expected robot twice as short" rose $?

tampered status rose.expect.json 'doc["solve"]["status"] = "infeasible"'
expect_regression "expected infeasible" rose $?

tampered core infeasible/out-of-reach.expect.json 'doc["front_stage"][0]["core"] = ["obstacles[0]"]'
expect_regression "another front-stage core" infeasible/out-of-reach $?

tampered front rose.expect.json 'doc["front_stage"][0]["result"] = "unsat"'
expect_regression "front stage expected unsat" rose $?

# Better than recorded: reported, not a failure.
tampered longer rose.expect.json 'doc["solve"]["total_link_length"] *= 2.0'
code=$?
[ "$code" -eq 0 ] || fail "a shorter robot than recorded fails the regression (exit $code)"
grep -q "improved" "$tmp/out" || fail "a shorter robot is not reported as an improvement"

tampered unknown rose.expect.json 'doc["solve"].update(status="unknown", dof=None, total_link_length=None)'
code=$?
[ "$code" -eq 0 ] || fail "solved where unknown was recorded fails the regression (exit $code)"

# Within the tolerance: unchanged.
tampered close rose.expect.json 'doc["solve"]["total_link_length"] *= 0.98'
[ $? -eq 0 ] || fail "a 2% longer robot counts as a regression at the default 5% tolerance"

# A missing expectation and an expectation without a task both fail.
rm -rf "$tmp/missing" && cp -r "$root/encodings" "$tmp/missing" && rm "$tmp/missing/rose.expect.json"
timeout 300 "$bin" regress encodings --dir "$tmp/missing" --tasks "$root/tasks" >"$tmp/out" 2>&1
expect_regression "missing expectation" rose $?
rm -rf "$tmp/stale" && cp -r "$root/encodings" "$tmp/stale" && cp "$tmp/stale/rose.expect.json" "$tmp/stale/gone.expect.json"
timeout 300 "$bin" regress encodings --dir "$tmp/stale" --tasks "$root/tasks" >"$tmp/out" 2>&1
expect_regression "stale expectation" gone $?

# A changed dump is reported, not failed.
rm -rf "$tmp/dump" && cp -r "$root/encodings" "$tmp/dump" && echo "; edited" >>"$tmp/dump/rose.dof2.smt2"
timeout 300 "$bin" regress encodings --dir "$tmp/dump" --tasks "$root/tasks" >"$tmp/out" 2>&1
[ $? -eq 0 ] || fail "an edited encoding dump fails the regression"
grep -q "changed" "$tmp/out" || fail "an edited encoding dump is not reported"

# Regenerating into an empty folder reproduces the committed files.
timeout 300 "$bin" regress encodings --regenerate --dir "$tmp/regen" --tasks "$root/tasks" >"$tmp/out" 2>&1 ||
    fail "--regenerate failed: $(tail -3 "$tmp/out")"
(cd "$root/encodings" && find . -name '*.smt2' | sort) >"$tmp/committed"
(cd "$tmp/regen" && find . -name '*.smt2' | sort) >"$tmp/fresh"
cmp -s "$tmp/committed" "$tmp/fresh" || fail "--regenerate writes other files than the committed ones"

finish regress
