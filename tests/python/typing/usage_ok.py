"""Calls as an editor should accept them (mypy checks this file against the
package's annotations and the compiled core's stubs)."""

from typing import List, Optional

import numpy as np

import modsynth


def link_total(path: str) -> float:
    task: modsynth.Task = modsynth.Task.load(path)
    events: List[modsynth.ProgressEvent] = []
    solution: modsynth.Solution = modsynth.solve(task, time_limit=10.0, seed=1, progress=events.append)
    robot = solution.robot
    if isinstance(robot, modsynth.Robot):
        lengths: np.ndarray = robot.link_lengths
        return float(lengths.sum())
    if isinstance(robot, modsynth.DhRobot):
        return robot.total_length
    return 0.0


def describe(solution: modsynth.Solution) -> str:
    c: modsynth.Certificate = solution.certificate
    modules: Optional[modsynth.Modules] = solution.modules
    names = modules.names if modules is not None else []
    q: np.ndarray = solution.samples.q
    return f"{solution.status} {c.ok} {c.min_clearance} {names} {q.shape}"


def explain_core(task: modsynth.Task) -> List[str]:
    e: modsynth.Explanation = modsynth.explain(task, time_limit=30.0, solve_seconds=5.0)
    return e.core + [s.change for s in e.suggestions]


def imported() -> modsynth.Task:
    d: modsynth.ImportedDrawing = modsynth.import_drawing("drawing.svg", width=0.2, at=(0.4, 0.1))
    return d.task


def batch(paths: List[str]) -> List[str]:
    return [r.status for r in modsynth.batch(paths, time_limit=5.0)]


def build() -> modsynth.Task:
    return modsynth.Task(
        [modsynth.line([0.4, 0.1], [0.55, 0.1]), modsynth.arc([0.55, 0.1], [0.55, 0.2], [0.55, 0.15], "ccw")],
        obstacles=[modsynth.obstacle([0.3, 0.4], 0.05)],
        base_regions=[modsynth.region([-0.1, -0.1], [0.1, 0.1])],
        robot={"dof": [2, 3]},
        name="built",
    )
