#!/usr/bin/env bash
# Hostile input to the commands that read files (README "Limits"): what is
# not a regular file, files too large, folders that link to themselves,
# times no controller can hold, motions that fail verification, task names
# made of control bytes, and the messages of out-of-range options. Each is
# refused at once with exit 2 naming the file or part, or read as the
# documented behaviour says; nothing hangs, nothing is read whole first.
set -u
source "$(dirname "$0")/shell_test_lib.sh"

expect_exit() {  # expected-code description command...
    local want=$1 what=$2
    shift 2
    timeout 20 "$@" >"$tmp/out" 2>"$tmp/err"
    local got=$?
    [ "$got" -eq "$want" ] || fail "$what: exit $got, expected $want ($(head -c 300 "$tmp/err"))"
}
expect_message() {  # description text...
    local what=$1
    shift
    for want in "$@"; do
        grep -qF -- "$want" "$tmp/err" || fail "$what: message lacks '$want': $(head -c 300 "$tmp/err")"
    done
}
rose=$root/tasks/rose.json

# What is not a regular file is refused before anything is read: a device
# (which would be read for ever), a FIFO (which would block), a folder.
mkfifo "$tmp/fifo.json"
for cmd in "validate" "solve -o $tmp/x.json" "explain" "export-svg -o $tmp/x.svg"; do
    set -- $cmd
    expect_exit 2 "$1 /dev/zero" "$bin" "$1" /dev/zero "${@:2}"
    expect_message "$1 /dev/zero" "/dev/zero: is not a regular file"
    expect_exit 2 "$1 a FIFO" "$bin" "$1" "$tmp/fifo.json" "${@:2}"
    expect_message "$1 a FIFO" "fifo.json: is not a regular file"
done
expect_exit 2 "validate a folder" "$bin" validate "$tmp"
expect_message "validate a folder" "is a folder"
mkfifo "$tmp/fifo.svg"
expect_exit 2 "import a FIFO" "$bin" import "$tmp/fifo.svg" -o "$tmp/x.json"
expect_message "import a FIFO" "fifo.svg: is not a regular file"

# A solution file is capped as a task file is: a sparse 1 GB file is refused
# by its size, not read.
truncate -s 1G "$tmp/huge.solution.json"
for cmd in "export $rose $tmp/huge.solution.json --csv $tmp/x.csv" \
           "export $rose /dev/zero --csv $tmp/x.csv" "export $rose $tmp/fifo.json --csv $tmp/x.csv"; do
    expect_exit 2 "$cmd" $bin $cmd
done
"$bin" export "$rose" "$tmp/huge.solution.json" --csv "$tmp/x.csv" 2>"$tmp/err"
expect_message "a 1 GB solution" "1073741824 bytes, more than the 268435456 allowed for a solution file"

# A solved solution whose motion is not rose's: it fails verification.
python3 - "$tmp/wrong.json" "$tmp/far.json" <<'PY'
import json, sys
samples = [{"t": 0.1 * i, "phase": "trace", "primitive": 0, "q": [0.2 + 0.001 * i, 1.0],
            "qd": [0.0, 0.0], "qdd": [0.0, 0.0]} for i in range(5)]
doc = {"format": "modsynth-solution/1", "task": "rose", "status": "solved",
       "robot": {"dof": 2, "base": [0.0, 0.0], "link_lengths": [0.35, 0.3], "link_diameter": 0.03175},
       "samples": samples}
json.dump(doc, open(sys.argv[1], "w"))
for s in samples:
    s["t"] = 1e300 if s["t"] > 0 else 0.0
json.dump(doc, open(sys.argv[2], "w"))
PY
# A controller would command it: no CSV or joint trajectory, exit 2, unless
# the user asks for them.
expect_exit 2 "export an uncertified motion" "$bin" export "$rose" "$tmp/wrong.json" \
    --csv "$tmp/w.csv" --joint-trajectory "$tmp/w.yaml" --report "$tmp/w.html"
expect_message "export an uncertified motion" "not certified" "--csv $tmp/w.csv: not written" \
    "--joint-trajectory $tmp/w.yaml: not written" "--write-uncertified"
