#!/usr/bin/env bash
# `modsynth import --plane` and `--cylinder`: the spatial task each writes
# (valid, on its surface, strokes connected) and exit 2 naming the option
# for bad values. Fast: imports only.
set -u
source "$(dirname "$0")/shell_test_lib.sh"
drawing=$root/tasks/drawings/sketch.svg

refused() {  # option-name expected-text import-args...
    local name=$1 text=$2
    shift 2
    "$bin" import "$drawing" -o "$tmp/bad.json" "$@" >"$tmp/out" 2>"$tmp/err"
    local code=$?
    [ "$code" -eq 2 ] || { fail "$*: exit $code, expected 2"; return; }
    grep -q -- "$name" "$tmp/err" || fail "$*: the message does not name $name: $(cat "$tmp/err")"
    grep -q -- "$text" "$tmp/err" || fail "$*: expected '$text' in: $(cat "$tmp/err")"
    [ ! -e "$tmp/bad.json" ] || fail "$*: wrote a task"
}
refused --plane "not a unit vector" --plane 0.5,0,0.3,0,2,0,0,0,1
refused --plane "not perpendicular" --plane 0.5,0,0.3,0,1,0,0,0.0995,0.995
refused --plane "expected 9 numbers" --plane 0.5,0,0.3,0,1,0,0,0
refused --plane "" --plane 0.5,0,0.3,0,1,0,0,0,nan
refused --plane "" --plane 0.5,0,0.3,0,1,0,0,0,1 --at 0,0
refused --cylinder "radius" --cylinder 0.5,0,0.3,0,0,1,0
refused --cylinder "radius" --cylinder 0.5,0,0.3,0,0,1,-0.1
refused --cylinder "no direction" --cylinder 0.5,0,0.3,0,0,0,0.1
refused --cylinder "expected 7 numbers" --cylinder 0.5,0,0.3,0,0,1
refused --cylinder "" --cylinder 0.5,0,0.3,0,0,1,0.1 --plane 0.5,0,0.3,0,1,0,0,0,1
refused --cylinder "more than the cylinder's circumference" --width 0.2 --cylinder 0.5,0,0.3,0,0,1,0.02
refused --base "xmin,ymin,zmin,xmax,ymax,zmax" --plane 0.5,0,0.3,0,1,0,0,0,1 --base -0.1,-0.1,0.1,0.1
refused --base "xmin,ymin,xmax,ymax" --base -0.1,-0.1,0,0.1,0.1,0
refused --tool-length "only with --plane" --tool-length 0.05
refused --dof "has 3 to 6" --dof 2,3 --plane 0.5,0,0.3,0,1,0,0,0,1
refused --tool "only with --plane" --tool square
refused --tool "" --tool sideways --plane 0.5,0,0.3,0,1,0,0,0,1
refused --tool "only with --cylinder" --tool toward --plane 0.5,0,0.3,0,1,0,0,0,1

check_spatial() {  # task.json surface: plane|cylinder
    python3 - "$1" "$2" <<'PY' || fail "$1: the task is not as expected"
import json, math, sys
doc = json.load(open(sys.argv[1]))
assert doc["space"] == "3d", doc.get("space")
strokes = doc["strokes"] if "strokes" in doc else [doc["trajectory"]]
kinds = set()
for s, st in enumerate(strokes):
    for j, p in enumerate(st):
        kinds.add(p["type"])
        if j:
            gap = math.dist(p["start"], st[j - 1]["end"])
            assert gap <= 1e-6, f"strokes[{s}][{j}] gap {gap}"
        # Every start on the surface: the plane x = 0.5 or the cylinder of
        # radius 0.1 about the vertical through (0.5, 0).
        x, y, z = p["start"]
        if sys.argv[2] == "plane":
            assert abs(x - 0.5) <= 1e-9, p
        else:
            assert abs(math.hypot(x - 0.5, y) - 0.1) <= 1e-4, p
print(sorted(kinds))
PY
}
"$bin" import "$drawing" -o "$tmp/wall.json" --width 0.2 --plane 0.5,0,0.3,0,1,0,0,0,1 \
    --base -0.1,-0.1,0,0.1,0.1,0.02 >"$tmp/out" 2>"$tmp/err" || fail "--plane: exit $?: $(cat "$tmp/err")"
grep -q "on a plane" "$tmp/out" || fail "--plane: $(cat "$tmp/out")"
check_spatial "$tmp/wall.json" plane
"$bin" validate "$tmp/wall.json" >/dev/null 2>&1 || fail "--plane: the task does not validate"
"$bin" import "$drawing" -o "$tmp/bottle.json" --width 0.2 --cylinder 0.5,0,0.3,0,0,1,0.1 \
    --tolerance 1e-4 >"$tmp/out" 2>"$tmp/err" || fail "--cylinder: exit $?: $(cat "$tmp/err")"
