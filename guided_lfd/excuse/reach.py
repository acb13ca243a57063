"""Can the robot reach the goal from a candidate excuse state?

The check that decides whether a change set is an excuse.  Unlike a fresh
planner call per candidate (the paper's method), one oracle serves the whole
excuse search:

* states are projected onto the relevant atoms and searched with the
  relevant actions only (irrelevant atoms cannot influence the goal);
* every state of an exhausted (failed) search is remembered as *dead*, and
  every state on a found plan as *alive* with its remaining plan, so later
  candidates stop as soon as they meet a known state;
* the search is greedy best-first on the number of unsatisfied goal atoms,
  which finds plans fast and is complete (duplicate detection, finite space).
"""

from __future__ import annotations

import heapq
import time
from dataclasses import dataclass

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.grounding import GroundAction, bits


@dataclass
class ReachStats:
    """Work done by the oracle."""

    calls: int = 0
    expanded: int = 0
    memo_hits: int = 0


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
        init = task.init
        self._by_first_pre: dict[int, list[tuple]] = {}
        for act in self.actions:
            if act.pre_pos:
                key = max(act.pre_pos_ids, key=lambda i: (not (init >> i) & 1, rarity[i], i))
                self._by_first_pre.setdefault(key, []).append((act, act.pre_pos, act.pre_neg, act.delete, act.add & mask))
        self._key_mask = 0
        for key in self._by_first_pre:
            self._key_mask |= 1 << key

    def _goal_distance(self, state: int) -> int:
        return (self.goal_pos & ~state).bit_count() + (self.goal_neg & state).bit_count()

    def solve(self, state: int) -> list[GroundAction] | None:
        """A plan from ``state`` to the goal, or None if the goal is unreachable."""
        self.stats.calls += 1
        start = state & self.mask
        parents: dict[int, tuple[int, GroundAction] | None] = {start: None}
        counter = 0
        heap = [(self._goal_distance(start), counter, start)]
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
        path: list[tuple[int, GroundAction]] = []
        s = found
        while parents[s] is not None:
            prev, act = parents[s]  # type: ignore[misc]
            path.append((prev, act))
            s = prev
        path.reverse()
        for (prev, act), nxt in zip(path, [p for p, _ in path[1:]] + [found]):
            self.alive[prev] = (act, nxt)
        plan = [act for _, act in path]
        s = found
        while self.alive.get(s) is not None:
            act, s = self.alive[s]  # type: ignore[misc]
            plan.append(act)
        return plan

