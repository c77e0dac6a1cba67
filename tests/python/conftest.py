"""What the Python tests share: the checkout, the command line they compare
the module with, and the module itself (PYTHONPATH=build/python, as CTest
runs them)."""

import os
import subprocess
import sys

import pytest

ROOT = os.environ.get("MODSYNTH_ROOT") or os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("MODSYNTH_BUILD_DIR") or os.path.join(ROOT, "build")
CLI = os.environ.get("MODSYNTH_CLI") or os.path.join(BUILD, "modsynth")
SHARED = os.path.normpath(os.path.join(ROOT, "..", "shared"))

if os.path.join(BUILD, "python") not in sys.path and not os.environ.get("PYTHONPATH"):
    sys.path.insert(0, os.path.join(BUILD, "python"))


def path(*parts: str) -> str:
    return os.path.join(ROOT, *parts)


def run_cli(*args: str, timeout: float = 600) -> subprocess.CompletedProcess:
    if not os.access(CLI, os.X_OK):
        pytest.skip(f"{CLI} is not built")
    return subprocess.run([CLI, *args], capture_output=True, text=True, timeout=timeout)


def child_env() -> dict:
    """The environment for a child Python that imports the same module."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    env["MPLBACKEND"] = "Agg"
    return env
