"""Optimal planning on guided-lfd's ground tasks: pruning and A* with LM-cut.

* :func:`reachable_actions`: the actions a delete-relaxed run from a state
  can apply (what a planner's reachability grounding keeps); the others can
  never be applied in any state reachable from there.
* :func:`relevant_actions`: of those, the ones backward relevance from the
  goal keeps (an action that changes no atom the goal depends on is never
  needed in an optimal plan).
* :func:`astar`: A* with the LM-cut heuristic of :class:`RelaxedTask` (the
  heuristic pyperplan's ``astar -H lmcut`` uses, on flat integer tables),
  states as bit masks, applicable actions found through an index on one
  precondition each.  The plan is optimal: LM-cut is admissible and A*
  re-opens a state reached again more cheaply.
"""

from __future__ import annotations

import heapq
import itertools
import time
from collections import defaultdict
from typing import Callable, Sequence

from guided_lfd.errors import SearchTimeout
from guided_lfd.planning.task import GroundAction, GroundTask, bits
from guided_lfd.planning.relaxation import INF, RelaxedTask, close
from guided_lfd.planning.relevance import relevance
from guided_lfd.planning.successors import SuccessorIndex


def reachable_actions(actions: Sequence[GroundAction], state: int) -> list[GroundAction]:
    """The actions a delete-relaxed run from ``state`` reaches, in their order.

    Negative preconditions are taken as satisfiable (an over-approximation:
    an atom true now may be deleted later), so nothing applicable in a state
    reachable from ``state`` is left out.
    """
    n_atoms = max([state.bit_length(), *(act.add.bit_length() for act in actions)])
    waiting: defaultdict[int, list[int]] = defaultdict(list)  # atom -> the actions it is missing for
    unsat = [0] * len(actions)
    free: list[int] = []  # the adds of actions applicable in ``state``
    for ai, act in enumerate(actions):
        need = [i for i in act.pre_pos_ids if not state >> i & 1]
        unsat[ai] = len(need)
        if not need:
            free.extend(act.add_ids)
        for i in need:
            waiting[i].append(ai)
    reached = bytearray(n_atoms)
    for i in bits(state):
        reached[i] = 1
    close(free, reached, unsat, waiting, [act.add_ids for act in actions])
    return [act for act, left in zip(actions, unsat) if not left]


def relaxed_reach(actions: Sequence[GroundAction], state: int) -> tuple[int, int]:
    """(``state`` with every atom the actions a delete-relaxed run from it reaches add: no atom outside it is ever
    true, a proof; the atoms those actions delete), negative preconditions taken as satisfiable."""
    reached, deletable = state, 0
    for act in reachable_actions(actions, state):
        reached |= act.add
        deletable |= act.delete
    return reached, deletable


def relevant_actions(task: GroundTask, actions: Sequence[GroundAction]) -> list[GroundAction]:
    """The actions backward relevance from the goal keeps (see :func:`~guided_lfd.planning.relevance.relevance`)."""
    return relevance(task, list(actions))[1]


def planning_actions(task: GroundTask, state: int, actions: Sequence[GroundAction] | None = None) -> list[GroundAction]:
    """The actions an optimal plan from ``state`` may use: reachable, then relevant."""
    return relevant_actions(task, reachable_actions(task.actions if actions is None else actions, state))


def _balanced_index(actions: Sequence[GroundAction]) -> SuccessorIndex[int]:
    """Each action's index under its precondition that keys the fewest actions so far: buckets stay small, so a
    state checks few actions."""
    load: dict[int, int] = {}
    entries: list[tuple[int | None, int]] = []
    for ai, act in enumerate(actions):
        if not act.pre_pos_ids:
            entries.append((None, ai))
            continue
        key = min(act.pre_pos_ids, key=lambda i: load.get(i, 0))
        load[key] = load.get(key, 0) + 1
        entries.append((key, ai))
    return SuccessorIndex(entries)


class SearchStopped(Exception):
    """:func:`astar` was told to stop: another search of a portfolio has answered."""


def astar(
    actions: Sequence[GroundAction],
    init: int,
    goal_pos: int,
    goal_neg: int,
    relaxed: RelaxedTask | None = None,
    deadline: float | None = None,
    successor: Callable[[GroundAction, int], int] | None = None,
    stop: Callable[[], bool] | None = None,
) -> list[GroundAction] | None:
    """An optimal plan from ``init`` with ``actions`` (None: proved unsolvable).

    ``relaxed`` is the LM-cut table over the same actions and goal (built
    here if not given; its first actions are ``actions``); action costs are its ``base_costs``.
    ``successor``: the state an applicable action leads to, when it is more than adds and deletes
    (an ADL task's :meth:`~guided_lfd.planning.task.GroundTask.successor`).
    Raises :class:`SearchTimeout` past ``deadline`` (a ``time.monotonic()`` value), and
    :class:`SearchStopped` when ``stop()`` (asked every 16 expansions) says another search has answered.
    """
    actions = list(actions)
    relaxed = relaxed or RelaxedTask(actions, goal_pos, goal_neg)
    lmcut = relaxed.lmcut
    cost = relaxed.base_costs
    pre_pos = [a.pre_pos for a in actions]
    pre_neg = [a.pre_neg for a in actions]
    add = [a.add for a in actions]
    keep = [~(a.delete & ~a.add) for a in actions]  # adds win over deletes
    successors = _balanced_index(actions)
    h_of: dict[int, float] = {init: lmcut(init)}
    if h_of[init] == INF:
        return None
    g_of: dict[int, int] = {init: 0}
    parent: dict[int, tuple[int, int]] = {}
    tie = itertools.count()
    heap: list[tuple[float, float, int, int, int]] = [(h_of[init], h_of[init], 0, 0, init)]
    pop, push = heapq.heappop, heapq.heappush
    expanded = 0
    # Hot loop: one pass per expansion; plain lists and locals on purpose.
    while heap:
        _, _, _, g, state = pop(heap)
        if g > g_of[state]:
            continue  # reached again more cheaply since this entry was pushed
        if state & goal_pos == goal_pos and not state & goal_neg:
            return _path(actions, parent, state)
        expanded += 1
        if deadline is not None and time.monotonic() > deadline:  # every expansion: LM-cut can take 0.1 s each
            raise SearchTimeout("planner exceeded its time limit")
        if stop is not None and not expanded % 16 and stop():
            raise SearchStopped()
        for bucket in successors.candidates(state):
            for ai in bucket:
                pp = pre_pos[ai]
                if state & pp != pp or state & pre_neg[ai]:
                    continue
                # GroundAction.apply on the masks above (adds win over deletes); an ADL task's own successor.
                nxt = (state & keep[ai]) | add[ai] if successor is None else successor(actions[ai], state)
                ng = g + cost[ai]
                if ng >= g_of.get(nxt, INF):
                    continue
                g_of[nxt] = ng
                parent[nxt] = (state, ai)
                h = h_of.get(nxt)
                if h is None:
                    h = h_of[nxt] = lmcut(nxt)
                if h == INF:
                    continue
                push(heap, (ng + h, h, next(tie), ng, nxt))
    return None


def _path(actions: list[GroundAction], parent: dict[int, tuple[int, int]], state: int) -> list[GroundAction]:
    plan: list[GroundAction] = []
    while state in parent:
        state, ai = parent[state]
        plan.append(actions[ai])
    plan.reverse()
    return plan
