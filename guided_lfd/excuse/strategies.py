"""Excuse search strategies.

Every strategy finds change sets E of minimum weight (cost first, size second)
such that I Δ E does not satisfy the goal, keeps the invariants (consistent
semantics) and lets the robot reach the goal.  New strategies register in
:data:`STRATEGIES`; the test suite runs every registered strategy against
brute force, so a registration is all a new strategy needs to be checked.
"""

from __future__ import annotations

import bisect
import heapq
import time
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Iterator, Protocol

from guided_lfd.deadline import linger
from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.hitting import HittingSetSearch
from guided_lfd.excuse.lmcut import INF, Bound, RelaxedExcuseTask
from guided_lfd.excuse.progress import ProgressMeter
from guided_lfd.excuse.reach import CheckPaused, ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.excuse.portfolio import PortfolioSearch
from guided_lfd.excuse.symbolic import SymbolicSearch
from guided_lfd.planning.grounding import GroundAction, bits
from guided_lfd.planning.search import SearchStopped

__all__ = ["STRATEGIES", "DEFAULT_STRATEGY", "SearchLimits", "SearchOutcome", "SearchStopped", "Strategy"]


#: Seconds a candidate's reachability check runs before it pauses for the rest of its f (doubled each turn).
CHECK_SLICE_S = 1.0


def clock() -> float:
    """The searches' clock, ``time.monotonic()``: what deadlines and :class:`Probe` times are compared with.

    A test replaces it (one tick per reading) to end a search after a set
    number of checks, whatever the machine's speed.
    """
    return time.monotonic()


@contextmanager
def oracle_until(oracle: ReachabilityOracle, until: float) -> Iterator[None]:
    """Within the block, ``oracle`` gives up by ``until`` (a :func:`clock` value) or its own deadline, the
    earlier; its own deadline again after."""
    hard = oracle.deadline
    # The oracle reads time.monotonic(): the time left, in its terms (a test's clock() may tick otherwise).
    soft = time.monotonic() + max(0.0, until - clock())
    oracle.deadline = soft if hard is None else min(hard, soft)
    try:
        yield
    finally:
        oracle.deadline = hard


@dataclass
class Probe:
    """A pause of the landmark search, once, for a greedy search for any excuse.

    A run that may time out then still has an answer: an excuse that passed
    the reachability check, not proven minimal.  The greedy search shares the
    oracle and its memory; the A* search resumes where it paused.
    """

    start: float  # clock() time: pause when no excuse is found by then
    until: float  # clock() time the greedy search ends by, found or not
    #: Gets what the greedy search found: (change set, plan from its state).
    accept: Callable[[int, list[GroundAction]], None]


@dataclass
class SearchLimits:
    """What a search may spend and must return."""

    all_minimal: bool = False
    max_size: int | None = None
    deadline: float | None = None  # a clock() value
    max_solutions: int = 1000
    #: With ``all_minimal``: also the excuses up to this much costlier than the minimum (none of them a
    #: superset of another: adding changes to an excuse is no other choice).
    slack: int = 0
    probe: Probe | None = None
    #: Asked between steps: True ends the search with :class:`SearchStopped` (a portfolio's other member answered).
    stop: Callable[[], bool] | None = None
    #: Called between the landmark search's steps (never inside a check): another search's turn in the same
    #: process, when its time has come (the portfolio's hitting-set search); it ends this one through ``stop``.
    turn: Callable[[], None] | None = None


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
    #: Proven: every excuse within ``max_size`` weighs at least this (the weight of the lightest change set
    #: the search had not ruled out when it ended).
    lower_bound: int = 0
    #: Which search answered, where a strategy runs several (the portfolio); empty: the strategy itself.
    answered_by: str = ""


