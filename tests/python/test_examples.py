"""The examples of examples/python/ run headless and say what they should."""

import os
import subprocess
import sys

import pytest

from conftest import child_env, path


def run_example(name, *args, timeout=900):
    done = subprocess.run(
        [sys.executable, path("examples", "python", name), *args],
        capture_output=True,
        text=True,
        env=child_env(),
        timeout=timeout,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def png(file):
    with open(file, "rb") as f:
        head = f.read(8)
    return head == b"\x89PNG\r\n\x1a\n" and os.path.getsize(file) > 20000


def test_rose_design(tmp_path):
    pytest.importorskip("matplotlib")
    out = str(tmp_path / "rose.png")
    text = run_example("rose_design.py", "--out", out)
    assert "rose: solved" in text and "certified: True" in text and "modules:" in text
    assert png(out)


def test_obstacle_sweep(tmp_path):
    pytest.importorskip("matplotlib")
    out = str(tmp_path / "sweep.png")
    text = run_example("obstacle_sweep.py", "--out", out)
    lines = text.splitlines()
    statuses = [line.split(": ")[-1] for line in lines if line.startswith("obstacle at y")]
    assert statuses[0] == "solved" and "infeasible" in statuses
    assert "stops being feasible at y =" in text
    core = next(line for line in lines if line.startswith("core: "))
    assert "obstacles[0]" in core and "trajectory[0]" in core
    assert png(out)


def test_dask_batch():
    pytest.importorskip("distributed")
    text = run_example("dask_batch.py", "--workers", "2", "--count", "2")
    assert text.strip().endswith("0 answered against their planted answer")
    assert text.count("(planted solved)") >= 2 and text.count("(planted infeasible)") >= 2
