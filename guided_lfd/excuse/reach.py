"""Can the robot reach the goal from a candidate excuse state?

The check that decides whether a change set is an excuse.  Unlike a fresh
planner call per candidate (the paper's method), one oracle serves the whole
excuse search:

* states are projected onto the relevant atoms and searched with the
  relevant actions only (irrelevant atoms cannot influence the goal);
* every state of an exhausted (failed) search is remembered as *dead*, and
  every state on a found plan as *alive* with its remaining plan, so later
  candidates stop as soon as they meet a known state;
* a check first asks h^2 (:mod:`guided_lfd.planning.h2`) whether the goal is
  reachable at all when pairs of facts must be reachable together: that
  refutes most candidates that are not excuses in milliseconds, without
  searching (an instrument calibrated but not powered on stays so);
* on large tasks it then hill-climbs on h^FF with helpful actions (a plan
  in about plan-length heuristic evaluations; a relaxed dead end proves the
  goal unreachable at once), trying first the state the relaxed plan itself
  leads to (Vidal's lookahead);
* what is still undecided goes to a portfolio run in turns: greedy
  best-first search on the number of unsatisfied goal atoms (cheap per
  state: it refutes by exhausting the states), lazy greedy search on h^FF
  with helpful actions, boosted as Fast Downward boosts them, and each
  state's lookahead taken next (it confirms plans where the goal count
  wanders plateaus of interchangeable objects),
  the rest of the h^2 check on a large task, and, after the others have had
  :data:`COUNTING_AFTER_S`, the operator-counting program
  (:mod:`guided_lfd.planning.counting`: resources that only run down).  Both searches are
  complete (duplicate detection, finite space); the first to decide answers.
"""

from __future__ import annotations

import heapq
import time
from collections import deque
from dataclasses import dataclass
from typing import Any, Callable, Generator, Iterator

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.planning.counting import OperatorCounting
from guided_lfd.planning.task import GroundAction, bits
from guided_lfd.planning.h2 import PairReachability
from guided_lfd.planning.relaxation import RelaxedTask
from guided_lfd.planning.successors import SuccessorIndex

#: Relevant actions from which reachability checks first hill-climb on h^FF.
GUIDED_MIN_ACTIONS = 1000
#: Heuristic evaluations a hill-climb may spend (plus 4 per step of the
#: first relaxed plan) before the complete search takes over.
HILL_CLIMB_EVALUATIONS = 50
#: Time the h^2 pair check gets before anything else on a candidate (it
#: decides most IPC candidates in a few milliseconds; on a house it goes on
#: as a portfolio member beside the searches).
PAIR_CHECK_FIRST_S = 0.02
#: The pair check is built before its first slice when it needs at most this much memory (every IPC
#: task of the excuse suite); a wider one is built inside its slices, so a candidate that the
#: hill-climb confirms first never pays for it (a house of hundreds of items: gigabytes, seconds).
PAIR_CHECK_EAGER_BYTES = 256 * 2**20
#: Turns the helpful-action queue of the h^FF search gets first after each new best heuristic value
#: (Fast Downward's ``boost`` of ``lazy_greedy``, the same number).
PREFERRED_BOOST = 1000
#: Time a portfolio member runs before the member with the least time so far
#: takes its turn.
PORTFOLIO_SLICE_S = 0.02
#: Portfolio time on a candidate before the operator-counting program is asked (most candidates are decided
#: sooner, and the program costs tens to hundreds of milliseconds), and the most its solver may take.
COUNTING_AFTER_S = 0.5
COUNTING_LIMIT_S = 1.0
#: The program's own limit: above this many relevant actions it is not asked (its LM-cut pass alone takes a
#: second at 5,000 actions and is not interruptible; the houses' checks are the hill-climb's anyway).
COUNTING_MAX_ACTIONS = 20_000
#: Checks paused undecided (``solve``'s ``pause_at``) kept to be resumed; when one more pauses, the one paused
#: longest ago is dropped (its searches closed: asked again, it starts afresh).
MAX_PAUSED = 3


class CheckPaused(Exception):
    """A reachability check reached its pause time undecided; asked again, it resumes where it stopped."""


