"""The delete relaxation: one core for every relaxed question the tool asks.

A relaxed task is a table of facts and actions: each action's precondition
facts and add facts (deletes ignored).  On such a table this module holds
the one implementation of each idea:

* :func:`index_facts`: each fact's consumers and achievers;
* :func:`close`: the relaxed closure (what a delete-free run reaches), grown
  in place, optionally stopping at the goal;
* :func:`hmax`: h^max from seeded facts, a level at a time (zero-cost actions
  extend a level as a closure);
* :func:`lmcut`: the LM-cut loop (Helmert and Domshlak 2009) over any such
  h^max and cut rule.

:class:`RelaxedTask` is the planner's table over a fixed set of ground
actions: facts are the atoms the actions and the goal mention, plus
complement facts ("not p") for negative preconditions and goals, made true by
the actions that delete ``p``.  Fact 0 is "true at the start" (the
precondition of precondition-free actions), fact 1 the goal, added by an
artificial goal action of cost 0 (the last action).  It gives

* :meth:`RelaxedTask.lmcut`: an admissible lower bound on the cost of a plan
  (the planner's A* heuristic and its optimality proofs);
* :meth:`RelaxedTask.relaxed_plan` and :meth:`RelaxedTask.helpful` (the FF
  heuristic, Hoffmann and Nebel 2001): a relaxed plan from h^add's best
  supporters and the helpful actions it suggests, used to guide the excuse
  search's reachability checks.

The excuse search's relaxed task (:mod:`guided_lfd.excuse.lmcut`) is the
compiled excuse task on the same core: changes are precondition-free actions
(h^max seeds at their cost), the robot's actions cost 0.
"""

from __future__ import annotations

import bisect
import heapq
from typing import Any, Callable, Collection, Iterable, Sequence

from guided_lfd.planning.task import GroundAction, bits, mask_of

INF = float("inf")


def _descending(f: int) -> int:
    return -f


def index_facts(n_facts: int, pre: Sequence[Sequence[int]], add: Sequence[Sequence[int]]
                ) -> tuple[list[list[int]], list[list[int]]]:
    """Each fact's consumers (the actions it is a precondition of) and achievers (those that add it)."""
    prec_of: list[list[int]] = [[] for _ in range(n_facts)]
    achievers: list[list[int]] = [[] for _ in range(n_facts)]
    for ai, p in enumerate(pre):
        for f in p:
            prec_of[f].append(ai)
        for f in add[ai]:
            achievers[f].append(ai)
    return prec_of, achievers


def close(facts: Iterable[int], reached: bytearray, unsat: list[int], prec_of: Sequence[Sequence[int]],
          add: Sequence[Sequence[int]], goal: Collection[int] = (), left: int = -1) -> tuple[list[int], int]:
    """Make ``facts`` reached and close under the relaxed actions: an action whose last unreached precondition
    is reached adds its facts (``reached`` and ``unsat``, each action's unreached preconditions, are updated).

    Returns the facts newly reached, in order, and how many of ``goal`` are still unreached (``left`` on
    entry); the closure stops when that count reaches 0 (never, with the default -1).
    """
    order: list[int] = []
    for f in facts:
        if not reached[f]:
            reached[f] = 1
            order.append(f)
            if f in goal:
                left -= 1
    i = 0
    while left and i < len(order):
        for ai in prec_of[order[i]]:
            n = unsat[ai] - 1
            unsat[ai] = n
            if n:
                continue
            for q in add[ai]:
                if not reached[q]:
                    reached[q] = 1
                    order.append(q)
                    if q in goal:
                        left -= 1
        i += 1
    return order, left


