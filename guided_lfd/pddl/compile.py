"""Compiling negative preconditions away, for planners that lack them.

Pyperplan's own PDDL parser (and other STRIPS-only tools) reject
``(not p)`` in preconditions.  The standard compilation adds a complement
predicate ``not_p`` for every predicate used negatively: every action that
adds ``p`` deletes ``not_p`` and vice versa, ``(not (p x))`` becomes
``(not_p x)``, and the problem's initial state gets ``not_p`` for every
type-correct atom ``p`` it does not contain.  Plans are unchanged.
"""

from __future__ import annotations

import itertools
from dataclasses import replace
from typing import Callable

from guided_lfd.errors import Location, UnsupportedFeatureError
from guided_lfd.pddl.model import EQUALITY, ActionSchema, Atom, Domain, Literal, Predicate, Problem, objects_by_type


def _complement_name(pred: str, taken: set[str]) -> str:
    name, k = f"not_{pred}", 1
    while name in taken:
        k += 1
        name = f"not_{pred}_{k}"
    return name


def negated_predicates(domain: Domain, problem: Problem | None = None) -> list[str]:
    """Predicates used in negative preconditions (or negative goals of ``problem``), sorted."""
    used = {l.atom.predicate for a in domain.actions for l in a.precondition if not l.positive}
    if problem is not None:
        used |= {l.atom.predicate for l in problem.goal if not l.positive}
    return sorted(used - {EQUALITY})


def _may_corefer(a: Atom, b: Atom, params: dict[str, str], constants: dict[str, str],
                 subtypes: dict[str, set[str]]) -> bool:
    """Whether some binding of the action's parameters makes ``a`` and ``b`` the same ground atom."""
    if a.predicate != b.predicate or len(a.args) != len(b.args):
        return False
    for x, y in zip(a.args, b.args):
        if x == y:
            continue
        tx, ty = params.get(x, constants.get(x, "object")), params.get(y, constants.get(y, "object"))
        if x not in params and y not in params:
            return False  # two different constants
        if tx not in subtypes.get(ty, {ty}) and ty not in subtypes.get(tx, {tx}):
            return False  # no object has both types
    return True


def compile_negative_preconditions(domain: Domain, problem: Problem,
                                   locate: Callable[[str], Location] | None = None) -> tuple[Domain, Problem]:
    """An equivalent domain and problem without negative preconditions or goals.

    ``locate`` maps an action name to where it is written, for errors.  An
    action that deletes one atom of a complemented predicate and adds another
    that may be the same atom (``(not (p ?x)) (p ?y)`` with ``?x = ?y``) is
    refused: PDDL lets the add win, which complement atoms cannot express
    without conditional effects.
    """
    def where(name: str) -> Location:
        return locate(name) if locate is not None else Location(domain.path)

    for act in domain.actions:
        if any(l.atom.predicate == EQUALITY for l in act.precondition):
            raise UnsupportedFeatureError(
                f"action {act.name} has an equality precondition, which STRIPS-only planners lack", where(act.name))
    taken = set(domain.predicates)
    complement: dict[str, str] = {}
    for pred in negated_predicates(domain, problem):
        complement[pred] = _complement_name(pred, taken)
        taken.add(complement[pred])
    subtypes = domain.subtypes()
    for act in domain.actions:
        params = dict(act.params)
        for d in act.delete:
            if d.predicate not in complement or d in act.add:
                continue
            clash = next((a for a in act.add if _may_corefer(d, a, params, domain.constants, subtypes)), None)
            if clash is not None:
                raise UnsupportedFeatureError(
                    f"action {act.name} deletes {d} and adds {clash}, which may be the same atom; complement "
                    f"predicates cannot express that the add wins (expected actions whose deleted and added "
                    f"{d.predicate} atoms differ)", where(act.name))

    def flip(atom: Atom) -> Atom:
        return Atom(complement[atom.predicate], atom.args)

    def literal(lit: Literal) -> Literal:
        if lit.positive or lit.atom.predicate not in complement:
            return lit
        return Literal(flip(lit.atom))

    actions = []
    for act in domain.actions:
        adds = set(act.add) | {flip(a) for a in act.delete if a.predicate in complement and a not in act.add}
        dels = set(act.delete) | {flip(a) for a in act.add if a.predicate in complement}
        actions.append(ActionSchema(act.name, act.params, tuple(literal(l) for l in act.precondition),
                                    tuple(sorted(adds)), tuple(sorted(dels - adds)), act.origin, act.cost))
    predicates = dict(domain.predicates)
    for pred, name in complement.items():
        predicates[name] = Predicate(name, domain.predicates[pred].params)
    reqs = tuple(r for r in domain.requirements if r != ":negative-preconditions")
    new_domain = replace(domain, requirements=reqs, predicates=predicates, actions=actions)
    by_type = objects_by_type(domain, problem)
    init = set(problem.init)
    for pred, name in complement.items():
        for atom in _ground_atoms(domain.predicates[pred], by_type):
            if atom not in problem.init:
                init.add(Atom(name, atom.args))
    new_problem = replace(problem, init=frozenset(init), goal=tuple(literal(l) for l in problem.goal))
    return new_domain, new_problem


def _ground_atoms(pred: Predicate, by_type: dict[str, list[str]]) -> list[Atom]:
    pools = [by_type.get(t, []) for _, t in pred.params]
    return [Atom(pred.name, tuple(args)) for args in itertools.product(*pools)]
