"""Can the robot reach the goal from a candidate excuse state?

The check that decides whether a change set is an excuse.  Unlike a fresh
planner call per candidate (the paper's method), one oracle serves the whole
excuse search:

* states are projected onto the relevant atoms and searched with the
  relevant actions only (irrelevant atoms cannot influence the goal);
* every state of an exhausted (failed) search is remembered as *dead*, and
  every state on a found plan as *alive* with its remaining plan, so later
  candidates stop as soon as they meet a known state;
* on large tasks a check first hill-climbs on h^FF with helpful actions
  (a plan in about plan-length heuristic evaluations; a relaxed dead end
  proves the goal unreachable at once);
* otherwise, or when hill-climbing gives up, the search is greedy
  best-first on the number of unsatisfied goal atoms, which is complete
  (duplicate detection, finite space).
"""

from __future__ import annotations

import heapq
import time
from collections import deque
from dataclasses import dataclass

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.grounding import GroundAction, bits
from guided_lfd.relaxation import RelaxedTask

#: Relevant actions from which reachability checks first hill-climb on h^FF.
GUIDED_MIN_ACTIONS = 1000
#: Heuristic evaluations a hill-climb may spend (plus 4 per step of the
#: first relaxed plan) before the complete search takes over.
HILL_CLIMB_EVALUATIONS = 50


@dataclass
class ReachStats:
    """Work done by the oracle."""

    calls: int = 0
    expanded: int = 0
    memo_hits: int = 0
    hill_climbs: int = 0  # calls answered by hill-climbing on h^FF


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
        self.dead: set[int] = set()
        self.alive: dict[int, tuple[GroundAction, int] | None] = {}
        self.stats = ReachStats()
        # Large tasks first try hill-climbing on h^FF (see _hill_climb); on
        # small ones the goal-count search is cheaper than one h^FF pass.
        self.guided = len(self.actions) >= GUIDED_MIN_ACTIONS
        self._relaxed: RelaxedTask | None = None
        # Index actions by one positive precondition so successor generation
        # skips most inapplicable actions; actions without one are always tried
        # (bucket 0, entries with pre_pos = 0).
        mask = self.mask
        self._unconditional = [(a, 0, a.pre_neg, a.delete, a.add & mask) for a in self.actions if not a.pre_pos]
        # Index each action under its precondition that is most likely false:
        # one false in the initial state (states met are I with a few changes
        # and what the robot does from there: ``(in_hand ?i)`` rather than
        # ``(clear ?c)``), then an atom of the predicate with the most ground
        # atoms (``(lifting h c)`` rather than ``(available h)``), so few
        # actions are tried per state.
        per_predicate: dict[str, int] = {}
        for atom in task.atoms:
            per_predicate[atom.predicate] = per_predicate.get(atom.predicate, 0) + 1
        rarity = [per_predicate[a.predicate] for a in task.atoms]
        true_in_init = set(bits(task.init))
        self._by_first_pre: dict[int, list[tuple]] = {}
        for act in self.actions:
            if act.pre_pos:
                key = max(act.pre_pos_ids, key=lambda i: (i not in true_in_init, rarity[i], i))
                self._by_first_pre.setdefault(key, []).append((act, act.pre_pos, act.pre_neg, act.delete, act.add & mask))
        self._key_mask = 0
        for key in self._by_first_pre:
            self._key_mask |= 1 << key

    def _goal_distance(self, state: int) -> int:
        return (self.goal_pos & ~state).bit_count() + (self.goal_neg & state).bit_count()

    def relaxed_task(self) -> RelaxedTask:
        """The delete relaxation of the relevant actions (built on first use; shared with the optimality proof)."""
        if self._relaxed is None:
            self._relaxed = RelaxedTask(self.actions, self.goal_pos, self.goal_neg)
        return self._relaxed

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
        h, needed = len(first[0]), first[1]
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

    def solve(self, state: int) -> list[GroundAction] | None:
        """A plan from ``state`` to the goal, or None if the goal is unreachable."""
        self.stats.calls += 1
        start = state & self.mask
        if self.guided and start not in self.alive and start not in self.dead:
            climbed = self._hill_climb(start)
            if climbed is None:
                self.dead.add(start)
                return None
            if climbed is not False and climbed:
                self.stats.hill_climbs += 1
                return self._record(climbed, climbed[-1][2])
        parents: dict[int, tuple[int, GroundAction] | None] = {start: None}
        counter = 0
        heap = [(self._goal_distance(start), counter, start)]
        # The last call's frontier stays referenced until the next call: a
        # deadline that stops this one does not wait for it to be freed.
        self._scratch = (parents, heap)
        expanded = 0
        found: int | None = None
        # The loop is the oracle's hot path: successor generation and the goal
        # distance are inlined (a generator and two calls per state cost more
        # than the bit operations themselves).  States are already projected on
        # the relevant atoms, and so are the stored add effects.
        goal_pos, goal_neg = self.goal_pos, self.goal_neg
        alive, dead, by_first = self.alive, self.dead, self._by_first_pre
        unconditional, key_mask, deadline = self._unconditional, self._key_mask, self.deadline
        memo_hits = 0
        pop, push = heapq.heappop, heapq.heappush
        while heap:
            _, _, s = pop(heap)
            if s in alive:
                found = s
                memo_hits += 1
                break
            if not (goal_pos & ~s or goal_neg & s):
                alive[s] = None
                found = s
                break
            expanded += 1
            if deadline is not None and not expanded & 63 and time.monotonic() > deadline:
                self.stats.expanded += expanded
                self.stats.memo_hits += memo_hits
                raise SearchTimeout("excuse search exceeded its time limit")
            buckets = [unconditional] if unconditional else []
            keys = s & key_mask
            while keys:
                low = keys & -keys
                keys ^= low
                buckets.append(by_first[low.bit_length() - 1])
            for bucket in buckets:
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
        self.stats.memo_hits += memo_hits
        self.stats.expanded += expanded
        if found is None:
            self.dead.update(parents)
            return None
        # Path from start to the meeting state, then the remembered rest.
        steps: list[tuple[int, GroundAction, int]] = []
        s = found
        while parents[s] is not None:
            prev, act = parents[s]  # type: ignore[misc]
            steps.append((prev, act, s))
            s = prev
        steps.reverse()
        return self._record(steps, found)

