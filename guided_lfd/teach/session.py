"""A teaching session's model and its documents: who demonstrates, each round, the whole session.

:class:`TeachSession` is what ``session.json`` (format ``guided-lfd/teach``)
and ``session.md`` hold; :class:`Round` one round of it; a
:class:`Demonstrator` is whoever gives the demonstrations.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from guided_lfd.excuse.change import Change
from guided_lfd.io import json_document
from guided_lfd.pddl.model import Atom, Problem
from guided_lfd.planning.validation import PlanStep

__all__ = ["SESSION_VERSION", "Demonstrator", "Round", "TeachSession"]

#: ``session.json``'s format version: 2 added each round's ``outcome``, ``outcome_reason``, ``check`` and
#: ``asked_again`` (issue #52); a version-1 session folder is still read back (its task, to replace it).
#: 3 added ``skill_request`` (a round asking for a skill once more, from a skill excuse) and ``answer`` (the
#: teacher's "cannot be done there").
SESSION_VERSION = 3


class Demonstrator(Protocol):
    """Whoever demonstrates: given the round's folder, the world's state and the request, a hand trace.

    A demonstrator may also have a ``why_none(state, request, problem) -> str`` method: asked after
    ``demonstrate`` gave None, it says why in one line (the session's ``reason``).
    """

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """(trace CSV, state CSV) of the demonstration, or None when there is none to give."""
        ...


@dataclass
class Round:
    """One round of teaching: what was asked, why, what came of it."""

    index: int
    excuse: list[Change]
    request: list[Change]
    request_text: list[str]
    why: list[str]
    keep: list[Atom]
    keep_text: list[str]
    demonstration_length: int | None = None  # demonstrated actions (segments that act)
    new_actions: int | None = None  # of those, the ones no skill of the robot already does (the useful part)
    learned_actions: list[str] = field(default_factory=list)
    request_met: bool | None = None
    unmet: list[Change] = field(default_factory=list)  # the request's changes the demonstration did not make
    solvable_after: bool | None = None
    files: dict[str, str] = field(default_factory=dict)
    preference: str | None = None  # why this excuse among the minimal ones (--prefer demonstration)
    error: str | None = None  # why the demonstration could not be used (it ended the session)
    vocabulary: str | None = None  # the hand facts the demonstration was learned in, and where they came from
    #: the demonstration checked against the request (a teach.check.DemonstrationCheck): its outcome and why
    check: Any = None
    asked_again: list[str] = field(default_factory=list)  # the request reworded after the last demonstration
    held: str = ""  # what the round's excuse held fixed and why, in one line (said to the teacher, not stored)
    #: A round from a skill excuse: the skill to show again and where (a teach.skill_request.SkillRequest).
    skill: Any = None
    answer: str | None = None  # the teacher's answer instead of a demonstration: the skill cannot be done there

    @property
    def outcome(self) -> str | None:
        """The demonstration's outcome (accepted, partial, misdirected, unhelpful, inconsistent), or None."""
        return None if self.check is None else self.check.outcome

    def excuse_text(self) -> str | None:
        """How the request relates to the minimal excuse when it asks for only part of it, else None."""
        if not self.excuse or self.request == self.excuse:
            return None
        return (f"the minimal excuse is {' '.join(str(c) for c in self.excuse)}; the request is the part of it "
                "that suffices")

    def to_dict(self) -> dict[str, Any]:
        """The round as ``session.json`` has it."""
        return {
            "round": self.index, "excuse": [str(c) for c in self.excuse], "request": [str(c) for c in self.request],
            "request_text": self.request_text, "why": self.why, "keep": [str(a) for a in self.keep],
            "keep_text": self.keep_text, "demonstration_length": self.demonstration_length,
            "new_actions": self.new_actions,
            "learned_actions": self.learned_actions, "request_met": self.request_met,
            "unmet": [str(c) for c in self.unmet], "solvable_after": self.solvable_after, "files": self.files,
            "preference": self.preference, "error": self.error, "vocabulary": self.vocabulary,
            "asked_again": self.asked_again, "outcome": self.outcome,
            "outcome_reason": None if self.check is None else self.check.reason,
            "check": None if self.check is None else self.check.to_dict(),
            "skill_request": None if self.skill is None else self.skill.to_dict(), "answer": self.answer,
        }


@dataclass
class TeachSession:
    """A whole teaching session: its rounds, how it ended, and the robot's plan at the end."""

    robot: str
    problem: str
    #: solved | already-solvable | demonstration-only | no-excuse | no-demonstration | bad-demonstration
    #: | max-rounds | timeout
    status: str
    rounds: list[Round]
    plan: list[PlanStep] | None  # the robot's plan from the state the session ended in
    plans_original_task: bool | None  # whether the taught robot plans the task from its original state
    robot_domain: str  # the taught domain's file
    error: Any = field(default=None, repr=False, compare=False)  # the GuidedLfdError that ended it, if any
    reason: str | None = None  # why it ended unsolved, in one line (None when solved)
    task: str | None = None  # the problem's PDDL name: a later session in the folder must be of the same task

    @property
    def solved(self) -> bool:
        """Whether the robot can plan the task at the end."""
        return self.status in ("solved", "already-solvable")

    def to_dict(self) -> dict[str, Any]:
        """The body of ``session.json`` (format ``guided-lfd/teach``, version :data:`SESSION_VERSION`)."""
        return {"robot": self.robot, "problem": self.problem, "solved": self.solved, "status": self.status,
                "rounds": [r.to_dict() for r in self.rounds],
                "plan": None if self.plan is None else [str(s) for s in self.plan],
                "plans_original_task": self.plans_original_task, "robot_domain": self.robot_domain,
                "reason": self.reason, "task": self.task}

    def to_json(self) -> str:
        """The ``session.json`` document."""
        return json_document("teach", self.to_dict(), version=SESSION_VERSION)

    def to_markdown(self) -> str:
        """``session.md``: the rounds as a person reads them."""
        lines = [f"# Teaching session: {self.problem}", "", f"Robot: `{self.robot}`; status: **{self.status}**.", ""]
        if self.reason:
            lines += [f"Why: {self.reason}.", ""]
        for r in self.rounds:
            lines += [f"## Round {r.index}", "", "Request: " + "; ".join(r.request_text) + ".", ""]
            lines += [f"- asked again: {line}" for line in r.asked_again]
            if not r.excuse and r.skill is None:
                lines.append("- no excuse exists: a new skill that makes this true must be demonstrated")
            elif r.excuse_text():
                lines.append(f"- {r.excuse_text()}")
            if r.preference:
                lines.append(f"- {r.preference}")
            lines += [f"- why: {w}" for w in r.why]
            if r.keep_text:
                lines.append("- leave as it is: " + "; ".join(r.keep_text))
            lines.append(f"- demonstrated actions: {r.demonstration_length if r.demonstration_length is not None else '-'}"
                         f"; learned: {', '.join(r.learned_actions) or '-'}")
            if r.vocabulary:
                lines.append(f"- hand facts: {r.vocabulary}")
            if r.error:
                lines.append(f"- the demonstration could not be used: {r.error}")
            if r.request_met is False:
                lines.append("- the demonstration did not make: " + ", ".join(str(c) for c in r.unmet))
            if r.skill is not None and r.skill.robot_first:
                lines.append("- the robot first did, itself: " + ", ".join(f"`{s}`" for s in r.skill.robot_first))
            if r.answer:
                lines.append(f"- the teacher answered: {r.answer}; the precondition is confirmed")
            if r.check is not None:
                lines.append(f"- outcome: **{r.check.outcome}**: {r.check.reason}")
            lines.append("")
        if self.plan is not None:
            lines += ["## The robot's plan", ""] + [f"{i}. `{s}`" for i, s in enumerate(self.plan, 1)] + [""]
        return "\n".join(lines)

