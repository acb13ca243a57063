"""The answer of an excuse search: its excuses and how the run ended (data; the renderers read it).

The report's documents are made by :mod:`guided_lfd.excuse.document` (JSON
and text), :mod:`guided_lfd.excuse.picture` and :mod:`guided_lfd.excuse.svg`
(the picture), which know the report only as the type of what they read; its
``to_*`` methods call them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from guided_lfd.excuse.change import Change, SkillChange
from guided_lfd.excuse.space import MutexGroup, Semantics
from guided_lfd.excuse.statistics import ExcuseStatistics
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.pddl.model import Atom, Domain, Literal, Problem
from guided_lfd.planning.validation import PlanStep


@dataclass
class Excuse:
    """A minimal excuse: the changes, the excuse state and the robot's plan from it."""

    changes: list[Change]
    cost: int
    state: frozenset[Atom]
    #: The robot's plan from the excuse state (validated), step by step.
    plan: list[PlanStep]
    plan_optimal: bool
    #: The plan's cost: its length, or its total-cost under the problem's metric (:action-costs).
    plan_cost: int | None = None
    #: False for a timed-out run's best candidate (``ExcuseReport.best_candidate``) whose cost does not meet
    #: the proven lower bound.
    proven_minimal: bool = True
    #: Learned preconditions the excuse drops (skill changes, :mod:`guided_lfd.excuse.skills`); the plan is the
    #: robot's with them dropped.
    skill_changes: list[SkillChange] = field(default_factory=list)

    @property
    def size(self) -> int:
        return len(self.changes) + len(self.skill_changes)


@dataclass
class ExcuseReport:
    """Result of :func:`find_excuses`."""

    status: ExcuseStatus
    excuses: list[Excuse]
    semantics: Semantics
    strategy: str
    statistics: ExcuseStatistics
    unachievable_goals: list[Literal]
    invariant_groups: list[MutexGroup]
    robot_plan: list[PlanStep] | None = None  # when the task is already solvable
    robot_plan_cost: int | None = None  # the cost of ``robot_plan`` (see Excuse.plan_cost)
    #: Why the first excuse was chosen among the minimal ones (:func:`guided_lfd.preference.apply_preference`).
    preference: str | None = None
    #: The task asked about (its paths and spellings go into the document).
    domain: Domain | None = field(default=None, repr=False)
    problem: Problem | None = field(default=None, repr=False)
    #: A timed-out run: the cheapest excuse found (checked like every excuse), usually not proven minimal.
    best_candidate: Excuse | None = None
    #: Every change costs 1 (no ``--cost``): a cost is a number of changes.
    unit_costs: bool = True
    #: The run's ``max_size`` (a lower bound speaks of the excuses within it).
    max_size: int | None = None
    #: ``--slack`` the run had (its list holds excuses up to this much costlier than the minimum).
    slack: int = 0

    @property
    def excuse(self) -> Excuse | None:
        """The first minimal excuse, or None."""
        return self.excuses[0] if self.excuses else None

    @property
    def spellings(self) -> dict[str, str]:
        """Names as the files write them (the domain's spelling of a predicate wins)."""
        if self.domain is None or self.problem is None:
            return {}
        return {**self.problem.spellings, **self.domain.spellings}

    def to_dict(self) -> dict[str, Any]:
        """The body of the ``guided-lfd/excuse`` document, as ``guided-lfd excuse --json`` writes it."""
        from guided_lfd.excuse.document import excuse_document

        domain = self.domain.path if self.domain is not None else "<domain>"
        problem = self.problem.path if self.problem is not None else "<problem>"
        return excuse_document(self, domain, problem, self.spellings)

    def to_json(self) -> str:
        """Exactly the document ``guided-lfd excuse --json`` prints (format and version included)."""
        from guided_lfd.io import json_document

        return json_document("excuse", self.to_dict())

    def to_text(self) -> str:
        """The report as ``guided-lfd excuse`` prints it for people."""
        from guided_lfd.excuse.document import excuse_text

        if self.problem is None:
            raise ValueError("a report made without its problem has no text form")
        return excuse_text(self, self.problem, self.spellings)

    def to_svg(self) -> str:
        """The first excuse as a picture, SVG: the initial state and the excuse state side by side, the changed
        facts marked (what ``guided-lfd excuse --svg`` writes; see :mod:`guided_lfd.excuse.picture`)."""
        from guided_lfd.excuse.picture import excuse_scene
        from guided_lfd.excuse.svg import scene_svg

        return scene_svg(excuse_scene(self))

    def to_dot(self) -> str:
        """The same picture as Graphviz DOT text (what ``guided-lfd excuse --dot`` writes)."""
        from guided_lfd.excuse.picture import excuse_scene, scene_dot

        return scene_dot(excuse_scene(self))
