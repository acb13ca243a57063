"""Atoms and literals: the ground or lifted facts every other part of the model is built from.

Their own module so that formulas (:mod:`guided_lfd.pddl.formula`) and the
model's declarations (:mod:`guided_lfd.pddl.model`) both build on them, the
model on the formulas and never the other way.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import AbstractSet

#: The equality predicate of ``:equality`` (``(= ?a ?b)``).
EQUALITY = "="


@dataclass(frozen=True, order=True)
class Atom:
    """``(predicate arg ...)``; arguments are objects or ``?variables``."""

    predicate: str
    args: tuple[str, ...] = ()

    def __str__(self) -> str:
        return "(" + " ".join((self.predicate, *self.args)) + ")"

    def substitute(self, binding: dict[str, str]) -> "Atom":
        """The atom with variables replaced according to ``binding``."""
        return Atom(self.predicate, tuple(binding.get(a, a) for a in self.args))


@dataclass(frozen=True, order=True)
class Literal:
    """An atom or its negation."""

    atom: Atom
    positive: bool = True

    def __str__(self) -> str:
        return str(self.atom) if self.positive else f"(not {self.atom})"

    def substitute(self, binding: dict[str, str]) -> "Literal":
        """The literal with variables replaced according to ``binding``."""
        return Literal(self.atom.substitute(binding), self.positive)

    def holds(self, state: AbstractSet[Atom]) -> bool:
        """Whether the ground literal is true in ``state`` (a set of ground atoms); equality compares objects."""
        atom = self.atom
        value = atom.args[0] == atom.args[1] if atom.predicate == EQUALITY else atom in state
        return value == self.positive