class Strategy(Protocol):
    """A minimal-excuse search."""

    name: str
    description: str

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: ProgressMeter | None = None,
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
    return limits.deadline is not None and clock() > limits.deadline


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

    A node's children split its extensions: the k-th adds the k-th atom of the
    branch and *pins* the atoms before it (its extensions never flip them).  So
    no change set is queued twice, and a child's LM-cut knows which changes it
    may no longer make: under the consistent semantics, a truck or hoist left
    where it is can no longer be "at two places" in the relaxation.

    Nodes leave the open list in non-decreasing f, so the f of the last one
    taken is a proven lower bound on the weight of every excuse (within
    ``max_size``): a timed-out search reports it.  With ``limits.probe``, a
    search that has found no excuse by ``probe.start`` pauses once for the
    same search ordered by h alone (greedy), which finds some excuse sooner.
    """

    name = "landmark"
    description = "A* over change sets with LM-cut bounds and landmark branching"
    lists_slack = True  # --slack: lists the excuses up to that much costlier too

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: ProgressMeter | None = None,
               oracle: ReachabilityOracle | None = None, relaxed: RelaxedExcuseTask | None = None) -> SearchOutcome:
        """A* over change sets; ``oracle`` and ``relaxed`` are reused when given."""
        # Reusing the caller's oracle keeps the dead states its "already
        # solvable?" search found: most candidates' searches run into them.
        run = _LandmarkRun(space, limits, relaxed or RelaxedExcuseTask(space),
                           oracle or ReachabilityOracle(space, limits.deadline))
        return run_to_outcome(run, limits, progress)


def run_to_outcome(run: Any, limits: SearchLimits, progress: ProgressMeter | None) -> SearchOutcome:
    """Run a search's ``loop`` to its outcome (a timed-out one at the deadline); its oracle's checks stop when
    ``limits.stop`` says so."""
    run.oracle.interrupt = limits.stop
    try:
        run.loop(progress)
    except SearchTimeout:
        return run.outcome(timed_out=True)
    finally:
        run.oracle.interrupt = None
    return run.outcome()


class _LandmarkRun:
    """One landmark search: the open list, each node's inherited landmarks, and what was found.

    Heap entries are ``(key, -g, tie, changes)`` with key f (A*) or f - g
    (``greedy``: the bound on what is still needed); ``inherited`` holds per
    queued node its landmarks as (mask of changes, cost share) pairs, or None:
    compute afresh.
    """

    def __init__(self, space: ChangeSpace, limits: SearchLimits, relaxed: RelaxedExcuseTask,
                 oracle: ReachabilityOracle, greedy: bool = False) -> None:
        self.space, self.limits, self.relaxed, self.oracle = space, limits, relaxed, oracle
        self.greedy, self.probe = greedy, limits.probe
        self.bound = 0  # A*: the f of the last node taken, a proven lower bound
        self.probe_expanded = 0
        self.task = space.task
        self.cheapest = min(space.weights.values(), default=0)
        self.relevant_changes = space.relevant_atoms & space.changeable
        self.goal_atoms = (self.task.goal_pos | self.task.goal_neg) & space.changeable
        self.counter = 0
        self.heap: list[tuple[float, int, int, int]] = [(0, 0, 0, 0)]
        self.inherited: dict[int, list[tuple[int, int]] | None] = {0: None}
        self.pins: dict[int, int] = {0: 0}
        self.slices: dict[int, float] = {}  # a paused candidate's next check slice
        #: Candidates whose check paused: (when it resumes, its heap entry), the earliest first.
        self.paused: list[tuple[float, tuple[float, int, int, int]]] = []
        linger(self.heap, self.inherited, self.pins)  # never freed after a deadline (see guided_lfd.deadline)
        self.best: float | None = None
        self.g_limit: float = INF  # the heaviest node still worth expanding, once an excuse is found
        self.solutions: list[int] = []
        self.plans: dict[int, list[GroundAction]] = {}
        #: The probe's excuse (change set, plan, weight): minimal once the bound meets its weight.
        self.incumbent: tuple[int, list[GroundAction], int] | None = None
        self.adopted = False
        self.candidates = self.expanded = self.evaluations = 0
        self.size_pruned = False
        # Only A* splits on static groups: a moved group's child looks cheap to a greedy search (its other
        # groups still "at two places"), which then goes deep into moves and rarely finds an excuse.
        self.static_groups = [] if greedy else static_groups(space)

    def push(self, f: float, g: int, changes: int, landmarks: list[tuple[int, int]] | None, pinned: int) -> None:
        """Queue ``changes`` (cost ``g``) at priority ``f`` with the landmarks it inherits and the atoms its
        extensions leave alone (``pinned``)."""
        self.counter += 1
        self.inherited[changes] = landmarks
        self.pins[changes] = pinned
        heapq.heappush(self.heap, (f - g if self.greedy else f, -g, self.counter, changes))

    def loop(self, progress: ProgressMeter | None) -> None:
        """Expand nodes in order of f until the minimal excuses are found or the open list is empty."""
        heap, task, greedy = self.heap, self.task, self.greedy
        # Hot loop: one pass per node; the steps it calls do the work.
        while heap or self.paused:
            key, neg_g, tie, changes = self.paused_due() or heapq.heappop(heap)
            g = -neg_g
            f = key + g if greedy else key
            if self.best is not None and f > self.g_limit:
                return
            if self.incumbent is not None and f >= self.incumbent[2] and not self.limits.all_minimal:
                self.adopt_incumbent(f)  # (--all wants every minimal excuse: the search goes on)
                return
            if _timed_out(self.limits):
                raise SearchTimeout("excuse search exceeded its time limit")
            if self.limits.turn is not None:
                self.limits.turn()
            if self.limits.stop is not None and self.limits.stop():
                raise SearchStopped()
            if self.probe is not None and not self.solutions and clock() > self.probe.start:
                heapq.heappush(heap, (key, neg_g, tie, changes))  # taken up again after the pause
                self.pause_for_probe(progress)
                continue
            if not greedy:
                self.bound = f
            state = task.init ^ changes
            landmarks = self.inherited.pop(changes)
            pinned = self.pins.pop(changes)
            if not landmarks:
                landmarks = self.evaluate(f, g, state, changes, landmarks, pinned)
                if landmarks is None:
                    continue  # requeued with a better bound, or a dead end
            if changes not in self.slices:  # a candidate whose check resumes was counted once
                self.expanded += 1
            if progress is not None and progress.due():
                progress.search(self.expanded, self.oracle.stats.calls, self.candidates,
                                self.space.cost_bound(self.bound))
            branch = self.branch(f, g, state, changes, landmarks, pinned)
            if branch is None:
                continue
            if branch == _DONE:
                return
            self.expand(f, g, changes, landmarks, branch, pinned)

    def paused_due(self) -> tuple[float, int, int, int] | None:
        """The heap entry of a paused candidate to resume now, if any: the first one that comes before every
        node left in the heap (A* decides it before any node of a higher f), else the first whose turn has
        come (the others have had as long as its last slice) and that comes no later than the heap's next."""
        paused = self.paused
        if not paused:
            return None
        top = self.heap[0][0] if self.heap else INF
        first = min(range(len(paused)), key=lambda k: paused[k][1])
        if paused[first][1][0] < top:
            return paused.pop(first)[1]
        now = clock()
        for k, (due, entry) in enumerate(paused):
            if due > now:
                break
            if entry[0] <= top:
                return paused.pop(k)[1]
        return None

    def pause_for_probe(self, progress: ProgressMeter | None) -> None:
        """Search greedily for any excuse until ``probe.until`` (once), drop the changes it can do without, and
        hand it to ``probe.accept``."""
        probe, self.probe = self.probe, None
        assert probe is not None
        if progress is not None:
            progress.phase("probing for any excuse")
        limits = replace(self.limits, all_minimal=False, deadline=probe.until, probe=None)
        greedy = _LandmarkRun(self.space, limits, self.relaxed, self.oracle, greedy=True)
        found = None
        try:
            with oracle_until(self.oracle, probe.until):
                greedy.loop(None)
                if greedy.solutions:
                    found = greedy.solutions[0], greedy.plans[greedy.solutions[0]]
                    found = self.trimmed(*found, probe.until)
        except SearchTimeout:
            if _timed_out(self.limits):
                raise  # the run's time is up, not only the probe's
        finally:
            self.probe_expanded = greedy.expanded
        if progress is not None:
            progress.phase("searching")
        if found is not None:
            probe.accept(*found)
            self.incumbent = (*found, self.space.weight(found[0]))

    def adopt_incumbent(self, bound: float) -> None:
        """The bound met the probe's excuse's weight: no lighter excuse exists, so it is a minimal one."""
        assert self.incumbent is not None
        self.bound = bound
        changes, plan, _ = self.incumbent
        self.solutions, self.plans = [changes], {changes: plan}
        self.adopted = True

    def trimmed(self, changes: int, plan: list[GroundAction], until: float) -> tuple[int, list[GroundAction]]:
        """The excuse ``changes`` without each change it can do without (tried once each, the heaviest first),
        as far as the time until ``until`` allows; the greedy search's excuses often carry many."""
        space, task = self.space, self.task
        for i in sorted(bits(changes), key=lambda i: (-space.weights[i], i)):
            smaller = changes & ~(1 << i)
            state = task.init ^ smaller
            if clock() > until:
                break
            if not smaller or task.satisfies_goal(state) or not space.consistent(state):
                continue
            try:
                shorter = self.oracle.solve(state)
            except SearchTimeout:
                break
            if shorter is not None:
                changes, plan = smaller, shorter
        return changes, plan

    def evaluate(self, f: float, g: int, state: int, changes: int, landmarks: list[tuple[int, int]] | None,
                 pinned: int) -> list[tuple[int, int]] | None:
        """A node without landmarks left: its fresh landmarks, or None when it was requeued or is dead."""
        self.evaluations += 1
        relaxed = self.relaxed
        # A node whose inherited landmarks are all hit is usually
        # relaxed-solvable: a closure proves h = 0 without LM-cut.
        if landmarks is not None:
            if not relaxed.reaches_goal_unchanged(state):
                # h >= the cheapest change: requeue with that bound
                # and pay for LM-cut only if the node comes up again.
                self.push(max(f, g + self.cheapest), g, changes, None, pinned)
                return None
            bound = Bound(0, [], [])
        else:
            bound = relaxed.bound(state, changes, pinned)
        if bound.h == INF:
            return None
        fresh = [(_mask(l), m) for l, m in zip(bound.landmarks, bound.costs)]
        h = max(bound.h, self.space.consistency_bound(state))
        if g + h > f:
            self.push(g + h, g, changes, fresh, pinned)
            return None
        return fresh

    def branch(self, f: float, g: int, state: int, changes: int, landmarks: list[tuple[int, int]],
               pinned: int) -> int | None:
        """The atoms to branch on (none of ``pinned``): a violated group's repairs, the smallest landmark, or,
        at a relaxed-solvable consistent node, the oracle's verdict (an excuse, or all relevant changes).

        None: nothing to expand here; ``_DONE``: the search is over.
        """
        space = self.space
        branch = 0
        violated = space.violated(state)
        free = space.changeable & ~changes & ~pinned
        if violated:
            group = min(violated, key=lambda gr: gr.mask.bit_count())
            if (state & group.mask).bit_count() > 1:
                branch = group.mask & state & free
            else:
                branch = group.mask & ~state & free
            if not branch:
                return None  # the group cannot be repaired any more
        if landmarks:
            smallest = min((lm for lm, _ in landmarks), key=int.bit_count)
            if not violated and self.static_groups and self.decide(f, g, state, changes, landmarks, pinned,
                                                                   smallest):
                return None
            if not branch or smallest.bit_count() < branch.bit_count():
                branch = smallest
        elif not violated:
            if self.task.satisfies_goal(state):
                branch = self.goal_atoms & free
            else:
                return self.check_candidate(f, g, state, changes, pinned)
        return branch

    def decide(self, f: float, g: int, state: int, changes: int, landmarks: list[tuple[int, int]], pinned: int,
               landmark: int) -> bool:
        """Split on a static group ``landmark`` meets, if any: its true atom stays, or it moves to another.

        A static group's atoms are added by no robot action, so its atom in the excuse state is its atom
        for good; but the delete relaxation keeps the initial atom beside one a change adds (a truck that
        cannot drive "moved" to a second place serves both).  So before branching on such a landmark the
        node splits: one child pins the group's true atom q (the relaxation is exact for the group and
        LM-cut is recomputed), and each other child moves it (removes q, adds one of the group's targets:
        see :func:`static_groups`).  Removing q alone is no child: with no negative precondition or goal on q (see
        :func:`static_groups`) it only disables actions, so an excuse doing it is never minimal.
        True when the children were queued.
        """
        space, max_size = self.space, self.limits.max_size
        free = space.changeable & ~changes & ~pinned
        for mask, targets in self.static_groups:
            if not landmark & mask:
                continue
            present = state & mask
            if present.bit_count() != 1 or not present & free:
                continue  # decided already: its atom was changed, pinned or is fixed
            q = present.bit_length() - 1
            init, weights = self.task.init, space.weights
            moves = targets & free & ~present
            if moves and max_size is not None and changes.bit_count() + 2 > max_size:
                self.size_pruned, moves = True, 0
            for i in bits(moves):
                moved = changes | present | (1 << i)
                cg = g + weights[q] + weights[i]
                # Its extensions add no other atom of the group (pinned: no change set is queued twice).
                self.push(max(f, cg + space.consistency_bound(init ^ moved)), cg, moved, [],
                          pinned | (mask & free & ~present & ~(1 << i)))
            kept_pins = pinned | (mask & free)
            if all(lm & ~kept_pins for lm, _ in landmarks):
                # Fresh LM-cut when it comes up (None): the pins make its bound the stronger one.
                self.push(f, g, changes, None, kept_pins)
            return True
        return False

    def check_candidate(self, f: float, g: int, state: int, changes: int, pinned: int) -> int | None:
        """Ask the oracle about a candidate excuse; the relevant changes to branch on (none pinned) if it is
        none.

        A check still undecided after its slice (:data:`CHECK_SLICE_S`, doubled each time it comes back)
        pauses: the other nodes of its f go on for as long again (another candidate as light may be a
        quicker question) before it resumes where it stopped (:meth:`paused_due`), and it always resumes
        before any node of a higher f.
        """
        if self.solutions and (g > self.g_limit or any(changes & found == found for found in self.solutions)
                               or self.space.cost(changes) > self.space.cost(self.solutions[0]) + self.limits.slack):
            return None  # beyond the slack, or an excuse with changes added: no other choice
        slice_s = self.slices.get(changes)
        if slice_s is None:
            self.candidates += 1
            slice_s = CHECK_SLICE_S
        try:
            plan = self.oracle.solve(state, pause_at=time.monotonic() + slice_s)
        except CheckPaused:
            self.slices[changes] = 2 * slice_s
            self.inherited[changes], self.pins[changes] = [], pinned
            self.counter += 1
            entry = (f - g if self.greedy else f, -g, self.counter, changes)
            bisect.insort(self.paused, (clock() + slice_s, entry))
            return None
        if plan is None:
            return self.relevant_changes & self.space.changeable & ~changes & ~pinned
        if self.best is None:
            self.best = g
            # Weights are cost x size_factor + size: all excuses up to the slack's cost weigh less than this.
            slack = self.limits.slack
            self.g_limit = g if not slack else (self.space.cost(changes) + slack + 1) * self.space.size_factor - 1
        self.solutions.append(changes)
        self.plans[changes] = plan
        if not self.limits.all_minimal or len(self.solutions) >= self.limits.max_solutions:
            return _DONE
        return None

    def expand(self, f: float, g: int, changes: int, landmarks: list[tuple[int, int]], branch: int,
               pinned: int) -> None:
        """Queue each child that adds one atom of ``branch``, with the landmarks it inherits.

        The children split the extensions of ``changes`` that hit ``branch`` (and flip no pinned atom)
        between them: the k-th adds the k-th atom and pins the ones before it.  So no change set is queued
        twice, and a child's bound knows what it may no longer flip (a landmark all pinned: a dead child).
        """
        space, limits = self.space, self.limits
        size = changes.bit_count()
        if limits.max_size is not None and size + 1 > limits.max_size:
            self.size_pruned = self.size_pruned or bool(branch)
            return
        init, weights = self.task.init, space.weights
        earlier = 0
        for i in bits(branch):
            child = changes | (1 << i)
            child_pins = pinned | earlier
            earlier |= 1 << i
            if (init >> i) & 1 and i in space.groups_of:
                # Removing a group atom: the parent's shares may include a
                # charge for exactly this removal; recompute instead.
                kept = []
            else:
                kept = [(lm & ~child_pins, m) for lm, m in landmarks if not (lm >> i) & 1] if landmarks else []
                if any(not lm for lm, _ in kept):
                    continue  # a landmark left with pinned atoms only: no excuse extends the child
            cg = g + weights[i]
            h_child = max(self.relaxed.unscale(sum(m for _, m in kept)), space.consistency_bound(init ^ child))
            self.push(max(f, cg + h_child), cg, child, kept, child_pins)

    def outcome(self, timed_out: bool = False) -> SearchOutcome:
        """What the search found, with its effort."""
        stats = self.oracle.stats
        probed = {"probe_expanded": self.probe_expanded} if self.probe_expanded else {}
        if self.adopted:
            probed["probe_adopted"] = 1
        if timed_out:
            return SearchOutcome(self.solutions, self.plans, ExcuseStatus.TIMEOUT, self.candidates, stats.calls,
                                 self.expanded, {"evaluations": self.evaluations, "oracle_expanded": stats.expanded,
                                                 **probed}, self.bound)
        status = (ExcuseStatus.FOUND if self.solutions
                  else ExcuseStatus.NONE_WITHIN_SIZE if self.size_pruned else ExcuseStatus.NONE)
        return SearchOutcome(sorted(self.solutions), self.plans, status, self.candidates, stats.calls, self.expanded,
                             {"evaluations": self.evaluations, "oracle_expanded": stats.expanded,
                              "oracle_memo_hits": stats.memo_hits, "oracle_hill_climbs": stats.hill_climbs,
                              "oracle_pair_proofs": stats.pair_proofs, "oracle_ff_searches": stats.ff_searches,
                              "oracle_counting_proofs": stats.counting_proofs, **probed}, self.bound)


