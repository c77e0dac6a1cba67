#!/usr/bin/env bash
# `modsynth batch` end to end: one results line per task with the right
# figures and exit codes, shards that partition the suite, and a watchdog
# kill reported as a timeout instead of a hang.
set -u
source "$(dirname "$0")/shell_test_lib.sh"

# The bundled tasks plus one that cannot be parsed.
mkdir -p "$tmp/suite"
cp -r "$root/tasks/." "$tmp/suite/"
echo '{"format": "modsynth-task/1", "trajectory": []}' >"$tmp/suite/zz-bad.json"
expected_count=$(find "$tmp/suite" -name '*.json' ! -name '*.core.json' | wc -l)

# Runs batch under an outer limit far above what it needs, so that a hang
# fails the test instead of stalling it.
batch() { timeout 300 "$bin" batch "$@" >"$tmp/out" 2>"$tmp/err"; }

batch "$tmp/suite" --jobs 2 --out "$tmp/all.jsonl" --solutions "$tmp/sol"
code=$?
[ "$code" -eq 1 ] || fail "batch with a bad task: exit $code, expected 1 ($(tail -3 "$tmp/err"))"
grep -q "failed" "$tmp/out" || fail "no summary table on stdout"
grep -q "\[$expected_count/$expected_count\]" "$tmp/err" || fail "no final progress line on stderr"

python3 - "$tmp/all.jsonl" "$tmp/suite" "$expected_count" <<'EOF' || fail "results.jsonl content"
import json, os, sys
path, suite, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
lines = [json.loads(l) for l in open(path)]
assert len(lines) == count, f"{len(lines)} lines for {count} tasks"
keys = {"task", "name", "status", "exit_code", "seconds", "dof", "total_link_length",
        "clearance_margin"}
for l in lines:
    assert keys <= l.keys(), f"missing keys in {l}"
    assert l["seconds"] >= 0
by_name = {os.path.basename(l["task"]): l for l in lines}
bad = by_name["zz-bad.json"]
assert bad["status"] == "invalid" and bad["exit_code"] == 2, bad
assert "trajectory" in bad["message"], bad
rose = by_name["rose.json"]
assert rose["status"] == "solved" and rose["exit_code"] == 0, rose
assert rose["dof"] == 2 and 0.1 < rose["total_link_length"] < 3.0, rose
assert rose["clearance_margin"] is not None and rose["clearance_margin"] >= 0, rose
assert os.path.isfile(rose["solution"]), rose
for l in lines:
    if "/infeasible/" in l["task"]:
        assert l["status"] == "infeasible" and l["exit_code"] == 3 and l["core"], l
assert [l["task"] for l in lines] == sorted(l["task"] for l in lines), "lines not in task order"
EOF

# A list file, split into shards: together they are the whole suite, once.
find "$tmp/suite" -name '*.json' ! -name '*.core.json' | sort -r >"$tmp/list.txt"
echo "# a comment" >>"$tmp/list.txt"
for n in 2 3; do
    for k in $(seq 1 "$n"); do
        batch "$tmp/list.txt" --jobs 2 --shard "$k/$n" --out "$tmp/shard-$n-$k.jsonl" --time-limit 30
    done
    python3 - "$tmp/list.txt" "$tmp"/shard-"$n"-*.jsonl <<'EOF' || fail "shards of $n do not partition the suite"
import sys
listed = sorted(l.strip() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#"))
import json
shards = [[json.loads(l)["task"] for l in open(p)] for p in sys.argv[2:]]
union = [t for s in shards for t in s]
assert sorted(union) == listed, (union, listed)
assert len(set(union)) == len(union), "a task is in two shards"
n = len(shards)
for k, s in enumerate(shards):
    assert s == listed[k::n], (k, s)
EOF
done

# The watchdog: a limit no solve can meet, no grace. Every run must be
# killed and reported, promptly.
start=$(date +%s)
batch "$tmp/suite" --jobs 2 --out "$tmp/killed.jsonl" --time-limit 0.001 --grace 0
code=$?
[ "$code" -eq 1 ] || fail "batch past its limits: exit $code, expected 1"
[ $(($(date +%s) - start)) -lt 60 ] || fail "watchdog did not stop the runs promptly"
python3 - "$tmp/killed.jsonl" "$expected_count" <<'EOF' || fail "killed runs not reported as timeouts"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
assert len(lines) == int(sys.argv[2])
for l in lines:
    assert l["status"] == "timeout" and l["exit_code"] == 137 and l["signal"] == 9, l
EOF

# Usage errors.
batch "$tmp/suite" --out "$tmp/x.jsonl" --shard 3/2
[ $? -eq 2 ] || fail "--shard 3/2 accepted"
grep -q -- "--shard" "$tmp/err" || fail "bad --shard message does not name the option"
batch "$tmp/suite" --out "$tmp/x.jsonl" --shard two
[ $? -eq 2 ] || fail "--shard two accepted"
batch "$tmp/no-such-folder" --out "$tmp/x.jsonl"
[ $? -eq 2 ] || fail "missing input accepted"
batch "$tmp/suite" --out "$tmp/x.jsonl" --jobs 0
[ $? -eq 2 ] || fail "--jobs 0 accepted"

finish batch
