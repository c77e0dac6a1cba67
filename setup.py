"""Packages the Python module that CMake builds (python/CMakeLists.txt) in
the project's build folder, build/ as scripts/build makes it, or the one
MODSYNTH_BUILD_DIR names: configures it for the interpreter that runs pip
(a venv's base interpreter), builds the module's target (only what it needs
when the folder is new) and copies build/python/modsynth into the wheel."""

import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.abspath(os.environ.get("MODSYNTH_BUILD_DIR", os.path.join(ROOT, "build")))


class CMakeBuild(build_ext):
    def run(self):
        # A venv's interpreter builds against its base's headers, and keeps
        # the folder configured for the interpreter the test suite uses.
        python = getattr(sys, "_base_executable", sys.executable) or sys.executable
        os.makedirs(BUILD, exist_ok=True)
        subprocess.check_call(
            ["cmake", "-S", ROOT, "-B", BUILD, "-DCMAKE_BUILD_TYPE=Release",
             "-DMODSYNTH_BUILD_PYTHON=ON", f"-DPython3_EXECUTABLE={python}"],
            stdout=subprocess.DEVNULL)
        subprocess.check_call(
            ["cmake", "--build", BUILD, "--target", "modsynth_python", f"-j{os.cpu_count() or 1}"])
        package = os.path.join(BUILD, "python", "modsynth")
        if not os.path.isfile(os.path.join(package, "__init__.py")):
            sys.exit(f"{package}: the Python module was not built (are python3-dev and pybind11-dev installed?)")
        shutil.copytree(package, os.path.join(self.build_lib, "modsynth"), dirs_exist_ok=True)


# setuptools keeps its own files beside CMake's, out of the checkout.
os.makedirs(os.path.join(BUILD, "pip"), exist_ok=True)

setup(
    packages=["modsynth"],
    package_dir={"modsynth": "python/modsynth"},
    package_data={"modsynth": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("modsynth._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": os.path.join(BUILD, "pip")},
             "egg_info": {"egg_base": os.path.join(BUILD, "pip")}},
    zip_safe=False,
)
