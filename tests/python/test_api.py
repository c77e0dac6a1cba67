"""The Python module's basics, without a synthesis: tasks from files, dicts
and code, their validation, solutions read back, certification, the
writers and drawing import, each checked against the command line."""

import glob
import json
import os
import pickle
import warnings

import numpy as np
import pytest

import modsynth
from conftest import ROOT, path, run_cli

TASK_FILES = sorted(
    glob.glob(path("tasks", "*.json"))
    + glob.glob(path("tasks", "spatial", "*.json"))
    + glob.glob(path("tasks", "infeasible", "*.task.json"))
    + glob.glob(path("tests", "fixtures", "valid", "*.json"))
    + glob.glob(path("tests", "fixtures", "spatial", "*.task.json"))
)
INVALID_FILES = sorted(
    glob.glob(path("tests", "fixtures", "invalid", "*.json"))
    + glob.glob(path("tests", "fixtures", "invalid-spatial", "*.json"))
)
LINE_TASK = path("tests", "fixtures", "python", "line.task.json")
LINE_SOLUTION = path("tests", "fixtures", "python", "line-solved.json")
SPATIAL_TASK = path("tests", "fixtures", "spatial", "s3-0001.task.json")
SPATIAL_SOLUTION = path("tests", "fixtures", "spatial", "s3-0001.planted.json")


def test_the_package_finds_its_catalog_beside_it():
    here = os.path.dirname(modsynth.__file__)
    assert modsynth.CATALOG_FOLDER == os.path.join(here, "data", "catalog")
    assert modsynth._core.catalog_folder() == modsynth.CATALOG_FOLDER
    shipped = sorted(os.listdir(path("catalog")))
    assert sorted(os.listdir(modsynth.CATALOG_FOLDER)) == shipped


@pytest.mark.parametrize("file", TASK_FILES, ids=lambda f: os.path.relpath(f, ROOT))
def test_every_task_file_round_trips(file):
    with open(file) as f:
        doc = json.load(f)
    task = modsynth.Task.load(file)
    assert task.to_dict() == doc
    assert task.spatial == (doc.get("space") == "3d")
    # A task without a name takes the file's, as the command line names it.
    stem = os.path.basename(file)[: -len(".json")]
    assert task.name == doc.get("name", stem)
    again = modsynth.Task.from_dict(task.to_dict())
    assert again == task
    with open(file) as f:
        assert modsynth.Task.from_json(f.read()) == task
    # The library's own document of the parsed task reads back the same.
    canonical = json.loads(task._core.to_json())
    assert modsynth.Task.from_dict(canonical)._core.to_json() == task._core.to_json()
    assert pickle.loads(pickle.dumps(task)) == task


def test_a_task_built_in_code_equals_its_file():
    rose = modsynth.Task(
        [
            modsynth.line([0.50, 0.05], [0.50, 0.22]),
            modsynth.arc([0.50, 0.22], [0.60, 0.22], [0.55, 0.22], "cw"),
            modsynth.arc([0.60, 0.22], [0.50, 0.22], [0.55, 0.22], "cw"),
            modsynth.line([0.50, 0.22], [0.50, 0.32]),
            modsynth.circle([0.50, 0.32], [0.50, 0.37], "ccw", radius=0.05),
            modsynth.arc([0.50, 0.32], [0.50, 0.40], [0.50, 0.36], "ccw"),
            modsynth.arc([0.50, 0.40], [0.50, 0.34], [0.50, 0.37], "ccw"),
        ],
        obstacles=[
            modsynth.obstacle([0.36, 0.33], 0.04),
            modsynth.obstacle([0.66, 0.40], 0.04),
            modsynth.obstacle(np.array([0.64, 0.07]), np.float64(0.03)),
        ],
        base_regions=[modsynth.region([-0.05, -0.05], [0.10, 0.10])],
        robot={"dof": [2, 3], "link_diameter": 0.03175, "min_link_length": 0.05, "max_link_length": 1.0},
        name="rose",
        description=modsynth.Task.load(path("tasks", "rose.json")).to_dict()["description"],
    )
    assert rose == modsynth.Task.load(path("tasks", "rose.json"))

    helix = modsynth.Task.load(path("tasks", "spatial", "helix-pipe.json")).to_dict()
    built = modsynth.Task(
        [modsynth.helix(**{k: v for k, v in helix["trajectory"][0].items() if k != "type"})],
        obstacles=helix["obstacles"],
        base_regions=helix["base_regions"],
        robot=helix.get("robot"),
        name="helix-pipe",
        space="3d",
        **{k: v for k, v in helix.items() if k not in ("format", "name", "space", "trajectory", "obstacles", "base_regions", "robot")},
    )
    assert built.spatial
    assert built.to_dict() == helix


