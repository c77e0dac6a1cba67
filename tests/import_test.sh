#!/usr/bin/env bash
# `modsynth import` on the bundled drawings and on broken ones: the
# tolerance it reports, the task it writes (checked against the formats
# contract and the shared grader's reader), the SVG round trip, and exit 2
# with a message naming the offending element.
set -u
source "$(dirname "$0")/shell_test_lib.sh"

check_task() {  # task.json expected-strokes-at-least
    python3 - "$1" "$2" "$root/../shared/grader" <<'PY' || fail "$1: $(tail -1 "$tmp/py" 2>/dev/null)"
import json, math, os, sys
doc = json.load(open(sys.argv[1]))
assert doc["format"] == "modsynth-task/1"
assert ("strokes" in doc) != ("trajectory" in doc), "exactly one of trajectory/strokes"
strokes = doc["strokes"] if "strokes" in doc else [doc["trajectory"]]
assert len(strokes) >= int(sys.argv[2]), f"{len(strokes)} strokes"
if "strokes" in doc:
    assert len(strokes) > 1, "strokes with a single stroke: trajectory expected"
for s, st in enumerate(strokes):
    assert st, f"stroke {s} empty"
    for j, p in enumerate(st):
        assert p["type"] in ("line", "arc", "circle")
        if j:
            gap = math.dist(p["start"], st[j - 1]["end"])
            assert gap <= 1e-6, f"strokes[{s}][{j}] gap {gap}"
        if p["type"] != "line":
            r0 = math.dist(p["start"], p["center"])
            assert r0 > 0
            if p["type"] == "arc":
                assert abs(math.dist(p["end"], p["center"]) - r0) <= 1e-6
                assert p["direction"] in ("ccw", "cw")
grader = sys.argv[3]
if os.path.exists(os.path.join(grader, "check_solution.py")):
    sys.path.insert(0, grader)
    import check_solution
    t = check_solution.parse_task(doc)
    assert len(t["strokes"]) == len(strokes)
PY
}

reported_deviation() {  # output file -> deviation in metres
    sed -n 's/^deviation: \([0-9.e+-]*\) m.*/\1/p' "$1"
}

# The two bundled drawings, at the default tolerance and a looser one.
for args in "sketch.svg --obstacles-from Obstacles" "bracket.dxf --obstacles-from keepout"; do
    set -- $args
    for tol in 0.0001 0.001; do
        out="$tmp/$1.$tol.json"
        "$bin" import "$root/tasks/drawings/$1" -o "$out" --tolerance "$tol" "${@:2}" >"$tmp/out" 2>"$tmp/err" ||
            fail "import $1: exit $? ($(cat "$tmp/err"))"
        dev=$(reported_deviation "$tmp/out")
        [ -n "$dev" ] || fail "import $1: no deviation printed: $(cat "$tmp/out")"
        python3 -c "import sys; sys.exit(0 if 0 < float('$dev') <= $tol else 1)" ||
            fail "import $1: deviation $dev beyond tolerance $tol"
        grep -q "^primitives per stroke: [0-9]" "$tmp/out" || fail "import $1: no primitives per stroke"
        grep -q "^travel: [0-9]" "$tmp/out" || fail "import $1: no travel length"
        check_task "$out" 3
    done
done
python3 -c "
import json, sys
d = json.load(open('$tmp/sketch.svg.0.0001.json'))
assert len(d['obstacles']) == 2 and d['obstacles'][0]['radius'] == 0.006, d['obstacles']
" || fail "sketch.svg: obstacles from the layer"

# Placement options and a single stroke (trajectory).
cat >"$tmp/one.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">
  <path id="s" d="M 10,50 C 30,10 70,90 90,50"/>
</svg>
SVG
"$bin" import "$tmp/one.svg" -o "$tmp/one.json" --width 0.4 --at 0.5,0.2 --rotate 90 \
    --base -0.1,-0.1,0.1,0.1 --base 0.2,0.2,0.3,0.3 --dof 3 >"$tmp/out" 2>"$tmp/err" ||
    fail "import one.svg: $(cat "$tmp/err")"
check_task "$tmp/one.json" 1
python3 -c "
import json
d = json.load(open('$tmp/one.json'))
assert 'trajectory' in d and 'strokes' not in d
assert len(d['base_regions']) == 2 and d['robot']['dof'] == [3]
ys = [p[k][1] for p in d['trajectory'] for k in ('start', 'end')]
assert abs(max(ys) - min(ys) - 0.4) < 1e-3, (min(ys), max(ys))  # width turned upright
" || fail "one.svg: placement, base regions or dof"
"$bin" validate "$tmp/one.json" >/dev/null || fail "one.svg: the task does not validate"

