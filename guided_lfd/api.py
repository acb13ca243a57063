"""The library's front door: read a task, plan, validate (excuses: :mod:`guided_lfd.excuse.engine`).

A robot program imports these from :mod:`guided_lfd` (see
``docs/python.md``); the command line is a thin layer over the
same calls, so a program gets exactly what ``guided-lfd`` prints.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Sequence

from guided_lfd.deadline import checked_time_limit
from guided_lfd.errors import OptionError
from guided_lfd.pddl.model import Domain, Problem
from guided_lfd.planning.validation import PlanStep, ValidationReport

__all__ = ["PlanReport", "plan", "read_task", "validate"]

#: What a file path or PDDL text may be given as.
Source = str | Path


def _is_text(source: Source) -> bool:
    """PDDL or plan text rather than a path: a string with a parenthesis or a line break in it, or nothing.

    File names with either are possible but rare; such a file can be given as a ``Path``.
    """
    return isinstance(source, str) and ("(" in source or "\n" in source or not source.strip())


def read_task(domain: Source, problem: Source | None = None) -> tuple[Domain, Problem]:
    """The task of a domain and a problem, each a path or PDDL text (``"(define (domain ..."``).

    :func:`guided_lfd.read_task` also takes a unified-planning ``Problem``
    alone (the extra ``up``): :mod:`guided_lfd.up` reads it, this module
    never imports it.  Raises the one-line
    :class:`~guided_lfd.errors.GuidedLfdError` of the command line
    (``file:line:col``; ``<domain>``/``<problem>`` for text).
    """
    if not isinstance(domain, (str, Path)):
        raise OptionError("read_task: expected a domain and a problem (paths or PDDL text), or a unified-planning "
                          f"Problem alone; got {type(domain).__name__}"
                          + ("" if problem is None else f" and {type(problem).__name__}"))
    if problem is None:
        raise OptionError("read_task: a domain needs its problem (a path or PDDL text)")
    if not isinstance(problem, (str, Path)):
        raise OptionError(f"read_task: expected the problem as a path or PDDL text, got {type(problem).__name__}")
    from guided_lfd.pddl.reader import parse_task

    # Text as a file would give it: without a byte-order mark.
    domain_text = domain.removeprefix("\ufeff") if _is_text(domain) else None  # type: ignore[union-attr]
    problem_text = problem.removeprefix("\ufeff") if _is_text(problem) else None  # type: ignore[union-attr]
    return parse_task("<domain>" if domain_text is not None else domain,
                      "<problem>" if problem_text is not None else problem,
                      domain_text=domain_text, problem_text=problem_text)


@dataclass
class PlanReport:
    """A validated plan (or a proof that there is none), as ``guided-lfd plan`` reports it."""

    domain: str
    problem: str
    #: The plan, validated on the lifted domain; None when the task is unsolvable.
    plan: list[PlanStep] | None
    #: Length, or total-cost under the problem's metric; None when unsolvable.
    cost: int | None
    optimal: bool | None
    search: str
    time_s: float
    #: What found the plan or proved there is none: the search, or ``symbolic`` (the default's prover).
    answered_by: str = ""

    @property
    def solved(self) -> bool:
        """Whether a plan was found."""
        return self.plan is not None

    def to_dict(self) -> dict[str, Any]:
        """The body of the ``guided-lfd/plan`` document (the same keys for both statuses)."""
        return {
            "domain": self.domain, "problem": self.problem, "status": "solved" if self.solved else "unsolvable",
            "plan": None if self.plan is None else [str(s) for s in self.plan],
            "cost": self.cost, "optimal": self.optimal, "validated": True if self.solved else None,
            "search": self.search, "answered_by": self.answered_by or self.search, "time_s": round(self.time_s, 4),
        }

    def to_json(self) -> str:
        """Exactly the document ``guided-lfd plan --json`` prints."""
        from guided_lfd.io import json_document

        return json_document("plan", self.to_dict())


def plan(domain: Domain, problem: Problem, search: str | None = None,
         time_limit: float | None = None) -> PlanReport:
    """An optimal plan for ``(domain, problem)`` (see :data:`guided_lfd.planning.SEARCHES`), validated.

    Raises :class:`~guided_lfd.errors.SearchTimeout` past ``time_limit``
    seconds, and :class:`RuntimeError` if the planner's plan does not
    validate or its cost disagrees with the validator's (a bug, never hidden).
    """
    from guided_lfd.planning import DEFAULT_SEARCH, SEARCHES
    from guided_lfd.symbolic.portfolio import validated_plan

    _check_task("plan", domain, problem)
    search = search or DEFAULT_SEARCH
    if not isinstance(search, str) or search not in SEARCHES:
        raise OptionError(f"unknown search {search!r} (expected one of: {', '.join(SEARCHES)})")
    result, steps, cost = validated_plan(domain, problem, search, checked_time_limit(time_limit, "time_limit"))
    if steps is None:
        return PlanReport(domain.path, problem.path, None, None, None, search, result.time_s, result.answered_by)
    return PlanReport(domain.path, problem.path, steps, cost, result.optimal, search, result.time_s,
                      result.answered_by)


def _check_task(call: str, domain: object, problem: object) -> None:
    """A domain and a problem of the wrong kind, as the documented :class:`~guided_lfd.errors.OptionError`."""
    for name, value, kind in (("domain", domain, Domain), ("problem", problem, Problem)):
        if not isinstance(value, kind):
            raise OptionError(f"{call}: expected the {name} as a {kind.__name__} (guided_lfd.read_task), got "
                              f"{type(value).__name__}")


def validate(domain: Domain, problem: Problem, plan: Source | Sequence[PlanStep | str]) -> ValidationReport:
    """Execute ``plan`` (a plan file, IPC plan text, or steps) from the initial state; cost included.

    Steps may be :class:`~guided_lfd.planning.validation.PlanStep` objects or strings
    such as ``"(drive home shop)"``; a bad step is a one-line
    :class:`~guided_lfd.errors.PlanFileError`, as on the command line.
    """
    from guided_lfd.planning.validation import parse_plan, parse_plan_text, validate_plan

    _check_task("validate", domain, problem)
    if not isinstance(plan, (str, Path, list, tuple)):
        raise OptionError(f"validate: expected the plan as a path, plan text or a list of steps, got "
                          f"{type(plan).__name__}")
    if isinstance(plan, Path) or (isinstance(plan, str) and not _is_text(plan)):
        steps = parse_plan(str(plan), domain, problem)
    elif isinstance(plan, str):
        steps = parse_plan_text(plan, "<plan>", domain, problem)
    else:
        text = "\n".join(str(step) for step in plan)
        steps = parse_plan_text(text, "<plan>", domain, problem)
    return validate_plan(domain, problem.init, problem.goal, steps, problem, problem.goal_condition)
