"""The session folder: refused before any work unless it is new, empty or a previous session of the same task;
a previous session set aside while the new one runs, and put back as it was if the new one fails."""

from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from guided_lfd.pddl.model import Problem

__all__ = ["SESSION_FILES", "LIBRARY_FILES", "check_session_folder", "check_library_folder",
           "replacing_previous_session", "make_folder"]


#: What a session writes into its folder (besides ``round-N/``).
SESSION_FILES = ("robot.pddl", "session.json", "session.md")
#: What a sequence of sessions writes into its folder (besides ``task-N/``).
LIBRARY_FILES = ("robot.pddl", "library.json", "library.md")


def check_library_folder(out: Path, problems: list[Problem]) -> None:
    """Refuse (exit 40), before any work, a folder for a sequence of tasks that is neither new, nor empty, nor a
    previous sequence of the same tasks (replaced whole, its ``task-N/`` folders included); a link where the
    sequence writes, or another file, is refused, as for one session."""
    import json

    from guided_lfd.errors import Location, OutputError

    def refuse(why: str) -> None:
        raise OutputError(f"{why}; expected a new or empty folder, or a previous teaching of these tasks",
                          Location(str(out)))

    entries = _entries(out, "the tasks' sessions")
    for entry in entries:
        if entry.name not in LIBRARY_FILES and not (entry.name.startswith("task-") and entry.name[5:].isdigit()):
            refuse(f"holds {entry.name}, which is no file of a teaching of tasks in sequence")
        if entry.is_symlink():
            refuse(f"holds {entry.name} as a link (the sessions would write through it)")
        if entry.name.startswith("task-") and not entry.is_dir():
            refuse(f"holds {entry.name} as a file, not a task's session folder")
    record = out / "library.json"
    if record.exists():
        try:
            earlier = [t.get("task") for t in json.loads(record.read_text(encoding="utf-8"))["tasks"]]
        except (OSError, ValueError, KeyError, TypeError, AttributeError):
            refuse("holds a library.json that is not a teaching of tasks in sequence")
            return
        if earlier != [p.name for p in problems]:
            refuse(f"holds a teaching of other tasks ({', '.join(map(str, earlier))})")


def _entries(out: Path, whose: str) -> list[Path]:
    """What ``out`` holds (nothing when it does not exist yet); a file, a link loop or a folder the OS refuses is
    the output error (exit 40)."""
    from guided_lfd.errors import Location, OutputError

    try:
        if not out.exists():
            return []
        if not out.is_dir():
            raise OutputError(f"is a file, expected a folder for {whose}", Location(str(out)))
        return sorted(out.iterdir())
    except (OSError, RuntimeError) as exc:  # a link loop, a folder the OS refuses
        raise OutputError(f"cannot use it as the folder for {whose} ({getattr(exc, 'strerror', None) or exc})",
                          Location(str(out))) from None


def check_session_folder(out: Path, problem: Problem) -> None:
    """Refuse (exit 40), before any work, a session folder that is neither new, nor empty, nor a previous session
    of the same task (which :func:`replacing_previous_session` then replaces whole).

    Nothing the user had is overwritten: a folder holding other files, or a link where the session writes (a
    ``robot.pddl`` linking to the robot's own domain), is refused."""
    from guided_lfd.errors import Location, OutputError

    def refuse(why: str) -> None:
        raise OutputError(f"{why}; expected a new or empty folder, or a previous session of this task",
                          Location(str(out)))

    entries = _entries(out, "the session")
    for entry in entries:
        ours = entry.name in SESSION_FILES or (entry.name.startswith("round-") and entry.name[6:].isdigit())
        if not ours:
            refuse(f"holds {entry.name}, which is no file of a teaching session")
        if entry.is_symlink():
            refuse(f"holds {entry.name} as a link (the session would write through it)")
    if entries:
        _check_same_task(out, problem, refuse)


def _check_same_task(out: Path, problem: Problem, refuse) -> None:
    """A previous session in ``out`` must be of ``problem``: the same PDDL problem name (its session.json's
    ``task``) and problem file name (the recorded path may be relative to another working folder).  A session
    without a session.json was interrupted before its end."""
    import json

    record = out / "session.json"
    if not record.exists():
        return  # a session that ended before writing it (interrupted): its rounds are replaced
    try:
        doc = json.loads(record.read_text(encoding="utf-8"))
        earlier, task = Path(doc["problem"]), doc.get("task")
    except (OSError, ValueError, KeyError, TypeError):
        refuse("holds a session.json that is not a teaching session's")
        return
    if task is not None and problem.name and task != problem.name:
        refuse(f"holds a session of another task ({task})")
    if problem.path and earlier.name != Path(problem.path).name:
        refuse(f"holds a session of another task ({earlier})")


@contextmanager
def replacing_previous_session(out: Path, was_there: bool = True) -> Iterator[None]:
    """Set aside what a previous session of the task left in ``out`` (checked by :func:`check_session_folder`)
    while the new one runs: it is deleted when the new one ends, and put back as it was if the new one fails
    or is interrupted (an error, Ctrl-C, SIGTERM), so such a run loses nothing and leaves nothing (``was_there``:
    whether ``out`` existed before the run; if not, it is removed again).  A previous session the OS will not
    let us move is the output error (exit 40), with nothing moved."""
    import shutil

    aside = _set_aside(out)
    try:
        yield
    except BaseException:
        _put_back(out, aside, was_there)
        raise
    if aside is not None:
        shutil.rmtree(aside, ignore_errors=True)


def _set_aside(out: Path) -> Path | None:
    """Move the previous session's entries in ``out`` into a new hidden folder beside it (None: nothing there)."""
    import tempfile

    from guided_lfd.errors import Location, OutputError

    moved: list[Path] = []
    aside: Path | None = None
    try:
        previous = sorted(out.iterdir()) if out.is_dir() else []
        if not previous:
            return None
        aside = Path(tempfile.mkdtemp(prefix=f".{out.name}.previous-", dir=out.parent))
        for entry in previous:
            entry.rename(aside / entry.name)
            moved.append(entry)
    except BaseException as exc:  # an OS refusal, or Ctrl-C/SIGTERM part-way: move back what was moved
        for entry in moved:
            (aside / entry.name).rename(entry)
        if aside is not None:
            aside.rmdir()
        if not isinstance(exc, OSError):
            raise
        raise OutputError(f"cannot set the previous session aside ({exc.strerror or exc}); nothing was changed",
                          Location(str(out))) from None
    return aside


def _put_back(out: Path, aside: Path | None, was_there: bool) -> None:
    """Undo a failed run: remove what it made in ``out``, return the previous session from ``aside``."""
    import shutil

    for entry in out.iterdir() if out.is_dir() else []:
        shutil.rmtree(entry) if entry.is_dir() and not entry.is_symlink() else entry.unlink()
    if aside is not None:
        for entry in aside.iterdir():
            entry.rename(out / entry.name)
        aside.rmdir()
    elif not was_there and out.is_dir():
        out.rmdir()


def make_folder(folder: Path) -> Path:
    """``folder``, created if need be; one the OS refuses is the output error (exit 40)."""
    from guided_lfd.errors import Location, OutputError

    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot make the session folder ({exc.strerror or exc})", Location(str(folder))) from None
    return folder

