"""Admissible excuse bounds and landmarks: LM-cut on the compiled relaxed task.

Following Göbelbecker et al. (2010), the excuse search is compiled into one
planning task: a *change* action per atom flip (cost = its weight, no
precondition) and the robot's actions (cost 0).  Its delete relaxation,
evaluated with LM-cut, gives

* ``h``: a lower bound on the weight of any excuse extending a change set, and
* disjunctive landmarks: sets of changes of which every such excuse must make
  at least one.  Branching on the smallest landmark keeps the search complete
  while only trying changes that can matter.

Negative preconditions and goals are handled with complement facts ("not p"),
which a change can also make true (deleting p).
"""

from __future__ import annotations

import heapq
from dataclasses import dataclass

from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.grounding import bits

INF = float("inf")


@dataclass
class Bound:
    """LM-cut result: ``h`` (INF = no excuse extends the change set) and landmarks."""

    h: float
    landmarks: list[list[int]]


class RelaxedExcuseTask:
    """The delete relaxation of the compiled excuse task, over relevant facts only."""

    def __init__(self, space: ChangeSpace) -> None:
        self.space = space
        pos = list(bits(space.relevant_atoms))
        neg = list(bits(space.negation_needed))
        self.pos_id = {a: f for f, a in enumerate(pos)}
        self.neg_id = {a: len(pos) + f for f, a in enumerate(neg)}
        self.fact_atom = pos + neg  # fact id -> atom index it flips
        self.fact_positive = [True] * len(pos) + [False] * len(neg)
        self.n_facts = len(self.fact_atom)
        pre: list[list[int]] = []
        add: list[list[int]] = []
        for act in space.relevant_actions:
            p = [self.pos_id[i] for i in bits(act.pre_pos)] + [self.neg_id[i] for i in bits(act.pre_neg)]
            e = [self.pos_id[i] for i in bits(act.add) if i in self.pos_id]
            e += [self.neg_id[i] for i in bits(act.delete & ~act.add) if i in self.neg_id]
            pre.append(p)
            add.append(e)
        self.pre = pre
        self.add = add
        self.n_pre = [len(p) for p in pre]
        self.precondition_of: list[list[int]] = [[] for _ in range(self.n_facts)]
        self.achievers: list[list[int]] = [[] for _ in range(self.n_facts)]
        for ai, p in enumerate(pre):
            for f in p:
                self.precondition_of[f].append(ai)
            for f in add[ai]:
                self.achievers[f].append(ai)
        self.free_actions = [ai for ai, n in enumerate(self.n_pre) if n == 0]
        task = space.task
        self.goal = [self.pos_id[i] for i in bits(task.goal_pos)] + [self.neg_id[i] for i in bits(task.goal_neg)]
        self.rel_mask = space.relevant_atoms
        self.neg_mask = space.negation_needed

    def _initial_costs(self, state: int, changes: int) -> tuple[list[int], dict[int, int]]:
        """Facts true in ``state`` and the remaining change cost of the others."""
        true_facts = [self.pos_id[i] for i in bits(state & self.rel_mask)]
        true_facts += [self.neg_id[i] for i in bits(self.neg_mask & ~state)]
        flippable = self.space.changeable & ~changes
        weights = self.space.weights
        costs: dict[int, int] = {}
        for i in bits(self.rel_mask & ~state & flippable):
            costs[self.pos_id[i]] = weights[i]
        for i in bits(self.neg_mask & state & flippable):
            costs[self.neg_id[i]] = weights[i]
        return true_facts, costs

    def _hmax(self, true_facts: list[int], costs: dict[int, int]) -> tuple[list[float], list[int]]:
        h = [INF] * self.n_facts
        heap: list[tuple[float, int]] = []
        for f, c in costs.items():
            h[f] = c
            heap.append((c, f))
        for f in true_facts:
            h[f] = 0
            heap.append((0, f))
        heapq.heapify(heap)
        unsat = self.n_pre[:]
        pcf = [-1] * len(unsat)
        add = self.add
        for ai in self.free_actions:
            pcf[ai] = -2
            for q in add[ai]:
                if h[q] > 0:
                    h[q] = 0
                    heapq.heappush(heap, (0, q))
        precondition_of = self.precondition_of
        while heap:
            c, f = heapq.heappop(heap)
            if c > h[f]:
                continue
            for ai in precondition_of[f]:
                unsat[ai] -= 1
                if unsat[ai] == 0:
                    pcf[ai] = f
                    for q in add[ai]:
                        if c < h[q]:
                            h[q] = c
                            heapq.heappush(heap, (c, q))
        return h, pcf

    def bound(self, state: int, changes: int, want_landmarks: bool = True) -> Bound:
        """LM-cut value and landmarks (as atom indices to flip) for excuses extending ``changes``."""
        true_facts, costs = self._initial_costs(state, changes)
        if not self.goal:
            return Bound(0, [])
        total = 0
        landmarks: list[list[int]] = []
        while True:
            h, pcf = self._hmax(true_facts, costs)
            goal_fact = max(self.goal, key=lambda g: h[g])
            if h[goal_fact] == INF:
                return Bound(INF, [])
            if h[goal_fact] == 0:
                return Bound(total, landmarks)
            # Goal zone: facts that reach the goal through zero-cost robot actions.
            zone = {goal_fact}
            stack = [goal_fact]
            while stack:
                q = stack.pop()
                for ai in self.achievers[q]:
                    f = pcf[ai]
                    if f >= 0 and f not in zone and h[f] > 0:
                        zone.add(f)
                        stack.append(f)
            cut = [f for f in zone if costs.get(f, 0) > 0]
            if not cut:  # cannot happen for finite h; guard against a silent loop
                return Bound(total, landmarks)
            m = min(costs[f] for f in cut)
            total += m
            for f in cut:
                costs[f] -= m
            if want_landmarks:
                landmarks.append(sorted(self.fact_atom[f] for f in cut))
