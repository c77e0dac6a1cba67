"""Tasks: modsynth-task/1 documents (docs/formats.md), planar or spatial,
from dicts, JSON text, files, or built in code."""

from __future__ import annotations

import copy
import json
import math
import os
import warnings
from typing import Any, Dict, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core
from ._errors import TaskError, TaskWarning

TASK_FORMAT = "modsynth-task/1"

Point = Sequence[float]
PathLike = Union[str, "os.PathLike[str]"]


def _plain(value: Any, part: str) -> Any:
    """The value as JSON types, NumPy arrays and numbers included; a value
    JSON cannot hold is a TaskError naming where it is."""
    if isinstance(value, Mapping):
        out = {}
        for key, item in value.items():
            if not isinstance(key, str):
                raise TaskError(f"key {key!r} is not a string", part or "task")
            out[key] = _plain(item, f"{part}.{key}" if part else key)
        return out
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return [_plain(item, f"{part}[{i}]") for i, item in enumerate(value)]
    if isinstance(value, np.generic):
        value = value.item()
    if value is None or isinstance(value, (bool, str, int)):
        return value
    if isinstance(value, float):
        if not math.isfinite(value):
            raise TaskError(f"{value} is not a finite number", part or "task")
        return value
    raise TaskError(f"a {type(value).__name__} cannot be written in a task document", part or "task")


def _dumps(doc: Mapping[str, Any]) -> str:
    return json.dumps(_plain(doc, ""))