[ ! -e "$tmp/w.csv" ] && [ ! -e "$tmp/w.yaml" ] || fail "controller files written for an uncertified motion"
[ -s "$tmp/w.html" ] || fail "the report of an uncertified motion is not written"
expect_exit 0 "export an uncertified motion on request" "$bin" export "$rose" "$tmp/wrong.json" \
    --csv "$tmp/w.csv" --joint-trajectory "$tmp/w.yaml" --write-uncertified
[ -s "$tmp/w.csv" ] && [ -s "$tmp/w.yaml" ] || fail "--write-uncertified wrote no controller files"
# Times beyond any motion are refused by name, never written as a negative
# duration.
expect_exit 2 "export times of 1e300 s" "$bin" export "$rose" "$tmp/far.json" \
    --joint-trajectory "$tmp/f.yaml" --write-uncertified
expect_message "export times of 1e300 s" "samples[1].t: 1e+300 s"
[ ! -e "$tmp/f.yaml" ] || fail "a joint trajectory written for times of 1e300 s"

# export-svg reads a task as every command does: not both trajectory and
# strokes, parts named strokes[s][j].
python3 - "$rose" "$tmp" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
both = dict(t, strokes=[t["trajectory"]])
json.dump(both, open(sys.argv[2] + "/both.json", "w"))
bad = {k: v for k, v in t.items() if k != "trajectory"}
bad["strokes"] = [t["trajectory"][:2], [dict(t["trajectory"][2], start=[9.0, 9.0])]]
json.dump(bad, open(sys.argv[2] + "/badstroke.json", "w"))
PY
expect_exit 2 "export-svg of trajectory and strokes" "$bin" export-svg "$tmp/both.json" -o "$tmp/x.svg"
expect_message "export-svg of trajectory and strokes" "strokes"
expect_exit 2 "export-svg of a bad stroke" "$bin" export-svg "$tmp/badstroke.json" -o "$tmp/x.svg"
expect_message "export-svg of a bad stroke" "strokes[1][0]"
grep -qF "trajectory[0]" "$tmp/err" && fail "export-svg names trajectory[0] in a task of strokes: $(cat "$tmp/err")"

