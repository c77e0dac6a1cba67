"""The calls: solve, explain, certify, the writers and drawing import."""

from __future__ import annotations

import math
import numbers
import os
import re
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional, Sequence, Union

from . import _core
from ._errors import ExportError, ImportTimeout, TaskError
from ._solution import Explanation, Solution
from ._tasks import PathLike, Task, TaskLike, as_task

#: The longest time limit taken, as on the command line: a week.
MAX_SECONDS = 7 * 24 * 3600.0

ProgressCallback = Callable[["_core.ProgressEvent"], Any]


def _seconds(value: float, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a number of seconds, not {type(value).__name__}")
    value = float(value)
    if not (math.isfinite(value) and 0 < value <= MAX_SECONDS):
        raise ValueError(f"{name} must be a positive number of seconds, at most a week, got {value}")
    return value


def _progress(progress: Optional[ProgressCallback]) -> Optional[ProgressCallback]:
    if progress is not None and not callable(progress):
        raise TypeError("progress must be a callable taking a ProgressEvent, or None")
    return progress


def solve(
    task: TaskLike,
    *,
    time_limit: float = 60.0,
    seed: int = 0,
    progress: Optional[ProgressCallback] = None,
) -> Solution:
    """Designs a robot and its control for the task: the same answer as
    ``modsynth solve`` (byte for byte in ``Solution.to_json()``).

    ``task`` is a ``Task``, a task document (dict) or a task file's path.
    ``time_limit`` bounds the whole synthesis (seconds); ``seed`` varies
    the initial guesses (same seed, same answer). ``progress`` is called
    with each ``ProgressEvent`` on the calling thread while the solve runs
    (the GIL is released meanwhile). Ctrl-C (KeyboardInterrupt) cancels the
    solve and is raised once it has stopped. Raises TaskError for an
    invalid task, naming the part.
    """
    t = as_task(task)
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or not 0 <= int(seed) < 2**32:
        raise ValueError(f"seed must be an integer from 0 to 2**32 - 1, got {seed!r}")
    core = _core.solve(t._core, _seconds(time_limit, "time_limit"), int(seed), _progress(progress))
    return Solution(core)


def explain(
    task: TaskLike,
    *,
    time_limit: float = 60.0,
    solve_seconds: float = 10.0,
    proof_seconds: float = 10.0,
    progress: Optional[ProgressCallback] = None,
) -> Explanation:
    """Why a task cannot be done: a proof of infeasibility with the
    conflicting parts (``core``) and the smallest changes that remove the
    conflict, each re-checked with ``solve_seconds`` of synthesis; or, when
    there is no proof, what a full run finds. The same flow as ``modsynth
    explain``, within ``time_limit`` seconds in all."""
    t = as_task(task)
    core = _core.explain(
        t._core,
        _seconds(time_limit, "time_limit"),
        _seconds(solve_seconds, "solve_seconds"),
        _seconds(proof_seconds, "proof_seconds"),
        _progress(progress),
    )
    return Explanation(core, t.name)


def certify(task: TaskLike, solution: Union[Solution, PathLike]) -> "_core.Certificate":
    """Checks the solution's motion against the task over the whole
    continuum, independently of how it was made, as ``modsynth certify``.
    ``solution`` is a Solution or a solution file's path. A solution that is
    not solved gets a certificate that is not ok."""
    t = as_task(task)
    s = solution if isinstance(solution, Solution) else Solution.load(solution)
    return _core.certify(t._core, s._core)


def _path(value: Optional[PathLike]) -> str:
    return "" if value is None else os.fspath(value)


def write_exports(
    task: TaskLike,
    solution: Union[Solution, PathLike],
    *,
    report: Optional[PathLike] = None,
    urdf: Optional[PathLike] = None,
    csv: Optional[PathLike] = None,
    joint_trajectory: Optional[PathLike] = None,
    build_sheet: Optional[PathLike] = None,
    write_uncertified: bool = False,
) -> List[str]:
    """Writes the files given, as ``modsynth export TASK SOLUTION`` does:
    the solution is verified again and its modules chosen first. ``report``
    is HTML, ``urdf`` the arm's model, ``csv`` the samples, ``joint_trajectory``
    a ROS 2 trajectory_msgs/JointTrajectory (YAML), ``build_sheet`` Markdown.
    Returns one line per file not written and why (an unsolved solution has
    no robot; the CSV and joint trajectory of a motion that is not certified
    are written only with ``write_uncertified``)."""
    t = as_task(task)
    s = solution if isinstance(solution, Solution) else Solution.load(solution)
    return list(
        _core.write_exports(
            t._core,
            s._core,
            _path(report),
            _path(urdf),
            _path(csv),
            _path(joint_trajectory),
            _path(build_sheet),
            bool(write_uncertified),
            s.had_certificate,
        )
    )


def _write_one(kind: str, task: TaskLike, solution: Union[Solution, PathLike], path: PathLike, **options: Any) -> None:
    if path is None or _path(path) == "":
        raise ValueError("path must name the file to write")
    files: Dict[str, Any] = {kind: path, **options}
    skipped = write_exports(task, solution, **files)
    if skipped:
        raise ExportError(skipped[0])


def write_report(task: TaskLike, solution: Union[Solution, PathLike], path: PathLike) -> None:
    """The visual report (self-contained HTML; a 3-D view for a spatial
    task). Any solution has one."""
    _write_one("report", task, solution, path)


def write_urdf(task: TaskLike, solution: Union[Solution, PathLike], path: PathLike) -> None:
    """The arm as a URDF model, with its modules. ExportError unless solved."""
    _write_one("urdf", task, solution, path)


def write_csv(
    task: TaskLike, solution: Union[Solution, PathLike], path: PathLike, *, write_uncertified: bool = False
) -> None:
    """The samples as CSV (t, q1..qn, phase, primitive, qd1..qdn,
    qdd1..qddn). ExportError unless solved and certified again (or
    ``write_uncertified``)."""
    _write_one("csv", task, solution, path, write_uncertified=write_uncertified)


def write_joint_trajectory(
    task: TaskLike, solution: Union[Solution, PathLike], path: PathLike, *, write_uncertified: bool = False
) -> None:
    """The motion as a ROS 2 trajectory_msgs/JointTrajectory (YAML).
    ExportError unless solved and certified again (or ``write_uncertified``)."""
    _write_one("joint_trajectory", task, solution, path, write_uncertified=write_uncertified)


def write_build_sheet(task: TaskLike, solution: Union[Solution, PathLike], path: PathLike) -> None:
    """The build sheet (Markdown): parts, tube cut lengths, base, start pose."""
    _write_one("build_sheet", task, solution, path)


@dataclass
class ImportedDrawing:
    """A task made from a drawing: the ``task``, its document as ``modsynth
    import`` writes it (``task_json``, the same bytes), and what the import
    found: primitives per stroke, obstacles, the worst deviation from the
    drawing (m), the pen-up travel (m), the surface in space ("" in the
    plane, "plane" or "cylinder"), what the reader skipped (``warnings``),
    filled shapes whose outlines were traced and the DXF layers with their
    entity counts."""

    task: Task
    task_json: str
    primitives_per_stroke: List[int]
    obstacles: int
    deviation: float
    travel: float
    surface: str
    warnings: List[str] = field(default_factory=list)
    filled_outlines: int = 0
    layers: Dict[str, int] = field(default_factory=dict)

    def save(self, path: PathLike) -> None:
        """Writes the task file ``modsynth import -o`` writes."""
        with open(os.fspath(path), "wb") as f:
            f.write(self.task_json.encode("utf-8"))


# How the library names the options (as the command line spells them), and
# how import_drawing's keywords do.
_OPTION_NAMES = {
    "--base": "base_regions",
    "--dof": "dof",
    "--tool-length": "tool_length",
    "--text": "text",
    "--font": "font",
    "--height": "text_height",
    "--plane": "plane",
    "--cylinder": "cylinder",
    "--width": "width",
    "--scale": "scale",
    "--at": "at",
    "--rotate": "rotate",
    "--tolerance": "tolerance",
    "--time-limit": "time_limit",
    "--layers": "layers",
    "--strict": "strict",
    "--hatch-boundaries": "hatch_boundaries",
    "--obstacles-from": "obstacle_layer",
    "--keep-order": "keep_order",
    "--link-diameter": "link_diameter",
    "--tool": "tool",
    "--tool-tolerance": "tool_tolerance",
}
_OPTION_PATTERN = re.compile("|".join(re.escape(o) for o in sorted(_OPTION_NAMES, key=len, reverse=True)))


def _keyword_names(text: str) -> str:
    return _OPTION_PATTERN.sub(lambda m: _OPTION_NAMES[m.group(0)], text)


def _numbers(value: Any, name: str, counts: Sequence[int]) -> List[float]:
    """A flat list of finite numbers from nested sequences (a point per
    row, or all in one)."""
    flat: List[float] = []

    def add(v: Any) -> None:
        if isinstance(v, (list, tuple)) or hasattr(v, "tolist"):
            for item in v.tolist() if hasattr(v, "tolist") else v:
                add(item)
        elif isinstance(v, numbers.Real) and not isinstance(v, bool) and math.isfinite(float(v)):
            flat.append(float(v))
        else:
            raise TaskError(f"expected finite numbers, got {v!r}", name)

    add(value)
    if len(flat) not in counts:
        raise TaskError(f"expected {' or '.join(map(str, counts))} numbers, got {len(flat)}", name)
    return flat


def _optional_number(value: Optional[float], name: str) -> Optional[float]:
    if value is None:
        return None
    return _numbers(value, name, (1,))[0]


def import_drawing(
    source: Optional[PathLike] = None,
    *,
    text: Optional[str] = None,
    contents: Union[str, bytes, None] = None,
    format: Optional[str] = None,  # noqa: A002 (the drawing's format)
    font: str = "futural",
    text_height: float = 0.03,
    name: Optional[str] = None,
    width: Optional[float] = None,
    scale: Optional[float] = None,
    at: Optional[Sequence[float]] = None,
    rotate: float = 0.0,
    tolerance: float = 1e-4,
    time_limit: float = 60.0,
    base_regions: Sequence[Sequence[float]] = (),
    obstacle_layer: Optional[str] = None,
    layers: Sequence[str] = (),
    strict: bool = False,
    hatch_boundaries: bool = False,
    keep_order: bool = False,
    dof: Sequence[int] = (),
    link_diameter: Optional[float] = None,
    plane: Optional[Sequence[Any]] = None,
    cylinder: Optional[Sequence[Any]] = None,
    tool_length: Optional[float] = None,
    tool: Optional[str] = None,
    tool_tolerance: float = 5.0,
) -> ImportedDrawing:
    """A task from a drawing, as ``modsynth import`` makes it: its curves
    fitted with lines and arcs within ``tolerance`` metres.

    Give one of ``source`` (an .svg or .dxf file), ``contents`` (a drawing's
    text with its ``format``, "svg" or "dxf") or ``text`` (written in the
    Hershey font ``font``, capitals ``text_height`` metres tall).

    Placement in the plane: ``width`` (m) or ``scale`` (m per drawing unit;
    default the file's units), ``at`` (x, y) for the drawing's centre,
    ``rotate`` (degrees, counter-clockwise). In space: ``plane`` (origin, u,
    v: nine numbers, or three points) or ``cylinder`` (centre, axis, radius:
    seven numbers). ``base_regions``: rectangles (xmin, ymin, xmax, ymax),
    boxes (xmin, ymin, zmin, xmax, ymax, zmax) in space. ``obstacle_layer``
    names the layer whose circles are obstacles; ``layers`` the DXF layers
    to import; ``strict`` refuses what cannot be traced instead of skipping
    it; ``hatch_boundaries`` traces DXF hatches' boundaries; ``keep_order``
    keeps the file's stroke order. ``dof``, ``link_diameter`` and (in
    space) ``tool_length`` go into the task's robot. In space, ``tool``
    "square" holds the tool square into the surface while it traces,
    "toward" (round a cylinder) at its axis, within ``tool_tolerance``
    degrees (the task's ``tool_axis``).

    Raises TaskError naming the keyword or the drawing's part, and
    ImportTimeout past ``time_limit`` seconds.
    """
    request = _core.DrawingImport()
    if source is not None:
        request.path = os.fspath(source)
    if contents is not None:
        if isinstance(contents, bytes):
            contents = contents.decode("utf-8", errors="surrogateescape")
        request.contents = contents
        if format is None:
            raise TaskError('give the format ("svg" or "dxf") of a drawing\'s contents', "format")
    if format is not None:
        request.format = str(format).lower()
    if text is not None:
        request.text = text
    request.font = font
    request.text_height = _numbers(text_height, "text_height", (1,))[0]
    if name is not None:
        request.name = name
    request.width = _optional_number(width, "width")
    request.scale = _optional_number(scale, "scale")
    if at is not None:
        x, y = _numbers(at, "at", (2,))
        request.at = (x, y)
    request.rotate_degrees = _numbers(rotate, "rotate", (1,))[0]
    request.tolerance = _numbers(tolerance, "tolerance", (1,))[0]
    request.time_limit = _seconds(time_limit, "time_limit")
    spatial = plane is not None or cylinder is not None
    request.base_regions = [
        _numbers(b, f"base_regions[{i}]", (6,) if spatial else (4,)) for i, b in enumerate(base_regions)
    ]
    if obstacle_layer is not None:
        request.obstacle_layer = obstacle_layer
    request.layers = [str(x) for x in layers]
    request.strict = bool(strict)
    request.hatch_boundaries = bool(hatch_boundaries)
    request.keep_order = bool(keep_order)
    request.dof = [int(n) for n in dof]
    request.link_diameter = _optional_number(link_diameter, "link_diameter")
    if plane is not None:
        request.plane = _numbers(plane, "plane", (9,))
    if cylinder is not None:
        request.cylinder = _numbers(cylinder, "cylinder", (7,))
    request.tool_length = _optional_number(tool_length, "tool_length")
    if tool is not None:
        request.tool = str(tool)
    request.tool_tolerance_degrees = _numbers(tool_tolerance, "tool_tolerance", (1,))[0]
    try:
        r = _core.import_drawing(request)
    except TaskError as e:
        raise TaskError(_keyword_names(e.problem), _keyword_names(e.part), e.file) from None
    except ImportTimeout as e:
        raise ImportTimeout(_keyword_names(str(e))) from None
    return ImportedDrawing(
        task=Task.from_json(r.task_json),
        task_json=r.task_json,
        primitives_per_stroke=list(r.primitives_per_stroke),
        obstacles=r.obstacles,
        deviation=r.deviation,
        travel=r.travel,
        surface=r.surface,
        warnings=list(r.warnings),
        filled_outlines=r.filled_outlines,
        layers=dict(r.layers),
    )
