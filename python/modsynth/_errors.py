"""The exceptions modsynth raises besides Python's own."""

from __future__ import annotations


class TaskError(ValueError):
    """Bad input: a task, a solution document or an option that cannot be
    used, with ``part`` naming the offending part as the task format does
    (``"trajectory[3].center"``, ``"robot.dof"``, ``"samples[12].q[1]"``) or
    the option (``"base_regions"``); ``problem`` says what is wrong with it.
    ``str(error)`` is ``"part: problem"``, as the command line prints it."""

    def __init__(self, problem: str, part: str = "") -> None:
        super().__init__(f"{part}: {problem}" if part else problem)
        self.problem = problem
        self.part = part

    def __reduce__(self):  # type: ignore[no-untyped-def]
        return (type(self), (self.problem, self.part))


class ImportTimeout(TimeoutError):
    """A drawing was not imported within its time limit."""


class ExportError(RuntimeError):
    """A file that was asked for could not be written from this solution
    (an unsolved one has no robot; an uncertified motion is not handed to a
    controller)."""
