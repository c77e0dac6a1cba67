"""Runs pytest on the test files given (the CTest entries of
tests/CMakeLists.txt), after checking that the Python modules they need are
installed: a missing one skips the test (exit 77) with the Debian package
that brings it, instead of failing it. --needs=MODULE adds one."""

import importlib.util
import sys


def main() -> int:
    args = sys.argv[1:]
    needs = ["pytest", "numpy"]
    while args and args[0].startswith("--needs="):
        needs.append(args.pop(0)[len("--needs="):])
    for module in needs:
        if importlib.util.find_spec(module) is None:
            print(f"skipped: the Python module {module} is not installed for {sys.executable} "
                  f"(Debian: python3-{module}; scripts/install-deps --for-tests installs it)")
            return 77
    import pytest

    # tornado (under Dask) warns of its own deprecated call; nothing of ours.
    quiet = ["-W", "ignore:make_current is deprecated:DeprecationWarning"]
    return pytest.main(["-p", "no:cacheprovider", "-q", "-rs", *quiet, *args])


# Guarded: the worker processes a Dask LocalCluster spawns import this
# module again, and must not run the tests.
if __name__ == "__main__":
    sys.exit(main())
