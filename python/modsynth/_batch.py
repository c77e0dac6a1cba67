"""Batches of solves on a Dask cluster (distributed), one task per solve,
results as they finish, none lost when a worker dies."""

from __future__ import annotations

import os
import socket
import time
import uuid
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Dict, Iterable, Iterator, Optional, Tuple

from ._calls import _seconds
from ._errors import TaskError
from ._solution import Solution
from ._tasks import Task, TaskLike, as_task

if TYPE_CHECKING:  # distributed is needed only for batches
    from distributed import Client, Future


@dataclass
class BatchResult:
    """One task's outcome in a batch.

    ``status`` is the answer ("solved", "infeasible", "unknown") or why
    there is none: "invalid" (the task could not be read or used; ``error``
    names the part) or "error" (the solve failed, or the task killed the
    worker that ran it ``max_attempts`` times). ``index`` is the task's
    place in the input, ``source`` its file path when it came from a file,
    ``seconds`` the solve's wall time on the worker, ``attempts`` how many
    times it was submitted (more than one when a worker died under it), and
    ``worker`` the host and process that answered."""

    index: int
    name: str
    source: Optional[str]
    status: str
    solution: Optional[Solution] = None
    error: Optional[str] = None
    seconds: Optional[float] = None
    attempts: int = 1
    worker: Optional[str] = None


def _solve_on_worker(task_json: str, time_limit: float, seed: int) -> Dict[str, Any]:
    """Runs on a Dask worker: the solve of one task, its errors as values so
    that one bad task does not fail the batch."""
    from . import solve

    started = time.monotonic()
    where = f"{socket.gethostname()}:{os.getpid()}"
    try:
        solution = solve(Task.from_json(task_json), time_limit=time_limit, seed=seed)
    except TaskError as e:
        return {"status": "invalid", "error": str(e), "worker": where}
    except Exception as e:  # noqa: BLE001 (kept as the task's error)
        return {"status": "error", "error": f"{type(e).__name__}: {e}", "worker": where}
    return {"status": solution.status, "solution": solution, "seconds": time.monotonic() - started, "worker": where}


def _local_client() -> Tuple["Client", Any]:
    from distributed import Client, LocalCluster

    cluster = LocalCluster(
        n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True, dashboard_address=None
    )
    return Client(cluster), cluster


def batch(
    tasks: Iterable[TaskLike],
    client: Optional["Client"] = None,
    *,
    time_limit: float = 60.0,
    seed: int = 0,
    max_attempts: int = 3,
) -> Iterator[BatchResult]:
    """Solves every task on a Dask cluster and yields a ``BatchResult`` for
    each as it finishes (not in input order: see ``index``).

    ``tasks`` holds Tasks, task documents (dicts) or task file paths; they
    are read here, so the workers need no shared files, only the modsynth
    package. A task that cannot be read is an "invalid" result at once; the
    others go to the cluster. ``client`` is a ``distributed.Client``; without
    one a ``LocalCluster`` of one single-threaded worker process per CPU is
    started and closed afterwards. Each worker process solves one task at a
    time (the solver is not re-entrant), so give workers one thread each or
    let their tasks queue. When a worker dies while solving, the task is
    submitted again, up to ``max_attempts`` deaths, after which it is an
    "error" result.
    """
    from distributed import as_completed
    from distributed.scheduler import KilledWorker

    _seconds(time_limit, "time_limit")
    if not (isinstance(max_attempts, int) and max_attempts >= 1):
        raise ValueError("max_attempts must be a positive integer")
    owned = None
    if client is None:
        client, owned = _local_client()
    cluster: "Client" = client
    try:
        run = uuid.uuid4().hex[:8]
        pending: Dict["Future", Tuple[int, str, Optional[str], str, int]] = {}
        ready = []

        def submit(index: int, name: str, source: Optional[str], text: str, attempt: int) -> "Future":
            future = cluster.submit(
                _solve_on_worker, text, time_limit, seed, key=f"modsynth-solve-{run}-{index}-{attempt}", pure=False
            )
            pending[future] = (index, name, source, text, attempt)
            return future

        for index, item in enumerate(tasks):
            source = os.fspath(item) if isinstance(item, (str, os.PathLike)) else None
            try:
                task = as_task(item)
            except (TaskError, OSError, TypeError) as e:
                name = os.path.basename(source) if source else f"task {index}"
                ready.append(BatchResult(index, name, source, "invalid", error=str(e), attempts=0))
                continue
            submit(index, task.name, source, task.to_json(indent=None), 1)
        yield from ready

        done = as_completed(list(pending))
        for future in done:
            index, name, source, text, attempt = pending.pop(future)
            if future.status == "finished":
                out = future.result()
                yield BatchResult(
                    index,
                    name,
                    source,
                    out["status"],
                    solution=out.get("solution"),
                    error=out.get("error"),
                    seconds=out.get("seconds"),
                    attempts=attempt,
                    worker=out.get("worker"),
                )
                continue
            error = future.exception() if future.status == "error" else None
            # A worker that died under the task (KilledWorker once the
            # scheduler gives up on it), or a future lost with its worker:
            # the task goes again, under a new key.
            if (error is None or isinstance(error, KilledWorker)) and attempt < max_attempts:
                done.add(submit(index, name, source, text, attempt + 1))
                continue
            why = f"{type(error).__name__}: {error}" if error is not None else f"the future was {future.status}"
            yield BatchResult(index, name, source, "error", error=why, attempts=attempt)
    finally:
        if owned is not None:
            cluster.close()
            owned.close()