@dataclass
class _Turns:
    """A check's portfolio: its members and the time each has had (kept across a pause)."""

    members: list[Generator]
    start_after: dict[int, float]  # member -> portfolio time before its first turn
    pairs_pending: bool  # the last member is the h^2 check's rest (it did not finish in its first slice)

    def __post_init__(self) -> None:
        self.spent = [0.0] * len(self.members)
        self.live = set(range(len(self.members)))
        self.waiting = dict(self.start_after)


@dataclass
class ReachStats:
    """Work done by the oracle."""

    calls: int = 0
    expanded: int = 0
    memo_hits: int = 0
    hill_climbs: int = 0  # calls answered by hill-climbing on h^FF
    pair_proofs: int = 0  # calls answered "unreachable" by the h^2 pair check
    ff_searches: int = 0  # calls answered by the h^FF search of the portfolio
    counting_proofs: int = 0  # calls answered "unreachable" by the operator-counting program


class ReachabilityOracle:
    """Goal reachability from excuse states, with memory across calls."""

    def __init__(self, space: ChangeSpace, deadline: float | None = None) -> None:
        self.space = space
        self.mask = space.relevant_atoms
        self.actions = space.relevant_actions
        task = space.task
        self.goal_pos = task.goal_pos
        self.goal_neg = task.goal_neg
        self.deadline = deadline
        #: Asked between the members' turns: True stops the call (:class:`~guided_lfd.planning.search.SearchStopped`).
        self.interrupt: Callable[[], bool] | None = None
        self.dead: set[int] = set()
        self.alive: dict[int, tuple[GroundAction, int] | None] = {}
        self.stats = ReachStats()
        # Large tasks first try hill-climbing on h^FF (see _hill_climb); on
        # small ones the goal-count search is cheaper than one h^FF pass.
        self.guided = len(self.actions) >= GUIDED_MIN_ACTIONS
        self._relaxed: RelaxedTask | None = None
        self._pairs: PairReachability | None = None
        self._counting: OperatorCounting | None = None
        self._paused: dict[int, _Turns] = {}
        # Index each action under its precondition that is most likely false:
        # one false in the initial state (states met are I with a few changes
        # and what the robot does from there: ``(in_hand ?i)`` rather than
        # ``(clear ?c)``), then an atom of the predicate with the most ground
        # atoms (``(lifting h c)`` rather than ``(available h)``), so few
        # actions are tried per state.  Payloads hold the masks the hot loops
        # test and apply (adds projected on the relevant atoms).
        mask = self.mask
        per_predicate: dict[str, int] = {}
        for atom in task.atoms:
            per_predicate[atom.predicate] = per_predicate.get(atom.predicate, 0) + 1
        rarity = [per_predicate[a.predicate] for a in task.atoms]
        true_in_init = set(bits(task.init))
        unconditional = [(None, (a, 0, a.pre_neg, a.delete, a.add & mask)) for a in self.actions if not a.pre_pos]
        self._index = SuccessorIndex(unconditional + [
            (max(act.pre_pos_ids, key=lambda i: (i not in true_in_init, rarity[i], i)),
             (act, act.pre_pos, act.pre_neg, act.delete, act.add & mask))
            for act in self.actions if act.pre_pos])

    def _goal_distance(self, state: int) -> int:
        return (self.goal_pos & ~state).bit_count() + (self.goal_neg & state).bit_count()

    def relaxed_task(self) -> RelaxedTask:
        """The delete relaxation of the relevant actions (built on first use; shared with the optimality proof)."""
        if self._relaxed is None:
            self._relaxed = RelaxedTask(self.actions, self.goal_pos, self.goal_neg)
        return self._relaxed

    def pairs(self) -> PairReachability:
        """The h^2 pair check over the relevant actions (built on first use)."""
        if self._pairs is None:
            self._pairs = PairReachability(self.relaxed_task())
            if self._pairs.estimated_bytes() <= PAIR_CHECK_EAGER_BYTES:
                for _ in self._pairs.build():
                    pass
        return self._pairs

    def _hill_climb(self, start: int) -> list[tuple[int, GroundAction, int]] | None | bool:
        """Enforced hill-climbing on h^FF with helpful actions (Hoffmann and Nebel 2001).

        Returns the path (steps ``(state, action, next state)``) to a goal
        state or to a state known to be alive, ``None`` when the relaxation
        proves the goal unreachable, and ``False`` when it gives up (a
        plateau too wide, a dead end): the complete search then decides.
        A candidate that is an excuse is usually confirmed in about
        plan-length evaluations, where the goal-count search explores whole
        plateaus of interchangeable objects.
        """
        ff = self.relaxed_task()
        mask, actions, goal_pos, goal_neg = self.mask, self.actions, self.goal_pos, self.goal_neg
        first = ff.relaxed_plan(start)
        if first is None:
            return None
        rplan, needed = first
        h = len(rplan)
        budget = HILL_CLIMB_EVALUATIONS + 4 * h
        evaluations = 1
        path: list[tuple[int, GroundAction, int]] = []
        s = start
        while goal_pos & ~s or goal_neg & s:
            if s in self.alive:
                return path
            frontier = deque([(s, needed, ())])
            seen = {s}
            improved = None
            ahead, chain = self._lookahead(s, rplan)
            if chain and ahead not in self.dead:  # the relaxed plan's state first: often a better one
                if ahead in self.alive or not (goal_pos & ~ahead or goal_neg & ahead):
                    return path + list(chain)
                evaluations += 1
                result = ff.relaxed_plan(ahead)
                if result is not None and len(result[0]) < h:
                    improved = (ahead, result, chain)
            while frontier and improved is None:
                u, u_needed, u_steps = frontier.popleft()
                for ai in ff.helpful(u, u_needed):
                    act = actions[ai]
                    t = (u & ~act.delete) | (act.add & mask)
                    if t in seen or t in self.dead:
                        continue
                    seen.add(t)
                    steps = (*u_steps, (u, act, t))
                    if t in self.alive or not (goal_pos & ~t or goal_neg & t):
                        return path + list(steps)
                    evaluations += 1
                    if evaluations > budget:
                        return False
                    if self.deadline is not None and time.monotonic() > self.deadline:
                        raise SearchTimeout("excuse search exceeded its time limit")
                    result = ff.relaxed_plan(t)
                    if result is None:
                        self.dead.add(t)  # relaxed-unreachable: unreachable
                        continue
                    if len(result[0]) < h:
                        improved = (t, result, steps)
                        break
                    frontier.append((t, result[1], steps))
            if improved is None:
                return False
            s, (rplan, needed), steps = improved
            h = len(rplan)
            path.extend(steps)
        return path

    def _record(self, path: list[tuple[int, GroundAction, int]], end: int) -> list[GroundAction]:
        """Remember a found path's states as alive; the whole plan: the path to ``end``, then its remembered rest.

        ``end`` is a goal state or a state already known to be alive.
        """
        alive = self.alive
        path = _without_loops(path)
        for prev, act, nxt in path:
            if prev not in alive:
                alive[prev] = (act, nxt)
        if end not in alive:
            alive[end] = None
        plan = [act for _, act, _ in path]
        s = end
        while alive.get(s) is not None:
            act, s = alive[s]  # type: ignore[misc]
            plan.append(act)
        return plan

    def solve(self, state: int, pause_at: float | None = None) -> list[GroundAction] | None:
        """A plan from ``state`` to the goal, or None if the goal is unreachable.

        With ``pause_at`` (a ``time.monotonic()`` value) a check still undecided then raises
        :class:`CheckPaused`; the next call for the same state resumes it (up to :data:`MAX_PAUSED` kept).
        """
        start = state & self.mask
        turns = self._paused.pop(start, None)
        if turns is None:
            self.stats.calls += 1  # a resumed check is the same call
        if start in self.alive or start in self.dead:
            for member in turns.members if turns is not None else ():
                member.close()  # decided meanwhile by another check
            self.stats.memo_hits += 1
            return self._record([], start) if start in self.alive else None
        if turns is None:
            decided, answer = self._first_checks(start)
            if decided:
                return answer
            turns = answer
        # The last call's searches stay referenced until the next call: a
        # deadline that stops this one does not wait for them to be freed.
        self._scratch = turns.members
        try:
            index, result = self._portfolio(turns, pause_at)
        except CheckPaused:
            self._pause(start, turns)
            raise
        for member in turns.members:
            member.close()  # decided: the others stop (their statistics are counted)
        if index == 2 and turns.pairs_pending:
            return self._proved_dead(start)
        if index == 1:
            self.stats.ff_searches += 1
        if index in turns.start_after:
            self.stats.counting_proofs += 1
        kind, found = result
        if kind == "dead":
            self.dead.update(found)
            return None
        steps, end = found
        return self._record(steps, end)

    def _first_checks(self, start: int) -> tuple[bool, Any]:
        """(True, the answer) when the h^2 check's first slice or the hill-climb decides ``start``, else
        (False, the portfolio that decides it)."""
        pairs = self.pairs().steps(start)
        verdict = _run_for(pairs, PAIR_CHECK_FIRST_S)
        if verdict is False:
            return True, self._proved_dead(start)
        if self.guided:
            climbed = self._hill_climb(start)
            if climbed is None:
                self.dead.add(start)
                return True, None
            if climbed is not False and climbed:
                self.stats.hill_climbs += 1
                return True, self._record(climbed, climbed[-1][2])
        members = [self._goal_count_search(start), self._ff_search(start)]
        if verdict is None:  # the pair check did not finish in its first slice: it goes on beside the searches
            members.append(pairs)
        start_after = {}
        if not self.space.task.is_adl and len(self.actions) <= COUNTING_MAX_ACTIONS:
            start_after[len(members)] = COUNTING_AFTER_S
            members.append(self._counting_check(start))
        return False, _Turns(members, start_after, verdict is None)

    def _pause(self, start: int, turns: _Turns) -> None:
        """Keep ``turns`` to resume ``start``'s check, dropping the check paused longest ago beyond
        :data:`MAX_PAUSED`."""
        self._paused[start] = turns
        while len(self._paused) > MAX_PAUSED:
            oldest = next(iter(self._paused))
            for member in self._paused.pop(oldest).members:
                member.close()

    def _proved_dead(self, start: int) -> None:
        self.stats.pair_proofs += 1
        self.dead.add(start)
        return None

    def _counting_check(self, start: int) -> Generator[None, None, tuple[str, Any] | bool]:
        """The operator-counting program as a portfolio member: ("dead", {start}) when it has no solution,
        else True (undecided: the searches go on).  Set up on its first turn."""
        yield
        if self._counting is None:
            self._counting = OperatorCounting(self.relaxed_task(), self.goal_pos)
        limit = COUNTING_LIMIT_S
        if self.deadline is not None and self.deadline - time.monotonic() < 2 * COUNTING_LIMIT_S:
            return True  # too close to the deadline for a step that cannot be interrupted
        if self._counting.dead(start, limit):
            return "dead", {start}
        return True

    def _portfolio(self, turns: _Turns, pause_at: float | None = None) -> tuple[int, Any]:
        """Run the members in turns, each when it has had the least time, until one decides.

        Returns (member index, its verdict).  The goal-count search is cheap
        per state and refutes small spaces; the h^FF search confirms a plan
        in about plan-length evaluations; the pair check refutes with no
        search at all.  Interleaved, a call costs at most a few times what the
        member suited to the candidate would have cost alone.  Past ``pause_at``
        it raises :class:`CheckPaused` (``turns`` keeps where it stopped).
        """
        members, spent, live, waiting = turns.members, turns.spent, turns.live, turns.waiting
        deadline = self.deadline
        while True:
            if waiting:
                total = sum(spent)
                for i in [i for i, after in waiting.items() if total >= after]:
                    del waiting[i]
            index = min(live - waiting.keys(), key=spent.__getitem__)
            member = members[index]
            began = time.monotonic()
            try:
                while True:  # at least one step per turn
                    next(member)
                    now = time.monotonic()
                    if now - began >= PORTFOLIO_SLICE_S:
                        break
            except StopIteration as done:
                if done.value is not True:  # True: the pair check could not refute; the searches go on
                    return index, done.value
                live.discard(index)
                now = time.monotonic()
            spent[index] += now - began
            if deadline is not None and now > deadline:
                raise SearchTimeout("excuse search exceeded its time limit")
            if self.interrupt is not None and self.interrupt():
                from guided_lfd.planning.search import SearchStopped

                raise SearchStopped()
            if pause_at is not None and now > pause_at:
                raise CheckPaused()

    def _successors(self, s: int) -> Iterator[tuple[GroundAction, int]]:
        """(action, next state) for every relevant action applicable in ``s``."""
        buckets = self._index.candidates(s)
        for bucket in buckets:
            for act, pre_pos, pre_neg, delete, add in bucket:
                if (s & pre_pos) == pre_pos and not s & pre_neg:
                    yield act, (s & ~delete) | add

    def _ff_search(self, start: int) -> Generator[None, None, tuple[str, Any]]:
        """Lazy greedy best-first search on h^FF with helpful actions preferred (a portfolio member).

        Lazy, as Fast Downward's ``lazy_greedy``: a state is evaluated when it
        is expanded, its successors queued with its value; helpful successors
        also enter a second queue, and the two queues take turns, the helpful
        one boosted on progress (:class:`AlternatingQueues`).  States the
        relaxation proves dead are pruned and remembered.  Complete: when both
        queues run dry, every state reached is dead.
        """
        ff = self.relaxed_task()
        parents: dict[int, tuple[int, GroundAction] | None] = {}
        queues = AlternatingQueues()
        queues.push(0, (start, None), False)
        goal_pos, goal_neg, mask = self.goal_pos, self.goal_neg, self.mask
        alive, dead, actions = self.alive, self.dead, self.actions
        best_h: int | None = None
        try:
            while queues:
                s, parent = queues.pop()
                if s in parents:
                    continue
                parents[s] = parent
                if s in alive or not (goal_pos & ~s or goal_neg & s):
                    return "plan", (_path(parents, s), s)
                if s in dead:
                    continue
                yield
                relaxed = ff.relaxed_plan(s)
                if relaxed is None:
                    dead.add(s)
                    continue
                h = len(relaxed[0])
                if best_h is None or h < best_h:
                    if best_h is not None:
                        queues.boost()
                    best_h = h
                ahead, chain = self._lookahead(s, relaxed[0])
                if chain and ahead not in parents and ahead not in dead:  # value 0: taken next, as YAHSP does
                    queues.push(0, (ahead, (s, chain)), True)
                for act, t in self._successors(s):
                    if t not in parents and t not in dead:
                        queues.push(h, (t, (s, act)), False)
                for ai in ff.helpful(s, relaxed[1]):
                    act = actions[ai]
                    t = (s & ~act.delete) | (act.add & mask)
                    if t not in parents and t not in dead:
                        queues.push(h, (t, (s, act)), True)
            return "dead", parents
        finally:
            self.stats.expanded += len(parents)  # the states it expanded (or met alive)

    def _lookahead(self, s: int, plan: list[int]) -> tuple[int, tuple[tuple[int, GroundAction, int], ...]]:
        """The state reached by applying the relaxed plan's actions while any applies (Vidal's lookahead, YAHSP).

        Each step applies the first applicable action of the plan (in h^add order) that deletes nothing
        another of its actions still needs, or else the first applicable one; each action once.  Returns
        that state and the steps to it (none when nothing applies).  Where the relaxed plan is mostly a real
        one (transport, depot), its state is many steps ahead for one evaluation.
        """
        actions, mask, alive = self.actions, self.mask, self.alive
        goal_pos, goal_neg = self.goal_pos, self.goal_neg
        todo = [actions[ai] for ai in plan]
        steps: list[tuple[int, GroundAction, int]] = []
        visited = {s}  # a step back to a state of the chain is not taken (a plan must not loop)
        while todo and s not in alive and (goal_pos & ~s or goal_neg & s):
            after = [0] * (len(todo) + 1)  # after[k]: what the actions after the k-th need
            for k in range(len(todo) - 1, -1, -1):
                after[k] = after[k + 1] | todo[k].pre_pos
            before = 0
            harmless = first = None
            for k, act in enumerate(todo):
                others = before | after[k + 1]
                before |= act.pre_pos
                if (s & act.pre_pos) == act.pre_pos and not s & act.pre_neg:
                    if not act.delete & others & s:
                        harmless = k
                        break
                    if first is None:
                        first = k
            k = harmless if harmless is not None else first
            if k is None:
                break
            act = todo.pop(k)
            t = (s & ~act.delete) | (act.add & mask)
            if t not in visited:
                visited.add(t)
                steps.append((s, act, t))
                s = t
        return s, tuple(steps)

    def _goal_count_search(self, start: int) -> Generator[None, None, tuple[str, Any]]:
        """Greedy best-first search on the number of unsatisfied goal atoms (a portfolio member).

        Complete (duplicate detection, finite space) and cheap per state, so
        it is the member that refutes a candidate by exhausting its states.
        """
        parents: dict[int, tuple[int, GroundAction] | None] = {start: None}
        counter = 0
        heap = [(self._goal_distance(start), counter, start)]
        expanded = 0
        # The loop is the oracle's hot path: successor generation and the goal
        # distance are inlined (a generator and two calls per state cost more
        # than the bit operations themselves).  States are already projected on
        # the relevant atoms, and so are the stored add effects.
        goal_pos, goal_neg = self.goal_pos, self.goal_neg
        alive, dead = self.alive, self.dead
        candidates = self._index.candidates
        memo_hits = 0
        pop, push = heapq.heappop, heapq.heappush
        try:
            while heap:
                _, _, s = pop(heap)
                if s in alive:
                    memo_hits += 1
                    return "plan", (_path(parents, s), s)
                if not (goal_pos & ~s or goal_neg & s):
                    alive[s] = None
                    return "plan", (_path(parents, s), s)
                expanded += 1
                if not expanded & 255:
                    yield
                for bucket in candidates(s):
                    for act, pre_pos, pre_neg, delete, add in bucket:
                        if (s & pre_pos) != pre_pos or s & pre_neg:
                            continue
                        t = (s & ~delete) | add
                        if t in parents:
                            continue
                        if t in dead:
                            memo_hits += 1
                            continue
                        parents[t] = (s, act)
                        counter += 1
                        push(heap, ((goal_pos & ~t).bit_count() + (goal_neg & t).bit_count(), counter, t))
            return "dead", parents
        finally:
            self.stats.memo_hits += memo_hits
            self.stats.expanded += expanded


