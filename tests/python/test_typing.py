"""The annotations and the compiled core's stubs (_core.pyi) let a type
checker complete and check calls: mypy accepts correct use, the package
itself, and the examples, and flags each wrong call."""

import os
import re
import subprocess
import sys

import pytest

from conftest import BUILD, path

pytest.importorskip("mypy")


def mypy(*files):
    env = dict(os.environ, MYPYPATH=os.path.join(BUILD, "python"))
    return subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir=/dev/null", "--ignore-missing-imports",
         "--no-error-summary", "--show-error-codes", *files],
        capture_output=True,
        text=True,
        env=env,
        cwd=path(),
        timeout=600,
    )


def test_correct_use_the_package_and_the_examples_check():
    files = [path("tests", "python", "typing", "usage_ok.py"), os.path.join(BUILD, "python", "modsynth")]
    files += [path("examples", "python", f) for f in sorted(os.listdir(path("examples", "python"))) if f.endswith(".py")]
    done = mypy(*files)
    assert done.returncode == 0, done.stdout + done.stderr


def test_each_wrong_call_is_flagged():
    file = path("tests", "python", "typing", "usage_errors.py")
    with open(file) as f:
        wrong = {i for i, line in enumerate(f, 1) if line.rstrip().endswith("# wrong")}
    done = mypy(file)
    flagged = {int(m.group(1)) for m in re.finditer(r"usage_errors\.py:(\d+): error", done.stdout)}
    assert flagged == wrong, done.stdout
