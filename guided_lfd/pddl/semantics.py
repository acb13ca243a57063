"""What lifted ADL actions and derived predicates do to a state, on plain atom sets.

Independent of the grounder and of Fast Downward's normal form (which the
planner uses): the validator and the excuse's own check apply plans with
this code, so a grounding or normalisation bug cannot confirm itself.

Derived predicates follow PDDL 2.2: stratified rules (a predicate used
negatively in a rule, or inside a ``forall``, is computed in an earlier
stratum: :func:`guided_lfd.pddl.derived.strata`), each stratum the least
fixpoint of its rules over the objects of the parameters' types.
"""

from __future__ import annotations

from typing import Iterable

from guided_lfd.pddl.derived import strata
from guided_lfd.pddl.formula import (ConditionalEffect, DerivedRule, Formula, Junction, bindings_of, holds,
                                     substitute)
from guided_lfd.pddl.model import ActionSchema, Atom, Domain

__all__ = ["conjuncts", "derived_atoms", "effect_atoms", "failed_conditions", "strata"]


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