@pytest.mark.parametrize("file", INVALID_FILES, ids=lambda f: os.path.relpath(f, ROOT))
def test_invalid_tasks_raise_the_command_lines_error(file):
    cli = run_cli("validate", file)
    assert cli.returncode == 2, cli.stderr
    with pytest.raises(modsynth.TaskError) as raised:
        modsynth.Task.load(file)
    # `validate` prints "error: FILE: PART: problem"; the exception says
    # the same
    assert f"error: {raised.value}" in cli.stderr
    # and names the file and the part on their own.
    assert raised.value.part and raised.value.file == file
    assert str(raised.value) == f"{file}: {raised.value.part}: {raised.value.problem}" or (
        raised.value.part == "(document)" and str(raised.value) == f"{file}: {raised.value.problem}"
    )
    # The same document as a dict (where Python reads it as the library
    # does: valid UTF-8 and finite numbers) fails on the same part.
    with open(file, "rb") as f:
        data = f.read()
    try:
        doc = json.loads(data.decode("utf-8"), parse_constant=lambda c: 1 / 0)
    except (ValueError, ZeroDivisionError):
        return
    if isinstance(doc, dict) and "name" in doc:
        with pytest.raises(modsynth.TaskError) as from_dict:
            modsynth.Task.from_dict(doc)
        assert from_dict.value.part == raised.value.part


@pytest.mark.parametrize("name", ["base-region-typo", "millimetres"])
def test_mistakes_are_warned_of_as_the_command_line_does(name, recwarn):
    file = path("tests", "fixtures", "mistakes", f"{name}.json")
    cli = run_cli("validate", file)
    assert cli.returncode == 0, cli.stderr
    said = [line[len("warning: ") :] for line in cli.stderr.splitlines() if line.startswith("warning: ")]
    assert said
    task = modsynth.Task.load(file)
    warned = [str(w.message) for w in recwarn if w.category is modsynth.TaskWarning]
    assert warned == said
    # Without the file, from a dict or its text, the same words.
    recwarn.clear()
    with open(file) as f:
        doc = json.load(f)
    modsynth.Task.from_dict(doc)
    modsynth.Task.from_json(json.dumps(doc))
    unfiled = [m[len(file) + 2 :] for m in said]
    assert [str(w.message) for w in recwarn if w.category is modsynth.TaskWarning] == unfiled * 2
    # A pickled task is not warned of again where it is read back.
    recwarn.clear()
    assert pickle.loads(pickle.dumps(task)) == task
    assert not [w for w in recwarn if w.category is modsynth.TaskWarning]
    # As errors, when asked, as `--strict` makes them.
    with warnings.catch_warnings():
        warnings.simplefilter("error", modsynth.TaskWarning)
        with pytest.raises(modsynth.TaskWarning):
            modsynth.Task.load(file)


def test_bad_values_in_dicts_name_their_part():
    doc = modsynth.Task.load(path("tasks", "rose.json")).to_dict()
    doc["obstacles"][1]["radius"] = float("nan")
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.Task.from_dict(doc)
    assert e.value.part == "obstacles[1].radius"
    doc["obstacles"][1]["radius"] = object()
    with pytest.raises(modsynth.TaskError, match=r"obstacles\[1\].radius: a object cannot be written"):
        modsynth.Task.from_dict(doc)
    doc["obstacles"][1]["radius"] = -0.01
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.Task.from_dict(doc)
    assert e.value.part == "obstacles[1].radius"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.Task([modsynth.line([0, 0], [0.2, 0]), modsynth.line([0.3, 0], [0.4, 0])])
    assert e.value.part == "trajectory[1]" and "start" in e.value.problem
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.Task([modsynth.line([0, 0, 0], [0.2, 0, 0.1])], space="3d", robot={"dof": [2]})
    assert e.value.part.startswith("robot.dof")
    with pytest.raises(modsynth.TaskError):
        modsynth.Task.from_json("{ not json")
    with pytest.raises(modsynth.TaskError):
        modsynth.Task.from_dict([1, 2])
    with pytest.raises(TypeError):
        modsynth.solve(42)
    # As the command line says it: the file named, and why it cannot be read.
    with pytest.raises(modsynth.TaskError, match="no-such-task.json: cannot open"):
        modsynth.solve(path("tasks", "no-such-task.json"))
    # The errors travel between processes (a Dask batch) intact.
    again = pickle.loads(pickle.dumps(e.value))
    assert (again.part, again.problem) == (e.value.part, e.value.problem)


