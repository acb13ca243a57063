"""What lifted ADL actions and derived predicates do to a state, on plain atom sets.

Independent of the grounder and of Fast Downward's normal form (which the
planner uses): the validator and the excuse's own check apply plans with
this code, so a grounding or normalisation bug cannot confirm itself.

Derived predicates follow PDDL 2.2: stratified rules (a predicate used
negatively in a rule is computed in an earlier stratum), each stratum the
least fixpoint of its rules over the objects of the parameters' types.
"""

from __future__ import annotations

from typing import Iterable

from guided_lfd.errors import Location, PddlSemanticError
from guided_lfd.pddl.formula import (ConditionalEffect, DerivedRule, Formula, Junction, bindings_of, holds,
                                     literals_of, substitute)
from guided_lfd.pddl.model import ActionSchema, Atom, Domain


def strata(domain: Domain) -> list[list[DerivedRule]]:
    """The derived rules in strata: a predicate used negatively comes from an earlier stratum.

    Raises :class:`PddlSemanticError` when the rules use a derived predicate
    negatively through itself (no stratification exists).
    """
    derived = domain.derived_predicates()
    level = {p: 0 for p in derived}
    rules = list(domain.axioms)
    for _ in range(len(derived) + 1):
        changed = False
        for rule in rules:
            for lit in literals_of(rule.condition):
                q = lit.atom.predicate
                if q not in derived:
                    continue
                need = level[q] + (0 if lit.positive else 1)
                if level[rule.predicate] < need:
                    level[rule.predicate] = need
                    changed = True
        if not changed:
            break
    else:
        raise PddlSemanticError(
            "the derived predicates depend negatively on themselves (no stratification)",
            domain.locate(rules[0].predicate, ":derived") if rules else Location(domain.path))
    out: list[list[DerivedRule]] = [[] for _ in range(max(level.values(), default=-1) + 1)]
    for rule in rules:
        out[level[rule.predicate]].append(rule)
    return [stratum for stratum in out if stratum]


def derived_atoms(domain: Domain, state: frozenset[Atom] | set[Atom], objects: dict[str, list[str]],
                  layers: list[list[DerivedRule]] | None = None) -> set[Atom]:
    """The derived atoms true in ``state`` (a set of basic atoms)."""
    if not domain.axioms:
        return set()
    world = set(state)
    derived: set[Atom] = set()
    for stratum in layers if layers is not None else strata(domain):
        changed = True
        while changed:
            changed = False
            for rule in stratum:
                for binding in bindings_of(rule.params, objects):
                    atom = Atom(rule.predicate, tuple(binding[v] for v, _ in rule.params))
                    if atom not in world and holds(rule.condition, world, objects, binding):
                        world.add(atom)
                        derived.add(atom)
                        changed = True
    return derived


def conjuncts(formula: Formula) -> list[Formula]:
    """The parts of a top-level conjunction (the formula itself otherwise)."""
    if isinstance(formula, Junction) and formula.kind == "and":
        return [p for part in formula.parts for p in conjuncts(part)]
    return [formula]


def effect_atoms(schema: ActionSchema, binding: dict[str, str], world: frozenset[Atom] | set[Atom],
                 objects: dict[str, list[str]]) -> tuple[set[Atom], set[Atom]]:
    """(adds, deletes) of ``schema`` under ``binding`` in ``world`` (basic and derived atoms):
    plain effects, and each conditional effect whose condition holds there, for every binding of its variables."""
    adds = {a.substitute(binding) for a in schema.add}
    dels = {a.substitute(binding) for a in schema.delete}
    for effect in schema.effects:
        for inner in _effect_bindings(effect, objects, binding):
            if holds(effect.condition, world, objects, inner):
                (adds if effect.literal.positive else dels).add(effect.literal.atom.substitute(inner))
    return adds, dels


def _effect_bindings(effect: ConditionalEffect, objects: dict[str, list[str]],
                     binding: dict[str, str]) -> Iterable[dict[str, str]]:
    return bindings_of(effect.variables, objects, binding) if effect.variables else (binding,)


def failed_conditions(schema: ActionSchema, binding: dict[str, str], world: frozenset[Atom] | set[Atom],
                      objects: dict[str, list[str]]) -> list[Formula]:
    """The parts of the precondition that do not hold, ground (empty: the action applies)."""
    parts: list[Formula] = list(schema.precondition) if schema.condition is None else conjuncts(schema.condition)
    return [substitute(p, binding) for p in parts if not holds(p, world, objects, binding)]

