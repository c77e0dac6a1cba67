#!/usr/bin/env bash
# scripts/keyhole-tasks: the same seeds give the same bytes; every planted
# 3-joint answer keeps its links clear of the posts and its tip on the path,
# checked here with plain forward kinematics, by the generator's --check
# (which must also catch a spoiled answer), by the shared grader and by
# modsynth's verifier (export). modsynth solves every task with 3 joints (the
# shared grader passes the solutions) and, with 2 joints, proves it
# infeasible as the generator's test says.
# Arguments: modsynth, source root, shared folder (default:
# MODSYNTH_SHARED_DIR, else beside the source root).
set -u
source "$(dirname "$0")/shell_test_lib.sh"
shared=${3:-${MODSYNTH_SHARED_DIR:-$root/../shared}}
grader=$shared/grader/check_solution.py
gen=$root/scripts/keyhole-tasks

python3 "$gen" --seed 1 --count 3 --out "$tmp/a" >"$tmp/gen" 2>&1 || fail "generator exit $?: $(tail -3 "$tmp/gen")"
python3 "$gen" --seed 1 --count 3 --out "$tmp/b" >/dev/null 2>&1 || fail "generator exit $? on the second run"
[ "$(ls "$tmp/a" | wc -l)" -eq 9 ] || fail "expected 3 tasks, expectations and planted answers: $(ls "$tmp/a")"
for f in "$tmp"/a/*; do
    cmp -s "$f" "$tmp/b/$(basename "$f")" || fail "$(basename "$f") differs between two runs of the same seed"
done
cmp -s "$tmp/a/keyhole-0001.task.json" "$tmp/a/keyhole-0002.task.json" && fail "seeds 1 and 2 give the same task"

# Plain forward kinematics, independent of the generator's code.
python3 - "$tmp/a" >"$tmp/fk" 2>&1 <<'PY' || fail "independent check: $(tail -3 "$tmp/fk")"
import glob, json, math, sys

def seg_dist(a, b, p):
    ab, ap = (b[0] - a[0], b[1] - a[1]), (p[0] - a[0], p[1] - a[1])
    t = max(0.0, min(1.0, (ap[0] * ab[0] + ap[1] * ab[1]) / (ab[0] ** 2 + ab[1] ** 2)))
    return math.hypot(ap[0] - t * ab[0], ap[1] - t * ab[1])

for tpath in sorted(glob.glob(sys.argv[1] + "/*.task.json")):
    stem = tpath[: -len(".task.json")]
    task, sol = json.load(open(tpath)), json.load(open(stem + ".planted.json"))
    expect = json.load(open(stem + ".expect.json"))
    bot, diam = sol["robot"], task["robot"]["link_diameter"]
    assert task["robot"]["dof"] == [2, 3], task["robot"]
    assert 1 <= len(task["trajectory"]) <= 2, "one or two primitives"
    assert {p["type"] for p in task["trajectory"]} <= {"line", "arc"}
    assert expect["status"] == "solved" and expect["planted_dof"] == 3 == bot["dof"], expect
    assert abs(expect["planted_sum_link_lengths"] - sum(bot["link_lengths"])) < 1e-9, expect
    reg = task["base_regions"][0]
    assert all(reg["min"][k] <= bot["base"][k] <= reg["max"][k] for k in range(2)), "base"
    posts = task["obstacles"]
    # The ring: posts equidistant from its centre, neighbours overlapping
    # but for one opening wider than a link.
    angles = sorted(math.atan2(o["center"][1] - bot["base"][1], o["center"][0] - bot["base"][0])
                    for o in posts)
    ring = [math.dist(o["center"], bot["base"]) for o in posts]
    assert max(ring) - min(ring) < 1e-9, "posts not on one circle round the base"
    gaps = [(b - a) * ring[0] for a, b in zip(angles, angles[1:] + [angles[0] + 2 * math.pi])]
    rho = posts[0]["radius"]
    wide = [g for g in gaps if g > 2 * rho]
    assert len(wide) == 1 and wide[0] > 2 * rho + diam, "exactly one opening, wide enough for a link"
    worst, pts_seen = float("inf"), set()
    for smp in sol["samples"]:
        pts, a = [bot["base"]], 0.0
        for l, q in zip(bot["link_lengths"], smp["q"]):
            a += q
            pts.append((pts[-1][0] + l * math.cos(a), pts[-1][1] + l * math.sin(a)))
        for k in range(3):
            for o in posts:
                worst = min(worst, seg_dist(pts[k], pts[k + 1], o["center"]) - o["radius"] - diam / 2)
        prim = task["trajectory"][smp["primitive"]]
        if prim["type"] == "line":
            off = seg_dist(prim["start"], prim["end"], pts[-1])
        else:
            off = abs(math.dist(pts[-1], prim["center"]) - math.dist(prim["start"], prim["center"]))
        assert off < 1e-6, "tip %.2e m off the path" % off
        pts_seen.add(smp["primitive"])
    assert worst > 0, "%s: a link touches a post (clearance %.4f)" % (stem, worst)
    assert pts_seen == set(range(len(task["trajectory"]))), "a primitive is never traced"
    print("%s clearance %.4f" % (stem, worst))
PY

python3 "$gen" --seed 1 --count 3 --out "$tmp/a" --check >"$tmp/check" 2>&1 ||
    fail "--check rejects fresh tasks: $(cat "$tmp/check")"
# A spoiled answer: link 1 turned away from the opening, into the ring.
python3 - "$tmp/b/keyhole-0002.planted.json" <<'PY'
import json, sys
sol = json.load(open(sys.argv[1]))
for smp in sol["samples"]:
    smp["q"][0] += 1.0
json.dump(sol, open(sys.argv[1], "w"))
PY
python3 "$gen" --seed 2 --out "$tmp/b" --check >"$tmp/check" 2>&1 && fail "--check accepts link 1 turned into the ring"
grep -q "cuts a post" "$tmp/check" || fail "--check does not say a link cuts a post: $(cat "$tmp/check")"

if [ -f "$grader" ]; then
    for t in "$tmp"/a/*.task.json; do
        python3 "$grader" "$t" "${t%.task.json}.planted.json" --expect solved >"$tmp/grade" 2>&1 ||
            fail "$(basename "$t"): grader rejects the planted answer: $(tail -1 "$tmp/grade")"
    done
else
    echo "note: no shared grader at $grader; its checks are skipped"
fi

# modsynth's own verifier certifies every planted answer too.
for t in "$tmp"/a/*.task.json; do
    "$bin" export "$t" "${t%.task.json}.planted.json" --csv "$tmp/planted.csv" >"$tmp/out" 2>&1 ||
        fail "$(basename "$t"): export of the planted answer exit $?: $(tail -2 "$tmp/out")"
    grep -q "not certified" "$tmp/out" && fail "$(basename "$t"): planted answer not certified: $(cat "$tmp/out")"
done

# modsynth solves every task: with 3 joints (a 2-joint arm cannot reach the
# path), and the grader passes the solution. Each takes 1-3 s on one core;
# the limit leaves room for a loaded machine.
for task in "$tmp"/a/*.task.json; do
    name=$(basename "$task" .task.json)
    "$bin" solve "$task" -o "$tmp/sol.json" --time-limit 30 >"$tmp/out" 2>&1
    code=$?
    [ $code -eq 0 ] || fail "$name: solve exit $code, expected 0 (solved): $(tail -3 "$tmp/out")"
    python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(d["robot"]["dof"] != 3)' \
        "$tmp/sol.json" || fail "$name: solved with other than 3 joints: $(tail -2 "$tmp/out")"
    if [ -f "$grader" ]; then
        python3 "$grader" "$task" "$tmp/sol.json" --expect solved >"$tmp/grade" 2>&1 ||
            fail "$name: grader rejects modsynth's solution: $(tail -1 "$tmp/grade")"
    fi
done
task=$tmp/a/keyhole-0001.task.json

# Two joints cannot do it: the generator's sampled test, and modsynth's
# 2-joint branch and bound proves it on the same task (a 2-joint solution
# would contradict the generator).
python3 -c 'import json,sys; t=json.load(open(sys.argv[1])); t["robot"]["dof"]=[2]; json.dump(t,open(sys.argv[2],"w"))' \
    "$task" "$tmp/two.task.json"
"$bin" solve "$tmp/two.task.json" -o "$tmp/two.sol.json" --time-limit 30 >"$tmp/out" 2>&1
code=$?
case $code in
    3) grep -q '"trajectory\[0\]"' "$tmp/two.sol.json" || fail "2 joints: core does not name trajectory[0]" ;;
    *) fail "2 joints: solve exit $code, expected 3 (infeasible): $(tail -3 "$tmp/out")" ;;
esac
finish keyhole
