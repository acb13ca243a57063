"""Successor generation: the actions indexed by one positive precondition each.

A state only tries the actions whose indexed precondition it holds (plus those
without a positive precondition), so a search's expansion looks at a few
buckets instead of every action.  Which precondition indexes an action is the
caller's choice (the planner balances the buckets; the excuse oracle picks the
precondition most likely false); the applicability test and the successor
(:meth:`~guided_lfd.planning.task.GroundAction.apply`) stay in the searches'
hot loops, over the payloads they store.
"""

from __future__ import annotations

from typing import Generic, Iterable, TypeVar

__all__ = ["SuccessorIndex"]

T = TypeVar("T")


class SuccessorIndex(Generic[T]):
    """Payloads (an action, its index, or its masks) bucketed under one atom each."""

    __slots__ = ("always", "buckets", "mask")

    def __init__(self, entries: Iterable[tuple[int | None, T]]) -> None:
        """``entries``: (the atom that indexes the action, or None for an action without a positive
        precondition, its payload), in the order the searches try them."""
        self.always: list[T] = []
        self.buckets: dict[int, list[T]] = {}
        for key, payload in entries:
            if key is None:
                self.always.append(payload)
            else:
                self.buckets.setdefault(key, []).append(payload)
        self.mask = sum(1 << key for key in self.buckets)

    def candidates(self, state: int) -> list[list[T]]:
        """The buckets whose atom holds in ``state``, by increasing atom, after the unconditional one: every
        action applicable in ``state`` is in one of them."""
        out = [self.always] if self.always else []
        buckets = self.buckets
        keys = state & self.mask
        while keys:
            low = keys & -keys
            keys ^= low
            out.append(buckets[low.bit_length() - 1])
        return out
