"""Operator counting: a linear program over how often each action occurs in a plan, as a dead-end test.

Any plan from a state, counted per action, satisfies (Pommerening, Röger, Helmert and Bonet 2014):

* the state equation, one inequality per atom p: p can become true at most once per occurrence of an
  action adding it (without requiring it), and surely becomes false at each occurrence of an action
  requiring and deleting it, so ``s(p) + produced(p) - consumed(p) >= goal(p)`` (and ``>= 0``);
* LM-cut's landmarks: at least one occurrence of some action of each cut.

When no non-negative counts satisfy both, no plan exists.  This sees what relaxations and h^2 cannot:
resources that only run down (two calibrated cameras and no ``calibrate`` take at most two images)
combined with what the goal needs of them.  scipy's HiGHS decides the program.
"""

from __future__ import annotations

from typing import Sequence

from guided_lfd.planning.task import GroundAction, bits
from guided_lfd.planning.relaxation import INF, RelaxedTask


class OperatorCounting:
    """The state equation of a fixed set of STRIPS actions, with LM-cut's landmarks per state."""

    def __init__(self, relaxed: RelaxedTask, goal_pos: int) -> None:
        self.relaxed = relaxed
        actions: Sequence[GroundAction] = relaxed.actions
        produced: dict[int, list[int]] = {}
        consumed: dict[int, list[int]] = {}
        for k, act in enumerate(actions):
            for p in bits(act.add & ~act.pre_pos):
                produced.setdefault(p, []).append(k)
            for p in bits(act.delete & act.pre_pos & ~act.add):
                consumed.setdefault(p, []).append(k)
        self.goal = goal_pos
        # Atoms whose inequality can bind: those something consumes, and goal atoms.
        self.rows = [(p, produced.get(p, []), consumed.get(p, [])) for p in sorted(set(consumed) | set(bits(goal_pos)))]
        self.n_actions = len(actions)

    def dead(self, state: int, time_limit: float = 1.0) -> bool:
        """True when no plan from ``state`` can exist (the program has no solution); False: undecided
        (a solution, or HiGHS out of its ``time_limit`` seconds)."""
        import numpy as np
        from scipy.optimize import linprog
        from scipy.sparse import coo_matrix

        cuts: list[list[int]] = []
        if self.relaxed.lmcut(state, cuts) == INF:
            return True
        rows, cols, vals, bound = [], [], [], []
        r = 0
        for p, produced, consumed in self.rows:
            have = state >> p & 1
            need = self.goal >> p & 1
            if not consumed and have >= need:
                continue  # satisfied by no action at all
            # consumed - produced <= s(p) - goal(p)
            for k in consumed:
                rows.append(r), cols.append(k), vals.append(1.0)
            for k in produced:
                rows.append(r), cols.append(k), vals.append(-1.0)
            bound.append(have - need)
            r += 1
        for cut in cuts:
            for k in cut:
                rows.append(r), cols.append(k), vals.append(-1.0)
            bound.append(-1.0)
            r += 1
        if r == 0:
            return False
        matrix = coo_matrix((vals, (rows, cols)), shape=(r, self.n_actions)).tocsr()
        result = linprog(np.zeros(self.n_actions), A_ub=matrix, b_ub=np.array(bound, dtype=float),
                         bounds=(0, None), method="highs", options={"time_limit": max(time_limit, 0.01)})
        return result.status == 2  # 2: infeasible
