#!/usr/bin/env python3
"""`modsynth import` on hostile drawings, as README "Tasks from drawings"
promises: each returns within its --time-limit plus 1 s and under 500 MB,
with exit 0 (a valid drawing), 2 (refused, naming the entity) or 4 (the time
limit), never hanging or ballooning.

usage: import_limits_test.py MODSYNTH SOURCE_DIR
"""
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

BIN, ROOT = sys.argv[1], sys.argv[2]
SKETCH = os.path.join(ROOT, "tasks", "drawings", "sketch.svg")
TIME_LIMIT = 3.0
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, file=sys.stderr, flush=True)


def dxf(entities, header="9\n$INSUNITS\n70\n4\n"):
    return ("0\nSECTION\n2\nHEADER\n" + header + "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" +
            entities + "0\nENDSEC\n0\nEOF\n")


def svg(body, size='width="100mm" height="100mm" viewBox="0 0 100 100"'):
    return '<svg xmlns="http://www.w3.org/2000/svg" %s>%s</svg>' % (size, body)


LINE = "0\nLINE\n8\n0\n10\n0\n20\n0\n11\n100\n21\n0\n"
SPLINE_1E160 = ("0\nSPLINE\n8\n0\n70\n8\n71\n3\n72\n8\n73\n4\n" +
                "".join("40\n%d\n" % k for k in (0, 0, 0, 0, 1, 1, 1, 1)) +
                "".join("10\n%s\n20\n%s\n30\n0\n" % p for p in
                        (("0", "0"), ("1e-160", "2e-160"), ("2e-160", "-1e-160"), ("3e-160", "0"))))
ONE_CURVE = svg('<path id="c" d="M 10,50 C 30,10 70,90 90,50"/>')


def curves(n):
    """A closed path of n cubic curves across the page: a large clip shape."""
    return "M10 10 " + " ".join("C%d 5 %d 95 %d 90" % (10 + k % 80, 12 + k % 80, 14 + k % 80)
                                for k in range(n)) + " Z"


def line(i, clip):
    y = 20 + i % 60
    return '<line x1="20" y1="%d" x2="80" y2="%d" stroke="black" clip-path="url(#%s)"/>' % (y, y, clip)


# Every line clipped by one clip path of thousands of curves (its outline
# once flattened per line: 7.5 GB), and every line by its own.
CLIP_SHARED = svg('<clipPath id="c"><path d="%s"/></clipPath>' % curves(5000) +
                  "".join(line(i, "c") for i in range(10000)))
CLIP_EACH = svg("".join('<clipPath id="c%d"><path d="%s"/></clipPath>' % (i, curves(150))
                        for i in range(400)) + "".join(line(i, "c%d" % i) for i in range(400)))

