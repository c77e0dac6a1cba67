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
assert rose["motion_seconds"] is not None and rose["motion_seconds"] > 0, rose
assert bad["motion_seconds"] is None, bad
assert os.path.isfile(rose["solution"]), rose
# Stage seconds come from the run's summary line: each one a share of the run.
stages = [rose[k] for k in ("front_seconds", "refine_seconds", "verify_seconds")]
assert all(s >= 0 for s in stages) and stages[0] > 0, rose
assert sum(stages) <= rose["seconds"] + 0.01, rose
assert "front_seconds" not in bad, bad
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

# Outputs are named after the path below the suite folder: tasks of the
# same file name in two folders, and one whose name looks like a numbered
# duplicate, keep apart.
mkdir -p "$tmp/same/a" "$tmp/same/b"
for t in a/x b/x a/x-2; do cp "$root/tasks/rose.json" "$tmp/same/$t.task.json"; done
batch "$tmp/same" --jobs 2 --out "$tmp/same.jsonl" --solutions "$tmp/same-sol" --time-limit 30
code=$?
[ "$code" -eq 0 ] || fail "batch of same-named tasks: exit $code ($(tail -3 "$tmp/err"))"
python3 - "$tmp/same.jsonl" "$tmp/same" "$tmp/same-sol" <<'EOF' || fail "same-named tasks share output files"
import json, os, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
suite, sol = sys.argv[2], sys.argv[3]
got = {os.path.relpath(l["task"], suite): l["solution"] for l in lines}
want = {t + ".task.json": os.path.join(sol, t + ".solution.json") for t in ("a/x", "a/x-2", "b/x")}
assert got == want, got
for path in want.values():
    assert json.load(open(path))["status"] == "solved", path
    assert os.path.isfile(path[: -len(".solution.json")] + ".log"), path
EOF

# A folder, a missing file and a task named in a list: two failed lines, the
# task still solved.
mkdir -p "$tmp/listed-folder"
printf '%s\n' "$tmp/listed-folder" "$tmp/no-such.json" "$root/tasks/rose.json" >"$tmp/odd-list.txt"
batch "$tmp/odd-list.txt" --jobs 2 --out "$tmp/odd.jsonl" --time-limit 30
code=$?
[ "$code" -eq 1 ] || fail "batch with a folder in its list: exit $code, expected 1 ($(tail -3 "$tmp/err"))"
python3 - "$tmp/odd.jsonl" <<'EOF' || fail "a folder or a missing file in a list is not one failed line"
import json, sys
lines = {l["task"].rsplit("/", 1)[-1]: l for l in map(json.loads, open(sys.argv[1]))}
assert len(lines) == 3, lines
folder, missing, rose = lines["listed-folder"], lines["no-such.json"], lines["rose.json"]
assert folder["status"] == "invalid" and "folder" in folder["message"], folder
assert missing["status"] == "invalid" and "no such file" in missing["message"], missing
assert rose["status"] == "solved", rose
EOF

# --shorten-gap reaches every solve: with 0.5 m the rose keeps its first
# certified robot (0.97 m; the other elbow's is 0.54 m).
mkdir -p "$tmp/gap"
cp "$root/tasks/rose.json" "$tmp/gap/rose.json"
batch "$tmp/gap" --out "$tmp/gap.jsonl" --time-limit 60 --shorten-gap 0.5
code=$?
[ "$code" -eq 0 ] || fail "batch --shorten-gap: exit $code ($(tail -3 "$tmp/err"))"
python3 - "$tmp/gap.jsonl" <<'EOF' || fail "--shorten-gap is not passed to the solves"
import json, sys
(line,) = map(json.loads, open(sys.argv[1]))
assert line["status"] == "solved" and line["total_link_length"] > 0.9, line
EOF
"$bin" batch "$tmp/gap" --out "$tmp/gap2.jsonl" --shorten-gap -1 >/dev/null 2>&1
[ $? -eq 2 ] || fail "batch --shorten-gap -1 is not a usage error"

# Children die with their parent, even one killed by SIGKILL.
mkdir -p "$tmp/slow"
for i in 1 2; do cp "$root/tasks/wipe-table.json" "$tmp/slow/wipe$i.json"; done  # ~15 s each
"$bin" batch "$tmp/slow" --jobs 2 --out "$tmp/slow.jsonl" --solutions "$tmp/slow-sol" \
    --time-limit 60 >/dev/null 2>&1 &
parent=$!
children=""
for _ in $(seq 100); do
    children=$(pgrep -P "$parent" | tr '\n' ' ')
    [ -n "$children" ] && break
    sleep 0.05
done
[ -n "$children" ] || fail "batch started no solve to kill"
kill -KILL "$parent"
wait "$parent" 2>/dev/null
alive() {  # pids: those still running (a zombie is dead)
    for pid in "$@"; do
        state=$(ps -o stat= -p "$pid" 2>/dev/null) && [ "${state#Z}" = "$state" ] && echo "$pid"
    done
}
for _ in $(seq 50); do
    [ -z "$(alive $children)" ] && break
    sleep 0.1
done
left=$(alive $children)
[ -z "$left" ] || { fail "solves outlive a SIGKILLed batch: $left"; kill -KILL $left 2>/dev/null; }

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