#: ``_LandmarkRun.branch``'s answer when the search is over (enough minimal excuses found).
_DONE = -1


def static_groups(space: ChangeSpace) -> list[tuple[int, int]]:
    """The mutex groups of the consistent semantics whose atom in the excuse state is there for good, and whose
    true atom q an excuse only removes to put another in its place: (group mask, the atoms worth moving to).

    No relevant robot action adds an atom of the group; one atom q is true initially, in no other group,
    no goal, no negative precondition or goal.  Without negative conditions on q, removing it only
    disables actions (STRIPS is monotone), and q's only group stays consistent with q: an excuse that
    removes q and adds no atom of the group weighs more than the same excuse keeping q.  Nor does adding
    an irrelevant atom g in its place help, unless g also fills another exactly-one group (dropping both
    changes then breaks that group).  Tasks with conditional effects or derived atoms have none.
    """
    task = space.task
    if task.is_adl or not space.groups:
        return []
    candidates = []
    for k, group in enumerate(space.groups):
        present = task.init & group.mask
        if present.bit_count() != 1 or not group.mask & space.relevant_atoms:
            continue
        q = present.bit_length() - 1
        if len(space.groups_of.get(q, ())) == 1 and not present & (space.negation_needed | task.goal_pos):
            candidates.append((k, group))
    if not candidates:
        return []
    # Indices, not a mask: OR-ing every action's atoms into one wide integer costs 0.1 s on a house.
    added = {i for act in space.relevant_actions for i in act.add_ids}
    out = []
    for k, group in candidates:
        if any(i in added for i in bits(group.mask)):
            continue
        targets = group.mask & space.relevant_atoms
        for i in bits(group.mask & ~space.relevant_atoms):
            if any(_fills_usefully(space, j, k) for j in space.groups_of.get(i, ())):
                targets |= 1 << i
        out.append((group.mask, targets))
    return out