# Round trip: export-svg then import at the same scale gives the same primitives.
"$bin" import "$root/tasks/drawings/sketch.svg" -o "$tmp/a.json" --keep-order >/dev/null 2>&1 || fail "import --keep-order"
"$bin" export-svg "$tmp/a.json" -o "$tmp/a.svg" >/dev/null 2>"$tmp/err" || fail "export-svg: $(cat "$tmp/err")"
"$bin" import "$tmp/a.svg" -o "$tmp/b.json" --keep-order >/dev/null 2>"$tmp/err" || fail "re-import: $(cat "$tmp/err")"
python3 - "$tmp/a.json" "$tmp/b.json" <<'PY' || fail "round trip changed the primitives"
import json, math, sys
a, b = (json.load(open(f))["strokes"] for f in sys.argv[1:3])
assert len(a) == len(b)
for sa, sb in zip(a, b):
    assert len(sa) == len(sb), (len(sa), len(sb))
    for p, q in zip(sa, sb):
        assert p["type"] == q["type"]
        for k in ("start", "end", "center"):
            if k in p:
                assert math.dist(p[k], q[k]) <= 1e-9 * 0.2, (k, p[k], q[k])
PY

# Broken drawings: exit 2, a message naming the element.
expect_error() {  # file-content-name expected-text...
    local file=$1
    shift
    "$bin" import "$file" -o "$tmp/bad.json" >"$tmp/out" 2>"$tmp/err"
    local got=$?
    [ "$got" -eq 2 ] || fail "$(basename "$file"): exit $got, expected 2 ($(cat "$tmp/err"))"
    for want in "$@"; do
        grep -qF -- "$want" "$tmp/err" || fail "$(basename "$file"): message lacks '$want': $(cat "$tmp/err")"
    done
}
svg() { printf '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">\n%s\n</svg>\n' "$2" >"$tmp/$1"; }
svg malformed.svg '<path id="p3" d="M 10,"/>'
expect_error "$tmp/malformed.svg" "path#p3 (line 2)" "malformed path data" "M 10,"
svg text.svg '<text id="t1" style="writing-mode:tb">Hello</text>'
expect_error "$tmp/text.svg" "text#t1 (line 2)" "vertical writing"
svg image.svg '<path d="M 1,1 L 2,2"/>
<image id="logo" href="x.png"/>'
expect_error "$tmp/image.svg" "image#logo (line 3)" "bitmap"
svg zero.svg '<path id="dot" d="M 5,5 L 5,5"/>'
expect_error "$tmp/zero.svg" "path#dot (line 2)" "zero-length"
svg empty.svg ''
expect_error "$tmp/empty.svg" "empty drawing"
svg huge.svg '<path id="far" d="M 0,0 L 1e12,0"/>'
expect_error "$tmp/huge.svg" "path#far" "out of range"
svg far.svg '<path id="big" d="M 0,0 L 1e8,0"/>'
expect_error "$tmp/far.svg" "path#big" "beyond 1000 m"
echo '{"format": "modsynth-task/1"}' >"$tmp/notsvg.svg"
expect_error "$tmp/notsvg.svg" "not an SVG file"
echo 'hello' >"$tmp/notdxf.dxf"
expect_error "$tmp/notdxf.dxf" "not a DXF file"
printf '0\nSECTION\n2\nENTITIES\n0\nHATCH\n8\n0\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n' >"$tmp/hatch.dxf"
expect_error "$tmp/hatch.dxf" "nothing to draw" "HATCH #1 (layer 0)"
# With --strict, what cannot be traced is refused even beside what can.
printf '0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n100\n21\n0\n0\nHATCH\n8\n0\n0\nENDSEC\n0\nEOF\n' >"$tmp/hatchline.dxf"
"$bin" import "$tmp/hatchline.dxf" --scale 0.001 -o "$tmp/hl.json" >"$tmp/out" 2>"$tmp/err" ||
  fail "hatchline.dxf: not imported: $(cat "$tmp/err")"
grep -qF "warning: skipped what cannot be traced: HATCH #2 (layer 0)" "$tmp/err" ||
  fail "hatchline.dxf: no warning: $(cat "$tmp/err")"
"$bin" import "$tmp/hatchline.dxf" --strict --scale 0.001 -o "$tmp/hl.json" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && grep -qF "entities that cannot be drawn: HATCH" "$tmp/err" ||
  fail "hatchline.dxf --strict: not refused: $(cat "$tmp/err")"
# A few bytes that declare 200 million vertices or knots: refused at once,
# before the DXF library sizes its arrays from them.
printf '0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n200000000\n10\n0\n20\n0\n10\n1\n20\n1\n0\nENDSEC\n0\nEOF\n' >"$tmp/vertices.dxf"
expect_error "$tmp/vertices.dxf" "LWPOLYLINE (line 10)" "group code 90 declares 200000000"
printf '0\nSECTION\n2\nENTITIES\n0\nSPLINE\n8\n0\n71\n3\n72\n-5\n73\n4\n0\nENDSEC\n0\nEOF\n' >"$tmp/knots.dxf"
expect_error "$tmp/knots.dxf" "SPLINE (line 12)" "group code 72 gives a count of -5: a count cannot be negative"
echo 'x' >"$tmp/drawing.png"
expect_error "$tmp/drawing.png" ".svg or .dxf"
# A file beyond the size cap is refused before it is read.
head -c 17000000 /dev/zero | tr '\0' ' ' >"$tmp/big.svg"
expect_error "$tmp/big.svg" "17000000 bytes, more than the 16777216 allowed for a drawing file"
# A tolerance so tight the drawing needs too many pieces: refused, no hang.
timeout 60 "$bin" import "$root/tasks/drawings/sketch.svg" -o "$tmp/t.json" --tolerance 1e-9 --width 100 >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "raise --tolerance" "$tmp/err" || fail "tolerance 1e-9: $(cat "$tmp/err")"

