#!/usr/bin/env bash
# Walls in space: every task of tasks/spatial/infeasible/ is proved
# infeasible by solve (exit 3) with a wall whose witness the independent
# checker (check_enclosure.py, exact rational arithmetic, no code shared with
# the prover) accepts; a witness with a cell taken out, or with an obstacle
# of the wall dropped, is refused. explain gives the same core and witness,
# export writes a build sheet that says why and a report that draws the
# wall.
# Arguments: modsynth binary, source root.
set -u
source "$(dirname "$0")/shell_test_lib.sh"
check="python3 $root/tests/check_enclosure.py"
count=0
for task in "$root"/tasks/spatial/infeasible/*.json; do
    name=$(basename "$task" .task.json)
    count=$((count + 1))
    sol=$tmp/$name.solution.json
    "$bin" solve "$task" -o "$sol" --time-limit 30 >"$tmp/out" 2>&1
    code=$?
    [ "$code" -eq 3 ] || { fail "$name: solve exit $code, not 3: $(head -c 300 "$tmp/out")"; continue; }
    $check "$task" "$sol" >"$tmp/check" 2>&1 || fail "$name: the checker refuses the wall: $(cat "$tmp/check")"
    # Mutants: the checker must bite.
    python3 - "$sol" "$tmp/cut.json" "$tmp/thin.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
w = s["explanation"]["enclosure"]["walls"][0]
run = w["cells"][len(w["cells"]) // 2]
cut = json.loads(json.dumps(s))
cw = cut["explanation"]["enclosure"]["walls"][0]
cw["cells"] = [r for r in cw["cells"] if r != run] + ([[run[0], run[1], run[2] + 1, run[3]]] if run[3] > run[2] else [])
json.dump(cut, open(sys.argv[2], "w"))
thin = json.loads(json.dumps(s))
thin["explanation"]["enclosure"]["walls"][0]["obstacles"] = w["obstacles"][1:]
json.dump(thin, open(sys.argv[3], "w"))
PY
    $check "$task" "$tmp/cut.json" >/dev/null 2>&1 && fail "$name: the checker accepts a witness with a cell taken out"
    $check "$task" "$tmp/thin.json" >/dev/null 2>&1 && fail "$name: the checker accepts a wall without one of its obstacles"
    # explain: the same core and a witness the checker accepts.
    "$bin" explain "$task" --json --time-limit 20 >"$tmp/explain.json" 2>"$tmp/err"
    python3 - "$sol" "$tmp/explain.json" "$tmp/explained.json" <<'PY' || fail "$name: explain differs from solve"
import json, sys
s = json.load(open(sys.argv[1]))
e = json.load(open(sys.argv[2]))
assert e["status"] == "infeasible", e["status"]
assert e["core"] == s["explanation"]["core"], (e["core"], s["explanation"]["core"])
json.dump({"status": "infeasible", "explanation": {"core": e["core"], "enclosure": e["enclosure"]}},
          open(sys.argv[3], "w"))
PY
    $check "$task" "$tmp/explained.json" >/dev/null 2>&1 || fail "$name: explain's witness is refused"
    # The build sheet says why; the report draws the wall.
    "$bin" export "$task" "$sol" --build-sheet "$tmp/$name.md" --report "$tmp/$name.html" >"$tmp/out" 2>&1 ||
        fail "$name: export of the infeasible solution: $(cat "$tmp/out")"
    grep -q "No arm to build" "$tmp/$name.md" || fail "$name: the build sheet does not say there is no arm"
    grep -q "close in " "$tmp/$name.md" || fail "$name: the build sheet does not give the proof"
    # Plain text a person reads: no backslash before ':', '-', '(', ',' or '.'.
    ! grep -q '\\[:(),.-]' "$tmp/$name.md" || fail "$name: the build sheet is over-escaped: $(grep '\\[:(),.-]' "$tmp/$name.md" | head -2)"
    # A long core is one line by its ends.
    [ "$(grep -c '^- `obstacles\[' "$tmp/$name.md")" -le 8 ] || fail "$name: the build sheet lists every obstacle of the core on its own line"
    grep -q '"enclosure":\[{"inside"' "$tmp/$name.html" || fail "$name: the report carries no wall"
done
[ "$count" -ge 2 ] || fail "only $count walled examples in tasks/spatial/infeasible/"
# Walls of no cells: a base region inside an obstacle, a tube too thick for
# the path's surroundings. The obstacle that fills the cells is the wall and
# in the core, the checker accepts the witness and refuses it without that
# obstacle, and explain names the obstacle rather than the base region alone.
for task in "$root"/tests/fixtures/spatial-walls-empty/*.task.json; do
    name=$(basename "$task" .task.json)
    sol=$tmp/$name.solution.json
    "$bin" solve "$task" -o "$sol" --time-limit 30 >"$tmp/out" 2>&1
    code=$?
    [ "$code" -eq 3 ] || { fail "$name: solve exit $code, not 3: $(head -c 300 "$tmp/out")"; continue; }
    grep -q "no free point there" "$tmp/out" || fail "$name: the answer does not say why: $(head -c 300 "$tmp/out")"
    $check "$task" "$sol" >"$tmp/check" 2>&1 || fail "$name: the checker refuses the wall: $(cat "$tmp/check")"
    python3 - "$sol" "$tmp/thin.json" <<'PY' || fail "$name: the wall or the core lacks its obstacle"
import json, sys
s = json.load(open(sys.argv[1]))
w = s["explanation"]["enclosure"]["walls"][0]
assert w["obstacles"] and not w["cells"], w
for i in w["obstacles"]:
    assert "obstacles[%d]" % i in s["explanation"]["core"], s["explanation"]["core"]
w["obstacles"] = []
json.dump(s, open(sys.argv[2], "w"))
PY
    $check "$task" "$tmp/thin.json" >/dev/null 2>&1 && fail "$name: the checker accepts the wall without its obstacles"
    "$bin" explain "$task" --json --time-limit 20 >"$tmp/explain.json" 2>"$tmp/err"
    python3 - "$tmp/explain.json" <<'PY' || fail "$name: explain does not name the wall's obstacle"
import json, sys
e = json.load(open(sys.argv[1]))
assert e["status"] == "infeasible", e["status"]
assert any(p.startswith("obstacles[") for p in e["core"]), e["core"]
PY
done
finish spatial_walls