class Task:
    """A validated task, planar or spatial: its modsynth-task/1 document and
    the parsed task the pipeline works on.

    Build one from a dict (``Task.from_dict``), JSON text (``from_json``),
    a file (``load``), or in code::

        task = modsynth.Task(
            [modsynth.line([0.4, 0.1], [0.55, 0.1]),
             modsynth.arc([0.55, 0.1], [0.55, 0.2], center=[0.55, 0.15])],
            obstacles=[modsynth.obstacle([0.3, 0.4], 0.05)],
            base_regions=[modsynth.region([-0.1, -0.1], [0.1, 0.1])],
            robot={"dof": [2, 3]}, name="rose")

    Every key of the format may be given (``**keys`` for the others, e.g.
    ``tool_axis``); anything invalid raises ``TaskError`` naming the part, as
    the command line does. ``to_dict()`` gives the document back as given.
    """

    __slots__ = ("_doc", "_core")

    def __init__(
        self,
        trajectory: Optional[Sequence[Mapping[str, Any]]] = None,
        *,
        strokes: Optional[Sequence[Sequence[Mapping[str, Any]]]] = None,
        obstacles: Optional[Sequence[Mapping[str, Any]]] = None,
        base_regions: Optional[Sequence[Mapping[str, Any]]] = None,
        robot: Optional[Mapping[str, Any]] = None,
        name: str = "",
        space: Optional[str] = None,
        **keys: Any,
    ) -> None:
        doc: dict = {"format": TASK_FORMAT}
        if name:
            doc["name"] = name
        if space is not None:
            doc["space"] = space
        if trajectory is not None:
            doc["trajectory"] = list(trajectory)
        if strokes is not None:
            doc["strokes"] = [list(s) for s in strokes]
        if obstacles is not None:
            doc["obstacles"] = list(obstacles)
        if base_regions is not None:
            doc["base_regions"] = list(base_regions)
        if robot is not None:
            doc["robot"] = dict(robot)
        doc.update(keys)
        self._set(_plain(doc, ""))

    def _set(self, doc: dict, warn: bool = True) -> None:
        self._doc = doc
        text = json.dumps(doc)
        self._core = _core.parse_task(text)
        if warn:
            _warn(text)

    @classmethod
    def from_dict(cls, doc: Mapping[str, Any]) -> "Task":
        """A task from its document as a dict (what ``json.load`` gives)."""
        if not isinstance(doc, Mapping):
            raise TaskError(f"expected a task document (a dict), got a {type(doc).__name__}", "task")
        task = cls.__new__(cls)
        task._set(_plain(doc, ""))
        return task

    @classmethod
    def from_json(cls, text: str) -> "Task":
        """A task from its document as JSON text."""
        core = _core.parse_task(text)  # syntax errors name the line and column
        _warn(text)
        task = cls.__new__(cls)
        task._doc = json.loads(text)
        task._core = core
        return task

    @classmethod
    def load(cls, path: PathLike) -> "Task":
        """A task file. A task without a name takes the file's name without
        its extension, as ``modsynth solve`` names it."""
        path = os.fspath(path)
        core = _core.load_task(path)
        task = cls.__new__(cls)
        with open(path, "rb") as f:
            raw = f.read()
        _warn(raw.decode("utf-8", errors="replace"), path)
        task._doc = json.loads(raw)
        task._core = core
        return task

    @classmethod
    def _unpickled(cls, doc: dict) -> "Task":
        # Warned of when it was made: not again on every worker.
        task = cls.__new__(cls)
        task._set(doc, warn=False)
        return task

    @classmethod
    def _from_core(cls, core: "_core.TaskDocument") -> "Task":
        task = cls.__new__(cls)
        task._doc = json.loads(core.to_json())
        task._core = core
        return task

    @property
    def name(self) -> str:
        """The task's name (a file's stem when the document has none)."""
        return self._core.name

    @property
    def spatial(self) -> bool:
        """Whether the task lives in space (``"space": "3d"``)."""
        return self._core.spatial

    def to_dict(self) -> dict:
        """The task's document, a copy of what it was made from."""
        return copy.deepcopy(self._doc)

    def to_json(self, indent: Optional[int] = 2) -> str:
        return json.dumps(self._doc, indent=indent) + "\n"

    def save(self, path: PathLike) -> None:
        """Writes the task's document as a JSON file."""
        with open(os.fspath(path), "w", encoding="utf-8") as f:
            f.write(self.to_json())

    def replace(self, **keys: Any) -> "Task":
        """A new task with these top-level keys replaced (``obstacles=[...]``,
        ``robot={...}``); a key given None is removed."""
        doc = self.to_dict()
        for key, value in keys.items():
            if value is None:
                doc.pop(key, None)
            else:
                doc[key] = value
        return Task.from_dict(doc)

    def strokes(self) -> list:
        """The path as a list of strokes, each a list of primitive dicts (a
        task with ``trajectory`` has one stroke)."""
        if "strokes" in self._doc:
            return copy.deepcopy(self._doc["strokes"])
        return [copy.deepcopy(self._doc["trajectory"])]

    def path_points(self, step: float = 0.002) -> list:
        """Points along each stroke, at most ``step`` metres apart, for
        plotting: one NumPy array (n x 2, or n x 3 in space) per stroke."""
        if not step > 0:
            raise ValueError("step must be a positive number of metres")
        dim = 3 if self.spatial else 2
        return [np.vstack([_primitive_points(p, step, dim) for p in s]) for s in self.strokes()]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Task) and self._doc == other._doc

    def __hash__(self) -> int:
        return hash(json.dumps(self._doc, sort_keys=True))

    def __reduce__(self):  # type: ignore[no-untyped-def]
        return (Task._unpickled, (self._doc,))

    def __repr__(self) -> str:
        kind = "spatial " if self.spatial else ""
        count = sum(len(s) for s in self.strokes())
        return f"<{kind}Task {self.name!r}: {count} primitives>"


TaskLike = Union[Task, Mapping[str, Any], str, "os.PathLike[str]"]


def _warn(text: str, file: str = "") -> None:
    """Warns, as the command line does, of keys the format does not define
    and of lengths that look like millimetres (TaskWarning)."""
    for message in _core.task_warnings(text, file):
        warnings.warn(message, TaskWarning, stacklevel=4)