class AlternatingQueues:
    """Two priority queues of a greedy search, all successors in one and the preferred (helpful) ones in the
    other, taken in turns as by Fast Downward's alternation open list: the queue taken least often goes next
    (ties: the first), and :meth:`boost` gives the preferred queue :data:`PREFERRED_BOOST` turns first.  Within
    a queue, the lowest value first, then first in, first out.

    The boost on each new best heuristic value is what makes the helpful actions pay: without it, a depot
    candidate with 15 crates and a hoist at every place is not solved in 100 s by Fast Downward itself, with
    it in 2,172 states.
    """

    def __init__(self) -> None:
        self.queues: tuple[list[tuple[int, int, Any]], list[tuple[int, int, Any]]] = ([], [])
        self.turns = [0, 0]
        self.count = 0

    def __bool__(self) -> bool:
        return bool(self.queues[0] or self.queues[1])

    def push(self, value: int, entry: Any, preferred: bool) -> None:
        """Queue ``entry`` with ``value`` (in the preferred queue when ``preferred``)."""
        self.count += 1
        heapq.heappush(self.queues[preferred], (value, self.count, entry))

    def pop(self) -> Any:
        """The next entry: from the queue taken least often so far that has one."""
        every, preferred = self.queues
        side = 0 if not preferred or (every and self.turns[0] <= self.turns[1]) else 1
        self.turns[side] += 1
        return heapq.heappop(self.queues[side])[2]

    def boost(self) -> None:
        """Give the preferred queue the next :data:`PREFERRED_BOOST` turns (progress was made)."""
        self.turns[1] -= PREFERRED_BOOST


