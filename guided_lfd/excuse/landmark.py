"""The landmark search: A* over change sets, bounded by LM-cut and branching on landmarks (the default's core)."""

from __future__ import annotations

import bisect
import heapq
import time
from dataclasses import replace

from guided_lfd.deadline import linger
from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse import outcome
from guided_lfd.excuse.lmcut import INF, Bound, RelaxedExcuseTask
from guided_lfd.excuse.outcome import SearchLimits, SearchOutcome, run_to_outcome
from guided_lfd.excuse.progress import ProgressMeter
from guided_lfd.excuse.reach import CheckPaused, ReachabilityOracle
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.static_groups import static_groups
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.planning.search import SearchStopped
from guided_lfd.planning.task import GroundAction, bits


#: Seconds a candidate's reachability check runs before it pauses for the rest of its f (doubled each turn).
CHECK_SLICE_S = 1.0


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


def _mask(indices: list[int]) -> int:
    out = 0
    for i in indices:
        out |= 1 << i
    return out


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
            if outcome.timed_out(self.limits):
                raise SearchTimeout("excuse search exceeded its time limit")
            if self.limits.turn is not None:
                self.limits.turn()
            if self.limits.stop is not None and self.limits.stop():
                raise SearchStopped()
            if self.probe is not None and not self.solutions and outcome.clock() > self.probe.start:
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
        now = outcome.clock()
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
            with outcome.oracle_until(self.oracle, probe.until):
                greedy.loop(None)
                if greedy.solutions:
                    found = greedy.solutions[0], greedy.plans[greedy.solutions[0]]
                    found = self.trimmed(*found, probe.until)
        except SearchTimeout:
            if outcome.timed_out(self.limits):
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
            if outcome.clock() > until:
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
            bisect.insort(self.paused, (outcome.clock() + slice_s, entry))
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