# import checks the whole task once: a cap is named by its own part.
python3 -c '
import sys
circles = "".join("<circle cx=\"%d\" cy=\"%d\" r=\"1\"/>" % (5 + (k % 40) * 5, 5 + (k // 40) * 5) for k in range(1001))
open(sys.argv[1], "w").write("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"300mm\" height=\"300mm\" "
    "viewBox=\"0 0 300 300\"><path d=\"M 250,250 L 290,290\"/><g id=\"obs\">" + circles + "</g></svg>")' "$tmp/obs.svg"
expect_exit 2 "import 1001 obstacles" "$bin" import "$tmp/obs.svg" -o "$tmp/x.json" --obstacles-from obs
expect_message "import 1001 obstacles" "obstacles: 1001 obstacles, more than the 1000 allowed"
grep -qF "strokes[" "$tmp/err" && fail "import 1001 obstacles names a stroke: $(cat "$tmp/err")"

# batch and regress on folders that link to themselves: every task once, a
# bad entry one invalid row, no internal error.
# Infeasible tasks (proved in milliseconds) keep the runs short.
far=$root/tasks/infeasible/out-of-reach.task.json
mkdir -p "$tmp/suite/sub"
cp "$far" "$tmp/suite/sub/far.json"
ln -s loop.json "$tmp/suite/loop.json"
ln -s . "$tmp/suite/sub/again"
ln -s .. "$tmp/suite/sub/up"
python3 - "$far" "$tmp/suite/esc.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t["name"] = "esc\x1b]0;owned\x07\r\nfake line"
json.dump(t, open(sys.argv[2], "w"))
PY
timeout 120 "$bin" batch "$tmp/suite" --out "$tmp/r.jsonl" --jobs 2 --time-limit 20 >"$tmp/out" 2>"$tmp/err"
code=$?
[ "$code" -eq 1 ] || fail "batch of a folder linked to itself: exit $code, expected 1 ($(tail -3 "$tmp/err"))"
python3 - "$tmp/r.jsonl" <<'PY' || fail "batch of a folder linked to itself: $(cat "$tmp/r.jsonl")"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
tasks = sorted(l["task"].split("suite/")[1] for l in lines)
assert tasks == ["esc.json", "loop.json", "sub/far.json"], tasks
loop = [l for l in lines if l["task"].endswith("loop.json")][0]
assert loop["status"] == "invalid" and "symbolic links" in loop["message"], loop
PY
# The progress line shows the name escaped: no ESC, CR or LF of it.
python3 - "$tmp/err" <<'PY' || fail "batch prints a task name's control bytes: $(cat -v "$tmp/err")"
import sys
err = open(sys.argv[1], "rb").read()
assert b"\x1b" not in err and b"\x07" not in err and b"\r" not in err, err
assert b"fake line" not in err.split(b"\n")[0] or True
lines = [l for l in err.split(b"\n") if b"esc" in l]
assert lines and all(b"\\x1B" in l for l in lines), lines
assert not any(l.startswith(b"fake line") for l in err.split(b"\n")), err
PY
mkdir -p "$tmp/rtasks" "$tmp/renc"
ln -s self.json "$tmp/rtasks/self.json"
ln -s . "$tmp/rtasks/again"
expect_exit 1 "regress on a folder with a link to itself" "$bin" regress encodings --tasks "$tmp/rtasks" --dir "$tmp/renc"
grep -q "internal error" "$tmp/err" && fail "regress: internal error: $(cat "$tmp/err")"
grep -q "self" "$tmp/out" || fail "regress does not name the bad entry: $(cat "$tmp/out")"
cp "$far" "$tmp/rtasks/far.json"
mkfifo "$tmp/renc/far.expect.json"
expect_exit 1 "regress with a FIFO as its expectation" "$bin" regress encodings --tasks "$tmp/rtasks" \
    --dir "$tmp/renc" --time-limit 20
grep -q "far.*unreadable expectation.*not a regular file" "$tmp/out" ||
    fail "regress does not refuse a FIFO as its expectation: $(cat "$tmp/out")"

# Messages of out-of-range options say the range in a few digits.
expect_exit 2 "import --tolerance 1e-12" "$bin" import "$root/tasks/drawings/sketch.svg" -o "$tmp/x.json" --tolerance 1e-12
expect_message "import --tolerance 1e-12" "--tolerance" "at least 1e-09"
grep -q "0.000000" "$tmp/err" && fail "import --tolerance 1e-12: $(cat "$tmp/err")"
expect_exit 2 "import --width 0" "$bin" import "$root/tasks/drawings/sketch.svg" -o "$tmp/x.json" --width 0
expect_message "import --width 0" "--width" "greater than 0"
[ "$(wc -c <"$tmp/err")" -lt 300 ] || fail "import --width 0: a long message: $(cat "$tmp/err")"
for v in nan inf -1; do
    expect_exit 2 "import --width $v" "$bin" import "$root/tasks/drawings/sketch.svg" -o "$tmp/x.json" --width "$v"
    expect_exit 2 "import --scale $v" "$bin" import "$root/tasks/drawings/sketch.svg" -o "$tmp/x.json" --scale "$v"
    expect_exit 2 "import --time-limit $v" "$bin" import "$root/tasks/drawings/sketch.svg" -o "$tmp/x.json" --time-limit "$v"
done
expect_exit 4 "solve --time-limit 0.001" "$bin" solve "$rose" -o "$tmp/x.json" --time-limit 0.001 --quiet
python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))["explanation"]["message"]
assert ": ." not in m and not m.endswith(": "), m' "$tmp/x.json" || fail "solve --time-limit 0.001: $(cat "$tmp/x.json")"