def _without_loops(path: list[tuple[int, GroundAction, int]]) -> list[tuple[int, GroundAction, int]]:
    """``path`` with every stretch that comes back to a state it left cut out (a lookahead may step back to
    where the search came from; remembered as alive, such a loop would make the remaining plan endless)."""
    out: list[tuple[int, GroundAction, int]] = []
    at: dict[int, int] = {}
    for step in path:
        at[step[0]] = len(out)
        out.append(step)
        back = at.get(step[2])
        if back is not None:
            for cut in out[back:]:
                del at[cut[0]]
            del out[back:]
    return out


def _path(parents: dict[int, tuple[int, GroundAction] | None], end: int) -> list[tuple[int, GroundAction, int]]:
    """The steps (state, action, next state) from the search's start to ``end``."""
    steps: list[tuple[int, GroundAction, int]] = []
    s = end
    while parents[s] is not None:
        prev, act = parents[s]  # type: ignore[misc]
        if isinstance(act, tuple):  # a lookahead's steps
            steps.extend(reversed(act))
        else:
            steps.append((prev, act, s))
        s = prev
    steps.reverse()
    return steps


def _run_for(steps: Generator[None, None, bool], seconds: float) -> bool | None:
    """Advance ``steps`` for about ``seconds``: its answer, or None if it is not done by then."""
    began = time.monotonic()
    try:
        while time.monotonic() - began < seconds:
            next(steps)
    except StopIteration as done:
        return bool(done.value)
    return None