def test_bad_options_are_refused_before_any_work():
    task = modsynth.Task.load(LINE_TASK)
    for bad in (0, -1, float("nan"), float("inf"), 8 * 24 * 3600):
        with pytest.raises(ValueError, match="time_limit"):
            modsynth.solve(task, time_limit=bad)
    with pytest.raises(TypeError, match="time_limit"):
        modsynth.solve(task, time_limit="10")
    for bad in (-1, 2**32, 1.5, True):
        with pytest.raises(ValueError, match="seed"):
            modsynth.solve(task, seed=bad)
    with pytest.raises(TypeError, match="progress"):
        modsynth.solve(task, progress=3)
    with pytest.raises(ValueError, match="solve_seconds"):
        modsynth.explain(task, solve_seconds=0)


def test_path_points_follow_the_path():
    rose = modsynth.Task.load(path("tasks", "rose.json"))
    (points,) = rose.path_points(step=0.001)
    doc = rose.to_dict()
    assert np.allclose(points[0], doc["trajectory"][0]["start"])
    assert np.allclose(points[-1], doc["trajectory"][-1]["end"])
    assert np.max(np.linalg.norm(np.diff(points, axis=0), axis=1)) <= 0.001 + 1e-12
    # The bloom circle: its points are 5 cm from its centre.
    circle = doc["trajectory"][4]
    near = points[np.linalg.norm(points - circle["center"], axis=1) < 0.0501]
    assert len(near) > 300
    helix = modsynth.Task.load(path("tasks", "spatial", "helix-pipe.json"))
    (points,) = helix.path_points(step=0.002)
    assert points.shape[1] == 3
    assert np.allclose(np.linalg.norm(points[:, :2], axis=1), 0.12)
    assert points[-1, 2] == pytest.approx(0.1 + 2 * 0.05)