def _fills_usefully(space: ChangeSpace, j: int, k: int) -> bool:
    """Whether an atom of group ``j`` (not the static group ``k``) may be worth adding to fill that group: it is an
    exactly-one group whose initial atom h0 an excuse may want gone (h0 under a negative condition, a goal, or
    in another group where it makes room).  Otherwise an excuse removing h0 and adding the atom weighs more than
    the same excuse with both undone (the other group then holds h0 alone)."""
    group, task = space.groups[j], space.task
    if j == k or not group.exactly_one:
        return False
    initial = task.init & group.mask
    if initial.bit_count() != 1:
        return True  # not the case the argument covers: keep the atom
    h0 = initial.bit_length() - 1
    return bool(initial & (space.negation_needed | task.goal_pos | task.goal_neg)) or len(space.groups_of[h0]) > 1


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
        from guided_lfd.planning import find_plan

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
                if _timed_out(limits):
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
                    remaining = None if limits.deadline is None else max(0.01, limits.deadline - clock())
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


#: Registered strategies by name; the first is the default.
STRATEGIES: dict[str, Strategy] = {s.name: s for s in (PortfolioSearch(), LandmarkSearch(), BaselineSearch(),
                                                        SymbolicSearch(), HittingSetSearch())}
DEFAULT_STRATEGY = "portfolio"
