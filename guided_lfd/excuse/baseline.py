"""The paper's method as a strategy: change sets by increasing weight, one planner call each (the baseline)."""

from __future__ import annotations

import heapq
from typing import Iterator

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse import outcome
from guided_lfd.excuse.lmcut import RelaxedExcuseTask
from guided_lfd.excuse.outcome import SearchLimits, SearchOutcome
from guided_lfd.excuse.progress import ProgressMeter
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.planning import find_plan
from guided_lfd.planning.task import GroundAction, bits


def colex_subsets(atoms: list[int], size: int, end: int | None = None) -> Iterator[int]:
    """Every ``size``-subset of ``atoms[:end]`` as a bit mask, in increasing integer order.

    ``atoms`` must be increasing bit indices; then the integer order of the
    masks is the colexicographic order of the subsets.  Nothing but the current
    subset is held (a recursion ``size`` deep).
    """
    end = len(atoms) if end is None else end
    if size == 0:
        yield 0
        return
    for k in range(size - 1, end):
        top = 1 << atoms[k]
        for rest in colex_subsets(atoms, size - 1, k):
            yield rest | top


def by_weight(atoms: list[int], weights: dict[int, int], max_size: int | None = None) -> Iterator[tuple[int, int]]:
    """Every subset of ``atoms`` (of at most ``max_size``) as (weight, mask), in non-decreasing weight.

    Atoms are sorted by weight; a subset's successors are "add the next atom"
    and "replace the last atom by the next one".  That tree reaches every
    subset exactly once along edges that never lower the weight, so a heap of
    the open successors, at most one more than the subsets yielded, gives them
    in order of weight without holding a frontier of every next-size subset.
    """
    order = sorted(atoms, key=lambda i: (weights[i], i))
    yield 0, 0
    if not order or max_size == 0:
        return
    heap: list[tuple[int, int, int]] = [(weights[order[0]], 1 << order[0], 0)]  # (weight, mask, last position)
    while heap:
        w, changes, last = heapq.heappop(heap)
        yield w, changes
        nxt = last + 1
        if nxt < len(order):
            atom, new = order[last], order[nxt]
            if max_size is None or changes.bit_count() < max_size:
                heapq.heappush(heap, (w + weights[new], changes | (1 << new), nxt))
            heapq.heappush(heap, (w - weights[atom] + weights[new], (changes & ~(1 << atom)) | (1 << new), nxt))


class BaselineSearch:
    """The paper's method: breadth-first over change sets, a planner call each.

    Change sets are enumerated by increasing weight (breadth-first by size for
    unit costs) over every changeable atom, each generated once.  Every
    candidate whose state does not satisfy the goal (and, for consistent
    semantics, keeps the invariants) is checked with a fresh pyperplan search
    (greedy best-first with h_FF) on the full robot task, as the paper's
    model-space search calls a planner per node.  The enumeration holds no
    frontier of change sets (a heap of at most the candidates tried, for
    unequal weights), so an abandoned search is cheap to free.
    """

    name = "baseline"
    description = "breadth-first over change sets, one pyperplan call per candidate (the paper's method)"

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: ProgressMeter | None = None,
               oracle: ReachabilityOracle | None = None, relaxed: RelaxedExcuseTask | None = None) -> SearchOutcome:
        """Breadth-first over change sets; ``oracle`` and ``relaxed`` are unused (a planner call per candidate)."""
        task = space.task
        # ADL tasks: guided-lfd's A* (pyperplan reads STRIPS only); each plan is then optimal.
        planner = "astar-lmcut" if task.is_adl else "gbfs-hff"
        atoms = list(bits(space.changeable))
        weights = space.weights
        best: int | None = None
        solutions: list[int] = []
        plans: dict[int, list[GroundAction]] = {}
        candidates = calls = bound = 0
        try:
            for w, changes in self._candidates(atoms, weights, limits.max_size):
                if best is not None and w > best:
                    break
                if outcome.timed_out(limits):
                    raise SearchTimeout("excuse search exceeded its time limit")
                bound = w  # every lighter change set was tried: none is an excuse
                if any(s & changes == s for s in solutions):
                    continue  # a superset of an excuse is not minimal
                state = space.state(changes)
                candidates += 1
                if progress is not None and progress.due():
                    progress.search(candidates, calls, candidates, space.cost_bound(bound))
                if not task.satisfies_goal(state) and space.consistent(state):
                    calls += 1
                    remaining = None if limits.deadline is None else max(0.01, limits.deadline - outcome.clock())
                    result = find_plan(task, init=state, search=planner, time_limit_s=remaining)
                    if result.plan is not None:
                        best = w
                        solutions.append(changes)
                        plans[changes] = result.plan
                        if not limits.all_minimal or len(solutions) >= limits.max_solutions:
                            break
        except SearchTimeout:
            return SearchOutcome(solutions, plans, ExcuseStatus.TIMEOUT, candidates, calls, candidates,
                                 lower_bound=bound)
        # Sets beyond the size bound were never tried: no excuse found is then not a proof of none.
        size_pruned = limits.max_size is not None and limits.max_size < len(atoms)
        status = (ExcuseStatus.FOUND if solutions
                  else ExcuseStatus.NONE_WITHIN_SIZE if size_pruned else ExcuseStatus.NONE)
        return SearchOutcome(sorted(solutions), plans, status, candidates, calls, candidates)

    @staticmethod
    def _candidates(atoms: list[int], weights: dict[int, int], max_size: int | None) -> Iterator[tuple[int, int]]:
        """(weight, change set) in non-decreasing weight; for equal weights by size, then integer order."""
        if len({weights[i] for i in atoms}) <= 1:
            unit = weights[atoms[0]] if atoms else 1
            top = len(atoms) if max_size is None else min(max_size, len(atoms))
            for size in range(top + 1):
                for changes in colex_subsets(atoms, size):
                    yield size * unit, changes
            return
        yield from by_weight(atoms, weights, max_size)