# Outputs are checked before any work: never a FIFO (which would block),
# never an input (which would be lost), never in a folder that is not
# there; each refused at once, naming the option, and the input intact.
cp "$rose" "$tmp/in.json"
mkfifo "$tmp/out.fifo"
before=$(md5sum <"$tmp/in.json")
for args in "-o $tmp/out.fifo" "-o $tmp/x.json --report $tmp/out.fifo" "-o $tmp/x.json --events $tmp/out.fifo" \
            "-o $tmp/in.json" "-o $tmp/x.json --report $tmp/in.json" "-o $tmp/x.json --events $tmp/in.json" \
            "-o $tmp/x.json --csv $tmp/x.json" "-o $tmp/missing/dir/x.json" "-o $tmp/x.json --events /dev/full"; do
    start=$(date +%s%N)
    expect_exit 2 "solve $args" "$bin" solve "$tmp/in.json" $args --quiet
    [ $(( ($(date +%s%N) - start) / 1000000 )) -lt 2000 ] || fail "solve $args: not refused before the work"
done
"$bin" solve "$tmp/in.json" -o "$tmp/x.json" --csv "$tmp/x.json" >/dev/null 2>"$tmp/err"
expect_message "solve -o X --csv X" "-o $tmp/x.json: is also the output of --csv"
"$bin" solve "$tmp/in.json" -o "$tmp/in.json" >/dev/null 2>"$tmp/err"
expect_message "solve -o INPUT" "-o $tmp/in.json: is the input"
"$bin" solve "$tmp/in.json" -o "$tmp/missing/dir/x.json" >/dev/null 2>"$tmp/err"
expect_message "solve -o in a missing folder" "does not exist"
"$bin" solve "$rose" -o "$tmp/good.json" --quiet >/dev/null 2>&1 || fail "solve rose"
expect_exit 2 "export onto its solution" "$bin" export "$rose" "$tmp/good.json" --csv "$tmp/good.json"
expect_message "export onto its solution" "--csv $tmp/good.json: is the input"
ln -s in.json "$tmp/alias.json"
expect_exit 2 "a link to the input as output" "$bin" solve "$tmp/in.json" -o "$tmp/alias.json" --quiet
[ "$(md5sum <"$tmp/in.json")" = "$before" ] || fail "an input was overwritten"
python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$tmp/good.json" || fail "export destroyed its solution"
# In a --parts folder a link is replaced, never written through.
mkdir -p "$tmp/parts" && echo "outside" >"$tmp/outside.txt"
ln -s ../outside.txt "$tmp/parts/link_1.scad"
"$bin" export "$rose" "$tmp/good.json" --parts "$tmp/parts" >/dev/null 2>&1
[ "$(cat "$tmp/outside.txt")" = "outside" ] || fail "--parts wrote through a link to a file outside the folder"
[ -f "$tmp/parts/link_1.scad" ] && [ ! -L "$tmp/parts/link_1.scad" ] || fail "--parts left the link in place of link_1.scad"

# Speed caps lie in the range of joint limits (1e-6 to 1e6): no motion of
# centuries, no cap lost to rounding.
for v in 1e-9 1e-100 1e-300 1e7; do
    expect_exit 2 "--joint-speed $v" "$bin" solve "$rose" -o "$tmp/x.json" --joint-speed "$v" --quiet
    expect_message "--joint-speed $v" "--joint-speed"
    expect_exit 2 "--ee-speed $v" "$bin" solve "$rose" -o "$tmp/x.json" --ee-speed "$v" --quiet
done

