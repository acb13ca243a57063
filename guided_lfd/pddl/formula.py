"""ADL formulas, conditional effects and derived predicates in the lifted model.

A STRIPS action's precondition is a conjunction of literals
(:attr:`ActionSchema.precondition`); the domains robot teams write use more:
disjunctions, ``imply``, quantifiers, conditional and universal effects,
derived predicates.  This module holds them, in negation normal form as Fast
Downward's translator parser leaves them (``imply`` and negations of compound
formulas pushed down to the atoms), so that one reading serves every command:
the writer prints them back, the validator evaluates them on states, and the
planner hands them to the translator's normalisation (see
:mod:`guided_lfd.planning.adl`).
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import product
from typing import Iterable, Iterator, Union

from guided_lfd.pddl.atoms import Atom, Literal

#: Variables of a quantifier or a universal effect: (name, type) pairs.
Variables = tuple[tuple[str, str], ...]


@dataclass(frozen=True)
class Junction:
    """``(and ...)`` or ``(or ...)``; the empty ``and`` is true, the empty ``or`` false."""

    kind: str
    parts: tuple["Formula", ...]

    def __str__(self) -> str:
        return formula_text(self)


@dataclass(frozen=True)
class Quantified:
    """``(forall (?x - t ...) body)`` or ``(exists (?x - t ...) body)``."""

    kind: str
    variables: Variables
    body: "Formula"

    def __str__(self) -> str:
        return formula_text(self)


Formula = Union[Literal, Junction, Quantified]

TRUE = Junction("and", ())
FALSE = Junction("or", ())


@dataclass(frozen=True)
class ConditionalEffect:
    """``(forall (vars) (when condition literal))``: one literal, under a condition, for every binding."""

    variables: Variables
    condition: Formula
    literal: Literal


@dataclass(frozen=True)
class DerivedRule:
    """``(:derived (p ?x - t ...) condition)``: ``p`` holds where ``condition`` does (least fixpoint)."""

    predicate: str
    params: Variables
    condition: Formula


def typed_text(variables: Variables) -> str:
    """``?x - t ?y - u`` for a variable list."""
    return " ".join(f"{name} - {typ}" for name, typ in variables)


def formula_text(formula: Formula) -> str:
    """The formula as PDDL."""
    if isinstance(formula, Literal):
        return str(formula)
    if isinstance(formula, Junction):
        return f"({formula.kind}" + "".join(" " + formula_text(p) for p in formula.parts) + ")"
    return f"({formula.kind} ({typed_text(formula.variables)}) {formula_text(formula.body)})"


def effect_text(effect: ConditionalEffect) -> str:
    """The effect as PDDL: ``(forall (...) (when C L))``, each part only where needed."""
    text = str(effect.literal)
    if effect.condition != TRUE:
        text = f"(when {formula_text(effect.condition)} {text})"
    if effect.variables:
        text = f"(forall ({typed_text(effect.variables)}) {text})"
    return text


def literals_of(formula: Formula) -> Iterator[Literal]:
    """Every literal the formula mentions (variables of quantifiers left in)."""
    if isinstance(formula, Literal):
        yield formula
    elif isinstance(formula, Junction):
        for part in formula.parts:
            yield from literals_of(part)
    else:
        yield from literals_of(formula.body)


def top_literals(formula: Formula) -> tuple[Literal, ...]:
    """The literals every model of ``formula`` satisfies at its top-level conjunction."""
    if isinstance(formula, Literal):
        return (formula,)
    if isinstance(formula, Junction) and formula.kind == "and":
        return tuple(lit for part in formula.parts for lit in top_literals(part))
    return ()


def is_conjunction_of_literals(formula: Formula) -> bool:
    """Whether ``formula`` is plain STRIPS (literals under ``and`` only)."""
    if isinstance(formula, Literal):
        return True
    return isinstance(formula, Junction) and formula.kind == "and" and all(
        is_conjunction_of_literals(p) for p in formula.parts)


def substitute(formula: Formula, binding: dict[str, str]) -> Formula:
    """``formula`` with free variables replaced (a quantifier's own variables are left alone)."""
    if isinstance(formula, Literal):
        return formula.substitute(binding)
    if isinstance(formula, Junction):
        return Junction(formula.kind, tuple(substitute(p, binding) for p in formula.parts))
    bound = {name for name, _ in formula.variables}
    inner = {k: v for k, v in binding.items() if k not in bound}
    return Quantified(formula.kind, formula.variables, substitute(formula.body, inner))


def holds(formula: Formula, state: frozenset[Atom] | set[Atom], objects: dict[str, list[str]],
          binding: dict[str, str] | None = None) -> bool:
    """Whether ``formula`` holds in ``state`` (a set of ground atoms) under ``binding``.

    ``objects`` lists the objects of each type (subtypes included) that
    quantifiers range over.  Equality compares objects.
    """
    binding = binding or {}
    if isinstance(formula, Literal):
        return formula.substitute(binding).holds(state)
    if isinstance(formula, Junction):
        test = all if formula.kind == "and" else any
        return test(holds(p, state, objects, binding) for p in formula.parts)
    bindings = bindings_of(formula.variables, objects, binding)
    test = all if formula.kind == "forall" else any
    return test(holds(formula.body, state, objects, b) for b in bindings)


def bindings_of(variables: Variables, objects: dict[str, list[str]],
                outer: dict[str, str] | None = None) -> Iterable[dict[str, str]]:
    """Every binding of ``variables`` to objects of their types, extending ``outer``."""
    names = [name for name, _ in variables]
    for values in product(*(objects.get(typ, []) for _, typ in variables)):
        yield {**(outer or {}), **dict(zip(names, values))}
