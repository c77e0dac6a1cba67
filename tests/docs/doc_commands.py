#!/usr/bin/env python3
"""Runs every command the README and the guides show, and compares what it
prints with what they show.

    doc_commands.py MODSYNTH_BINARY SOURCE_DIR [--slow] [--only FILE] [-v]

What is checked, in README.md and docs/**/*.md:

- A fenced block tagged `console` holds commands, each a line starting with
  `$ ` (continued on the next lines while it ends with a backslash),
  followed by the output it shows. The command runs in bash, in a scratch
  folder that holds `build/modsynth` (also on PATH as `modsynth`) and links
  to the source's `tasks/`, `tests/` and `docs/` (and the build's
  `tests/modsynth_embed_example`); the blocks of one file
  share it, in order, so a command may read what an earlier one wrote.
  Standard output and standard error are read together, as a terminal
  shows them.
- Its exit code must be 0, or N when the command line ends with `# exit N`.
- Output: every shown line must match the next lines printed, in order.
  A line `...` stands for any number of lines (none too), and `...` inside
  a line for any text; a time (a number followed by ` s`, `s]` or ` ms`)
  matches any number, since it differs from run to run. Shown output may
  stop early: what the command prints past it is not compared.
- A command ending in `# until Ctrl-C` (the server) is started with
  `--port 0` added, so that it takes a free port (a URL shown matches any
  port); its shown lines must appear within 20 s, and it is then stopped
  with SIGINT and must exit 0.
- A block tagged `console slow` runs only with --slow (a CTest of the slow
  label), which also runs the other blocks of its file, before it as they
  stand, so that a slow command may use what a fast one wrote.
- A fenced block tagged `usage` holds synopses: each line that starts with
  `modsynth SUBCOMMAND` or `build/modsynth SUBCOMMAND`, and the indented
  lines that continue it, name options, each of which
  `modsynth SUBCOMMAND --help` must list.
- A fenced block tagged `json file=PATH` must hold the JSON of the file at
  PATH (relative to the source folder), so that a task shown is the task
  the commands use.
- No line starting with `$ ` may stand in any other block (but one tagged
  `markdown`, which shows Markdown source): every command shown is run.
- A link to a file of the project (`[design](../design.md)`) must lead to
  one.

To add an example to a guide: write the command and its output in a
`console` block; this test picks it up. Exit 0 when everything matches,
1 otherwise, with the differences.
"""
import argparse
import json
import os
import pathlib
import re
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time

TIME = r"[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?"
FENCE = re.compile(r"^(\s*)(```+)(.*)$")


def blocks(path):
    """(info, first line number, lines) of every fenced block of a file."""
    out = []
    lines = path.read_text(encoding="utf-8").splitlines()
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, fence, info = m.group(1), m.group(2), m.group(3).strip()
        start = i + 1
        body = []
        i += 1
        # Closed by a fence at least as long (a block may show a block).
        closing = re.compile(r"^\s*" + fence + r"`*\s*$")
        while i < len(lines) and not closing.match(lines[i]):
            body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i])
            i += 1
        out.append((info, start + 1, body))
        i += 1
    return out


def commands(body, first_line):
    """[(line number, command, expected lines)] of a console block."""
    out = []
    i = 0
    while i < len(body):
        if not body[i].startswith("$ "):
            i += 1
            continue
        number = first_line + i
        cmd = body[i][2:]
        while cmd.endswith("\\") and i + 1 < len(body):
            i += 1
            cmd = cmd[:-1] + " " + body[i].strip()
        i += 1
        expected = []
        while i < len(body) and not body[i].startswith("$ "):
            expected.append(body[i])
            i += 1
        while expected and not expected[-1].strip():
            expected.pop()
        out.append((number, cmd.strip(), expected))
    return out


def line_pattern(shown):
    """A shown output line as a regular expression."""
    parts = re.split(r"(\.\.\.)", shown)
    rx = ""
    for p in parts:
        if p == "...":
            rx += ".*"
            continue
        esc = re.escape(p)
        # Times: "0.241 s", "[  0.122s]", "12 ms".
        esc = re.sub(r"[0-9]+(?:\\\.[0-9]+)?(?:e[-+]?[0-9]+)?(?=(\\ s\b|s\\\]|\\ ms\b))", TIME, esc)
        rx += esc
    return re.compile(rx.rstrip() + r"\s*$")


