#!/usr/bin/env bash
# Timing a controller accepts (docs/formats.md, "Joint limits and timing"),
# end to end: shipped and planted tasks with robot.joint_limits added are
# solved, and the files `solve` writes are checked: the solution by the
# shared reference checker (time, timing, limits, rest) and by this test's
# own reading of the rules, the CSV and the ROS 2 joint trajectory by
# parsing them (times, lengths, joint names equal to the URDF's).
# Arguments: modsynth binary, source root, folder of the shared contract
# (default: beside the source root); without the shared checker its part is
# skipped and said so, the rest still runs.
set -u
source "$(dirname "$0")/shell_test_lib.sh"
shared=${3:-$root/../shared}
grader=$shared/grader/check_solution.py
planter=$shared/grader/plant.py
[ -f "$grader" ] || echo "note: no $grader; the shared checker's part is skipped"

# A copy of a task with robot.joint_limits set to the JSON given.
with_limits() {  # source destination limits-json
    python3 - "$@" <<'PY'
import json, sys
src, dst, limits = sys.argv[1], sys.argv[2], json.loads(sys.argv[3])
doc = json.load(open(src))
doc.setdefault("robot", {})["joint_limits"] = limits
json.dump(doc, open(dst, "w"), indent=1)
PY
}

# Solves a task with every controller output and checks them.
check_task() {  # name task-file
    local name=$1 task=$2 out="$tmp/$1"
    mkdir -p "$out"
    timeout 300 "$bin" solve "$task" -o "$out/solution.json" --quiet --csv "$out/t.csv" \
        --joint-trajectory "$out/t.yaml" --urdf "$out/r.urdf" --report "$out/r.html" \
        >"$out/stdout" 2>"$out/stderr"
    local code=$?
    [ "$code" -eq 0 ] || { fail "$name: solve exit $code: $(tail -3 "$out/stderr")"; return; }
    if [ -f "$grader" ]; then
        python3 "$grader" "$task" "$out/solution.json" --expect solved --json >"$out/grade" ||
            fail "$name: the shared checker rejects the solution: $(tail -c 600 "$out/grade")"
        python3 - "$out/grade" <<'PY' || fail "$name: the checker's figures: $(tail -c 400 "$out/grade")"
import json, sys
text = open(sys.argv[1]).read()
g = json.loads(text[text.index("{"):text.rindex("}") + 1])
assert g["max_velocity_ratio"] <= 1 + 1e-6 and g["max_acceleration_ratio"] <= 1 + 1e-6, g
assert g["duration"] > 0, g
PY
    fi
    python3 - "$task" "$out" <<'PY' || fail "$name: the output files: see above"
import csv, json, math, sys
import xml.etree.ElementTree as ET
task_path, out = sys.argv[1], sys.argv[2]
task = json.load(open(task_path))
sol = json.load(open(out + "/solution.json"))
samples, dof = sol["samples"], sol["robot"]["dof"]
lim = task["robot"]["joint_limits"]
V = lim["velocity"] if isinstance(lim["velocity"], list) else [lim["velocity"]] * dof
A = lim["acceleration"] if isinstance(lim["acceleration"], list) else [lim["acceleration"]] * dof
assert len(V) == dof and len(A) == dof, "limits do not fit the robot"

# The rules of formats.md, read independently of the shared checker.
for i, s in enumerate(samples):
    assert len(s["qd"]) == dof and len(s["qdd"]) == dof, i
    for k in range(dof):
        assert abs(s["qd"][k]) <= V[k] * (1 + 1e-6), (i, k, s["qd"][k])
        assert abs(s["qdd"][k]) <= A[k] * (1 + 1e-6), (i, k, s["qdd"][k])
    if i == 0:
        continue
    p = samples[i - 1]
    dt = s["t"] - p["t"]
    assert dt > 0, ("t does not increase", i)
    for k in range(dof):
        assert abs(s["qd"][k] - p["qd"][k]) <= A[k] * dt + 1e-6, (i, k)
        mean = (s["q"][k] - p["q"][k]) / dt
        assert abs(mean - (s["qd"][k] + p["qd"][k]) / 2) <= A[k] * dt / 4 + 1e-6, (i, k)
for s in (samples[0], samples[-1]):
    assert max(abs(v) for v in s["qd"]) <= 1e-6, "not at rest at an end"

# CSV: the header, one row per sample, the same numbers.
rows = list(csv.reader(open(out + "/t.csv")))
names = ["t"] + [f"q{k+1}" for k in range(dof)] + ["phase", "primitive"] + \
        [f"qd{k+1}" for k in range(dof)] + [f"qdd{k+1}" for k in range(dof)]
if "stroke" in samples[0]:  # several strokes: the stroke column comes last
    names.append("stroke")
assert rows[0] == names, rows[0]
assert len(rows) == len(samples) + 1, (len(rows), len(samples))
for s, r in zip(samples, rows[1:]):
    assert abs(float(r[0]) - s["t"]) <= 1e-6
    for k in range(dof):
        assert abs(float(r[1 + k]) - s["q"][k]) <= 1e-9
        assert abs(float(r[3 + dof + k]) - s["qd"][k]) <= 1e-9
        assert abs(float(r[3 + 2 * dof + k]) - s["qdd"][k]) <= 1e-9
t_csv = [float(r[0]) for r in rows[1:]]
assert all(b >= a for a, b in zip(t_csv, t_csv[1:])), "CSV times go backwards"

# The joint trajectory: a YAML trajectory_msgs/JointTrajectory.
try:
    import yaml
    msg = yaml.safe_load(open(out + "/t.yaml"))
except ImportError:  # a reader for the plain subset the file uses
    msg, point, key = {"points": []}, None, None
    for line in open(out + "/t.yaml"):
        line = line.split("#")[0].rstrip()
        if not line.strip():
            continue
        body = line.strip().lstrip("- ")
        name, _, value = body.partition(":")
        value = value.strip()
        parse = lambda v: [x.strip() for x in v[1:-1].split(",") if x.strip()]
        if name == "joint_names":
            msg["joint_names"] = parse(value)
        elif line.startswith("  - "):
            point = {"time_from_start": {}}
            msg["points"].append(point)
            point[name] = [float(x) for x in parse(value)]
        elif point is not None and name in ("velocities", "accelerations", "positions", "effort"):
            point[name] = [float(x) for x in parse(value)]
        elif point is not None and name in ("sec", "nanosec"):
            point["time_from_start"][name] = int(value)
urdf = ET.parse(out + "/r.urdf").getroot()
joints = [j.get("name") for j in urdf.findall("joint") if j.get("type") == "revolute"]
assert msg["joint_names"] == joints, (msg["joint_names"], joints)
points = msg["points"]
assert len(points) == len(samples), (len(points), len(samples))
stamps = []
for s, p in zip(samples, points):
    for key in ("positions", "velocities", "accelerations"):
        assert len(p[key]) == dof, key
    for k in range(dof):
        assert abs(p["positions"][k] - s["q"][k]) <= 1e-9
        assert abs(p["velocities"][k] - s["qd"][k]) <= 1e-9
        assert abs(p["accelerations"][k] - s["qdd"][k]) <= 1e-9
    d = p["time_from_start"]
    assert 0 <= d["nanosec"] < 10**9
    stamps.append(d["sec"] * 10**9 + d["nanosec"])
    assert abs(stamps[-1] - s["t"] * 1e9) <= 1, "time_from_start is not t"
assert all(b > a for a, b in zip(stamps, stamps[1:])), "time_from_start does not increase"
print(f"{task_path}: {len(samples)} samples, {samples[-1]['t']:.3f} s")
PY
    grep -q 'id="chart-qd"' "$out/r.html" || fail "$name: the report has no velocity chart"
}

