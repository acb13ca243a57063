"""A change of the initial state (an excuse is a set of them) and the excuse state it makes."""

from __future__ import annotations

from dataclasses import dataclass

from guided_lfd.pddl.model import Atom

__all__ = ["Change", "excuse_state"]


@dataclass(frozen=True)
class Change:
    """One atom made true (``added``) or false in the excuse state."""

    atom: Atom
    added: bool

    def __str__(self) -> str:
        return f"{'+' if self.added else '-'}{self.atom}"


def excuse_state(init: frozenset[Atom], changes: list[Change]) -> frozenset[Atom]:
    """I' = I Δ E."""
    state = set(init)
    for change in changes:
        if change.added:
            state.add(change.atom)
        else:
            state.discard(change.atom)
    return frozenset(state)
