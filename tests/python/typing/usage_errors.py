"""Calls an editor should flag: each line marked `# wrong` is one mypy
must report (the test reads the marks)."""

import modsynth

task = modsynth.Task.load("task.json")
modsynth.solve(task, time_limit="10")  # wrong
modsynth.solve(task, seed="1")  # wrong
modsynth.solve(task, progres=print)  # wrong
modsynth.solve(task).robot.link_lengths  # wrong
modsynth.certify(task, 3)  # wrong
modsynth.import_drawing("a.svg", width="wide")  # wrong
modsynth.write_urdf(task)  # wrong
n: int = modsynth.solve(task).status  # wrong
modsynth.solve(task).certificate.okay  # wrong
