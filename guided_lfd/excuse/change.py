"""A change of the initial state (an excuse is a set of them) and the excuse state it makes."""

from __future__ import annotations

from dataclasses import dataclass

from guided_lfd.pddl.model import Atom, pretty_atom

__all__ = ["Change", "describe_change", "excuse_state"]


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


def describe_change(change: Change, spellings: dict[str, str]) -> str:
    """``+(open pinkdrawer)`` -> ``Open PinkDrawer``; deletions read ``Not ...``."""
    text = pretty_atom(change.atom, spellings)
    return text if change.added else f"Not {text[:1].lower()}{text[1:]}"
