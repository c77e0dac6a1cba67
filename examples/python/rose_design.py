"""Designs an arm for the rose (tasks/rose.json) and plots it: the path, the
obstacles and the base region with the arm at a few poses, and the joint
angles, rates and accelerations over time.

    python3 examples/python/rose_design.py                 # a window
    python3 examples/python/rose_design.py --out rose.png  # a file
"""

from __future__ import annotations

import argparse
import os
import sys

import matplotlib

if "--out" in sys.argv:
    matplotlib.use("Agg")  # a file needs no display
import matplotlib.pyplot as plt
import numpy as np

import modsynth

HERE = os.path.dirname(os.path.abspath(__file__))


def plot_design(task: modsynth.Task, solution: modsynth.Solution, poses: int = 6) -> plt.Figure:
    fig, (arm, curves) = plt.subplots(1, 2, figsize=(12, 5), gridspec_kw={"width_ratios": [1, 1.4]})
    doc = task.to_dict()
    for r in doc.get("base_regions", []):
        (x0, y0), (x1, y1) = r["min"], r["max"]
        arm.add_patch(plt.Rectangle((x0, y0), x1 - x0, y1 - y0, color="tab:green", alpha=0.3))
    for o in doc.get("obstacles", []):
        arm.add_patch(plt.Circle(o["center"], o["radius"], color="tab:red", alpha=0.5))
    for points in task.path_points():
        arm.plot(points[:, 0], points[:, 1], color="black", linewidth=2)
    joints = solution.joint_positions()
    for k, i in enumerate(np.linspace(0, len(joints) - 1, poses).astype(int)):
        shade = plt.cm.viridis(k / max(1, poses - 1))
        arm.plot(joints[i, :, 0], joints[i, :, 1], "-o", color=shade, linewidth=3, markersize=5)
    ee = joints[:, -1, :]
    arm.plot(ee[:, 0], ee[:, 1], ":", color="tab:orange", linewidth=1)
    robot = solution.robot
    assert isinstance(robot, modsynth.Robot), "a planar task's arm"
    links = ", ".join(f"{x:.3f}" for x in robot.link_lengths)
    arm.set_title(f"{task.name}: {robot.dof} joints, links {links} m")
    arm.set_aspect("equal")
    arm.set_xlabel("x (m)")
    arm.set_ylabel("y (m)")

    s = solution.samples
    for k in range(robot.dof):
        line = curves.plot(s.t, s.q[:, k], label=f"q{k + 1} (rad)")[0]
        if s.qd is not None:
            curves.plot(s.t, s.qd[:, k], "--", color=line.get_color(), label=f"qd{k + 1} (rad/s)")
    curves.set_xlabel("t (s)")
    curves.set_title("joint angles and rates")
    curves.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    return fig


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--task", default=os.path.join(HERE, "..", "..", "tasks", "rose.json"))
    parser.add_argument("--out", help="write the figure here (PNG, PDF, SVG) instead of showing it")
    parser.add_argument("--time-limit", type=float, default=60.0)
    args = parser.parse_args()

    task = modsynth.Task.load(args.task)
    stages = []
    solution = modsynth.solve(task, time_limit=args.time_limit, progress=lambda e: stages.append(e.stage))
    print(f"{task.name}: {solution.status} after {len(stages)} progress events")
    if not solution.solved:
        print(f"  {solution.explanation.message}")
        return 1
    c = solution.certificate
    robot = solution.robot
    if not isinstance(robot, modsynth.Robot):
        print("  this example draws planar arms only")
        return 1
    print(f"  links {list(np.round(robot.link_lengths, 4))} m, base {list(np.round(robot.base, 4))}")
    print(f"  certified: {c.ok}, clearance margin {c.min_clearance:.4f} m, deviation <= {c.max_deviation:.2e} m")
    print(f"  motion {solution.samples.t[-1]:.2f} s in {len(solution.samples)} samples")
    if solution.modules is not None:
        print(f"  modules: {', '.join(solution.modules.names)}")
    fig = plot_design(task, solution)
    if args.out:
        fig.savefig(args.out, dpi=100)
        print(f"  figure: {args.out}")
    else:
        plt.show()
    return 0


if __name__ == "__main__":
    sys.exit(main())
