"""The members of a set of states nearest to a given state, by weighted Hamming distance.

A state's distance to ``origin`` is the summed weight of the atoms where the
two differ.  One pass over the diagram gives every node the least distance of
a path from it to ``true`` (a variable the path skips keeps ``origin``'s value,
at no cost: every weight is positive), and a best-first walk down from the
root, guided by those exact distances, then yields the members in
non-decreasing distance, each as the set of atoms it changes.  That is the
minimal excuse when the set is "the robot reaches the goal from here, the
goal does not hold yet, the invariants do" (paper, Definition 3).
"""

from __future__ import annotations

import heapq
import itertools
from dataclasses import dataclass
from typing import Any, Iterator

from guided_lfd.symbolic.diagrams import Diagrams

INF = float("inf")


@dataclass
class Distances:
    """The least distance from each node of a diagram to ``true`` (see the module docstring)."""

    dd: Diagrams
    atoms: list[int]  # the task atom of each variable
    weights: dict[int, int]  # per task atom: what changing it weighs
    origin: int  # the state distances are measured from (a bit set over task atoms)

    def __post_init__(self) -> None:
        self.memo: dict[Any, float] = {}

    def step(self, level: int, value: bool) -> float:
        """What giving the variable at ``level`` the value ``value`` costs."""
        atom = self.atoms[level]
        if bool(self.origin >> atom & 1) == value:
            return 0
        return self.weights.get(atom, INF)

    def of(self, root: Any) -> float:
        """The least distance of a member of ``root`` (INF: empty); one pass, remembered for every node."""
        dd, memo = self.dd, self.memo
        stack = [root]
        while stack:  # post-order without recursion: diagrams can be thousands of levels deep
            f = stack[-1]
            if f in memo:
                stack.pop()
                continue
            node = dd.top(f)
            if node is None:
                memo[f] = 0 if f == dd.true else INF
                stack.pop()
                continue
            level, high, low = node
            waiting = [c for c in (high, low) if c not in memo]
            if waiting:
                stack.extend(waiting)
                continue
            memo[f] = min(self.step(level, True) + memo[high], self.step(level, False) + memo[low])
            stack.pop()
        return memo[root]


def nearest(dd: Diagrams, root: Any, atoms: list[int], weights: dict[int, int], origin: int,
            max_size: int | None = None) -> Iterator[tuple[int, int]]:
    """Members of ``root`` as (distance, changed atoms as a bit set), in non-decreasing distance.

    Members that change atoms a path skips are left out (each is a superset of
    one yielded, at a greater distance).  ``max_size``: no member changing more
    atoms.
    """
    dist = Distances(dd, atoms, weights, origin)
    if dist.of(root) == INF:
        return
    memo = dist.memo
    tie = itertools.count()
    # (f = g + least distance below, g, tie, node, changes, size)
    heap: list[tuple[float, int, int, Any, int, int]] = [(memo[root], 0, next(tie), root, 0, 0)]
    while heap:
        _, g, _, f, changes, size = heapq.heappop(heap)
        node = dd.top(f)
        if node is None:
            yield g, changes  # true: the distance bound was exact
            continue
        level, high, low = node
        atom = atoms[level]
        for value, child in ((True, high), (False, low)):
            below = memo.get(child)
            if below is None:
                below = dist.of(child)
            if below == INF:
                continue
            cost = dist.step(level, value)
            if cost == INF:
                continue
            flipped = cost > 0
            if flipped and max_size is not None and size + 1 > max_size:
                continue
            heapq.heappush(heap, (g + cost + below, g + int(cost), next(tie), child,
                                  changes | (1 << atom) if flipped else changes, size + flipped))