with_limits "$root/tasks/rose.json" "$tmp/rose.json" '{"velocity": 3.35, "acceleration": 10}'
check_task rose "$tmp/rose.json"
with_limits "$root/tasks/wipe-table.json" "$tmp/wipe.json" '{"velocity": 2.0, "acceleration": 5}'
check_task wipe-table "$tmp/wipe.json"
# One value per joint: only 3-joint robots are considered.
with_limits "$root/tasks/clean-table.json" "$tmp/clean.json" \
    '{"velocity": [3.35, 2.5, 3.35], "acceleration": [10, 6, 10]}'
check_task clean-table "$tmp/clean.json"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['robot']['dof']==3" \
    "$tmp/clean-table/solution.json" || fail "per-joint limits of 3 joints, but not a 3-joint robot"
# Several strokes: the travel between them is timed like the rest.
with_limits "$root/tasks/strokes-two-circles.json" "$tmp/strokes.json" '{"velocity": 2.0, "acceleration": 5}'
check_task strokes-two-circles "$tmp/strokes.json"
with_limits "$root/tasks/strokes-around-post.json" "$tmp/post.json" '{"velocity": 3.35, "acceleration": 10}'
check_task strokes-around-post "$tmp/post.json"

# Jerk limits (docs/formats.md): the contract's rules hold, and this test's
# own finite differences of qdd over t stay within the jerk limit, with qd
# consistent with qdd and qdd 0 at both ends. The smooth s-wave does not
# stop on the way.
with_limits "$root/tasks/s-wave.json" "$tmp/wave.json" '{"velocity": 1.2, "acceleration": 3, "jerk": 30}'
check_task s-wave "$tmp/wave.json"
python3 - "$tmp/s-wave/solution.json" <<'PY' || fail "s-wave: the jerk rules or the stops: see above"
import json, sys
samples = json.load(open(sys.argv[1]))["samples"]
J = 30.0
for i in range(1, len(samples)):
    a, b = samples[i - 1], samples[i]
    dt = b["t"] - a["t"]
    for k in range(len(b["q"])):
        assert abs(b["qdd"][k] - a["qdd"][k]) / dt <= J * (1 + 1e-6) + 1e-6 / dt, ("jerk", i, k)
        rate = (b["qd"][k] - a["qd"][k]) / dt
        assert abs(rate - (a["qdd"][k] + b["qdd"][k]) / 2) <= J * dt / 4 + 1e-6, ("qd against qdd", i, k)
