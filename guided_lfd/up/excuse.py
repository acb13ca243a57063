"""The minimal excuse of a unified-planning problem, in UP's terms.

guided-lfd's excuse engine (:func:`guided_lfd.find_excuses`) runs on the
task :func:`guided_lfd.up.to_task` reads; each excuse's changes come back as
fluent expressions of the UP problem (``open(pinkdrawer)``) and the robot's
plan from the excuse state as a ``SequentialPlan`` of the problem's actions.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field, replace
from typing import Iterable

from unified_planning.exceptions import UPException
from unified_planning.model import FNode, Fluent, Problem as UPProblem
from unified_planning.plans import SequentialPlan

from guided_lfd.errors import OptionError
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.report import Excuse, ExcuseReport
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.up.task import UpTask, to_task

__all__ = ["UpExcuse", "UpExcuseReport", "find_up_excuses"]


@dataclass
class UpExcuse:
    """A minimal excuse: the facts to make true and false in the initial state, and the robot's plan from there."""

    #: Fluent expressions (``open(pinkdrawer)``) the excuse makes true, and those it makes false.
    added: list[FNode]
    removed: list[FNode]
    #: The robot's plan from the excuse state (validated by guided-lfd).
    plan: SequentialPlan
    #: guided-lfd's excuse, in the PDDL names of :attr:`UpExcuseReport.task`.
    excuse: Excuse = field(repr=False)
    up_problem: UPProblem = field(repr=False)

    @property
    def size(self) -> int:
        """How many facts the excuse changes."""
        return len(self.added) + len(self.removed)

    @property
    def cost(self) -> int:
        """The excuse's cost: its size, or the sum of ``ExcuseOptions.costs`` weights."""
        return self.excuse.cost

    @property
    def plan_cost(self) -> int | None:
        """The plan's cost: its length, or its total action cost under the problem's metric."""
        return self.excuse.plan_cost

    @property
    def plan_optimal(self) -> bool:
        """Whether the plan is proven cost-optimal."""
        return self.excuse.plan_optimal

    def excuse_problem(self) -> UPProblem:
        """A copy of the UP problem that starts in the excuse state (what the human demonstrates reaching)."""
        copy = self.up_problem.clone()
        for fact in self.added:
            copy.set_initial_value(fact, True)
        for fact in self.removed:
            copy.set_initial_value(fact, False)
        return copy


@dataclass
class UpExcuseReport:
    """The result of :func:`find_up_excuses`: guided-lfd's report, and its excuses in UP's terms."""

    report: ExcuseReport
    task: UpTask
    excuses: list[UpExcuse]
    #: The robot's own plan when the problem is already solvable (no excuse needed), else None.
    robot_plan: SequentialPlan | None

    @property
    def status(self) -> ExcuseStatus:
        """How the search ended (``excuse-found``, ``already-solvable``, ``no-excuse``, ...)."""
        return self.report.status

    @property
    def excuse(self) -> UpExcuse | None:
        """The first minimal excuse, or None."""
        return self.excuses[0] if self.excuses else None

    def to_json(self) -> str:
        """The ``guided-lfd excuse --json`` document of the search (in the PDDL names)."""
        return self.report.to_json()


def find_up_excuses(problem: UPProblem, options: ExcuseOptions | None = None,
                    fixed: Iterable[Fluent] = ()) -> UpExcuseReport:
    """Minimal excuses of the UP ``problem`` (see :func:`guided_lfd.find_excuses`; ``options.time_limit``
    counts from this call, reading the problem included).

    ``fixed`` are fluents of the problem no excuse may change (facts the
    human cannot change either, such as which doors connect which rooms);
    they join ``options.fixed``, whose names, as those of ``options.costs``,
    are guided-lfd's (``to_task(problem).pddl_name(fluent)``).
    """
    options = options or ExcuseOptions()
    started = time.monotonic() if options.started is None else options.started
    task = to_task(problem)
    options = replace(options, started=started, fixed=[*options.fixed, *(_fluent_name(task, f) for f in fixed)])
    report = find_excuses(task.domain, task.problem, options)
    robot_plan = None if report.robot_plan is None else task.sequential_plan(report.robot_plan)
    return UpExcuseReport(report, task, [_up_excuse(task, e) for e in report.excuses], robot_plan)


def _fluent_name(task: UpTask, fluent: Fluent) -> str:
    """guided-lfd's name of a fluent of the task's problem (:class:`OptionError` for any other)."""
    try:
        return task.pddl_name(fluent)
    except UPException:
        raise OptionError(f"fixed: {fluent} is not a fluent of problem '{task.up_problem.name}'") from None


def _up_excuse(task: UpTask, excuse: Excuse) -> UpExcuse:
    """``excuse`` in UP's terms."""
    added = [task.expression(c.atom) for c in excuse.changes if c.added]
    removed = [task.expression(c.atom) for c in excuse.changes if not c.added]
    return UpExcuse(added, removed, task.sequential_plan(excuse.plan), excuse, task.up_problem)
