#!/usr/bin/env python3
"""A motion of hundreds of thousands of samples (README "Limits"): solve
writes it in bounded memory, never past what the program reads back, and
certify and export read it back in memory of the samples, not of the file's
text and tree; a motion longer than a file holds is answered "unknown".

usage: long_motion_test.py MODSYNTH SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile
import time

BIN = sys.argv[1]
MAX_SOLUTION_BYTES = 256 << 20
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, file=sys.stderr, flush=True)


def helices(count, path):
    """`count` helices of 1000 turns up and down a post of radius 0.05 m."""
    pitch, turns, start, trajectory = 0.005, 1000, [0.05, 0.0, 0.1], []
    for h in range(count):
        up = h % 2 == 0
        trajectory.append({"type": "helix", "start": start, "center": [0, 0, start[2]],
                           "axis": [0, 0, 1 if up else -1], "direction": "ccw" if up else "cw",
                           "pitch": pitch, "turns": turns})
        start = [0.05, 0.0, round(start[2] + (pitch * turns if up else -pitch * turns), 9)]
    with open(path, "w") as f:
        json.dump({"format": "modsynth-task/1", "name": "long-helices", "space": "3d",
                   "trajectory": trajectory,
                   "base_regions": [{"min": [0.5, -0.05, 2.5], "max": [0.6, 0.05, 2.5]}],
                   "robot": {"dof": [3], "max_link_length": 3.0}}, f)


def run(args, timeout):
    """Exit code, stdout and stderr, seconds and peak RSS (MB) of one run."""
    start = time.monotonic()
    with tempfile.TemporaryFile() as log:
        p = subprocess.Popen([BIN] + args, stdout=log, stderr=subprocess.STDOUT)
        deadline = start + timeout
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() > deadline:
                p.kill()
            time.sleep(0.2)
        p.returncode = os.waitstatus_to_exitcode(status)
        log.seek(0)
        out = log.read().decode(errors="replace")
    return p.returncode, out, time.monotonic() - start, usage.ru_maxrss / 1024


with tempfile.TemporaryDirectory() as tmp:
    # 471,303 samples, a 162 MB file: solved, read back, exported.
    task, sol = os.path.join(tmp, "three.json"), os.path.join(tmp, "three.solution.json")
    helices(3, task)
    code, out, seconds, rss = run(["solve", task, "-o", sol, "--time-limit", "600", "-q"], 900)
    print("solve, 3 helices: exit %s, %.1f s, peak RSS %.0f MB" % (code, seconds, rss), flush=True)
    if code != 0:
        fail("solve of 3 helices: exit %s: %s" % (code, out[-300:]))
    else:
        size = os.path.getsize(sol)
        samples = int(out.split(" samples over ")[0].rsplit(" ", 1)[1])
        print("  %d samples, %.0f MB" % (samples, size / 2**20))
        if size > MAX_SOLUTION_BYTES:
            fail("solve wrote %d bytes, more than certify reads" % size)
        # Once 1.78 KB per sample (the whole text built several times).
        if rss * 2**20 / samples > 1200:
            fail("solve kept %.0f bytes per sample" % (rss * 2**20 / samples))
        for args in (["certify", task, sol], ["export", task, sol, "--csv", sol + ".csv"]):
            code, out, seconds, rss = run(args, 600)
            print("%s: exit %s, %.1f s, peak RSS %.0f MB" % (args[0], code, seconds, rss), flush=True)
            if code != 0:
                fail("%s: exit %s: %s" % (args[0], code, out[-300:]))
            # Once 1.7 KB per sample (the document's text and tree).
            if rss * 2**20 / samples > 600:
                fail("%s kept %.0f bytes per sample" % (args[0], rss * 2**20 / samples))
    # 1,256,808 samples: more than a file of three joints holds. Once solved
    # into a 431 MB file no command could read back, at 2.14 GB.
    task, sol = os.path.join(tmp, "eight.json"), os.path.join(tmp, "eight.solution.json")
    helices(8, task)
    code, out, seconds, rss = run(["solve", task, "-o", sol, "--time-limit", "60"], 300)
    print("solve, 8 helices: exit %s, %.1f s, peak RSS %.0f MB" % (code, seconds, rss), flush=True)
    if code != 4:
        fail("solve of 8 helices: exit %s, not 4: %s" % (code, out[-300:]))
    if "samples, the most a motion may have" not in out:
        fail("solve of 8 helices does not say it gave up at the sample cap: %s" % out[-300:])
    if os.path.exists(sol) and os.path.getsize(sol) > MAX_SOLUTION_BYTES:
        fail("solve of 8 helices wrote %d bytes" % os.path.getsize(sol))
    if rss > 1024:
        fail("solve of 8 helices: peak RSS %.0f MB" % rss)

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
