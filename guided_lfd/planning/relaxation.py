"""Delete relaxations of a ground task: LM-cut and the FF heuristic.

Both work on one table of relaxed facts and actions built once per task
(plain lists: the tasks are evaluated state by state in pure Python).  Facts
are the atoms the actions and the goal mention, plus complement facts
("not p") for negative preconditions and goals, made true by the actions
that delete ``p``.  Fact 0 is "true at the start" (the precondition of
precondition-free actions), fact 1 the goal, added by an artificial goal
action of cost 0 (the last action).

* :meth:`RelaxedTask.lmcut` (Helmert and Domshlak 2009): an admissible
  lower bound on the cost of a plan, used to prove plans optimal;
* :meth:`RelaxedTask.relaxed_plan` and :meth:`RelaxedTask.helpful` (the FF
  heuristic, Hoffmann and Nebel 2001): a relaxed plan from h^add's best
  supporters and the helpful actions it suggests, used to guide the excuse
  search's reachability checks.

One table serves both, so the oracle's hill-climb and the optimality proof
of the robot's plan share it.
"""

from __future__ import annotations

import heapq
from typing import Sequence

from guided_lfd.planning.task import GroundAction, bits, mask_of

INF = float("inf")


class RelaxedTask:
    """The relaxed facts and actions of a fixed set of ground actions (costs default to the actions' own)."""

    def __init__(self, actions: Sequence[GroundAction], goal_pos: int, goal_neg: int,
                 costs: Sequence[int] | None = None, sure_adds: Sequence[int] | None = None) -> None:
        """``sure_adds``: per action, the adds that surely happen (default: all of ``add``); a delete makes
        its complement fact true unless one of them re-adds the atom (an ADL action's conditional adds may not)."""
        self.actions = list(actions)
        negated_ids = set(bits(goal_neg))
        mentioned_ids = set(bits(goal_pos | goal_neg))
        for act in self.actions:
            negated_ids.update(act.pre_neg_ids)
            mentioned_ids.update(act.pre_pos_ids, act.pre_neg_ids, act.add_ids, act.delete_ids)
        # Fact 0 is "true at the start" (precondition of precondition-free
        # actions), fact 1 the goal (added by the artificial goal action).
        self.pos_id = {a: 2 + k for k, a in enumerate(sorted(mentioned_ids))}
        self.neg_id = {a: 2 + len(self.pos_id) + k for k, a in enumerate(sorted(negated_ids))}
        self.n_facts = 2 + len(self.pos_id) + len(self.neg_id)
        pos_id, neg_id = self.pos_id, self.neg_id
        pre: list[list[int]] = []
        add: list[list[int]] = []
        for k, act in enumerate(self.actions):
            p = [pos_id[i] for i in act.pre_pos_ids] + [neg_id[i] for i in act.pre_neg_ids]
            pre.append(p or [0])
            adds = act.add_ids
            sure = adds if sure_adds is None else set(bits(sure_adds[k]))
            add.append([pos_id[i] for i in adds]
                       + [neg_id[i] for i in act.delete_ids if i in neg_id and i not in sure])
        goal = [pos_id[i] for i in bits(goal_pos)] + [neg_id[i] for i in bits(goal_neg)]
        pre.append(goal or [0])  # the artificial goal action, cost 0
        add.append([1])
        self.pre, self.add = pre, add
        self.base_costs = [*(costs if costs is not None else [a.cost for a in self.actions]), 0]
        self._n_pre = [len(p) for p in pre]  # copied per h^max / h^add pass (cheaper than counting again)
        #: An applicable action adds only facts of h^add at most its cost: the needed facts above this
        #: have no applicable achiever, so helpful actions never look at them.
        self._max_cost = max(self.base_costs)
        self.prec_of: list[list[int]] = [[] for _ in range(self.n_facts)]
        self.achievers: list[list[int]] = [[] for _ in range(self.n_facts)]
        for ai, p in enumerate(pre):
            for f in p:
                self.prec_of[f].append(ai)
            for f in add[ai]:
                self.achievers[f].append(ai)
        self.negated, self.mentioned = mask_of(negated_ids), mask_of(mentioned_ids)
        self._cost_by_name: dict[str, int] | None = None

    def _true_facts(self, state: int) -> list[int]:
        pos_id, neg_id = self.pos_id, self.neg_id
        return [0, *(pos_id[i] for i in bits(state & self.mentioned)), *(neg_id[i] for i in bits(self.negated & ~state))]


    def plan_cost(self, plan: Sequence[GroundAction]) -> int:
        """The cost of ``plan`` (its actions must be among this task's)."""
        if self._cost_by_name is None:
            self._cost_by_name = {a.name: c for a, c in zip(self.actions, self.base_costs)}
        return sum(self._cost_by_name[a.name] for a in plan)

    def _hmax(self, true: list[int], cost: list[int]) -> tuple[list[float], list[int]]:
        """h^max of every fact and each reached action's precondition choice (-1 = not reached)."""
        n_actions = len(self.pre)
        h = [INF] * self.n_facts
        unsat = self._n_pre[:]
        pcf = [-1] * n_actions
        heap: list[tuple[float, int]] = []
        for f in true:
            h[f] = 0
            heap.append((0, f))
        heapq.heapify(heap)
        prec_of, add = self.prec_of, self.add
        pop, push = heapq.heappop, heapq.heappush
        while heap:
            c, f = pop(heap)
            if c > h[f]:
                continue
            # No early stop at the goal: the cut must see every reachable
            # achiever of the goal zone, or it may not be a landmark.
            for ai in prec_of[f]:
                left = unsat[ai] - 1
                unsat[ai] = left
                if left:
                    continue
                # Facts are settled in order of h: the last precondition is a maximal one.
                pcf[ai] = f
                reach = c + cost[ai]
                for q in add[ai]:
                    if reach < h[q]:
                        h[q] = reach
                        push(heap, (reach, q))
        return h, pcf

    def lmcut(self, state: int, cuts: list[list[int]] | None = None) -> float:
        """The LM-cut lower bound on the cost of a plan from ``state`` (INF = unsolvable).

        ``cuts``, when given, receives each cut: a disjunctive action landmark (every plan from ``state``
        has one of its actions; the artificial goal action never is one, being free).
        """
        cost = list(self.base_costs)
        true = self._true_facts(state)
        total = 0
        achievers, pre = self.achievers, self.pre
        while True:
            h, pcf = self._hmax(true, cost)
            if h[1] == INF:
                return INF  # only before the first cut: costs only ever decrease
            if h[1] == 0:
                return total
            # Goal zone: facts from which the goal is reached by zero-cost
            # actions along the precondition choice function.
            zone = {1}
            stack = [1]
            while stack:
                q = stack.pop()
                for ai in achievers[q]:
                    p = pcf[ai]
                    if p < 0 or cost[ai] != 0 or p in zone:
                        continue
                    zone.add(p)
                    stack.append(p)
            # The cut: actions of positive cost whose chosen precondition is
            # reached from the state without entering the zone, and that add a
            # zone fact (every relaxed plan uses one of them).
            seen = {f for f in true if f not in zone}
            stack = list(seen)
            cut = []
            prec_of, add = self.prec_of, self.add
            while stack:
                f = stack.pop()
                for ai in prec_of[f]:
                    if pcf[ai] != f:
                        continue
                    for q in add[ai]:
                        if q in zone:
                            if cost[ai] > 0:
                                cut.append(ai)
                        elif q not in seen:
                            seen.add(q)
                            stack.append(q)
            if not cut:
                return total  # guard: cannot happen for a finite positive h
            cut = list(set(cut))
            if cuts is not None:
                cuts.append(cut)
            m = min(cost[ai] for ai in cut)
            total += m
            for ai in cut:
                cost[ai] -= m

    def relaxed_plan(self, state: int) -> tuple[list[int], set[int]] | None:
        """(relaxed plan as action indices, in order of h^add, the facts it needs that an action applicable
        in ``state`` may add); None = relaxed dead end."""
        true = self._true_facts(state)
        n_actions = len(self.pre)
        h = [INF] * self.n_facts
        best = [-1] * self.n_facts
        unsat = self._n_pre[:]
        acc = [0.0] * n_actions
        for f in true:
            h[f] = 0
        heap = [(0, f) for f in true]
        heapq.heapify(heap)
        prec_of, add, cost = self.prec_of, self.add, self.base_costs
        pop, push = heapq.heappop, heapq.heappush
        while heap:
            c, f = pop(heap)
            if c > h[f]:
                continue
            if f == 1:
                break  # h^add is Dijkstra-like: the goal's value is final
            for ai in prec_of[f]:
                acc[ai] += c
                left = unsat[ai] - 1
                unsat[ai] = left
                if left:
                    continue
                reach = acc[ai] + cost[ai]
                for q in add[ai]:
                    if reach < h[q]:
                        h[q] = reach
                        best[q] = ai
                        push(heap, (reach, q))
        if h[1] == INF:
            return None
        chosen: set[int] = set()
        needed: set[int] = set()
        stack = [1]
        pre = self.pre
        while stack:
            q = stack.pop()
            if h[q] == 0 or q in needed:
                continue
            needed.add(q)
            ai = best[q]
            if ai not in chosen:
                chosen.add(ai)
                stack.extend(pre[ai])
        goal_action = n_actions - 1
        chosen.discard(goal_action)
        needed.discard(1)
        most = self._max_cost
        # In the order of h^add of the preconditions: an action before those that need what it adds, so the
        # plan can be tried as it stands (the oracle's lookahead).
        return sorted(chosen, key=lambda ai: (acc[ai], ai)), {q for q in needed if h[q] <= most}

    def helpful(self, state: int, needed: set[int]) -> list[int]:
        """Actions applicable in ``state`` that add a fact the relaxed plan needs (FF's helpful actions).

        Those adding the most needed facts come first: putting the plate
        *into the goal drawer* frees the hand and achieves a goal, putting
        it on any counter only frees the hand.
        """
        count: dict[int, int] = {}
        applicable: dict[int, bool] = {}
        actions = self.actions
        n = len(actions)
        for f in needed:
            for ai in self.achievers[f]:
                if ai >= n:
                    continue
                ok = applicable.get(ai)
                if ok is None:
                    act = actions[ai]
                    ok = applicable[ai] = (state & act.pre_pos) == act.pre_pos and not state & act.pre_neg
                if ok:
                    count[ai] = count.get(ai, 0) + 1
        return sorted(count, key=lambda ai: (-count[ai], ai))
