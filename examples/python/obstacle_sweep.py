"""Sweeps a task parameter, an obstacle's position, and shows where the task
stops being feasible: the obstacle moves from far above a straight stroke
down toward it (until it would touch the path, which no task may have),
each position is solved, and at the first infeasible one the explanation
names the conflicting parts (its core).

    python3 examples/python/obstacle_sweep.py                  # a window
    python3 examples/python/obstacle_sweep.py --out sweep.png  # a file
"""

from __future__ import annotations

import argparse
import sys

import matplotlib

if "--out" in sys.argv:
    matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import modsynth

COLOURS = {"solved": "tab:green", "infeasible": "tab:red", "unknown": "tab:gray"}


def stroke_task(obstacle_y: float) -> modsynth.Task:
    """A 20 cm stroke at y = 0.25 m, the base near the origin, two joints,
    and one obstacle of radius 3 cm above the stroke's middle at height
    obstacle_y."""
    return modsynth.Task(
        [modsynth.line([0.35, 0.25], [0.55, 0.25])],
        obstacles=[modsynth.obstacle([0.45, obstacle_y], 0.03)],
        base_regions=[modsynth.region([-0.05, -0.05], [0.05, 0.05])],
        robot={"dof": [2]},
        name=f"stroke, obstacle at y = {obstacle_y:.3f} m",
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--from", dest="start", type=float, default=0.40, help="first height (m)")
    parser.add_argument("--to", dest="stop", type=float, default=0.2825, help="last height (m)")
    parser.add_argument("--positions", type=int, default=12)
    parser.add_argument("--time-limit", type=float, default=20.0, help="seconds per solve")
    parser.add_argument("--out", help="write the figure here instead of showing it")
    args = parser.parse_args()

    heights = np.linspace(args.start, args.stop, args.positions)
    statuses = []
    first_infeasible = None
    for y in heights:
        solution = modsynth.solve(stroke_task(y), time_limit=args.time_limit)
        statuses.append(solution.status)
        print(f"obstacle at y = {y:.3f} m: {solution.status}")
        if solution.status == "infeasible" and first_infeasible is None:
            first_infeasible = y
    if first_infeasible is None:
        print("feasible at every position")
    else:
        task = stroke_task(first_infeasible)
        why = modsynth.explain(task, time_limit=30.0, solve_seconds=5.0)
        solved = [y for y, status in zip(heights, statuses) if status == "solved" and y > first_infeasible]
        if solved:
            print(f"solved down to y = {min(solved):.3f} m")
        print(f"stops being feasible at y = {first_infeasible:.3f} m: {why.message}")
        print(f"core: {', '.join(why.core)}")
        for s in why.suggestions:
            print(f"  suggestion: {s.change} -> {s.outcome}")

    fig, (scene, chart) = plt.subplots(1, 2, figsize=(11, 4.5))
    scene.plot([0.35, 0.55], [0.25, 0.25], color="black", linewidth=2, label="stroke")
    scene.add_patch(plt.Rectangle((-0.05, -0.05), 0.1, 0.1, color="tab:green", alpha=0.3))
    for y, status in zip(heights, statuses):
        scene.add_patch(plt.Circle((0.45, y), 0.03, fill=False, color=COLOURS[status]))
    scene.set_aspect("equal")
    scene.set_xlim(-0.1, 0.65)
    scene.set_ylim(-0.1, max(heights) + 0.08)
    scene.set_title("obstacle positions (green: solved, red: infeasible)")
    chart.scatter(heights, [1 if s == "solved" else 0 for s in statuses], c=[COLOURS[s] for s in statuses])
    if first_infeasible is not None:
        chart.axvline(first_infeasible, color="tab:red", linestyle="--")
    chart.set_yticks([0, 1], ["not solved", "solved"])
    chart.set_xlabel("obstacle height y (m)")
    chart.set_title("where the task stops being feasible")
    fig.tight_layout()
    if args.out:
        fig.savefig(args.out, dpi=100)
        print(f"figure: {args.out}")
    else:
        plt.show()
    return 0


if __name__ == "__main__":
    sys.exit(main())
