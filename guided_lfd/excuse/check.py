"""Independent check of an excuse (paper, Definition 2).

Works on the lifted model and plain atom sets only, with the plan validator;
it shares no code with the grounder or the searches, so it can catch their
mistakes.  Every excuse guided-lfd prints has passed this check.
"""

from __future__ import annotations

from collections.abc import Sequence

from guided_lfd.excuse.change import Change, excuse_state
from guided_lfd.excuse.laws import WorldLaws
from guided_lfd.pddl.model import Domain, Problem
from guided_lfd.planning.validation import PlanStep, validate_plan

__all__ = ["check_excuse", "change_cost"]


def change_cost(changes: list[Change], specs: Sequence[str]) -> int:
    """The cost of ``changes`` under ``--cost`` ``specs`` (``PRED=N``, ``(pred arg ...)=N``; an atom's own
    specification wins over its predicate's; 1 otherwise), read here again rather than taken from the search."""
    by_predicate: dict[str, int] = {}
    by_atom: dict[tuple[str, ...], int] = {}
    for spec in specs:
        target, _, value = spec.rpartition("=")
        target = target.strip().lower()
        if target.startswith("("):
            by_atom[tuple(target.strip("()").split())] = int(value)
        else:
            by_predicate[target] = int(value)
    total = 0
    for change in changes:
        key = (change.atom.predicate, *change.atom.args)
        total += by_atom.get(key, by_predicate.get(change.atom.predicate, 1))
    return total


def check_excuse(
    domain: Domain,
    problem: Problem,
    changes: list[Change],
    plan: list[PlanStep],
    laws: WorldLaws | None = None,
    fixed: Sequence[str] = (),
    costs: Sequence[str] | None = None,
    cost: int | None = None,
) -> list[str]:
    """Reasons why ``changes`` with ``plan`` is *not* a valid excuse (empty = valid).

    ``laws`` are the invariants the excuse state must keep (consistent semantics), derived by the checker
    itself (:func:`guided_lfd.excuse.laws.derive_laws`), not the engine's groups.  No change may touch a ``fixed``
    predicate; with ``costs`` (the ``--cost`` specifications), ``cost`` must
    be what they give the changes (:func:`change_cost`).
    """
    problems: list[str] = []
    problems += [f"{c} changes {c.atom.predicate}, which is fixed" for c in changes if c.atom.predicate in fixed]
    if costs is not None and cost is not None and change_cost(changes, costs) != cost:
        problems.append(f"the excuse's cost is {cost}, but its changes cost {change_cost(changes, costs)}")
    atoms = [c.atom for c in changes]
    if len(set(atoms)) != len(atoms):
        problems.append("an atom is changed twice")
    for change in changes:
        if change.added and change.atom in problem.init:
            problems.append(f"{change} adds an atom that is already true")
        if not change.added and change.atom not in problem.init:
            problems.append(f"{change} removes an atom that is already false")
        if change.atom.predicate not in domain.predicates:
            problems.append(f"{change} is not an atom of the domain")
        if change.atom.predicate in domain.derived_predicates():
            problems.append(f"{change} changes a derived predicate, which follows from the others")
    state = excuse_state(problem.init, changes)
    # The goal with the excuse state's derived atoms (ADL), evaluated by the validator's lifted code.
    if changes and not validate_plan(domain, state, problem.goal, [], problem, problem.goal_condition).unsatisfied_goal:
        problems.append("the excuse state already satisfies the goal")
    report = validate_plan(domain, state, problem.goal, plan, problem, problem.goal_condition)
    if not report.valid:
        failure = report.first_failure
        if failure is not None:
            problems.append(f"plan step {failure.index} {failure.step} is not applicable in the excuse state")
        else:
            problems.append("the plan does not reach the goal from the excuse state")
    if laws is not None:
        problems += [f"the excuse state breaks the invariant {law}" for law in laws.broken(frozenset(state))]
    return problems