grep -q "round a cylinder" "$tmp/out" || fail "--cylinder: $(cat "$tmp/out")"
dev=$(sed -n 's/^deviation: \([0-9.e+-]*\) m.*/\1/p' "$tmp/out")
python3 -c "import sys; sys.exit(0 if 0 < float('$dev') <= 1e-4 else 1)" ||
    fail "--cylinder: deviation '$dev' beyond the tolerance"
check_spatial "$tmp/bottle.json" cylinder
"$bin" validate "$tmp/bottle.json" >/dev/null 2>&1 || fail "--cylinder: the task does not validate"
"$bin" import --text "Hi" --height 0.04 -o "$tmp/text.json" --cylinder 0.5,0,0.3,0,0,1,0.1 \
    >"$tmp/out" 2>"$tmp/err" || fail "--text --cylinder: exit $?: $(cat "$tmp/err")"
check_spatial "$tmp/text.json" cylinder
# --tool square: the tool square into the surface (formats.md "Tool
# orientation"): into the wall along -(u x v); on the cylinder at its axis
# where a primitive turns about it, else where the surface faces.
"$bin" import "$drawing" -o "$tmp/easel.json" --width 0.2 --plane 0.5,0,0.3,0,1,0,0,0,1 \
    --tool square --tool-tolerance 4 >"$tmp/out" 2>"$tmp/err" || fail "--tool: exit $?: $(cat "$tmp/err")"
"$bin" import "$drawing" -o "$tmp/pipe.json" --width 0.2 --cylinder 0.5,0,0.3,0,0,1,0.1 \
    --tool toward >"$tmp/out" 2>"$tmp/err" || fail "--tool --cylinder: exit $?: $(cat "$tmp/err")"
for t in easel pipe; do
    "$bin" validate "$tmp/$t.json" >/dev/null 2>&1 || fail "--tool: $t does not validate"
done
python3 - "$tmp/easel.json" "$tmp/pipe.json" <<'PY' || fail "--tool: the tool axes are not square to the surface"
import json, math, sys
easel = json.load(open(sys.argv[1]))
axis = easel["tool_axis"]
assert axis["direction"] == [-1.0, 0.0, 0.0] or all(abs(a - b) < 1e-12 for a, b in zip(axis["direction"], [-1, 0, 0])), axis
assert abs(axis["tolerance"] - math.radians(4)) < 1e-12, axis
assert easel["robot"]["dof"] == [4, 5], easel["robot"]
pipe = json.load(open(sys.argv[2]))
assert "tool_axis" not in pipe
strokes = pipe["strokes"] if "strokes" in pipe else [pipe["trajectory"]]
toward = fixed = 0
for st in strokes:
    for p in st:
        a = p["tool_axis"]
        if "toward" in a:
            assert a["toward"] == "axis" and p["type"] in ("arc", "circle", "helix"), p
            toward += 1
        else:
            # Points from the surface to the axis at the primitive's start,
            # within half the tolerance.
            x, y, _ = p["start"]
            w = (0.5 - x, -y)
            n = math.hypot(*w)
            d = a["direction"]
            assert abs(d[2]) < 1e-9, a
            assert math.acos(min(1, (d[0] * w[0] + d[1] * w[1]) / n)) <= a["tolerance"] / 2 + 1e-9, p
            fixed += 1
assert toward > 0 and fixed > 0, (toward, fixed)
PY
# A line nearly along the axis, turned a hundredth of a degree: a helix of
# a pitch no task may hold becomes its chord, within the tolerance, never
# a refusal naming a part the user did not write.
printf '%s' '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100"><line x1="50" y1="10" x2="50" y2="90" stroke="black"/><line x1="20" y1="50" x2="80" y2="60" stroke="black"/></svg>' >"$tmp/axial.svg"
for turn in 0.01 0.00001 45; do
    "$bin" import "$tmp/axial.svg" -o "$tmp/axial.json" --cylinder 0,0,0,0,0,1,0.1 --rotate "$turn" \
        >"$tmp/out" 2>"$tmp/err" || fail "--cylinder --rotate $turn: exit $?: $(cat "$tmp/err")"
    "$bin" validate "$tmp/axial.json" >/dev/null 2>&1 || fail "--cylinder --rotate $turn: the task does not validate"
done
finish import_surface
