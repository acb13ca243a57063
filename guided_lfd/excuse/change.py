"""A change of the initial state or of a learned skill (an excuse is a set of them) and the excuse state it makes."""

from __future__ import annotations

from dataclasses import dataclass

from guided_lfd.pddl.model import Atom, Literal, pretty_atom

__all__ = ["Change", "SkillChange", "describe_change", "describe_skill_change", "excuse_state"]


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


@dataclass(frozen=True, order=True)
class SkillChange:
    """One precondition dropped from a learned robot skill: a skill excuse's change (``-(ontable ?y) in unstack``).

    It stands for "show me ``action`` once more, where ``literal`` does not hold": the precondition held in
    every demonstration of the skill so far, and none showed the skill failing without it."""

    action: str
    literal: Literal

    def __str__(self) -> str:
        return f"-{self.literal} in {self.action}"


def describe_skill_change(change: SkillChange, spellings: dict[str, str]) -> str:
    """``-(ontable ?y) in unstack`` -> ``Unstack where Ontable ?y is false``, in the domain's spellings."""
    name = spellings.get(change.action, change.action)
    atom = pretty_atom(change.literal.atom, spellings)
    truth = "false" if change.literal.positive else "true"
    return f"{name[:1].upper()}{name[1:]} where {atom} is {truth}"