def matches(expected, printed):
    """Whether the printed lines show the expected ones in order: '...'
    lines skip any number of lines. Returns (ok, why)."""
    def go(e, p):
        while e < len(expected):
            if expected[e].strip() == "...":
                if e + 1 == len(expected):
                    return True, ""
                for q in range(p, len(printed) + 1):
                    ok, _ = go(e + 1, q)
                    if ok:
                        return True, ""
                return False, f"nothing after '...' matches {expected[e + 1]!r}"
            if p >= len(printed):
                return False, f"missing: {expected[e]!r}"
            if not line_pattern(expected[e]).match(printed[p]):
                return False, f"expected {expected[e]!r}\n     got {printed[p]!r}"
            e += 1
            p += 1
        return True, ""
    return go(0, 0)


def scratch(binary, root):
    d = pathlib.Path(tempfile.mkdtemp(prefix="modsynth-docs-"))
    (d / "build").mkdir()
    shutil.copy2(binary, d / "build" / "modsynth")
    # The program finds libhsl.so beside itself (its build folder's rpath).
    lib = pathlib.Path(binary).parent / "libhsl.so"
    if lib.exists():
        shutil.copy2(lib, d / "build" / "libhsl.so")
    # The example program that embeds the library, where the build made it.
    example = pathlib.Path(binary).parent / "tests" / "modsynth_embed_example"
    if example.exists():
        (d / "build" / "tests").mkdir()
        os.symlink(example, d / "build" / "tests" / example.name)
    for name in ("tasks", "tests", "docs", "catalog"):
        os.symlink(root / name, d / name)
    return d


def run(cmd, where, timeout):
    env = dict(os.environ)
    env["PATH"] = str(where / "build") + os.pathsep + env.get("PATH", "")
    env["COLUMNS"] = "100"
    return subprocess.run(["bash", "-c", cmd], cwd=where, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=timeout)