def test_a_solution_file_reads_as_the_command_line_wrote_it():
    solution = modsynth.load_solution(LINE_SOLUTION)
    with open(LINE_SOLUTION, "rb") as f:
        written = f.read()
    assert solution.to_json().encode() == written
    assert solution.status == "solved" and solution.solved
    assert solution.task_name == "line"
    doc = json.loads(written)
    robot = solution.robot
    assert isinstance(robot, modsynth.Robot)
    assert robot.dof == doc["robot"]["dof"]
    assert list(robot.link_lengths) == doc["robot"]["link_lengths"]
    assert list(robot.base) == doc["robot"]["base"]
    s = solution.samples
    assert len(s) == len(doc["samples"])
    assert s.q.shape == (len(doc["samples"]), robot.dof)
    assert s.t.dtype == np.float64 and s.primitive.dtype.kind == "i"
    for i in (0, len(s) // 2, len(s) - 1):
        sample = doc["samples"][i]
        assert s.t[i] == sample["t"]
        assert list(s.q[i]) == sample["q"]
        assert list(s.qd[i]) == sample["qd"] and list(s.qdd[i]) == sample["qdd"]
        assert s.phase[i] == sample["phase"] and s.primitive[i] == sample["primitive"]
    # A document holds part of the modules only: they are chosen again
    # where they are needed (the writers), as `modsynth export` does.
    assert solution.modules is None and [j["module"] for j in doc["modules"]["joints"]] == ["X5-1", "X5-1"]
    assert solution.certificate.ok and solution.certificate.reason == ""
    # Dict, pickle: the same document.
    assert modsynth.Solution.from_dict(solution.to_dict()).to_dict() == doc
    assert pickle.loads(pickle.dumps(solution)).to_json() == solution.to_json()
    # The arm's end follows the path: the line from (0.4, 0.1) to (0.55, 0.1).
    ee = solution.joint_positions()[:, -1, :]
    assert np.max(np.abs(ee[:, 1] - 0.1)) < 1e-3
    assert ee[0, 0] == pytest.approx(0.4, abs=1e-3) and ee[-1, 0] == pytest.approx(0.55, abs=1e-3)


def test_bad_solution_documents_name_their_part():
    doc = modsynth.load_solution(LINE_SOLUTION).to_dict()
    doc["samples"][3]["q"][1] = "x"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.Solution.from_dict(doc)
    assert e.value.part == "samples[3].q[1]"
    with pytest.raises(modsynth.TaskError):
        modsynth.Solution.from_json("[]")


def test_certify_agrees_with_the_command_line():
    for task, solution in ((LINE_TASK, LINE_SOLUTION), (SPATIAL_TASK, SPATIAL_SOLUTION)):
        cli = json.loads(run_cli("certify", task, solution, "--json").stdout)
        c = modsynth.certify(task, solution)
        assert c.ok == cli["certified"] is True
        assert c.max_deviation == pytest.approx(cli["max_ee_deviation"], rel=1e-12)
        assert c.max_joint_step == pytest.approx(cli["max_joint_step"], rel=1e-12)
    # A solution whose motion was moved off the path is not certified, and
    # the reason names the sample.
    doc = modsynth.load_solution(LINE_SOLUTION).to_dict()
    for sample in doc["samples"][10:20]:
        sample["q"][0] += 0.05
    broken = modsynth.Solution.from_dict(doc)
    c = modsynth.certify(LINE_TASK, broken)
    assert not c.ok and not c
    assert c.reason.startswith("samples[") and c.violations
    # A solution of another task is refused by name.
    with pytest.raises(modsynth.TaskError):
        modsynth.certify(path("tasks", "rose.json"), LINE_SOLUTION)


def test_writers_write_what_export_writes(tmp_path):
    kinds = {"report": ".html", "urdf": ".urdf", "csv": ".csv", "joint_trajectory": ".yaml", "build_sheet": ".md"}
    for task, solution, name in ((LINE_TASK, LINE_SOLUTION, "line"), (SPATIAL_TASK, SPATIAL_SOLUTION, "s3")):
        cli_files = {k: str(tmp_path / f"{name}-cli{ext}") for k, ext in kinds.items()}
        options = [f"--{k.replace('_', '-')}={p}" for k, p in cli_files.items()]
        done = run_cli("export", task, solution, *options)
        assert done.returncode == 0, done.stderr
        py_files = {k: str(tmp_path / f"{name}-py{ext}") for k, ext in kinds.items()}
        assert modsynth.write_exports(task, solution, **py_files) == []
        for k in kinds:
            with open(cli_files[k], "rb") as a, open(py_files[k], "rb") as b:
                assert a.read() == b.read(), f"{name}: {k} differs from `modsynth export`"
        one = str(tmp_path / f"{name}-one.urdf")
        modsynth.write_urdf(task, solution, one)
        with open(one, "rb") as a, open(cli_files["urdf"], "rb") as b:
            assert a.read() == b.read()
        for writer in (modsynth.write_csv, modsynth.write_joint_trajectory, modsynth.write_report,
                       modsynth.write_build_sheet):
            writer(task, solution, str(tmp_path / f"{name}-{writer.__name__}"))
            assert os.path.getsize(tmp_path / f"{name}-{writer.__name__}") > 0


def test_writers_refuse_what_they_cannot_write(tmp_path):
    doc = modsynth.load_solution(LINE_SOLUTION).to_dict()
    for sample in doc["samples"][10:20]:
        sample["q"][0] += 0.05
    broken = modsynth.Solution.from_dict(doc)
    with pytest.raises(modsynth.ExportError, match="not certified"):
        modsynth.write_csv(LINE_TASK, broken, str(tmp_path / "x.csv"))
    assert not (tmp_path / "x.csv").exists()
    modsynth.write_csv(LINE_TASK, broken, str(tmp_path / "x.csv"), write_uncertified=True)
    assert (tmp_path / "x.csv").exists()
    unsolved = dict(format="modsynth-solution/1", task="line", status="unknown",
                    explanation={"message": "time limit", "core": []})
    with pytest.raises(modsynth.ExportError):
        modsynth.write_urdf(LINE_TASK, modsynth.Solution.from_dict(unsolved), str(tmp_path / "x.urdf"))
    modsynth.write_report(LINE_TASK, modsynth.Solution.from_dict(unsolved), str(tmp_path / "x.html"))
    with pytest.raises(RuntimeError, match="no-such-folder"):
        modsynth.write_urdf(LINE_TASK, LINE_SOLUTION, str(tmp_path / "no-such-folder" / "x.urdf"))


IMPORTS = [
    ("sketch", [path("tasks", "drawings", "sketch.svg")], dict(source=path("tasks", "drawings", "sketch.svg"))),
    (
        "bracket",
        [path("tasks", "drawings", "bracket.dxf"), "--width", "0.2", "--at", "0.45,0.2", "--base", "-0.1,-0.1,0.1,0.1"],
        dict(source=path("tasks", "drawings", "bracket.dxf"), width=0.2, at=(0.45, 0.2),
             base_regions=[(-0.1, -0.1, 0.1, 0.1)]),
    ),
    (
        "text",
        ["--text", "Hi", "--height", "0.04", "--at", "0.4,0.1", "--rotate", "10"],
        dict(text="Hi", text_height=0.04, at=[0.4, 0.1], rotate=10),
    ),
    (
        "plane",
        [path("tasks", "drawings", "sketch.svg"), "--width", "0.15", "--plane", "0.4,0,0.2,0,1,0,0,0,1",
         "--base", "-0.05,-0.05,0,0.05,0.05,0.02", "--dof", "3,4"],
        dict(source=path("tasks", "drawings", "sketch.svg"), width=0.15,
             plane=[[0.4, 0, 0.2], [0, 1, 0], [0, 0, 1]], base_regions=[[-0.05, -0.05, 0, 0.05, 0.05, 0.02]],
             dof=[3, 4]),
    ),
    (
        "cylinder",
        ["--text", "ab", "--height", "0.03", "--cylinder", "0.4,0,0.2,0,0,1,0.1", "--tool-length", "0.02"],
        dict(text="ab", text_height=0.03, cylinder=(0.4, 0, 0.2, 0, 0, 1, 0.1), tool_length=0.02),
    ),
]


@pytest.mark.parametrize("name,cli_args,keywords", IMPORTS, ids=[i[0] for i in IMPORTS])
def test_import_drawing_writes_what_import_writes(tmp_path, name, cli_args, keywords):
    out = str(tmp_path / f"{name}.cli.json")
    done = run_cli("import", *cli_args, "-o", out)
    assert done.returncode == 0, done.stderr
    imported = modsynth.import_drawing(**keywords)
    mine = str(tmp_path / f"{name}.py.json")
    imported.save(mine)
    with open(out, "rb") as a, open(mine, "rb") as b:
        assert a.read() == b.read()
    task = imported.task
    assert task.spatial == (name in ("plane", "cylinder"))
    assert imported.surface == ("" if name not in ("plane", "cylinder") else name)
    assert sum(imported.primitives_per_stroke) == sum(len(s) for s in task.strokes())
    assert f"primitives per stroke: {' '.join(map(str, imported.primitives_per_stroke))}" in done.stdout
    assert f"deviation: {imported.deviation:.3g} m" in done.stdout
    assert imported.deviation <= (keywords.get("tolerance") or 1e-4) + 1e-12


def test_import_drawing_from_contents_and_its_errors(tmp_path):
    with open(path("tasks", "drawings", "sketch.svg"), "rb") as f:
        svg = f.read()
    from_file = modsynth.import_drawing(path("tasks", "drawings", "sketch.svg"), name="sketch")
    from_bytes = modsynth.import_drawing(contents=svg, format="svg", name="sketch")
    assert from_bytes.task_json == from_file.task_json
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(contents=svg)
    assert e.value.part == "format"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing()
    assert e.value.part == "drawing"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(path("tasks", "drawings", "sketch.svg"), base_regions=[(1, 1, 0, 0)])
    assert e.value.part == "base_regions"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(path("tasks", "drawings", "sketch.svg"), base_regions=[(0, 0, 1)])
    assert e.value.part == "base_regions[0]"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(path("tasks", "drawings", "sketch.svg"), tolerance=2.0)
    assert e.value.part == "tolerance"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(path("tasks", "drawings", "sketch.svg"), width=float("nan"))
    assert e.value.part == "width"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(path("tasks", "drawings", "sketch.svg"), plane=[0, 0, 0, 1, 0, 0, 1, 0, 0])
    assert e.value.part == "plane"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(path("tasks", "drawings", "sketch.svg"), tool_length=0.1)
    assert e.value.part == "tool_length"
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(text="x", font="no-such-font")
    assert e.value.part == "font"
    bad = tmp_path / "bad.svg"
    bad.write_text("<svg><path d='M 0 0 L'/>")
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(bad)
    assert e.value.file == str(bad) and str(e.value).count(str(bad)) == 1
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.import_drawing(tmp_path / "missing.dxf")
    assert str(tmp_path / "missing.dxf") in str(e.value)
    with pytest.raises(modsynth.TaskError):
        modsynth.import_drawing(tmp_path / "drawing.png")


def test_the_stubs_cover_the_compiled_core():
    stub = path("python", "modsynth", "_core.pyi")
    with open(stub) as f:
        text = f.read()
    names = [n for n in dir(modsynth._core) if not n.startswith("_")]
    missing = [n for n in names if f"def {n}(" not in text and f"class {n}:" not in text and f"class {n}(" not in text]
    assert missing == []
    for name in modsynth.__all__:
        assert getattr(modsynth, name).__doc__, f"modsynth.{name} has no docstring"