# (name, file content, extra options, expected exit code, text the error names)
CASES = [
    ("long-comment.dxf", "999\n" + "c" * 5000 + "\n" + dxf(LINE), [], 0, None),
    ("long-layer.dxf", dxf("0\nLINE\n8\n" + "L" * 5000 + "\n10\n0\n20\n0\n11\n1\n21\n0\n"), [], 2,
     "5000 characters"),
    ("long-header.dxf", dxf(LINE, "9\n$PROJECTNAME\n1\n" + "p" * 1024 + "\n"), [], 2, "1024 characters"),
    ("spline-1e-160.dxf", dxf(SPLINE_1E160), [], 2, "across once placed"),
    ("one-curve-scale.svg", ONE_CURVE, ["--scale", "1e-200"], 2, "across once placed"),
    ("sketch-width.svg", open(SKETCH).read(), ["--width", "1e-300"], 2, "across once placed"),
    ("sketch-scale.svg", open(SKETCH).read(), ["--scale", "1e-300"], 2, "across once placed"),
    ("count-090.dxf", dxf("0\nLWPOLYLINE\n8\n0\n090\n200000000\n10\n0\n20\n0\n10\n1\n20\n1\n"), [], 2,
     "declares 200000000"),
    ("count-072.dxf", dxf("0\nSPLINE\n8\n0\n71\n3\n072\n150000000\n073\n150000000\n"), [], 2,
     "declares 150000000"),
    ("abc.dxf", dxf("0\nLINE\n8\n0\n10\nabc\n20\n0\n11\n1\n21\n0\n"), [], 2, "'abc', not a number"),
    ("10xyz.dxf", dxf("0\nLINE\n8\n0\n10\n10xyz\n20\n0\n11\n1\n21\n0\n"), [], 2, "'10xyz', not a number"),
    ("nan.dxf", dxf("0\nLINE\n8\n0\n10\nnan\n20\n0\n11\n1\n21\n0\n"), [], 2, "'nan', not a finite number"),
    ("inf-arc.dxf", dxf("0\nARC\n8\n0\n10\n0\n20\n0\n40\n5\n50\n0\n51\ninf\n"), [], 2,
     "'inf', not a finite number"),
    ("negative-radius.dxf", dxf("0\nARC\n8\n0\n10\n0\n20\n0\n40\n-5\n50\n0\n51\n90\n"), [], 2, "radius -5"),
    ("ratio-0.dxf", dxf("0\nELLIPSE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n40\n0\n41\n0\n42\n6.28\n"), [], 2,
     "axis ratio 0"),
    ("cut-off.dxf", dxf(LINE * 6)[:dxf(LINE * 6).rfind("0\nENDSEC") - 4], [], 2, "cut off"),
    ("bulge-1e-10.dxf", dxf("0\nLWPOLYLINE\n8\n0\n90\n2\n70\n0\n10\n0\n20\n0\n42\n1e-10\n10\n100\n20\n0\n"),
     [], 0, None),
    ("arc-1e-170.svg", svg('<path d="M 10,50 A 1e-170 1e-170 0 0 1 90,50"/>'), [], 0, None),
    ("hidden.svg", svg('<path d="M 10,10 L 90,10"/><g style="display:none"><text>x</text></g>'), [], 0, None),
    ("attributes.svg", svg("<path " + " ".join('a%d="x"' % i for i in range(300000)) + "/>"), [], 2,
     "attributes"),
    ("elements.svg", svg("<g/>" * 4000000), [], 2, "elements"),
    ("deep.svg", svg("<g>" * 5000 + "</g>" * 5000), [], 2, "XML error"),
    ("many-dxf.dxf", dxf(LINE * 21000), [], 2, "more than 20000 entities"),
    # Seconds of fitting before it finds the tolerance needs too many pieces:
    # stopped at the time limit instead.
    ("slow-fit.svg", open(SKETCH).read(), ["--tolerance", "1e-9", "--width", "100", "--time-limit", "1"],
     4, "the time limit was reached while fitting path#"),
    ("time-limit.svg", open(SKETCH).read(), ["--time-limit", "0.001"], 4, "time limit"),
    ("clip-shared.svg", CLIP_SHARED, [], 4, "the time limit was reached while clipping"),
    ("clip-each.svg", CLIP_EACH, [], 2, "points of outline in all"),
]


def run(path, extra, time_limit):
    out = path + ".task.json"
    args = [BIN, "import", path, "-o", out, "--time-limit", str(time_limit)] + extra
    if path.endswith(".dxf") and "--scale" not in extra:
        args += ["--scale", "0.001"]
    start = time.monotonic()
    try:
        p = subprocess.run(args, capture_output=True, text=True, errors="replace",
                           timeout=time_limit + 30)
        code, err = p.returncode, p.stderr
    except subprocess.TimeoutExpired:
        code, err = None, "still running 30 s past its time limit"
    wall = time.monotonic() - start
    return code, err, wall