# Drawings become tasks that solve: the SVG (Béziers, an ellipse, letters as
# paths) and the DXF (bulges, a spline), placed in reach of a base region,
# each solved with a certified motion over every stroke.
grader_py=$root/../shared/grader/check_solution.py
for drawing in sketch.svg bracket.dxf; do
    "$bin" import "$root/tasks/drawings/$drawing" -o "$tmp/solve-$drawing.json" --at 0.3,0.1 \
        --base -0.1,-0.1,0.1,0.1 >"$tmp/out" 2>&1 || fail "import $drawing to solve: $(cat "$tmp/out")"
    timeout 120 "$bin" solve "$tmp/solve-$drawing.json" -o "$tmp/solve-$drawing.sol.json" --quiet \
        >"$tmp/out" 2>&1 || fail "solve the imported $drawing: exit $?: $(tail -3 "$tmp/out")"
    grep -q "certified over the whole motion" "$tmp/out" || fail "imported $drawing: not certified"
    if [ -f "$grader_py" ]; then
        python3 "$grader_py" "$tmp/solve-$drawing.json" "$tmp/solve-$drawing.sol.json" \
            --expect solved >"$tmp/grade" 2>&1 || fail "imported $drawing: $(tail -2 "$tmp/grade")"
    fi
done

# Hatches: skipped with a warning that names the option; with
# --hatch-boundaries their boundary paths (a polyline path with a bulge,
# edge paths of lines, arcs, an elliptic arc and a spline) are closed
# strokes of a task that solves and passes the grader.
"$bin" import "$root/tests/fixtures/drawings/hatches.dxf" -o "$tmp/h.json" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && grep -qF "HATCH #1 (layer outline)" "$tmp/err" && grep -qF -- "--hatch-boundaries" "$tmp/err" ||
    fail "hatches.dxf without --hatch-boundaries: $(cat "$tmp/err")"
"$bin" import "$root/tests/fixtures/drawings/hatches.dxf" --hatch-boundaries -o "$tmp/solve-hatch.json" \
    --at 0.3,0.1 --base -0.1,-0.1,0.1,0.1 >"$tmp/out" 2>"$tmp/err" || fail "import hatches.dxf: $(cat "$tmp/err")"
[ -s "$tmp/err" ] && fail "hatches.dxf: unexpected warnings: $(cat "$tmp/err")"
grep -q "^.*hatches.dxf -> .*: 5 strokes" "$tmp/out" || fail "hatches.dxf: not 5 strokes: $(cat "$tmp/out")"
check_task "$tmp/solve-hatch.json" 5
timeout 120 "$bin" solve "$tmp/solve-hatch.json" -o "$tmp/solve-hatch.sol.json" --quiet \
    >"$tmp/out" 2>&1 || fail "solve the hatches: exit $?: $(tail -3 "$tmp/out")"
if [ -f "$grader_py" ]; then
    python3 "$grader_py" "$tmp/solve-hatch.json" "$tmp/solve-hatch.sol.json" --expect solved \
        >"$tmp/grade" 2>&1 || fail "hatches: $(tail -2 "$tmp/grade")"
fi

# Text in a single-stroke font: a task that solves and passes the grader.
"$bin" import --text "Hi" --height 0.05 -o "$tmp/solve-text.json" --at 0.3,0.1 \
    --base -0.1,-0.1,0.1,0.1 >"$tmp/out" 2>&1 || fail "import --text: $(cat "$tmp/out")"
grep -q "^--text -> .*: [0-9]* strokes" "$tmp/out" || fail "import --text: $(cat "$tmp/out")"
timeout 120 "$bin" solve "$tmp/solve-text.json" -o "$tmp/solve-text.sol.json" --quiet \
    >"$tmp/out" 2>&1 || fail "solve the text: exit $?: $(tail -3 "$tmp/out")"
if [ -f "$grader_py" ]; then
    python3 "$grader_py" "$tmp/solve-text.json" "$tmp/solve-text.sol.json" --expect solved \
        >"$tmp/grade" 2>&1 || fail "text: $(tail -2 "$tmp/grade")"
fi
"$bin" import --text "Hi" --font nosuch -o "$tmp/t.json" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 2 ] && grep -qF "no Hershey font 'nosuch'" "$tmp/err" || fail "--font nosuch: $(cat "$tmp/err")"

finish import
