"""Optimal robot plans without a second from-scratch planner run.

The excuse search already holds a plan from the excuse state (the oracle's
witness).  This module makes it short and, where it can, proves it optimal:

* :func:`shorten_plan` removes loops (a state met twice) and every action
  whose removal leaves a valid plan (greedy action elimination);
* :class:`LmCut` is the LM-cut heuristic (Helmert and Domshlak 2009) on a
  ground task with action costs: an admissible lower bound on the cost of
  any plan from a state;
* :func:`certified_optimal` says whether a plan's cost equals that bound,
  which proves the plan optimal.  When it does not, the caller falls back to
  an optimal planner.

Negative preconditions and goals are complement facts ("not p"), made true
by the actions that delete ``p``.
"""

from __future__ import annotations

import heapq
from typing import Sequence

from guided_lfd.grounding import GroundAction, bits, mask_of

INF = float("inf")


def is_plan(plan: Sequence[GroundAction], state: int, goal_pos: int, goal_neg: int) -> bool:
    """Whether ``plan`` is applicable from ``state`` and ends in a goal state."""
    for act in plan:
        if (state & act.pre_pos) != act.pre_pos or state & act.pre_neg:
            return False
        state = (state & ~act.delete) | act.add
    return (state & goal_pos) == goal_pos and not state & goal_neg


def _without_loops(plan: list[GroundAction], state: int) -> list[GroundAction]:
    """The plan with every stretch between two visits of one state cut out."""
    states = [state]
    for act in plan:
        states.append((states[-1] & ~act.delete) | act.add)
    out: list[GroundAction] = []
    trail = [state]  # states along ``out``
    last_seen: dict[int, int] = {state: 0}
    for act, nxt in zip(plan, states[1:]):
        if nxt in last_seen:
            keep = last_seen[nxt]
            for s in trail[keep + 1 :]:
                last_seen.pop(s, None)
            del out[keep:]
            del trail[keep + 1 :]
            continue
        out.append(act)
        trail.append(nxt)
        last_seen[nxt] = len(out)
    return out


def shorten_plan(plan: Sequence[GroundAction], state: int, goal_pos: int, goal_neg: int,
                 costs: dict[str, int] | None = None) -> list[GroundAction]:
    """A valid sub-plan of ``plan``: loops cut, then greedy action elimination.

    Actions are tried most expensive first; an action is dropped when the
    plan without it is still a plan.  ``plan`` must be a plan from ``state``.
    """
    current = _without_loops(list(plan), state)
    cost = (lambda a: costs.get(a.name, 1)) if costs else (lambda a: 1)
    changed = True
    while changed:
        changed = False
        for k in sorted(range(len(current)), key=lambda j: (-cost(current[j]), -j)):
            candidate = current[:k] + current[k + 1 :]
            if is_plan(candidate, state, goal_pos, goal_neg):
                current = _without_loops(candidate, state)
                changed = True
                break
    return current


class LmCut:
    """LM-cut over a fixed set of ground actions (with per-action costs, default 1).

    Built once per task; :meth:`value` evaluates a state.  Facts are the
    atoms the actions and the goal mention, plus complement facts for
    negative preconditions and goals.
    """

    def __init__(self, actions: Sequence[GroundAction], goal_pos: int, goal_neg: int,
                 costs: Sequence[int] | None = None) -> None:
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
        for act in self.actions:
            p = [pos_id[i] for i in act.pre_pos_ids] + [neg_id[i] for i in act.pre_neg_ids]
            pre.append(p or [0])
            adds = act.add_ids
            add.append([pos_id[i] for i in adds]
                       + [neg_id[i] for i in act.delete_ids if i in neg_id and i not in adds])
        goal = [pos_id[i] for i in bits(goal_pos)] + [neg_id[i] for i in bits(goal_neg)]
        pre.append(goal or [0])  # the artificial goal action, cost 0
        add.append([1])
        self.pre, self.add = pre, add
        self.base_costs = [*(costs if costs is not None else [1] * len(self.actions)), 0]
        self.prec_of: list[list[int]] = [[] for _ in range(self.n_facts)]
        self.achievers: list[list[int]] = [[] for _ in range(self.n_facts)]
        for ai, p in enumerate(pre):
            for f in p:
                self.prec_of[f].append(ai)
            for f in add[ai]:
                self.achievers[f].append(ai)
        self.negated, self.mentioned = mask_of(negated_ids), mask_of(mentioned_ids)

    def _true_facts(self, state: int) -> list[int]:
        pos_id, neg_id = self.pos_id, self.neg_id
        return [0, *(pos_id[i] for i in bits(state & self.mentioned)), *(neg_id[i] for i in bits(self.negated & ~state))]

    def _hmax(self, true: list[int], cost: list[int]) -> tuple[list[float], list[int]]:
        """h^max of every fact and each reached action's precondition choice (-1 = not reached)."""
        n_actions = len(self.pre)
        h = [INF] * self.n_facts
        unsat = [len(p) for p in self.pre]
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

    def value(self, state: int) -> float:
        """The LM-cut lower bound on the cost of a plan from ``state`` (INF = unsolvable)."""
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
            m = min(cost[ai] for ai in cut)
            total += m
            for ai in cut:
                cost[ai] -= m


def certified_optimal(plan: Sequence[GroundAction], state: int, actions: Sequence[GroundAction],
                      goal_pos: int, goal_neg: int, costs: dict[str, int] | None = None) -> bool:
    """Whether ``plan``'s cost equals LM-cut's lower bound from ``state`` (so it is optimal).

    ``actions`` must contain every action an optimal plan may use (all
    relevant ones).
    """
    cost_of = (lambda a: costs.get(a.name, 1)) if costs else (lambda a: 1)
    lmcut = LmCut(actions, goal_pos, goal_neg, [cost_of(a) for a in actions])
    return lmcut.value(state) >= sum(cost_of(a) for a in plan)