with tempfile.TemporaryDirectory() as tmp:
    worst_wall, worst_rss = 0.0, 0.0
    for name, content, extra, want, names in CASES:
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            f.write(content)
        limit = TIME_LIMIT
        if "--time-limit" in extra:
            limit = float(extra[extra.index("--time-limit") + 1])
            extra = extra[:extra.index("--time-limit")] + extra[extra.index("--time-limit") + 2:]
        code, err, wall = run(path, extra, limit)
        # This process's children end one at a time: the peak so far is at
        # least this child's, and a child past the cap shows in it.
        rss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        worst_wall, worst_rss = max(worst_wall, wall - limit), max(worst_rss, rss)
        print("%-24s exit %s, %.2f s, peak RSS so far %.0f MB" % (name, code, wall, rss), flush=True)
        if code != want:
            fail("%s: exit %s, expected %s: %s" % (name, code, want, err.strip()[:300]))
        elif names and names not in err:
            fail("%s: the message does not say '%s': %s" % (name, names, err.strip()[:300]))
        if wall > limit + 1.0:
            fail("%s: %.2f s, past its time limit of %g s plus 1 s" % (name, wall, limit))
        if rss >= 500:
            fail("%s: peak RSS %.0f MB, 500 MB or more" % (name, rss))
    print("worst: %.2f s past the time limit, %.0f MB peak RSS" % (worst_wall, worst_rss))


def timed(args):
    start = time.monotonic()
    p = subprocess.run([BIN] + args, capture_output=True, text=True, errors="replace", timeout=600)
    return p.returncode, p.stderr, time.monotonic() - start


# Linear, not quadratic: 5,000 strokes and 1,000 obstacles take about as
# long to write as an SVG, and to import with their obstacles, as the task
# takes to validate and the drawing to import without them (once 22 s
# against 0.06 s, and 4.75 s against 0.17 s). Measured against each other,
# so that a loaded machine slows both.
with tempfile.TemporaryDirectory() as tmp:
    strokes, entities = [], []
    for i in range(5000):
        x, y = 0.1 + (i % 100) * 0.004, 0.1 + (i // 100) * 0.004
        strokes.append([{"type": "line", "start": [x, y], "end": [x + 0.002, y]}])
        entities.append("0\nLINE\n8\n0\n10\n%g\n20\n%g\n11\n%g\n21\n%g\n" %
                        (1000 * x, 1000 * y, 1000 * x + 2, 1000 * y))
    circles = ["0\nCIRCLE\n8\nobs\n10\n%g\n20\n%g\n40\n2\n" % (-500 + (k % 40) * 10, 600 + (k // 40) * 10)
               for k in range(1000)]
    task = os.path.join(tmp, "strokes.json")
    with open(task, "w") as f:
        json.dump({"format": "modsynth-task/1", "name": "strokes", "strokes": strokes,
                   "obstacles": [{"center": [-0.5 + (k % 40) * 0.01, 0.6 + (k // 40) * 0.01],
                                  "radius": 0.002} for k in range(1000)]}, f)
    code, err, validate = timed(["validate", task])
    code_svg, err_svg, export = timed(["export-svg", task, "-o", os.path.join(tmp, "s.svg")])
    print("5000 strokes, 1000 obstacles: validate %.2f s, export-svg %.2f s" % (validate, export))
    if code != 0 or code_svg != 0:
        fail("validate / export-svg of 5000 strokes: exit %s / %s: %s" % (code, code_svg, (err + err_svg)[:300]))
    elif export > 5 * validate + 1:
        fail("export-svg took %.2f s against validate's %.2f s" % (export, validate))
    plain, with_obstacles = os.path.join(tmp, "plain.dxf"), os.path.join(tmp, "obstacles.dxf")
    for path, items in [(plain, entities), (with_obstacles, entities + circles)]:
        with open(path, "w") as f:
            f.write(dxf("".join(items)))
    code, err, alone = timed(["import", plain, "-o", os.path.join(tmp, "a.json"), "--keep-order"])
    code_obs, err_obs, along = timed(["import", with_obstacles, "-o", os.path.join(tmp, "b.json"),
                                      "--keep-order", "--obstacles-from", "obs"])
    print("5000 strokes: import %.2f s, with 1000 obstacles %.2f s" % (alone, along))
    if code != 0 or code_obs != 0:
        fail("import of 5000 strokes: exit %s / %s: %s" % (code, code_obs, (err + err_obs)[:300]))
    elif along > 4 * alone + 1:
        fail("import with 1000 obstacles took %.2f s against %.2f s without" % (along, alone))

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
