"""Optimal robot plans without a second from-scratch planner run.

The excuse search already holds a plan from the excuse state (the oracle's
witness).  This module makes it short and, where it can, proves it optimal:

* :func:`shorten_plan` removes loops (a state met twice) and every action
  whose removal leaves a valid plan (greedy action elimination);
* :meth:`~guided_lfd.planning.relaxation.RelaxedTask.lmcut` (LM-cut, Helmert and
  Domshlak 2009) gives an admissible lower bound on the cost of any plan
  from a state;
* :func:`certified_optimal` says whether a plan's cost equals that bound,
  which proves the plan optimal.  When it does not, the caller falls back to
  an optimal planner.
"""

from __future__ import annotations

from typing import Sequence

from guided_lfd.planning.task import GroundAction
from guided_lfd.planning.relaxation import RelaxedTask

__all__ = ["certified_optimal", "is_plan", "shorten_plan"]


def is_plan(plan: Sequence[GroundAction], state: int, goal_pos: int, goal_neg: int) -> bool:
    """Whether ``plan`` is applicable from ``state`` and ends in a goal state."""
    for act in plan:
        if not act.applicable(state):
            return False
        state = act.apply(state)
    return (state & goal_pos) == goal_pos and not state & goal_neg


def _without_loops(plan: list[GroundAction], state: int) -> list[GroundAction]:
    """The plan with every stretch between two visits of one state cut out."""
    states = [state]
    for act in plan:
        states.append(act.apply(states[-1]))
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


def certified_optimal(plan: Sequence[GroundAction], state: int, relaxed: RelaxedTask) -> bool:
    """Whether ``plan``'s cost equals LM-cut's lower bound from ``state`` (so it is optimal).

    ``relaxed`` must be built over every action an optimal plan may use (all
    relevant ones) and the task's goal.
    """
    return relaxed.lmcut(state) >= relaxed.plan_cost(plan)
