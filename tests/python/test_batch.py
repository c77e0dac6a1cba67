"""Batches on a Dask LocalCluster: results as they finish, every task
answered once with its planted answer, per-task errors kept, and nothing
lost when a worker is killed in the middle of a solve."""

import glob
import json
import os
import signal
import threading
import time

import pytest

import modsynth
from conftest import path

distributed = pytest.importorskip("distributed")

PLANTED = sorted(glob.glob(path("tests", "fixtures", "planted", "p2-*.task.json")))[:5] + sorted(
    glob.glob(path("tests", "fixtures", "planted", "ir-*.task.json"))
)[:2]


def expected(task_path):
    with open(task_path.replace(".task.json", ".expect.json")) as f:
        return json.load(f)["status"]


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40
    )
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


@pytest.fixture(scope="module")
def alone():
    """Each planted task solved here, without Dask: what the batch must give."""
    return {p: modsynth.solve(p, time_limit=60).to_json() for p in PLANTED}


def check(results, alone):
    by_index = {}
    for r in results:
        assert r.index not in by_index, f"task {r.index} answered twice"
        by_index[r.index] = r
    assert sorted(by_index) == list(range(len(PLANTED)))
    for i, p in enumerate(PLANTED):
        r = by_index[i]
        assert r.source == p and r.error is None, r
        assert r.status == expected(p) or (expected(p) == "solved" and r.status == "unknown"), r
        assert r.solution.to_json() == alone[p], f"{p}: the batch answered otherwise than a solve here"
        assert r.seconds > 0 and r.worker
    return by_index


def test_a_batch_answers_every_task_as_a_solve_here_does(client, alone):
    started = time.monotonic()
    finished = []
    results = []
    for r in modsynth.batch(PLANTED, client=client, time_limit=60):
        finished.append(time.monotonic() - started)
        results.append(r)
    check(results, alone)
    # As they finish: the first came well before the last.
    assert finished[0] < finished[-1]
    assert len({r.worker for r in results}) == 2


def test_errors_stay_with_their_task(client):
    doc = modsynth.Task.load(PLANTED[0]).to_dict()
    doc["robot"] = dict(doc.get("robot", {}), modules=["NO-SUCH-MODULE"])
    tasks = [PLANTED[0], {"format": "modsynth-task/1", "trajectory": []}, doc, path("tasks", "missing.json")]
    results = {r.index: r for r in modsynth.batch(tasks, client=client, time_limit=30)}
    assert sorted(results) == [0, 1, 2, 3]
    assert results[0].status == expected(PLANTED[0]) and results[0].error is None
    assert results[1].status == "invalid" and "trajectory" in results[1].error
    assert results[2].status == "invalid" and "NO-SUCH-MODULE" in results[2].error
    assert results[3].status == "invalid" and results[3].source.endswith("missing.json")


def test_no_task_is_lost_when_a_worker_dies_mid_solve(client, alone):
    killed = []

    def kill_a_busy_worker():
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not killed:
            for address, keys in client.processing().items():
                if any(str(k).startswith("modsynth-solve") for k in keys):
                    pid = client.run(os.getpid, workers=[address])[address]
                    os.kill(pid, signal.SIGKILL)
                    killed.append((address, pid, list(keys)))
                    return
            time.sleep(0.05)

    killer = threading.Thread(target=kill_a_busy_worker)
    killer.start()
    try:
        results = list(modsynth.batch(PLANTED, client=client, time_limit=60))
    finally:
        killer.join()
    assert killed, "no worker was seen solving"
    by_index = check(results, alone)
    print(f"killed worker {killed[0][0]} (pid {killed[0][1]}) while it held {killed[0][2]}")
    print("attempts:", {i: r.attempts for i, r in by_index.items()}, "workers:", {r.worker for r in results})
    # The nanny restarts the worker: the cluster is whole again.
    client.wait_for_workers(2, timeout=60)