# A task's name and the catalog's module names reach OpenSCAD, URDF,
# Markdown and the terminal escaped: no code, no broken comment, no control
# bytes. The catalog is copied beside a copy of the program (its installed
# place) with an entry of such a name, a FIFO and a file past the cap.
prefix=$tmp/prefix
mkdir -p "$prefix/bin" "$prefix/share/modsynth"
cp "$bin" "$prefix/bin/modsynth"
cp -r "$root/catalog" "$prefix/share/modsynth/catalog"
python3 - "$prefix/share/modsynth/catalog" "$rose" "$tmp" <<'PY'
import json, sys
cat, rose, tmp = sys.argv[1:4]
h = json.load(open(cat + "/hebi-x-series.json"))
evil = dict(h["entries"][0])
evil["name"] = "X9-evil --> <x/>\ncube([500,500,500]); include <inc.scad>\n// "
h["entries"].append(evil)
json.dump(h, open(cat + "/hebi-x-series.json", "w"))
t = json.load(open(rose))
t["name"] = "rose\ncube([500,500,500]); include <inc.scad>\n"
t["robot"]["modules"] = [evil["name"]]
json.dump(t, open(tmp + "/evil.json", "w"))
u = json.load(open(rose))
u["robot"]["modules"] = ["\x1b[2J\x07\rno-such", "y" * 1000000]
json.dump(u, open(tmp + "/unknown.json", "w"))
PY
evil_bin=$prefix/bin/modsynth
"$evil_bin" solve "$tmp/evil.json" -o "$tmp/evil.sol.json" --urdf "$tmp/evil.urdf" \
    --build-sheet "$tmp/evil.md" --parts "$tmp/evilparts" --quiet >"$tmp/out" 2>"$tmp/err" ||
    fail "solve with a hostile name: $(head -c 300 "$tmp/err")"
