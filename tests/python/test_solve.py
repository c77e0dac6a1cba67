"""Solving and explaining from Python: the same answers as the command line,
byte for byte; progress on the calling thread; the GIL free meanwhile."""

import glob
import json
import os
import threading
import time

import pytest

import modsynth
from conftest import path, run_cli

SAME_ANSWER = [path("tasks", f"{name}.json") for name in ("rose", "wipe-table", "clean-table")] + sorted(
    glob.glob(path("tasks", "spatial", "*.json"))
)


@pytest.mark.parametrize("file", SAME_ANSWER, ids=os.path.basename)
def test_solutions_equal_the_command_lines_byte_for_byte(tmp_path, file):
    cli = str(tmp_path / "cli.json")
    done = run_cli("solve", file, "-o", cli, "--quiet", "--time-limit", "60")
    assert done.returncode in (0, 3, 4), done.stderr
    solution = modsynth.solve(file, time_limit=60)
    mine = str(tmp_path / "python.json")
    solution.save(mine)
    with open(cli, "rb") as a, open(mine, "rb") as b:
        assert a.read() == b.read(), f"{file}: modsynth.solve and `modsynth solve` answer differently"
    assert solution.solved
    assert modsynth.certify(file, solution).ok


def test_the_rose_from_a_path_as_the_readme_shows():
    s = modsynth.solve(path("tasks", "rose.json"))
    assert s.status == "solved"
    assert s.robot.dof == len(s.robot.link_lengths) >= 2
    assert 0.1 < sum(s.robot.link_lengths) < 2.0
    t = s.samples.t
    assert (t[1:] >= t[:-1]).all() and t[0] == 0.0
    assert s.samples.qd is not None and s.samples.qd.shape == s.samples.q.shape
    assert s.modules is not None and s.modules.carried


def test_progress_arrives_on_the_calling_thread_while_the_gil_is_free():
    caller = threading.get_ident()
    events = []
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    try:
        started = time.monotonic()
        s = modsynth.solve(
            path("tasks", "spatial", "glue-box-edges.json"),
            progress=lambda e: events.append((threading.get_ident(), e)),
        )
        took = time.monotonic() - started
    finally:
        stop.set()
        ticker.join()
    assert s.solved
    assert events and all(ident == caller for ident, _ in events)
    stages = [e.stage for _, e in events]
    assert "front stage" in stages and "verification" in stages
    elapsed = [e.elapsed for _, e in events]
    assert elapsed == sorted(elapsed)
    assert all(isinstance(e.message, str) and e.message for _, e in events)
    assert str(events[0][1]).startswith("[")
    # The other thread ran all along: it never waited for the GIL as long
    # as the solve took (about 0.9 s since the spatial search got faster).
    gap = max(b - a for a, b in zip(ticks, ticks[1:]))
    assert took > 0.5 and gap < 0.25, (took, gap)


def test_an_exception_in_the_progress_callback_ends_the_solve():
    def fail(event):
        raise RuntimeError(f"stop at {event.stage}")

    started = time.monotonic()
    with pytest.raises(RuntimeError, match="stop at"):
        modsynth.solve(path("tasks", "clean-table.json"), time_limit=60, progress=fail)
    assert time.monotonic() - started < 5.0
    # The module solves again afterwards.
    assert modsynth.solve(path("tasks", "rose.json")).solved


def test_a_progress_callback_cannot_call_modsynth():
    errors = []

    def nested(event):
        try:
            modsynth.solve(path("tasks", "rose.json"))
        except RuntimeError as e:
            errors.append(str(e))

    assert modsynth.solve(path("tasks", "rose.json"), progress=nested).solved
    assert errors and "progress callback" in errors[0]


def test_threads_that_solve_at_once_take_turns_and_agree():
    alone = modsynth.solve(path("tasks", "rose.json"), seed=3).to_json()
    answers = {}

    def run(k):
        answers[k] = modsynth.solve(path("tasks", "rose.json"), seed=3).to_json()

    threads = [threading.Thread(target=run, args=(k,)) for k in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert list(answers.values()) == [alone] * 3


def test_unknown_modules_are_a_task_error():
    doc = modsynth.Task.load(path("tasks", "rose.json")).to_dict()
    doc["robot"]["modules"] = ["NO-SUCH-MODULE"]
    with pytest.raises(modsynth.TaskError) as e:
        modsynth.solve(modsynth.Task.from_dict(doc), time_limit=10)
    assert "NO-SUCH-MODULE" in str(e.value)


def test_explain_says_what_the_command_line_says():
    file = path("tasks", "infeasible", "out-of-reach.task.json")
    cli = json.loads(run_cli("explain", file, "--json", "--time-limit", "60").stdout)
    events = []
    e = modsynth.explain(file, time_limit=60, progress=events.append)
    assert e.proved and e.status == "infeasible"
    mine = e.to_dict()
    for key in ("task", "status", "message", "core"):
        assert mine[key] == cli[key]
    with open(path("tasks", "infeasible", "out-of-reach.core.json")) as f:
        assert set(json.load(f)["core"]) <= set(e.core)
    assert [s["change"] for s in mine["suggestions"]] == [s["change"] for s in cli["suggestions"]]
    assert [s.change for s in e.suggestions] == [s["change"] for s in cli["suggestions"]]
    assert [e.message for e in events][:2] == ["proving infeasibility", "looking for the smallest changes"]
    for s in e.suggestions:
        assert s.part in e.core
        # The suggested task, solved, is what the suggestion says.
        assert isinstance(s.task, modsynth.Task) and s.task != modsynth.Task.load(file)
    solved = [s for s in e.suggestions if s.status == "solved"]
    assert solved and modsynth.solve(solved[0].task, time_limit=30).solved


def test_an_infeasible_solution_names_its_core():
    s = modsynth.solve(path("tasks", "infeasible", "out-of-reach.task.json"), time_limit=30)
    assert s.status == "infeasible" and not s.solved
    with pytest.raises(ValueError, match="infeasible"):
        s.robot
    assert s.explanation.message and "trajectory" in " ".join(s.explanation.core)
    with pytest.raises(ValueError):
        s.joint_positions()
    assert s.to_dict()["explanation"]["core"] == s.explanation.core
