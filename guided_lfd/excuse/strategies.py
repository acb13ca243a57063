"""Excuse search strategies.

Every strategy finds change sets E of minimum weight (cost first, size second)
such that I Δ E does not satisfy the goal, keeps the invariants (consistent
semantics) and lets the robot reach the goal.  New strategies register in
:data:`STRATEGIES`; the test suite runs every registered strategy against
brute force, so a registration is all a new strategy needs to be checked.
"""

from __future__ import annotations

import heapq
import time
from dataclasses import dataclass, field
from typing import Callable, Iterator, Protocol

from guided_lfd.deadline import linger
from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.lmcut import INF, Bound, RelaxedExcuseTask
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.grounding import GroundAction, bits

#: Progress callback: (message, candidates tried so far, current bound).
Progress = Callable[[str, int, float], None]


@dataclass
class SearchLimits:
    """What a search may spend and must return."""

    all_minimal: bool = False
    max_size: int | None = None
    deadline: float | None = None  # time.monotonic() value
    max_solutions: int = 1000


@dataclass
class SearchOutcome:
    """Change sets found (all of minimum weight) and how the search ended.

    ``status`` is ``FOUND``, ``NONE`` (proved: no excuse exists),
    ``NONE_WITHIN_SIZE`` (none within ``max_size``) or ``TIMEOUT``.
    """

    solutions: list[int]
    plans: dict[int, list[GroundAction]]
    status: ExcuseStatus
    candidates: int = 0
    planner_calls: int = 0
    expanded: int = 0
    extra: dict[str, int] = field(default_factory=dict)


class Strategy(Protocol):
    """A minimal-excuse search."""

    name: str
    description: str

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: Progress | None = None,
               oracle: ReachabilityOracle | None = None, relaxed: RelaxedExcuseTask | None = None) -> SearchOutcome:
        """Minimal change sets for ``space``.

        ``oracle`` (with its memory of earlier calls) and ``relaxed`` (the
        compiled relaxed task) may be passed in when the caller built them.
        """
        ...


def _mask(indices: list[int]) -> int:
    out = 0
    for i in indices:
        out |= 1 << i
    return out


def _timed_out(limits: SearchLimits) -> bool:
    return limits.deadline is not None and time.monotonic() > limits.deadline


