"""Solutions (modsynth-solution/1 documents) and explanations, as the
pipeline answers them."""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from typing import Any, List, Mapping, Optional, Union

import numpy as np

from . import _core
from ._tasks import PathLike, Task


@dataclass(frozen=True)
class Samples:
    """The timed motion, one entry per sample: ``t`` (s), ``q`` (rad, one
    row per sample, one column per joint), ``qd`` and ``qdd`` (rad/s,
    rad/s^2; None when the motion is not timed for a controller), ``phase``
    ("trace", "transition", "travel"), ``primitive`` (index within its
    stroke) and ``stroke``."""

    t: np.ndarray
    q: np.ndarray
    qd: Optional[np.ndarray]
    qdd: Optional[np.ndarray]
    phase: List[str]
    primitive: np.ndarray
    stroke: np.ndarray

    def __len__(self) -> int:
        return len(self.t)


class Solution:
    """A certified robot and its timed motion, a proof that none exists, or
    "unknown" with the stage reached and why.

    ``status`` is "solved", "infeasible" or "unknown". A solved solution has
    ``robot`` (a planar ``Robot``, or a ``DhRobot`` for a spatial task),
    ``samples``, its ``certificate`` and the ``modules`` that carry it; the
    others have ``explanation`` (message and core). ``to_json()`` is the
    modsynth-solution/1 document, the bytes ``modsynth solve`` writes.
    """

    __slots__ = ("_core", "_text", "_samples", "had_certificate")

    def __init__(self, core: "_core.Solution", had_certificate: bool = True, text: Optional[str] = None) -> None:
        self._core = core
        #: The document it was read from, which to_json gives back as it was.
        self._text = text
        self._samples: Optional[Samples] = None
        #: Whether the document it was read from carried a certificate (one
        #: made by solve always does).
        self.had_certificate = had_certificate

    @classmethod
    def from_json(cls, text: str) -> "Solution":
        """A solution from its document (JSON text); TaskError naming the
        offending part when it is not valid. Its ``modules`` are None: a
        document holds only part of them, and the writers choose them again
        from the task (as ``modsynth export`` does); ``to_dict()["modules"]``
        has the document's."""
        core = _core.read_solution(text)
        return cls(core, "certificate" in json.loads(text), text)

    @classmethod
    def from_dict(cls, doc: Mapping[str, Any]) -> "Solution":
        from ._tasks import _dumps

        return cls.from_json(_dumps(doc))

    @classmethod
    def load(cls, path: PathLike) -> "Solution":
        with open(os.fspath(path), "rb") as f:
            return cls.from_json(f.read().decode("utf-8"))

    @property
    def status(self) -> str:
        return self._core.status

    @property
    def solved(self) -> bool:
        return self._core.status == "solved"

    @property
    def task_name(self) -> str:
        return self._core.task_name

    @property
    def status_stage(self) -> str:
        """Unknown only: the last stage reached ("3 joints: front stage")."""
        return self._core.status_stage

    @property
    def status_reason(self) -> str:
        """Unknown only: why the run stopped there ("time limit")."""
        return self._core.status_reason

    @property
    def robot(self) -> Union["_core.Robot", "_core.DhRobot"]:
        """The arm: a ``Robot`` (planar) or ``DhRobot`` (spatial). A solution
        that is not solved has none: ValueError with its explanation."""
        robot = self._core.robot if self._core.robot is not None else self._core.dh_robot
        if robot is None:
            raise ValueError(f"a solution that is {self.status} has no robot: {self.explanation.message}")
        return robot

    @property
    def samples(self) -> Samples:
        if self._samples is None:
            a = self._core.sample_arrays()
            self._samples = Samples(a["t"], a["q"], a["qd"], a["qdd"], a["phase"], a["primitive"], a["stroke"])
        return self._samples

    @property
    def certificate(self) -> "_core.Certificate":
        return self._core.certificate

    @property
    def modules(self) -> Optional["_core.Modules"]:
        """The actuator modules that carry the motion (solved only)."""
        return self._core.modules

    @property
    def explanation(self) -> "_core.SolutionExplanation":
        """Why it is infeasible or unknown: a message and the core (the task
        parts that conflict)."""
        return self._core.explanation

    def joint_positions(self) -> np.ndarray:
        """Where the joints are at every sample: an array of shape
        (samples, joints + 1, 2 or 3), the base first and the end effector
        last, for drawing the arm."""
        robot = self.robot
        q = self.samples.q
        if isinstance(robot, _core.Robot):
            angles = np.cumsum(q, axis=1)
            steps = np.stack([np.cos(angles), np.sin(angles)], axis=2) * robot.link_lengths[None, :, None]
            points = np.concatenate([np.zeros((len(q), 1, 2)), np.cumsum(steps, axis=1)], axis=1)
            return points + robot.base[None, None, :]
        return _dh_joint_positions(robot, q)

    def to_json(self) -> str:
        """The modsynth-solution/1 document (JSON text): as solve wrote it,
        or as it was read."""
        return self._text if self._text is not None else self._core.to_json()

    def to_dict(self) -> dict:
        return json.loads(self.to_json())

    def save(self, path: PathLike) -> None:
        """Writes the document: the same bytes as ``modsynth solve -o``."""
        with open(os.fspath(path), "wb") as f:
            f.write(self.to_json().encode("utf-8"))

    def __reduce__(self):  # type: ignore[no-untyped-def]
        # The document, and the modules in full (the document has only part
        # of them): the same solution in another process.
        return (_solution_from_state, (self.to_json(), self.had_certificate, self._core.modules, self._text is not None))

    def __repr__(self) -> str:
        if self.solved:
            return f"<Solution {self.task_name!r}: solved, {self.robot.dof} joints, {len(self.samples)} samples>"
        return f"<Solution {self.task_name!r}: {self.status}: {self.explanation.message}>"


