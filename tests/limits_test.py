#!/usr/bin/env python3
"""The documented limits as a user meets them: a 3,000-primitive task is
answered within --time-limit plus 1 s and under 2 GB by solve and explain;
tasks past the caps and non-finite numeric options are rejected with exit 2
naming the part or the option.

usage: limits_test.py MODSYNTH SOURCE_DIR
"""
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time

BIN, ROOT = sys.argv[1], sys.argv[2]
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, file=sys.stderr)


def zigzag_task(count, name):
    """`count` connected primitives (lines and half-circle arcs in turn) on a
    band 0.6 m wide within reach of a base region at the origin."""
    trajectory, x, y, up = [], -0.3, 0.4, True
    step = 0.6 / count
    for j in range(count):
        nx = x + step
        if j % 2 == 0:
            ny = y + (0.05 if up else -0.05)
            trajectory.append({"type": "line", "start": [x, y], "end": [nx, ny]})
            up = not up
        else:
            cx = (x + nx) / 2
            trajectory.append({"type": "arc", "start": [x, y], "end": [nx, y], "center": [cx, y],
                               "direction": "cw" if up else "ccw"})
            ny = y
        x, y = nx, ny
    return {"format": "modsynth-task/1", "name": name, "trajectory": trajectory,
            "obstacles": [{"center": [0.5, -0.5], "radius": 0.05}],
            "base_regions": [{"min": [-0.1, -0.1], "max": [0.1, 0.1]}]}


def run(args):
    """Exit code, stdout, stderr, wall seconds and the child's peak RSS in MB
    (this process has no other children, so RUSAGE_CHILDREN's maximum is
    this child's)."""
    start = time.monotonic()
    p = subprocess.run([BIN] + args, capture_output=True, text=True, errors="replace")
    wall = time.monotonic() - start
    rss_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return p.returncode, p.stdout, p.stderr, wall, rss_mb


with tempfile.TemporaryDirectory() as tmp:
    big = os.path.join(tmp, "zigzag-3000.json")
    with open(big, "w") as f:
        json.dump(zigzag_task(3000, "zigzag-3000"), f)
    sol = os.path.join(tmp, "sol.json")

    code, out, err, wall, rss = run(["validate", big])
    if code != 0:
        fail(f"validate 3000 primitives: exit {code}: {err[:300]}")

    report = os.path.join(tmp, "report.html")
    code, out, err, wall, rss = run(["solve", big, "-o", sol, "--time-limit", "5", "--quiet",
                                     "--report", report])
    print(f"solve --time-limit 5, 3000 primitives: exit {code}, {wall:.2f} s, peak RSS {rss:.0f} MB")
    if wall >= 6.0:
        fail(f"solve --time-limit 5 took {wall:.2f} s")
    if rss >= 2048:
        fail(f"solve peak RSS {rss:.0f} MB")
    if code not in (0, 4):
        fail(f"solve: exit {code}: {err[:300]}")
    elif code == 4:
        status = json.load(open(sol))["status"]
        if status != "unknown":
            fail(f"solve exit 4 wrote status {status}")
    # Whichever way the time ran out, the report asked for is written.
    if not os.path.isfile(report) or os.path.getsize(report) == 0:
        fail("solve --report: no report written")

    code, out, err, wall, rss = run(["explain", big, "--time-limit", "5", "--json"])
    print(f"explain --time-limit 5, 3000 primitives: exit {code}, {wall:.2f} s")
    if wall >= 6.0:
        fail(f"explain --time-limit 5 took {wall:.2f} s")
    if code not in (0, 3, 4):
        fail(f"explain: exit {code}: {err[:300]}")
    else:
        try:
            json.loads(out)
        except ValueError:
            fail(f"explain --json printed no JSON: {out[:300]}")

    code, out, err, wall, rss = run(["compare", big, "--time-limit", "2", "--baseline-time-limit", "2",
                                     "--quiet"])
    print(f"compare with 2 + 2 s, 3000 primitives: exit {code}, {wall:.2f} s")
    if wall >= 6.0:
        fail(f"compare with 2 + 2 s took {wall:.2f} s")

    # Past the cap: exit 2 naming the part and the cap, at once.
    with open(big, "w") as f:
        json.dump(zigzag_task(5001, "zigzag-5001"), f)
    code, out, err, wall, rss = run(["solve", big, "-o", sol])
    if code != 2 or "trajectory: 5001 primitives, more than the 5000 allowed" not in err:
        fail(f"5001 primitives: exit {code}: {err[:300]}")

    # Non-finite and meaningless numbers for every numeric option.
    rose = os.path.join(ROOT, "tasks", "rose.json")
    options = [
        (["solve", rose, "-o", sol], ["--time-limit", "--ee-speed", "--joint-speed"]),
        (["explain", rose], ["--time-limit", "--solve-seconds"]),
        (["batch", rose, "--out", os.path.join(tmp, "r.jsonl")], ["--time-limit", "--grace"]),
        (["compare", rose], ["--time-limit", "--baseline-time-limit", "--goal-bias"]),
        (["baseline", rose], ["--baseline-time-limit", "--goal-bias"]),
        (["serve"], ["--time-limit", "--grace", "--client-timeout"]),
        (["regress", "encodings"], ["--time-limit", "--tolerance"]),
    ]
    for command, names in options:
        for name in names:
            for value in ["nan", "inf", "-inf", "-1", "1e999"]:
                code, out, err, wall, rss = run(command + [name, value])
                if code != 2 or name not in err:
                    fail(f"{command[0]} {name} {value}: exit {code}: {err[:200]}")
    for command, name in [(["solve", rose, "-o", sol], "--time-limit"),
                          (["solve", rose, "-o", sol], "--ee-speed"),
                          (["explain", rose], "--solve-seconds")]:
        code, out, err, wall, rss = run(command + [name, "0"])
        if code != 2 or name not in err:
            fail(f"{command[0]} {name} 0: exit {code}: {err[:200]}")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