class LandmarkSearch:
    """Best-first search over change sets, guided and pruned by LM-cut.

    Nodes are change sets, ordered by weight + an admissible bound (A*, so
    the first excuse found has minimum weight).  A node branches on a set of
    changes every excuse extending it must hit: a violated invariant group or
    an LM-cut landmark (the smaller), else, when the relaxation is satisfied,
    on the goal atoms (if the state already satisfies the goal), else on every
    relevant change if the real reachability check fails.

    Landmarks are inherited: a landmark of a node that the child's change does
    not hit is still a landmark of the child, and the LM-cut cost partition
    restricted to the inherited landmarks is still admissible.  LM-cut is only
    recomputed when a node has no landmark left.  One reachability oracle with
    dead/alive memory answers all candidates.
    """

    name = "landmark"
    description = "A* over change sets with LM-cut bounds and landmark branching (default)"

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: Progress | None = None,
               oracle: ReachabilityOracle | None = None, relaxed: RelaxedExcuseTask | None = None) -> SearchOutcome:
        """A* over change sets; ``oracle`` and ``relaxed`` are reused when given."""
        relaxed = relaxed or RelaxedExcuseTask(space)
        # Reusing the caller's oracle keeps the dead states its "already
        # solvable?" search found: most candidates' searches run into them.
        oracle = oracle or ReachabilityOracle(space, limits.deadline)
        task = space.task
        weights = space.weights
        cheapest = min(weights.values(), default=0)
        relevant_changes = space.relevant_atoms & space.changeable
        goal_atoms = (task.goal_pos | task.goal_neg) & space.changeable
        # Heap entries: (f, -g, tie, changes); per node its inherited landmarks
        # as (mask of changes, cost share) pairs, or None = compute afresh.
        counter = 0
        heap: list[tuple[float, int, int, int]] = [(0, 0, 0, 0)]
        inherited: dict[int, list[tuple[int, int]] | None] = {0: None}
        seen = {0}
        linger(heap, inherited, seen)  # never freed after a deadline (see guided_lfd.deadline)
        best: float | None = None
        solutions: list[int] = []
        plans: dict[int, list[GroundAction]] = {}
        candidates = expanded = evaluations = 0
        size_pruned = False
        try:
            while heap:
                f, neg_g, _, changes = heapq.heappop(heap)
                if best is not None and f > best:
                    break
                if _timed_out(limits):
                    raise SearchTimeout("excuse search exceeded its time limit")
                g = -neg_g
                state = task.init ^ changes
                landmarks = inherited.pop(changes)
                if not landmarks:
                    evaluations += 1
                    # A node whose inherited landmarks are all hit is usually
                    # relaxed-solvable: a closure proves h = 0 without LM-cut.
                    if landmarks is not None:
                        if relaxed.reaches_goal_unchanged(state):
                            bound = Bound(0, [], [])
                        else:
                            # h >= the cheapest change: requeue with that bound
                            # and pay for LM-cut only if the node comes up again.
                            counter += 1
                            inherited[changes] = None
                            heapq.heappush(heap, (max(f, g + cheapest), neg_g, counter, changes))
                            continue
                    else:
                        bound = relaxed.bound(state, changes)
                    if bound.h == INF:
                        continue
                    landmarks = [(_mask(l), m) for l, m in zip(bound.landmarks, bound.costs)]
                    h = max(bound.h, space.consistency_bound(state))
                    if g + h > f:
                        counter += 1
                        inherited[changes] = landmarks
                        heapq.heappush(heap, (g + h, neg_g, counter, changes))
                        continue
                expanded += 1
                if progress and not expanded % 50:
                    progress("searching", candidates, f)
                branch = 0
                violated = space.violated(state)
                if violated:
                    group = min(violated, key=lambda gr: gr.mask.bit_count())
                    if (state & group.mask).bit_count() > 1:
                        branch = group.mask & state & ~changes & space.changeable
                    else:
                        branch = group.mask & ~state & ~changes & space.changeable
                    if not branch:
                        continue  # the group cannot be repaired any more
                if landmarks:
                    smallest = min((lm for lm, _ in landmarks), key=int.bit_count)
                    if not branch or smallest.bit_count() < branch.bit_count():
                        branch = smallest
                elif not violated:
                    if task.satisfies_goal(state):
                        branch = goal_atoms & ~changes
                    else:
                        candidates += 1
                        plan = oracle.solve(state)
                        if plan is not None:
                            best = g
                            solutions.append(changes)
                            plans[changes] = plan
                            if not limits.all_minimal or len(solutions) >= limits.max_solutions:
                                break
                            continue
                        branch = relevant_changes & ~changes
                size = changes.bit_count()
                if limits.max_size is not None and size + 1 > limits.max_size:
                    size_pruned = size_pruned or bool(branch)
                    continue
                for i in bits(branch):
                    child = changes | (1 << i)
                    if child in seen:
                        continue
                    seen.add(child)
                    if (state >> i) & 1 and i in space.groups_of:
                        # Removing a group atom: the parent's shares may include a
                        # charge for exactly this removal; recompute instead.
                        kept = []
                    else:
                        kept = [(lm, m) for lm, m in landmarks if not (lm >> i) & 1] if landmarks else []
                    cg = g + weights[i]
                    h_child = max(relaxed.unscale(sum(m for _, m in kept)), space.consistency_bound(task.init ^ child))
                    counter += 1
                    inherited[child] = kept
                    heapq.heappush(heap, (max(f, cg + h_child), -cg, counter, child))
        except SearchTimeout:
            return SearchOutcome(solutions, plans, ExcuseStatus.TIMEOUT, candidates, oracle.stats.calls, expanded,
                                 {"evaluations": evaluations, "oracle_expanded": oracle.stats.expanded})
        status = (ExcuseStatus.FOUND if solutions
                  else ExcuseStatus.NONE_WITHIN_SIZE if size_pruned else ExcuseStatus.NONE)
        return SearchOutcome(sorted(solutions), plans, status, candidates, oracle.stats.calls, expanded,
                             {"evaluations": evaluations, "oracle_expanded": oracle.stats.expanded,
                              "oracle_memo_hits": oracle.stats.memo_hits,
                              "oracle_hill_climbs": oracle.stats.hill_climbs,
                              "oracle_pair_proofs": oracle.stats.pair_proofs,
                              "oracle_ff_searches": oracle.stats.ff_searches})


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

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: Progress | None = None,
               oracle: ReachabilityOracle | None = None, relaxed: RelaxedExcuseTask | None = None) -> SearchOutcome:
        """Breadth-first over change sets; ``oracle`` and ``relaxed`` are unused (a planner call per candidate)."""
        from guided_lfd.planning import find_plan

        task = space.task
        atoms = list(bits(space.changeable))
        weights = space.weights
        best: int | None = None
        solutions: list[int] = []
        plans: dict[int, list[GroundAction]] = {}
        candidates = calls = 0
        try:
            for w, changes in self._candidates(atoms, weights, limits.max_size):
                if best is not None and w > best:
                    break
                if _timed_out(limits):
                    raise SearchTimeout("excuse search exceeded its time limit")
                if any(s & changes == s for s in solutions):
                    continue  # a superset of an excuse is not minimal
                state = task.init ^ changes
                candidates += 1
                if progress and not candidates % 200:
                    progress("baseline", candidates, w)
                if not task.satisfies_goal(state) and space.consistent(state):
                    calls += 1
                    remaining = None if limits.deadline is None else max(0.01, limits.deadline - time.monotonic())
                    result = find_plan(task, init=state, search="gbfs-hff", time_limit_s=remaining)
                    if result.plan is not None:
                        best = w
                        solutions.append(changes)
                        plans[changes] = result.plan
                        if not limits.all_minimal or len(solutions) >= limits.max_solutions:
                            break
        except SearchTimeout:
            return SearchOutcome(solutions, plans, ExcuseStatus.TIMEOUT, candidates, calls, candidates)
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


#: Registered strategies by name; the first is the default.
STRATEGIES: dict[str, Strategy] = {s.name: s for s in (LandmarkSearch(), BaselineSearch())}
DEFAULT_STRATEGY = "landmark"
