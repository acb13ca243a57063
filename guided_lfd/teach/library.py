"""Teaching a sequence of tasks: each starts from the skill library the earlier ones left.

The robot's skills are its library: what a task taught serves the next.  Each task is taught by
:func:`~guided_lfd.teach.loop.teach` in its own folder (``task-1/``, ``task-2/``, ...), starting from the
robot's domain the previous task left, read back from its ``robot.pddl`` (with each learned skill's evidence,
so that a skill shown again in another situation generalises, and a precondition the teacher confirmed stays).
A task therefore asks only for what the library still lacks: nothing when its skills already plan it, a skill
once more where one was learned too narrowly, a demonstration where one is missing.  ``library.json``
(format ``guided-lfd/teach-library``) records per task what was asked and learned; ``robot.pddl`` is the
library at the end.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.model import Domain, Problem
from guided_lfd.teach.folder import check_library_folder, make_folder, replacing_previous_session
from guided_lfd.teach.loop import teach
from guided_lfd.teach.session import Demonstrator, TeachSession

__all__ = ["LIBRARY_VERSION", "TeachLibrary", "teach_tasks"]

#: ``library.json``'s format version.
LIBRARY_VERSION = 1


@dataclass
class TeachLibrary:
    """A sequence of teaching sessions over one robot's growing skill library."""

    robot: str  # the robot's domain before the first task
    sessions: list[TeachSession] = field(default_factory=list)
    folders: list[str] = field(default_factory=list)
    robot_domain: str = ""  # the library after the last task

    @property
    def solved(self) -> bool:
        """Whether the robot plans every task at the end of its session."""
        return all(s.solved for s in self.sessions)

    def to_dict(self) -> dict[str, Any]:
        """The body of ``library.json``: per task its folder, status, what was asked and what was learned."""
        tasks = []
        for session, folder in zip(self.sessions, self.folders):
            rounds = session.rounds
            tasks.append({
                "problem": session.problem, "task": session.task, "folder": folder, "status": session.status,
                "solved": session.solved, "plans_original_task": session.plans_original_task,
                "rounds": len(rounds),
                "demonstrations": sum(r.demonstration_length is not None for r in rounds),
                "demonstrated_actions": sum(r.demonstration_length or 0 for r in rounds),
                "skill_requests": [str(r.skill.step) for r in rounds if r.skill is not None],
                "answers": [r.answer for r in rounds if r.answer],
                "learned_actions": sorted({name for r in rounds for name in r.learned_actions}),
                "reason": session.reason,
            })
        return {"robot": self.robot, "solved": self.solved, "tasks": tasks, "robot_domain": self.robot_domain}

    def to_json(self) -> str:
        """The ``library.json`` document."""
        return json_document("teach-library", self.to_dict(), version=LIBRARY_VERSION)

    def to_markdown(self) -> str:
        """``library.md``: one line per task, as a person reads the sequence."""
        lines = [f"# Teaching {len(self.sessions)} task(s) in sequence", "", f"Robot: `{self.robot}`; library at "
                 f"the end: `{self.robot_domain}`.", ""]
        for k, task in enumerate(self.to_dict()["tasks"], 1):
            asked = f"{task['demonstrations']} demonstration(s)"
            if task["skill_requests"]:
                asked += f", skill(s) shown once more: {', '.join(task['skill_requests'])}"
            if task["answers"]:
                asked += f", answered: {'; '.join(task['answers'])}"
            lines.append(f"{k}. `{task['problem']}`: **{task['status']}** in {task['rounds']} round(s); asked "
                         f"{asked}; learned {', '.join(task['learned_actions']) or 'nothing'} "
                         f"(see `{task['folder']}/session.md`)")
        return "\n".join(lines) + "\n"


def teach_tasks(robot: Domain, problems: list[Problem], demonstrator: Demonstrator, out: Path,
                **options: Any) -> TeachLibrary:
    """Teach ``problems`` in order, each in ``out/task-K`` from the library the earlier ones left (see the
    module's doc); ``options`` are :func:`~guided_lfd.teach.loop.teach`'s.  Every task is taught, whatever the
    earlier ones ended with; ``out/robot.pddl`` is the library at the end."""
    from guided_lfd.errors import OptionError
    from guided_lfd.pddl.reader import parse_domain

    if not isinstance(problems, list) or not problems or not all(isinstance(p, Problem) for p in problems):
        raise OptionError("problems: expected a non-empty list of Problems")
    out = Path(out)
    check_library_folder(out, problems)  # before any work: nothing the user had is written over
    was_there = out.exists()
    make_folder(out)
    library = TeachLibrary(robot.path)
    with replacing_previous_session(out, was_there):  # a previous teaching of these tasks is replaced whole
        current = robot
        for k, problem in enumerate(problems, 1):
            folder = out / f"task-{k}"
            session = teach(current, problem, demonstrator, folder, **options)
            write_text(folder / "session.json", session.to_json())
            write_text(folder / "session.md", session.to_markdown())
            library.sessions.append(session)
            library.folders.append(str(folder))
            current = parse_domain(session.robot_domain)  # as its file carries it: the evidence comments included
        _write_library(library, out)
    return library


def _write_library(library: TeachLibrary, out: Path) -> None:
    """The library at the end (``robot.pddl``), ``library.json`` and ``library.md``."""
    library.robot_domain = str(out / "robot.pddl")
    write_text(out / "robot.pddl", Path(library.sessions[-1].robot_domain).read_text())
    write_text(out / "library.json", library.to_json())
    write_text(out / "library.md", library.to_markdown())
