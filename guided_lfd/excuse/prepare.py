"""Ground a task, build its change space and the robot's reachability oracle: the one way it is done.

The excuse engine, the evaluation's "can the robot reach the goal from
here?" and the benchmark's "is this task unsolvable without the skill?" all
start here.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace, MutexGroup, Semantics, build_space
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.task import GroundTask
from guided_lfd.pddl.model import Domain, Problem

__all__ = ["PreparedTask", "prepare"]


@dataclass
class PreparedTask:
    """A ground task, the excuse changes it admits, and the oracle that answers reachability on it."""

    task: GroundTask
    groups: list[MutexGroup]
    space: ChangeSpace
    oracle: ReachabilityOracle
    #: Invariants left out because the task's goal breaks them (see :func:`~guided_lfd.excuse.invariants.mutex_groups`).
    refuted: list[str] = field(default_factory=list)
    #: Placing predicates whose objects the consistent semantics keeps in at most one place (``one_place``).
    kept_in_one_place: list[str] = field(default_factory=list)


def prepare(domain: Domain, problem: Problem, semantics: Semantics = Semantics.LITERAL, fixed: Sequence[str] = (),
            costs: Sequence[str] = (), invariants_from: Domain | None = None, deadline: float | None = None,
            on_phase: Callable[[str], None] | None = None, one_place: bool = False) -> PreparedTask:
    """Ground ``problem`` (``fixed`` predicates' static atoms pruned), synthesise invariants for the
    consistent semantics (from ``invariants_from``, else ``domain``), build the change space and the oracle.
    ``one_place``: the consistent semantics also keeps in at most one place what the invariants' source places
    without moving it (:func:`~guided_lfd.excuse.structure.placing_predicates`).

    ``on_phase`` hears each phase's name as it begins (for a timed-out run's report).
    """
    task = ground(domain, problem, fixed=fixed, deadline=deadline)
    groups: list[MutexGroup] = []
    refuted: list[str] = []
    kept: list[str] = []
    if semantics is Semantics.CONSISTENT and not task.satisfies_goal(task.init):
        if on_phase:
            on_phase("invariant synthesis")
        from guided_lfd.excuse.invariants import mutex_groups

        groups = mutex_groups(invariants_from or domain, task, deadline, refuted)
        if one_place:
            from guided_lfd.excuse.invariants import placement_groups
            from guided_lfd.excuse.structure import placing_predicates

            placing = placing_predicates(invariants_from or domain, problem)
            groups, kept = placement_groups(task, placing, groups, refuted)
    if on_phase:
        on_phase("change space")
    space = build_space(task, semantics, list(fixed), list(costs), groups)
    return PreparedTask(task, groups, space, ReachabilityOracle(space, deadline), refuted, kept)
