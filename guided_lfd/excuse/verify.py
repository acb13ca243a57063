"""Minimality re-verified by enumeration (``excuse --verify``).

The searches prove an excuse minimal with lower bounds; this check does not
trust them.  Every change set cheaper than the excuse (within ``--max-size``,
over the atoms the checker itself takes as changeable: every type-correct atom
of a predicate that is neither fixed nor derived) is built and refused one by
one: its state satisfies the goal, breaks a law the checker derived
(:mod:`guided_lfd.excuse.laws`), or pyperplan's A* (another planner than the
engine's) proves the goal unreachable from it.  Tasks with more than
:data:`MAX_VERIFIED_SETS` such sets are not enumerated and say so.
"""

from __future__ import annotations

import time
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from guided_lfd.excuse.change import Change
from guided_lfd.excuse.check import change_cost, check_excuse
from guided_lfd.excuse.laws import WorldLaws
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.planning.task import GroundAction
from guided_lfd.planning.validation import plan_steps, validated

__all__ = ["MAX_VERIFIED_SETS", "MinimalityCheck", "verify_minimal"]

#: More cheaper change sets than this: minimality is not re-verified (the statistics say so).
MAX_VERIFIED_SETS = 5000


@dataclass(frozen=True)
class MinimalityCheck:
    """The outcome: ``verified`` (no cheaper excuse exists), ``too-many`` (more than the cap, not enumerated)
    or ``timeout``; ``sets`` counted; ``smaller`` a cheaper excuse the search missed (a bug), if found."""

    outcome: str
    sets: int
    smaller: list[Change] | None = None


def verify_minimal(domain: Domain, problem: Problem, cost: int, laws: WorldLaws | None, fixed: Sequence[str],
                   costs: Sequence[str], max_size: int | None = None, deadline: float | None = None,
                   cap: int = MAX_VERIFIED_SETS) -> MinimalityCheck:
    """Whether no change set cheaper than ``cost`` is an excuse (see the module's description)."""
    from guided_lfd.planning.grounding import ground
    from guided_lfd.planning.task import ground_atoms

    skip = set(fixed) | domain.derived_predicates()
    atoms = ground_atoms(domain, problem, skip=skip)
    weights = [change_cost([Change(a, a not in problem.init)], costs) for a in atoms]
    limit = len(atoms) if max_size is None else max_size
    sets = list(_cheaper_sets(weights, cost, limit, cap + 1))
    if len(sets) > cap:
        return MinimalityCheck("too-many", len(sets))
    task = ground(domain, problem, fixed=fixed)
    # pyperplan takes plain STRIPS operators with unique names (an ADL task's disjunctions split into several).
    search = "astar-lmcut" if domain.is_adl or problem.goal_condition is not None else "pyperplan-astar-lmcut"
    for count, chosen in enumerate(sets, 1):
        if deadline is not None and time.monotonic() > deadline:
            return MinimalityCheck("timeout", count - 1)
        changes = [Change(atoms[i], atoms[i] not in problem.init) for i in chosen]
        if _is_excuse(task, problem, changes, laws, search, deadline):
            return MinimalityCheck("verified", count, changes)
    return MinimalityCheck("verified", len(sets))


def _cheaper_sets(weights: list[int], cost: int, max_size: int, stop: int) -> Iterator[tuple[int, ...]]:
    """Index sets of total weight below ``cost`` and at most ``max_size`` members, at most ``stop`` of them."""
    found = 0
    stack: list[tuple[int, tuple[int, ...], int]] = [(0, (), 0)]
    while stack and found < stop:
        start, chosen, weight = stack.pop()
        yield chosen
        found += 1
        if len(chosen) == max_size:
            continue
        for i in range(len(weights) - 1, start - 1, -1):
            if weight + weights[i] < cost:
                stack.append((i + 1, chosen + (i,), weight + weights[i]))


def _is_excuse(task, problem: Problem, changes: list[Change], laws: WorldLaws | None, search: str,
               deadline: float | None) -> bool:
    """Whether ``changes`` make an excuse state: not the goal, keeping the laws, the goal reachable from it."""
    from guided_lfd.planning import find_plan

    state: set[Atom] = set(problem.init)
    for change in changes:
        (state.add if change.added else state.discard)(change.atom)
    if laws is not None and laws.broken(frozenset(state)):
        return False
    mask = 0
    for atom in state:
        # The translator's grounding compiles fixed static atoms into the actions: they have no index.
        if atom in task.index:
            mask |= 1 << task.index[atom]
    mask = task.close(mask)
    if changes and task.satisfies_goal(mask):
        return False
    left = None if deadline is None else max(0.001, deadline - time.monotonic())
    return find_plan(task, init=mask, search=search, time_limit_s=left).plan is not None


def verify_excuse(domain: Domain, problem: Problem, changes: list[Change], plan: list[GroundAction],
            laws: WorldLaws | None = None, fixed: Sequence[str] = (), costs: Sequence[str] | None = None,
            cost: int | None = None) -> None:
    """Refuse to return an excuse the independent checker rejects (a bug); ``cost`` is the search's, which the
    checker recomputes from the ``--cost`` specifications ``costs``, ``laws`` the checker's own invariants."""
    steps = plan_steps(plan)
    if not changes:
        validated(domain, problem, steps, "the robot plan")
        return
    problems = check_excuse(domain, problem, changes, steps, laws, fixed, costs, cost)
    if problems:
        raise RuntimeError("internal check failed for excuse " + " ".join(map(str, changes)) + ": " + "; ".join(problems))
