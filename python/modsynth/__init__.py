"""modsynth designs a robot for a job: a modular arm that traces a task's
path exactly, clear of its obstacles, with a timed motion certified over
the whole continuum; or a proof that none exists, with the task parts that
conflict.

    import modsynth
    s = modsynth.solve("tasks/rose.json")
    print(s.status, s.robot.link_lengths)

Tasks: ``Task`` (from dicts, JSON files, or built in code with ``line``,
``arc``, ``circle``, ``helix``, ``obstacle``, ``region``, ...). Calls:
``solve``, ``explain``, ``certify``, ``import_drawing``, the writers
(``write_urdf``, ``write_csv``, ``write_joint_trajectory``, ``write_report``,
``write_build_sheet``, ``write_exports``) and ``batch`` (solves on a Dask
cluster). docs/python.md describes them all.
"""

from __future__ import annotations

import atexit as _atexit
import os as _os

from . import _core
from ._batch import BatchResult, batch
from ._calls import (
    ImportedDrawing,
    certify,
    explain,
    import_drawing,
    solve,
    write_build_sheet,
    write_csv,
    write_exports,
    write_joint_trajectory,
    write_report,
    write_urdf,
)
from ._core import (
    Certificate,
    DhRobot,
    DhRow,
    JointLoad,
    JointModule,
    Modules,
    ProgressEvent,
    Robot,
    SolutionExplanation,
    Violation,
)
from ._errors import ExportError, ImportTimeout, TaskError, TaskWarning
from ._solution import Explanation, Samples, Solution, Suggestion
from ._tasks import Task, arc, box, capsule, circle, helix, line, obstacle, region, sphere

__all__ = [
    "BatchResult",
    "Certificate",
    "DhRobot",
    "DhRow",
    "Explanation",
    "ExportError",
    "ImportTimeout",
    "ImportedDrawing",
    "JointLoad",
    "JointModule",
    "Modules",
    "ProgressEvent",
    "Robot",
    "Samples",
    "Solution",
    "SolutionExplanation",
    "Suggestion",
    "Task",
    "TaskError",
    "TaskWarning",
    "Violation",
    "arc",
    "batch",
    "box",
    "capsule",
    "certify",
    "circle",
    "explain",
    "helix",
    "import_drawing",
    "line",
    "load_solution",
    "obstacle",
    "region",
    "solve",
    "sphere",
    "write_build_sheet",
    "write_csv",
    "write_exports",
    "write_joint_trajectory",
    "write_report",
    "write_urdf",
]

__version__ = "0.1.0"

#: The module catalog the package reads, installed beside it.
CATALOG_FOLDER = _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "data", "catalog")
_core.set_catalog_folder(CATALOG_FOLDER)
# A solve still running at exit is cancelled and awaited, so that the
# interpreter does not end under it.
_atexit.register(_core.shut_down)


def load_solution(path: "_os.PathLike[str] | str") -> Solution:
    """A solution file (modsynth-solution/1), validated."""
    return Solution.load(path)