for s in (samples[0], samples[-1]):
    assert max(abs(v) for v in s["qdd"]) <= 1e-9, "qdd is not 0 at an end"
inside = [i for i, s in enumerate(samples[1:-1], 1) if max(abs(v) for v in s["qd"]) <= 1e-9]
assert not inside, ("stops inside a smooth path", inside)
PY
grep -q 'id="chart-jerk"' "$tmp/s-wave/r.html" || fail "s-wave: the report has no jerk chart"

# --ee-speed: the tool runs at that speed, and the summary says where the
# limits force it slower.
with_limits "$root/tasks/rose.json" "$tmp/even.json" '{"velocity": 1.2, "acceleration": 3}'
"$bin" solve "$tmp/even.json" -o "$tmp/even-solution.json" --quiet --ee-speed 0.08 >"$tmp/even.out" 2>&1 ||
    fail "solve --ee-speed: $(tail -3 "$tmp/even.out")"
grep -q "tool at 0.080 m/s along the path" "$tmp/even.out" || fail "no tool speed line: $(cat "$tmp/even.out")"
grep -q "trajectory\[4\] at" "$tmp/even.out" || fail "no slower stretch named: $(cat "$tmp/even.out")"

if [ -f "$planter" ]; then
    python3 "$planter" --kind 2dof --seed 7 --out "$tmp/planted" >/dev/null ||
        fail "plant.py failed"
    for t in "$tmp"/planted/*.task.json; do
        with_limits "$t" "$tmp/planted.json" '{"velocity": [1.5, 3.0], "acceleration": [4, 12]}'
        check_task planted "$tmp/planted.json"
    done
fi

# Bad limits: exit 2, naming the key.
expect_invalid() {  # limits-json part
    with_limits "$root/tasks/rose.json" "$tmp/bad.json" "$1"
    "$bin" validate "$tmp/bad.json" >"$tmp/out" 2>&1
    local code=$?
    [ "$code" -eq 2 ] || fail "limits $1: exit $code, expected 2"
    grep -qF -- "$2" "$tmp/out" || fail "limits $1: message does not name $2: $(cat "$tmp/out")"
}
expect_invalid '{"velocity": [1, -1], "acceleration": 5}' "robot.joint_limits.velocity[1]"
expect_invalid '{"velocity": [1, 1, 1, 1], "acceleration": 5}' "robot.joint_limits.velocity"
expect_invalid '{"velocity": 1, "acceleration": [5, 5, 5, 5]}' "robot.joint_limits.acceleration"
expect_invalid '{"velocity": [1, 2], "acceleration": [5, 5, 5]}' "robot.joint_limits.acceleration"
expect_invalid '{"velocity": 0, "acceleration": 5}' "robot.joint_limits.velocity"
expect_invalid '{"velocity": 1}' "robot.joint_limits.acceleration"
expect_invalid '[1, 2]' "robot.joint_limits"

# A saved solution without velocities is timed again by export, path kept.
python3 - "$tmp/rose/solution.json" "$tmp/bare.json" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
for s in doc["samples"]:
    del s["qd"], s["qdd"]
json.dump(doc, open(sys.argv[2], "w"))
PY
"$bin" export "$tmp/rose.json" "$tmp/bare.json" --joint-trajectory "$tmp/bare.yaml" \
    --csv "$tmp/bare.csv" >"$tmp/out" 2>&1 || fail "export of a solution without qd: $(cat "$tmp/out")"
cmp -s "$tmp/bare.yaml" "$tmp/rose/t.yaml" ||
    fail "export times a solution without qd otherwise than solve did"

finish timing
