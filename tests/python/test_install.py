"""The set-up docs/python.md gives works on Debian 12: pip installs the
module from the checkout into a venv that sees the system's packages, and
into the user's site (with --break-system-packages, as Debian's pip asks);
the installed module imports from anywhere, reads its own catalog and
solves the rose as the command line does."""

import os
import shutil
import subprocess
import sys

import pytest

from conftest import BUILD, ROOT, path, run_cli

SYSTEM_PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

CHECK = (
    "import modsynth, os; s = modsynth.solve({rose!r}); print(s.status, list(s.robot.link_lengths)); "
    "print(modsynth.__file__); print(modsynth.CATALOG_FOLDER); s.save({out!r})"
)


def pip_install(python, *args, env):
    done = subprocess.run(
        [python, "-m", "pip", "install", "--no-build-isolation", "--no-index", *args, ROOT],
        capture_output=True,
        text=True,
        env=env,
        timeout=1800,
    )
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]


def clean_env(tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}
    env["MODSYNTH_BUILD_DIR"] = BUILD
    env["HOME"] = str(tmp_path / "home")
    return env


def check_installed(python, site, tmp_path, env):
    out = str(tmp_path / "rose.python.json")
    done = subprocess.run(
        [python, "-c", CHECK.format(rose=path("tasks", "rose.json"), out=out)],
        capture_output=True,
        text=True,
        env=env,
        cwd=str(tmp_path),
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
    status, module, catalog = done.stdout.splitlines()[:3]
    assert status.startswith("solved [")
    assert module.startswith(site), f"{module} is not the installed module"
    assert catalog == os.path.join(os.path.dirname(module), "data", "catalog") and os.path.isdir(catalog)
    cli = str(tmp_path / "rose.cli.json")
    assert run_cli("solve", path("tasks", "rose.json"), "-o", cli, "--quiet").returncode == 0
    with open(cli, "rb") as a, open(out, "rb") as b:
        assert a.read() == b.read()


def test_pip_installs_into_a_venv_with_the_system_packages(tmp_path):
    venv = str(tmp_path / "venv")
    env = clean_env(tmp_path)
    made = subprocess.run([SYSTEM_PYTHON, "-m", "venv", "--system-site-packages", venv], capture_output=True, text=True)
    if made.returncode != 0:
        pytest.skip(f"no venv (Debian: python3-venv): {made.stderr.strip()[-200:]}")
    python = os.path.join(venv, "bin", "python")
    pip_install(python, env=env)
    check_installed(python, venv, tmp_path, env)
    done = subprocess.run([python, "-m", "pip", "uninstall", "-y", "modsynth"], capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr


def test_pip_installs_into_the_user_site(tmp_path):
    env = clean_env(tmp_path)
    env["PYTHONUSERBASE"] = str(tmp_path / "userbase")
    pip_install(SYSTEM_PYTHON, "--user", "--break-system-packages", env=env)
    check_installed(SYSTEM_PYTHON, str(tmp_path / "userbase"), tmp_path, env)
    shutil.rmtree(tmp_path / "userbase")