def hmax(seeds: Iterable[tuple[float, int]], n_facts: int, prec_of: Sequence[Sequence[int]],
         add: Sequence[Sequence[int]], n_pre: list[int], cost: Sequence[float], ordered: bool = False
         ) -> tuple[list[float], list[int]]:
    """h^max (Bonet and Geffner 2001) of every fact, and each reached action's precondition choice: the
    precondition reached last, a maximal one (-1 = the action is never reached).

    ``seeds``: (value, fact) pairs, the facts true at the start (value 0) and those a precondition-free
    action of that cost adds (the excuse task's changes).  Facts are settled a level (value) at a time;
    zero-cost actions extend the level they fire in, as a closure (the excuse task's robot actions cost 0,
    so its h^max is a few closures, no heap per fact).  With ``ordered`` a level's facts are settled in
    increasing index order, which fixes the precondition choice among ties (the planner's LM-cut relies on
    it for reproducible search).
    """
    h = [INF] * n_facts
    pending: dict[float, list[int]] = {}
    for value, f in seeds:
        if value < h[f]:
            h[f] = value
            pending.setdefault(value, []).append(f)
    levels = sorted(pending)
    unsat = n_pre[:]
    pcf = [-1] * len(n_pre)
    pop, push = heapq.heappop, heapq.heappush
    while levels:
        level = pop(levels)
        queue = [f for f in pending.pop(level) if h[f] == level]  # others were settled lower since
        if ordered:
            queue.sort(reverse=True)  # popped from the end: increasing index
        later, later_bucket = INF, None  # the last level pushed to (unit costs: always the next one)
        while queue:
            f = queue.pop()
            # No early stop at the goal: LM-cut's cut must see every reachable achiever of the goal zone.
            for ai in prec_of[f]:
                n = unsat[ai] - 1
                unsat[ai] = n
                if n:
                    continue
                pcf[ai] = f
                reach = level + cost[ai]
                for q in add[ai]:
                    if reach < h[q]:
                        h[q] = reach
                        if reach == later:
                            later_bucket.append(q)
                        elif reach == level:  # a zero-cost action: this level grows
                            if ordered:
                                bisect.insort(queue, q, key=_descending)
                            else:
                                queue.append(q)
                        else:
                            later_bucket = pending.get(reach)
                            if later_bucket is None:
                                later_bucket = pending[reach] = []
                                push(levels, reach)
                            later_bucket.append(q)
                            later = reach
    return h, pcf


def lmcut(hmax_of: Callable[[Any], Any], goal_value: Callable[[Any], float],
          cut_of: Callable[[Any, Any], list[int]], cost: Any) -> tuple[float, list[tuple[list[int], float]]]:
    """LM-cut (Helmert and Domshlak 2009) over any relaxed task: the lower bound and its cuts (each a
    disjunctive landmark with the cost it took).

    Repeats: h^max under ``cost`` (``hmax_of(cost)``, with whatever its cut needs beside it: the precondition
    choice, the goal fact); stop when the goal's value (``goal_value(h)``) is infinite (INF: unsolvable) or 0;
    else take the cut ``cut_of(h, cost)`` (the positive-cost entries, actions or changes, that enter the goal
    zone), add its cheapest cost to the bound and take that cost off each.  ``cost`` is consumed.
    """
    total: float = 0
    cuts: list[tuple[list[int], float]] = []
    while True:
        h = hmax_of(cost)
        value = goal_value(h)
        if value == INF:
            return INF, cuts  # only before the first cut: costs only ever decrease
        if value == 0:
            return total, cuts
        cut = cut_of(h, cost)
        if not cut:
            return total, cuts  # guard: cannot happen for a finite positive h
        m = min(cost[x] for x in cut)
        total += m
        for x in cut:
            cost[x] -= m
        cuts.append((cut, m))


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
        self.prec_of, self.achievers = index_facts(self.n_facts, pre, add)
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
        return hmax([(0, f) for f in true], self.n_facts, self.prec_of, self.add, self._n_pre, cost, ordered=True)

    def lmcut(self, state: int, cuts: list[list[int]] | None = None) -> float:
        """The LM-cut lower bound on the cost of a plan from ``state`` (INF = unsolvable).

        ``cuts``, when given, receives each cut: a disjunctive action landmark (every plan from ``state``
        has one of its actions; the artificial goal action never is one, being free).
        """
        true = self._true_facts(state)
        # Each h^max pass comes with its precondition choice, which the cut follows; fact 1 is the goal.
        total, found = lmcut(lambda cost: self._hmax(true, cost), lambda h_pcf: h_pcf[0][1],
                             lambda h_pcf, cost: self._cut(true, h_pcf[1], cost), list(self.base_costs))
        if cuts is not None:
            cuts.extend(cut for cut, _ in found)
        return total

    def _cut(self, true: list[int], pcf: list[int], cost: list[int]) -> list[int]:
        """The actions of positive cost whose chosen precondition is reached from the state without entering
        the goal zone, and that add a zone fact (every relaxed plan uses one of them)."""
        # Goal zone: facts from which the goal is reached by zero-cost actions along the precondition choice.
        achievers = self.achievers
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
        return list(set(cut))

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