ls "$tmp"/evilparts/*.scad >/dev/null 2>&1 || fail "no OpenSCAD sources written"
python3 - "$tmp"/evilparts/*.scad <<'PY' || fail "a name became OpenSCAD code"
import sys
for f in sys.argv[1:]:
    for n, line in enumerate(open(f), 1):
        code = line.split("//", 1)[0]
        if "cube([500" in code or "include <" in code:
            sys.exit("%s:%d: %s" % (f, n, line))
PY
python3 - "$tmp/evil.urdf" <<'PY' || fail "the URDF of a hostile module name is not well-formed XML"
import sys, xml.dom.minidom
xml.dom.minidom.parse(sys.argv[1])
PY
python3 - "$tmp/out" "$tmp/evil.md" <<'PY' || fail "control bytes of a name reached the terminal or the sheet"
import sys
for f in sys.argv[1:]:
    b = open(f, "rb").read()
    assert not any(c < 32 and c not in (9, 10) for c in b), f
PY
expect_exit 2 "unknown modules with control bytes" "$evil_bin" validate "$tmp/unknown.json"
python3 - "$tmp/err" <<'PY' || fail "an unknown module name is echoed raw: $(head -c 300 "$tmp/err" | cat -v)"
import sys
b = open(sys.argv[1], "rb").read()
assert b"\x1b" not in b and b"\x07" not in b and b"\r" not in b, b[:200]
assert b"\\x1B" in b, b[:200]
assert len(b) < 20000, len(b)
PY
mkfifo "$prefix/share/modsynth/catalog/pipe.json"
expect_exit 2 "a FIFO in the catalog" "$evil_bin" validate "$tmp/unknown.json"
expect_message "a FIFO in the catalog" "pipe.json: is not a regular file"
rm "$prefix/share/modsynth/catalog/pipe.json"
truncate -s 2M "$prefix/share/modsynth/catalog/huge.json"
expect_exit 2 "a catalog file past its cap" "$evil_bin" validate "$tmp/unknown.json"
expect_message "a catalog file past its cap" "huge.json: 2097152 bytes, more than the"

# Spatial checks count against the time limit: a helix of a thousand turns
# round posts that nearly touch it all along takes minutes to check.
python3 - "$tmp/coil.json" <<'PY'
import json, sys
obs = [{"type": "capsule", "a": [0, 0, 0], "b": [0, 0, 5.2], "radius": round(0.1199 - 1e-6 * i, 7)}
       for i in range(1000)]
json.dump({"format": "modsynth-task/1", "name": "coil", "space": "3d",
           "trajectory": [{"type": "helix", "start": [0.12, 0, 0.1], "center": [0, 0, 0.1],
                           "axis": [0, 0, 1], "direction": "ccw", "pitch": 0.005, "turns": 1000}],
           "obstacles": obs, "base_regions": [{"min": [-0.05, -0.05, -0.9], "max": [0.05, 0.05, -0.9]}]},
          open(sys.argv[1], "w"))
PY
for cmd in "validate --time-limit 2" "solve -o $tmp/coil.sol.json --time-limit 2 --quiet" "explain --time-limit 2"; do
    set -- $cmd
    start=$(date +%s%N)
    expect_exit 4 "$1 of a long coil" "$bin" "$1" "$tmp/coil.json" "${@:2}"
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    [ "$ms" -lt 3500 ] || fail "$1 of a long coil: $ms ms, past its 2 s limit"
    grep -q "time limit" "$tmp/out" || fail "$1 of a long coil does not say why: $(head -c 300 "$tmp/out")"
done
grep -q '"status": "unknown"' "$tmp/coil.sol.json" || fail "solve of a long coil: $(head -c 300 "$tmp/coil.sol.json")"
# Commands that take planar tasks only refuse it before checking it.
for cmd in "baseline" "compare" "export-svg -o $tmp/coil.svg"; do
    set -- $cmd
    start=$(date +%s%N)
    expect_exit 2 "$1 of a long coil" "$bin" "$1" "$tmp/coil.json" "${@:2}"
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    [ "$ms" -lt 1500 ] || fail "$1 of a long coil: $ms ms to refuse a spatial task"
    expect_message "$1 of a long coil" "spatial tasks are not supported by $1"
done

# A spatial solution's robot within the task limits: no 309-digit base.
python3 - "$tmp/good.json" "$tmp/far-base.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["robot"]["base"] = [1e308, 0.0]
json.dump(s, open(sys.argv[2], "w"))
PY
expect_exit 2 "a base at 1e308" "$bin" certify "$rose" "$tmp/far-base.json"
expect_message "a base at 1e308" "robot.base[0]: 1e+308 m is beyond"


# Jerk limits hold in space as in the plane: export hands a controller no
# timing that breaks the task's jerk, and times a motion saved without one
# within it (a CSV at 602 rad/s^3 for a limit of 1e-6 once).
spatial=$root/tests/fixtures/spatial/s3-0001.task.json
if "$bin" solve "$spatial" -o "$tmp/s3.json" --quiet --time-limit 60 >/dev/null 2>&1; then
    python3 - "$spatial" "$tmp/s3.json" "$tmp/s3-jerk.task.json" "$tmp/s3-untimed.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t.setdefault("robot", {})["joint_limits"] = {"velocity": 2, "acceleration": 5, "jerk": 0.5}
json.dump(t, open(sys.argv[3], "w"))
s = json.load(open(sys.argv[2]))
for x in s["samples"]:
    x.pop("qd", None)
    x.pop("qdd", None)
json.dump(s, open(sys.argv[4], "w"))
PY
    expect_exit 2 "export of a timing past the task's jerk" "$bin" export "$tmp/s3-jerk.task.json" "$tmp/s3.json" --csv "$tmp/s3.csv"
    expect_message "export of a timing past the task's jerk" "breaks robot.joint_limits"
    [ ! -e "$tmp/s3.csv" ] || fail "a CSV past the task's jerk was written"
    "$bin" export "$tmp/s3-jerk.task.json" "$tmp/s3-untimed.json" --csv "$tmp/s3u.csv" >"$tmp/out" 2>"$tmp/err" ||
        fail "export of an untimed spatial motion with jerk limits: $(head -c 300 "$tmp/err")"
    python3 - "$tmp/s3u.csv" <<'PY' || fail "the CSV of a spatial motion breaks the task's jerk"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
keys = [k for k in rows[0] if k.startswith("qdd")]
assert keys, rows[0].keys()
for k in keys:
    assert abs(float(rows[0][k])) < 1e-6 and abs(float(rows[-1][k])) < 1e-6, k
for a, b in zip(rows, rows[1:]):
    dt = float(b["t"]) - float(a["t"])
    for k in keys:
        # Between samples qdd changes by at most jerk * dt, up to the
        # CSV's rounding (t to 1e-6 s, qdd to 1e-9).
        assert abs(float(b[k]) - float(a[k])) <= 0.5 * (dt + 1e-6) * (1 + 1e-6) + 2e-9, (k, a["t"], b["t"])
PY
else
    fail "solve of $spatial"
fi

finish hostile