def as_task(task: TaskLike) -> Task:
    """A Task from a Task, a document dict, or a task file's path."""
    if isinstance(task, Task):
        return task
    if isinstance(task, Mapping):
        return Task.from_dict(task)
    if isinstance(task, (str, os.PathLike)):
        return Task.load(task)
    raise TypeError(f"expected a Task, a task document (dict) or a file path, got {type(task).__name__}")


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def _rotate(v: np.ndarray, axis: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """v turned by each angle about the unit axis (Rodrigues), one row per angle."""
    c, s = np.cos(angle)[:, None], np.sin(angle)[:, None]
    return v * c + np.cross(axis, v) * s + np.outer(1 - c[:, 0], axis * np.dot(axis, v))


def _primitive_points(p: Mapping[str, Any], step: float, dim: int) -> np.ndarray:
    start = np.asarray(p["start"], dtype=float)
    kind = p["type"]
    if kind == "line":
        end = np.asarray(p["end"], dtype=float)
        n = max(2, int(math.ceil(np.linalg.norm(end - start) / step)) + 1)
        u = np.linspace(0.0, 1.0, n)[:, None]
        return start + u * (end - start)
    center = np.asarray(p["center"], dtype=float)
    sign = 1.0 if p.get("direction", "ccw") == "ccw" else -1.0
    r = start - center
    radius = float(np.linalg.norm(r))
    if kind == "helix":
        axis = _unit(np.asarray(p["axis"], dtype=float))
        turns, pitch = float(p["turns"]), float(p["pitch"])
        length = turns * math.hypot(2 * math.pi * radius, pitch)
        u = np.linspace(0.0, 1.0, max(2, int(math.ceil(length / step)) + 1))
        return center + np.outer(pitch * turns * u, axis) + _rotate(r, axis, sign * 2 * math.pi * turns * u)
    if kind == "circle":
        sweep = 2 * math.pi
    else:
        e = np.asarray(p["end"], dtype=float) - center
        if dim == 2:
            cross = float(r[0] * e[1] - r[1] * e[0])
        else:
            cross = float(np.dot(np.cross(r, e), _unit(np.asarray(p["normal"], dtype=float))))
        angle = math.atan2(cross, float(np.dot(r, e))) * sign
        sweep = angle % (2 * math.pi) or 2 * math.pi
    n = max(2, int(math.ceil(sweep * radius / step)) + 1)
    angles = sign * np.linspace(0.0, sweep, n)
    if dim == 2:
        c, s = np.cos(angles), np.sin(angles)
        return center + np.column_stack([r[0] * c - r[1] * s, r[0] * s + r[1] * c])
    normal = _unit(np.asarray(p["normal"], dtype=float))
    return center + _rotate(r, normal, angles)


def line(start: Point, end: Point, **keys: Any) -> dict:
    """A line from start to end."""
    return {"type": "line", "start": list(start), "end": list(end), **keys}


def arc(
    start: Point, end: Point, center: Point, direction: str = "ccw", *, normal: Optional[Point] = None, **keys: Any
) -> dict:
    """An arc from start to end about center ("ccw" or "cw"); in space about
    ``normal`` too. An arc whose start equals its end is a full circle."""
    p: Dict[str, Any] = {"type": "arc", "start": list(start), "end": list(end), "center": list(center)}
    if normal is not None:
        p["normal"] = list(normal)
    p["direction"] = direction
    return {**p, **keys}


def circle(
    start: Point,
    center: Point,
    direction: str = "ccw",
    *,
    normal: Optional[Point] = None,
    radius: Optional[float] = None,
    **keys: Any,
) -> dict:
    """A full turn from start back to start about center; in space about
    ``normal`` too."""
    p: Dict[str, Any] = {"type": "circle", "start": list(start), "center": list(center)}
    if normal is not None:
        p["normal"] = list(normal)
    p["direction"] = direction
    if radius is not None:
        p["radius"] = radius
    return {**p, **keys}


def helix(
    start: Point,
    center: Point,
    axis: Point,
    pitch: float,
    turns: float,
    direction: str = "ccw",
    *,
    end: Optional[Point] = None,
    **keys: Any,
) -> dict:
    """A helix (spatial tasks): ``turns`` turns about ``axis`` through
    ``center`` (level with start), advancing ``pitch`` metres per turn."""
    p: Dict[str, Any] = {
        "type": "helix",
        "start": list(start),
        "center": list(center),
        "axis": list(axis),
        "direction": direction,
        "pitch": pitch,
        "turns": turns,
    }
    if end is not None:
        p["end"] = list(end)
    return {**p, **keys}


def obstacle(center: Point, radius: float) -> dict:
    """A disc in the plane, or a sphere in space."""
    return {"center": list(center), "radius": radius}


def sphere(center: Point, radius: float) -> dict:
    """A sphere (spatial tasks)."""
    return {"type": "sphere", "center": list(center), "radius": radius}


def capsule(a: Point, b: Point, radius: float) -> dict:
    """Every point within radius of the segment ab (spatial tasks)."""
    return {"type": "capsule", "a": list(a), "b": list(b), "radius": radius}


def box(min: Point, max: Point) -> dict:  # noqa: A002 (the format's words)
    """An axis-aligned box obstacle (spatial tasks)."""
    return {"type": "box", "min": list(min), "max": list(max)}


def region(min: Point, max: Point) -> dict:  # noqa: A002
    """A base region: a rectangle in the plane, a box in space."""
    return {"min": list(min), "max": list(max)}