def _solution_from_state(
    text: str, had_certificate: bool, modules: Optional["_core.Modules"], was_read: bool
) -> Solution:
    core = _core.read_solution(text)
    core.modules = modules
    return Solution(core, had_certificate, text if was_read else None)


def _dh_joint_positions(robot: "_core.DhRobot", q: np.ndarray) -> np.ndarray:
    n = len(q)
    frame = np.tile(np.eye(4), (n, 1, 1))
    frame[:, :3, 3] = robot.base
    points = [frame[:, :3, 3].copy()]
    for k, row in enumerate(robot.dh):
        c, s = np.cos(q[:, k]), np.sin(q[:, k])
        ca, sa = np.cos(row.alpha), np.sin(row.alpha)
        step = np.zeros((n, 4, 4))
        step[:, 0, 0], step[:, 0, 1], step[:, 0, 2], step[:, 0, 3] = c, -s * ca, s * sa, row.a * c
        step[:, 1, 0], step[:, 1, 1], step[:, 1, 2], step[:, 1, 3] = s, c * ca, -c * sa, row.a * s
        step[:, 2, 1], step[:, 2, 2], step[:, 2, 3] = sa, ca, row.d
        step[:, 3, 3] = 1.0
        frame = frame @ step
        points.append(frame[:, :3, 3].copy())
    return np.stack(points, axis=1)


class Suggestion:
    """A change of one part of the task that removes the conflict, checked
    with the full pipeline: ``part``, ``change`` in words, the relaxed
    ``task``, and what the pipeline then found (``status``, ``outcome``)."""

    __slots__ = ("part", "change", "status", "outcome", "task")

    def __init__(self, core: "_core.Suggestion") -> None:
        self.part: str = core.part
        self.change: str = core.change
        self.status: str = core.status
        self.outcome: str = core.outcome
        self.task: Task = Task._from_core(core.task)

    def __repr__(self) -> str:
        return f"<Suggestion {self.change}: {self.outcome}>"


class Explanation:
    """Why a task cannot be done: proved infeasible (``proved``, with the
    ``core`` of conflicting parts and the smallest ``suggestions`` that
    remove the conflict), or what a full run found (``status``)."""

    __slots__ = ("_core", "task_name", "suggestions")

    def __init__(self, core: "_core.Explanation", task_name: str) -> None:
        self._core = core
        self.task_name = task_name
        self.suggestions: List[Suggestion] = [Suggestion(s) for s in core.suggestions]

    @property
    def proved(self) -> bool:
        return self._core.proved

    @property
    def status(self) -> str:
        return self._core.status

    @property
    def message(self) -> str:
        return self._core.message

    @property
    def core(self) -> List[str]:
        return self._core.core

    def to_json(self) -> str:
        """As ``modsynth explain --json`` prints it."""
        return self._core.to_json(self.task_name)

    def to_dict(self) -> dict:
        return json.loads(self.to_json())

    def __repr__(self) -> str:
        return f"<Explanation {self.task_name!r}: {self.status}: {self.message}>"
