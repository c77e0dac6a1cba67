"""The exceptions modsynth raises besides Python's own."""

from __future__ import annotations


class TaskError(ValueError):
    """Bad input: a task, a solution document or an option that cannot be
    used, with ``part`` naming the offending part as the task format does
    (``"trajectory[3].center"``, ``"robot.dof"``, ``"samples[12].q[1]"``) or
    the option (``"base_regions"``); ``problem`` says what is wrong with it,
    and ``file`` the file it was read from ("" when it came from no file).
    ``str(error)`` is ``"file: part: problem"``, each named once, as the
    command line prints it."""

    def __init__(self, problem: str, part: str = "", file: str = "") -> None:
        super().__init__(_message(problem, part, file))
        self.problem = problem
        self.part = part
        self.file = file

    def __reduce__(self):  # type: ignore[no-untyped-def]
        return (type(self), (self.problem, self.part, self.file))


def _message(problem: str, part: str, file: str) -> str:
    # As the library words it: a part that is the file itself, or the whole
    # document of a named file, is not said twice.
    out = f"{file}: " if file else ""
    if part and part != file and not (part == "(document)" and file):
        out += f"{part}: "
    return out + problem


class TaskWarning(UserWarning):
    """A task that is valid but most likely not what its author meant: a
    key the task format does not define (a misspelt ``base_region`` is
    ignored, with the nearest known key named), or lengths that look like
    millimetres. ``warnings.simplefilter("error", modsynth.TaskWarning)``
    refuses such tasks, as ``modsynth solve --strict`` does."""


class ImportTimeout(TimeoutError):
    """A drawing was not imported within its time limit."""


class ExportError(RuntimeError):
    """A file that was asked for could not be written from this solution
    (an unsolved one has no robot; an uncertified motion is not handed to a
    controller)."""