def run_server(cmd, where, expected):
    env = dict(os.environ)
    env["PATH"] = str(where / "build") + os.pathsep + env.get("PATH", "")
    proc = subprocess.Popen(["bash", "-c", "exec " + cmd + " --port 0"], cwd=where, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    # The port it prints is the free one it took.
    expected = [re.sub(r"(https?://[0-9.]+):[0-9]+", r"\1:...", e) for e in expected]
    printed = []
    deadline = time.time() + 20
    ok, why = False, "no output"
    buffer = b""
    while time.time() < deadline and proc.poll() is None:
        ready, _, _ = select.select([proc.stdout], [], [], 0.2)
        if not ready:
            continue
        chunk = os.read(proc.stdout.fileno(), 4096)
        if not chunk:
            break
        buffer += chunk
        *done, buffer = buffer.split(b"\n")
        printed += [line.decode("utf-8", "replace") for line in done]
        ok, why = matches(expected, printed)
        if ok:
            break
    proc.send_signal(signal.SIGINT)
    try:
        code = proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        code = "killed"
    if ok and code != 0:
        ok, why = False, f"exit {code} after SIGINT"
    return ok, why, printed


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("source")
    ap.add_argument("--slow", action="store_true", help="run the blocks tagged `console slow`")
    ap.add_argument("--only", help="only this file (relative to the source folder)")
    ap.add_argument("-v", action="store_true", help="print every command and its output")
    args = ap.parse_args()
    root = pathlib.Path(args.source).resolve()
    binary = pathlib.Path(args.binary).resolve()
    files = [root / "README.md"] + sorted((root / "docs").rglob("*.md"))
    if args.only:
        files = [root / args.only]
    failures, checked, synopses = [], 0, 0
    helps = {}
    for path in files:
        rel = path.relative_to(root)
        where = None
        found = blocks(path)
        if not args.slow:
            # Links to the project's own files lead somewhere.
            for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", path.read_text(encoding="utf-8")):
                if re.match(r"[a-z]+:", target):
                    continue
                if not (path.parent / target).exists():
                    failures.append(f"{rel}: a link to {target}, which is not there")
        # The slow run takes a file's fast blocks too, in order: a slow
        # command may read what a fast one wrote.
        has_slow = any(info.split()[:1] == ["console"] and "slow" in info.split()[1:] for info, _, _ in found)
        if args.slow and not has_slow:
            continue
        for info, first, body in found:
            words = info.split()
            kind = words[0] if words else ""
            if args.slow and kind != "console":
                continue  # synopses and shown files are the fast run's
            if kind == "usage":
                sub = None
                for k, line in enumerate(body):
                    m = re.match(r"^(?:build/)?modsynth ([a-z-]+)(?: ([a-z][a-z-]*))?", line)
                    if m:
                        sub = m.group(1)
                        # A subcommand of the subcommand (regress encodings).
                        if m.group(2) and subprocess.run([str(binary), sub, m.group(2), "--help"],
                                                         capture_output=True).returncode == 0:
                            sub += " " + m.group(2)
                    elif not (sub and line[:1].isspace()):
                        sub = None  # a line of its own that is no synopsis
                    if not sub:
                        continue
                    if sub not in helps:
                        helps[sub] = subprocess.run([str(binary), *sub.split(), "--help"],
                                                    capture_output=True, text=True).stdout
                    for opt in re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", line):
                        synopses += 1
                        if not re.search(r"(?<![\w-])" + re.escape(opt) + r"\b", helps[sub]):
                            failures.append(f"{rel}:{first + k}: modsynth {sub} --help lists no {opt}")
                continue
            if kind == "json" and len(words) > 1 and words[1].startswith("file="):
                shown_file = root / words[1][len("file="):]
                try:
                    same = json.loads("\n".join(body)) == json.loads(shown_file.read_text())
                except (OSError, ValueError) as e:
                    same = False
                    failures.append(f"{rel}:{first}: {e}")
                if not same:
                    failures.append(f"{rel}:{first}: the JSON shown is not {words[1][5:]}")
                continue
            if kind != "console":
                if kind == "markdown":
                    continue  # Markdown source shown as such (how to write an example)
                for k, line in enumerate(body):
                    if line.startswith("$ "):
                        failures.append(f"{rel}:{first + k}: a command outside a console block: {line}")
                continue
            if "slow" in words[1:] and not args.slow:
                continue
            if where is None:
                where = scratch(binary, root)
            for number, cmd, expected in commands(body, first):
                checked += 1
                m = re.search(r"\s+#\s*(exit (\d+)|until Ctrl-C)\s*$", cmd)
                want = 0
                if m and m.group(2):
                    want = int(m.group(2))
                if m:
                    cmd = cmd[:m.start()]
                t0 = time.time()
                if m and m.group(1) == "until Ctrl-C":
                    ok, why, printed = run_server(cmd, where, expected)
                    code = 0
                else:
                    try:
                        r = run(cmd, where, timeout=600)
                    except subprocess.TimeoutExpired:
                        failures.append(f"{rel}:{number}: {cmd}\n   did not end within 600 s")
                        continue
                    printed = r.stdout.splitlines()
                    code = r.returncode
                    ok, why = matches(expected, printed)
                    if code != want:
                        ok, why = False, f"exit {code}, the guide says {want}"
                if args.v:
                    print(f"{rel}:{number}: $ {cmd}  ({time.time() - t0:.1f} s)")
                    for line in printed[:40]:
                        print("    " + line)
                if not ok:
                    shown = "\n".join("     | " + p for p in printed[:30])
                    failures.append(f"{rel}:{number}: $ {cmd}\n   {why}\n   printed:\n{shown}")
        if where is not None:
            shutil.rmtree(where, ignore_errors=True)
    for f in failures:
        print("FAIL: " + f)
    label = "slow" if args.slow else "fast"
    print(f"{checked} documented commands ({label}) run, {synopses} synopsis options checked, "
          f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
