"""Skill excuses: a learned precondition that was never tested, relaxed as one more kind of change.

A skill learned from demonstrations requires everything that held in all of
them (never more general than shown).  Some of those preconditions are
coincidences of the situations shown (``(ontable ?y)`` when every block was
taken off a block standing on the table).  When the robot cannot plan a task,
dropping such a precondition is a change beside the state changes: a skill
excuse, ``-(ontable ?y) in unstack``, which means "show me unstack once more,
where that is false".  A precondition may be dropped when its evidence says it
was never tested (:attr:`~guided_lfd.pddl.model.Evidence.untested`: held in
every demonstration, never refused by the teacher); the user's own skills
(no evidence) only with ``relax_prior``.

Each dropped precondition costs 1, like a state change without ``--cost``.
The minimal excuse over both kinds is found by enumerating the sets of dropped
preconditions by size and asking the state-excuse engine, on the domain with
those preconditions dropped, for the cheapest state changes that remain,
bounded by the best total so far.  The domain with every relaxable
precondition dropped gives a lower bound on the state part, which ends the
enumeration early.  Ties go to the excuse with fewer skill changes (a state
change asks for a demonstration the robot will certainly use; a skill change
asks a question the teacher may refuse).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from itertools import combinations
from typing import TYPE_CHECKING, Callable, Sequence

from guided_lfd.excuse.change import SkillChange
from guided_lfd.excuse.report import Excuse, ExcuseReport
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.pddl.model import EQUALITY, Domain

if TYPE_CHECKING:  # the engine's options; the engine calls this module, never the other way round
    from guided_lfd.excuse.engine import ExcuseOptions

__all__ = ["SKILL_CHANGE_COST", "relaxable_preconditions", "relaxed_domain", "minimal_over_skills"]

#: What dropping one learned precondition costs (a state change costs 1 without ``--cost``).
SKILL_CHANGE_COST = 1

#: A state-excuse search on a domain with some preconditions dropped: (domain, options) -> its report.
StateSearch = Callable[[Domain, "ExcuseOptions"], ExcuseReport]


def relaxable_preconditions(domain: Domain, relax_prior: bool = False) -> list[SkillChange]:
    """The preconditions a skill excuse may drop: a learned action's untested ones (its evidence says it held in
    every demonstration and the teacher never refused the skill without it); with ``relax_prior``, every
    precondition of an action without evidence (the user's own skills) too.

    Never a precondition of an action that changes nothing (an operator no trajectory showed); nor one the action
    itself consumes (a positive one it deletes, a negative one it adds): the skill's effect on it was learned from
    its holding before (an effect needs its precondition, as in SAM's safe models); nor an equality."""
    out = []
    for action in domain.actions:
        if action.is_adl or not (action.add or action.delete):
            continue  # an action that changes nothing helps no plan, whatever it needs
        if action.evidence:
            required, _ = action.learned_evidence()
            literals = [e.literal for e in required if e.untested]
        else:
            literals = list(action.precondition) if relax_prior else []
        out += [SkillChange(action.name, lit) for lit in literals
                if lit.atom.predicate != EQUALITY and lit.atom not in (action.delete if lit.positive else action.add)]
    return out


def relaxed_domain(domain: Domain, changes: Sequence[SkillChange]) -> Domain:
    """``domain`` with the ``changes``' preconditions dropped from their actions (evidence kept)."""
    dropped: dict[str, set] = {}
    for change in changes:
        dropped.setdefault(change.action, set()).add(change.literal)
    if not dropped:
        return domain
    actions = [replace(a, precondition=tuple(l for l in a.precondition if l not in dropped[a.name]))
               if a.name in dropped else a for a in domain.actions]
    return replace(domain, actions=actions)


@dataclass
class _Best:
    """The cheapest excuse over both kinds so far: its skill changes and the state search's report for them."""

    total: float
    skills: tuple[SkillChange, ...] = ()
    report: ExcuseReport | None = None
    #: The time limit ended the enumeration: the best is an excuse, not proven minimal.
    cut_short: bool = False


def _state_cost(report: ExcuseReport) -> int | None:
    """The cheapest state part a state search found (0: the task is solvable as it is; None: no excuse)."""
    if report.status is ExcuseStatus.ALREADY_SOLVABLE:
        return 0
    return report.excuse.cost if report.excuse is not None else None


def minimal_over_skills(domain: Domain, options: "ExcuseOptions", search: StateSearch) -> ExcuseReport:
    """The minimal excuse over state changes and dropped learned preconditions (see the module's doc).

    ``search`` is the state-excuse engine.  Without relaxable preconditions, or when the state search alone is
    answered (already solvable, out of time), its report is the answer unchanged."""
    # One clock for every search below: the time limit bounds them all.
    options = replace(options, started=time.monotonic() if options.started is None else options.started)
    base = search(domain, options)
    candidates = relaxable_preconditions(domain, options.relax_prior)
    if not candidates or base.status in (ExcuseStatus.ALREADY_SOLVABLE, ExcuseStatus.TIMEOUT):
        return base
    # The invariants are the world's as the robot's skills say it (dropping a precondition makes no new world).
    quick = replace(options, all_minimal=False, optimal_plans=False, verify=False,
                    invariants_from=options.invariants_from or domain)
    everything = search(relaxed_domain(domain, candidates), quick)
    floor, searches = _state_cost(everything), 2
    cost = _state_cost(base)
    best = _Best(float("inf") if cost is None else cost, (), base, everything.status is ExcuseStatus.TIMEOUT)
    if floor is not None:
        searches += _enumerate(domain, candidates, floor, best, quick, search)
    base.statistics.skill_changes_relaxable, base.statistics.skill_searches = len(candidates), searches
    base.statistics.time_s = round(time.monotonic() - options.started, 4)  # the whole run, the skill searches in
    if best.cut_short:
        return _cut_short(base, best)
    if not best.skills:
        return base
    return _skill_report(domain, options, best, search, base)


def _state_parts(report: ExcuseReport, base: ExcuseReport) -> list[Excuse]:
    """A state search's excuses on a relaxed domain; one of no changes where the task was solvable as it is."""
    if report.status is not ExcuseStatus.ALREADY_SOLVABLE:
        return report.excuses
    init = base.problem.init if base.problem else frozenset()
    return [Excuse([], 0, init, report.robot_plan or [], False, report.robot_plan_cost)]


def _state_size(room: float, costs: bool, cap: int | None, skills: int) -> int | None:
    """The most state changes a search for the state part may return (None: no bound): with unit costs its cost
    ``room`` is its size; the user's ``max_size`` (``cap``) counts the ``skills`` dropped too."""
    size = None if costs or room == float("inf") else int(room)
    if cap is not None:
        size = cap - skills if size is None else min(size, cap - skills)
    return size


def _cut_short(base: ExcuseReport, best: _Best) -> ExcuseReport:
    """The time limit ended the search over skill changes: the best excuse so far, as a timed-out run's candidate
    (checked, not proven minimal)."""
    candidate = base.excuse
    parts = _state_parts(best.report, base) if best.skills and best.report is not None else []
    if parts:
        found = parts[0]
        candidate = Excuse(list(found.changes), int(best.total), found.state, found.plan, False, None, False,
                           list(best.skills))
    if candidate is not None:
        candidate = replace(candidate, proven_minimal=False)
    base.statistics.phase = "skill changes"
    return replace(base, status=ExcuseStatus.TIMEOUT, excuses=[], best_candidate=candidate)


def _enumerate(domain: Domain, candidates: list[SkillChange], floor: int, best: _Best, quick: "ExcuseOptions",
               search: StateSearch) -> int:
    """Try the sets of dropped preconditions by size while they can beat ``best`` (updated); the searches run."""
    runs, cap = 0, quick.max_size
    for k in range(1, len(candidates) + 1):
        if k * SKILL_CHANGE_COST + floor >= best.total or (cap is not None and k > cap):
            break
        for chosen in combinations(candidates, k):
            room = best.total - k * SKILL_CHANGE_COST - 1  # the costliest state part that still beats the best
            if room < floor:
                break
            size = _state_size(room, bool(quick.costs), cap, k)
            report = search(relaxed_domain(domain, chosen), replace(quick, max_size=size))
            runs += 1
            if report.status is ExcuseStatus.TIMEOUT:
                best.cut_short = True
                return runs
            cost = _state_cost(report)
            if cost is not None and cost + k * SKILL_CHANGE_COST < best.total:
                best.total, best.skills, best.report = cost + k * SKILL_CHANGE_COST, chosen, report
    return runs


def _skill_report(domain: Domain, options: "ExcuseOptions", best: _Best, search: StateSearch,
                  base: ExcuseReport) -> ExcuseReport:
    """The report of the best excuse with skill changes: the state search on the relaxed domain again, with the
    caller's options (optimal plans, every minimal state part), each excuse carrying the skill changes."""
    skills = list(best.skills)
    room = int(best.total) - len(skills) * SKILL_CHANGE_COST
    size = _state_size(room, bool(options.costs), options.max_size, len(skills))
    final = replace(options, invariants_from=options.invariants_from or domain, max_size=size)
    report = search(relaxed_domain(domain, skills), final)
    if report.status is ExcuseStatus.TIMEOUT:
        return _cut_short(base, best)
    excuses = _state_parts(report, base)
    for excuse in excuses:
        excuse.skill_changes = skills
        excuse.cost += len(skills) * SKILL_CHANGE_COST
    stats = report.statistics
    stats.skill_changes_relaxable = base.statistics.skill_changes_relaxable
    stats.skill_searches = (base.statistics.skill_searches or 0) + 1
    stats.time_s = round(time.monotonic() - options.started, 4)
    return replace(report, status=ExcuseStatus.FOUND, excuses=excuses, robot_plan=None, robot_plan_cost=None,
                   domain=domain, invariant_groups=report.invariant_groups or base.invariant_groups)
