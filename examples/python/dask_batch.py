"""Solves planted tasks on a Dask cluster and checks each answer against the
answer planted in it: tasks from ../shared/grader/plant.py when it is beside
the checkout (made afresh), else the planted fixtures of the test suite.

    python3 examples/python/dask_batch.py                     # a LocalCluster
    python3 examples/python/dask_batch.py --scheduler HOST:8786

With --scheduler the tasks go to a running cluster (dask-scheduler and
dask-worker, docs/python.md); otherwise a LocalCluster of --workers
single-threaded worker processes is started on this machine.
"""

from __future__ import annotations

import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

import modsynth

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
PLANT = os.path.normpath(os.path.join(ROOT, "..", "shared", "grader", "plant.py"))
FIXTURES = os.path.join(ROOT, "tests", "fixtures", "planted")


def planted_tasks(folder: str, count: int) -> list:
    """count feasible 2-joint tasks and count out of reach, made by plant.py,
    or the fixtures without it."""
    if os.path.isfile(PLANT):
        for kind, seed in (("2dof", 5000), ("infeasible-reach", 6000)):
            subprocess.run(
                [sys.executable, PLANT, "--kind", kind, "--seed", str(seed), "--count", str(count), "--out", folder],
                check=True,
                stdout=subprocess.DEVNULL,
            )
        source = folder
    else:
        print(f"{PLANT} not found: solving the test suite's planted fixtures")
        source = FIXTURES
    return sorted(glob.glob(os.path.join(source, "*.task.json")))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scheduler", help="address of a running dask-scheduler")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--count", type=int, default=3, help="tasks of each kind to plant")
    parser.add_argument("--time-limit", type=float, default=60.0)
    args = parser.parse_args()

    from distributed import Client, LocalCluster

    with tempfile.TemporaryDirectory() as folder:
        paths = planted_tasks(folder, args.count)
        if args.scheduler:
            client = Client(args.scheduler)
            cluster = None
        else:
            cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True)
            client = Client(cluster)
        wrong = 0
        try:
            for r in modsynth.batch(paths, client=client, time_limit=args.time_limit):
                assert r.source is not None  # every task came from a file
                expect_path = r.source.replace(".task.json", ".expect.json")
                with open(expect_path) as f:
                    expected = json.load(f)["status"]
                # A planted feasible task must never be called infeasible;
                # "unknown" within the time limit is allowed but reported.
                ok = r.status == expected or (expected == "solved" and r.status == "unknown")
                wrong += not ok
                detail = r.error or (f"{r.seconds:.2f} s on {r.worker}" if r.seconds is not None else "")
                print(f"{os.path.basename(r.source):28} {r.status:10} (planted {expected}) {detail}")
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    print(f"{len(paths)} tasks, {wrong} answered against their planted answer")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
