#!/usr/bin/env bash
# Printable links (README "Printable links"): `--parts DIR` that is not a
# folder is refused naming --parts (exit 2) by solve and export; with
# `full`, a shipped planar task is solved with --parts and every part is
# rendered by openscad, every STL is a closed manifold by admesh's report,
# each link's two axis holes are link-length apart in the mesh (measured
# here from the mesh's vertices, apart from the program's own check), the
# build sheet lists the files, print settings, screws and the printed
# masses, and export --parts writes the same parts from the saved solution.
# Arguments: modsynth binary, source root, `fast` or `full`. Exit 77 (a
# skip) for `full` when openscad or admesh is not installed.
set -u
source "$(dirname "$0")/shell_test_lib.sh"
mode=${3:-fast}

expect_exit() {  # expected-code description command...
    local want=$1 what=$2
    shift 2
    "$@" >"$tmp/out" 2>"$tmp/err"
    local got=$?
    [ "$got" -eq "$want" ] || fail "$what: exit $got, expected $want ($(head -c 300 "$tmp/err"))"
}

task=$root/tasks/s-wave.json
touch "$tmp/a-file"
expect_exit 2 "solve --parts a file" "$bin" solve "$task" -o "$tmp/x.json" --parts "$tmp/a-file" -q
grep -q -- "--parts $tmp/a-file" "$tmp/err" || fail "solve --parts a file: $(cat "$tmp/err")"
[ -f "$tmp/x.json" ] && fail "solve --parts a file wrote a solution"
expect_exit 2 "solve --parts under a file" "$bin" solve "$task" -o "$tmp/x.json" \
    --parts "$tmp/a-file/sub" -q
grep -q -- "--parts $tmp/a-file/sub" "$tmp/err" || fail "solve --parts under a file: $(cat "$tmp/err")"
expect_exit 2 "export --parts a file" "$bin" export "$task" "$tmp/none.json" --parts "$tmp/a-file"
grep -q -- "--parts $tmp/a-file" "$tmp/err" || fail "export --parts a file: $(cat "$tmp/err")"

if [ "$mode" = full ]; then
    for tool in openscad admesh; do
        command -v $tool >/dev/null || { echo "skipped: $tool is not installed"; exit 77; }
    done
    expect_exit 0 "solve --parts" "$bin" solve "$task" -o "$tmp/sol.json" --parts "$tmp/parts" \
        --build-sheet "$tmp/sheet.md" -q
    links=$(ls "$tmp"/parts/link_*.scad 2>/dev/null | wc -l)
    [ "$links" -ge 2 ] || fail "expected a source per link: $(ls "$tmp/parts")"
    for part in "$tmp"/parts/*.scad; do
        stl=${part%.scad}.stl
        [ -s "$stl" ] || { fail "$(basename "$part") not rendered"; continue; }
        admesh "$stl" >"$tmp/admesh" 2>&1 || fail "admesh $(basename "$stl"): exit $?"
        python3 - "$tmp/admesh" <<'PY' || fail "$(basename "$stl") is not a closed manifold: $(grep -E 'disconnected|parts|added|Backwards|Degenerate|fixed' "$tmp/admesh")"
import re, sys
report = open(sys.argv[1]).read()
def figure(label):
    return int(re.search(label + r"\s*:\s*(\d+)", report).group(1))
assert figure("Number of parts") == 1
for label in ("Total disconnected facets", "Degenerate facets", "Edges fixed",
              "Facets added", "Facets reversed", "Backwards edges"):
    assert figure(label) == 0, label
PY
    done
    # The axes in the mesh: the ring of vertices round each axis hole on
    # the bed (z = 0), its centre the mean of its distinct vertices.
    for scad in "$tmp"/parts/link_*.scad; do
        python3 - "$scad" "${scad%.scad}.stl" >"$tmp/spacing" 2>&1 <<'PY' || fail "$(basename "$scad"): $(cat "$tmp/spacing")"
import math, re, sys
scad = open(sys.argv[1]).read()
def param(name):
    return float(re.search(r"\n" + name + r" = ([-0-9.]+);", scad).group(1))
length, bore, axis = param("link_length"), param("horn_bore"), param("axis_hole")
verts = set()
for m in re.finditer(r"vertex\s+(\S+)\s+(\S+)\s+(\S+)", open(sys.argv[2]).read()):
    x, y, z = map(float, m.groups())
    if abs(z) < 1e-6:
        verts.add((x, y))
def ring(cx, d):
    pts = [p for p in verts if abs(math.hypot(p[0] - cx, p[1]) - d / 2) < 0.01]
    assert len(pts) >= 32, "%d vertices on the ring of diameter %.3f at x %.3f" % (len(pts), d, cx)
    return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
h, a = ring(0.0, bore), ring(length, axis)
measured = math.hypot(a[0] - h[0], a[1] - h[1])
assert abs(measured - length) <= 0.1, "axes %.4f mm apart, link length %.4f mm" % (measured, length)
print("%.4f mm for %.4f mm" % (measured, length))
PY
    done
    for want in "## Printed parts" "link_1.stl" "base_plate.stl" "tool_holder.stl" "PLA" \
                "layers" "Screws" "M3" "mm apart in the mesh" "Printed link masses"; do
        grep -qF -- "$want" "$tmp/sheet.md" || fail "the build sheet lacks '$want'"
    done
    grep -q "a check failed" "$tmp/sheet.md" && fail "a check failed: $(grep 'a check failed' "$tmp/sheet.md")"
    expect_exit 0 "export --parts" "$bin" export "$task" "$tmp/sol.json" --parts "$tmp/again" \
        --build-sheet "$tmp/sheet2.md"
    for f in "$tmp"/parts/*.scad; do
        cmp -s "$f" "$tmp/again/$(basename "$f")" || fail "export wrote another $(basename "$f")"
    done
    # A spatial arm: a printed link for each link with a common normal, its
    # axes at a_k in the mesh, its mass in the dynamics the sheet's module
    # choice carries.
    spatial=$root/tasks/spatial/glue-box-edges.json
    expect_exit 0 "spatial solve --parts" "$bin" solve "$spatial" -o "$tmp/s.json" \
        --parts "$tmp/sparts" --build-sheet "$tmp/ssheet.md" -q
    python3 - "$tmp/s.json" "$tmp/sparts" >"$tmp/spatial" 2>&1 <<'PY' || fail "spatial parts: $(cat "$tmp/spatial")"
import json, os, re, sys
rows = json.load(open(sys.argv[1]))["robot"]["dh"]
for k, row in enumerate(rows, 1):
    scad = os.path.join(sys.argv[2], "link_%d.scad" % k)
    a = abs(row["a"] if isinstance(row, dict) else row[0])
    if a <= 0.001:
        assert not os.path.exists(scad), "link %d: a printed link for a = %g" % (k, a)
        continue
    length = float(re.search(r"\nlink_length = ([-0-9.]+);", open(scad).read()).group(1))
    assert abs(length - 1000 * a) < 1e-3, "link %d: %g mm for a = %g m" % (k, length, a)
    assert os.path.getsize(scad[:-5] + ".stl") > 0, "link %d: no STL" % k
PY
    grep -q "mm apart in the mesh" "$tmp/ssheet.md" || fail "the spatial build sheet lacks the spacing checks"
    grep -q "Printed link masses" "$tmp/ssheet.md" || fail "the spatial build sheet lacks the printed masses"
    grep -q "a check failed" "$tmp/ssheet.md" && fail "spatial: $(grep 'a check failed' "$tmp/ssheet.md")"
fi
finish "parts ($mode)"
