"""The lightest change set under linear constraints: a 0/1 program over atom flips (HiGHS, through scipy).

One binary variable per atom an excuse may flip (changeable, and relevant to
the goal or in a mutex group); the weight of the flips is minimised.  An
atom's truth in the excuse state is linear in its variable (``x`` when the
atom is false initially, ``1 - x`` when it is true, a constant when it may not
change), so "the state misses the goal", "the state keeps each invariant
group" and "the state holds an atom outside G" are linear rows.
"""

from __future__ import annotations

from typing import Any

from guided_lfd.errors import SearchTimeout
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.planning.task import bits

__all__ = ["ChangeProgram"]

_Row = tuple[list[int], list[float], float, float]  # columns, coefficients, lower, upper


class ChangeProgram:
    """Rows over the flips of one change space; :meth:`lightest` solves them."""

    def __init__(self, space: ChangeSpace, max_size: int | None = None) -> None:
        task = space.task
        grouped = 0
        for group in space.groups:
            grouped |= group.mask
        self.init = task.init
        self.atoms = list(bits(space.changeable & (space.relevant_atoms | grouped)))
        self.column = {a: k for k, a in enumerate(self.atoms)}
        #: The variables' atoms that reachability depends on (the only ones a landmark names).
        self.relevant_atoms = [a for a in self.atoms if (space.relevant_atoms >> a) & 1]
        self.weights = [float(space.weights[a]) for a in self.atoms]
        self.max_size = max_size
        self.rows: list[_Row] = []
        self.landmarks: set[frozenset[int]] = set()
        self.infeasible = False  # a row no assignment meets (a landmark of fixed atoms only)
        goal = list(bits(task.goal_pos))
        if goal:  # the excuse state misses the goal: fewer than all its atoms true
            self.add_truth_row(goal, -float("inf"), len(goal) - 1)
        for group in space.groups:
            self.add_truth_row(list(bits(group.mask)), 1.0 if group.exactly_one else -float("inf"), 1.0)

    def add_truth_row(self, atoms: list[int], lower: float, upper: float) -> None:
        """The row ``lower <= (how many of atoms are true in the excuse state) <= upper``."""
        columns, coefficients, constant = [], [], 0.0
        init, column = self.init, self.column
        for a in atoms:
            initially = (init >> a) & 1
            constant += initially  # x flips it: true is x, or 1 - x when it is true initially
            k = column.get(a)
            if k is not None:
                columns.append(k)
                coefficients.append(-1.0 if initially else 1.0)
        lower, upper = lower - constant, upper - constant
        if not columns:
            self.infeasible = self.infeasible or lower > 0 or upper < 0
            return
        self.rows.append((columns, coefficients, lower, upper))

    def exclude_within(self, inside: int) -> None:
        """Every excuse state holds a relevant atom outside ``inside`` (no state within it reaches the goal)."""
        self.require_one_of([a for a in self.relevant_atoms if not (inside >> a) & 1])

    def require_one_of(self, atoms: list[int]) -> None:
        """Every excuse state holds one of ``atoms`` (a row once: the same landmark again adds nothing)."""
        key = frozenset(atoms)
        if key not in self.landmarks:
            self.landmarks.add(key)
            self.add_truth_row(list(atoms), 1.0, float("inf"))

    def exclude_supersets(self, changes: int) -> None:
        """No later answer flips every atom of ``changes``."""
        columns = [self.column[a] for a in bits(changes)]
        if not columns:
            self.infeasible = True
            return
        self.rows.append((columns, [1.0] * len(columns), -float("inf"), len(columns) - 1.0))

    def lightest(self, time_left: float | None, sized: bool = True) -> tuple[int, int] | None:
        """(weight, change set) of a lightest assignment meeting every row, or None when there is none.

        ``sized``: with the size limit.  Raises :class:`SearchTimeout` when ``time_left`` runs out first.
        """
        if self.infeasible:
            return None
        result = self._solve(time_left, sized)
        if result.status == 2:  # infeasible
            return None
        if result.status != 0 or result.x is None:  # the time limit, before an optimum was proven
            raise SearchTimeout("excuse search exceeded its time limit")
        changes = 0
        for k, value in enumerate(result.x):
            if value > 0.5:
                changes |= 1 << self.atoms[k]
        return round(result.fun), changes

    def feasible_without_size(self, time_left: float | None) -> bool:
        """Whether the rows have a solution once the size limit is lifted (None-within-size vs none)."""
        return self.max_size is not None and self.lightest(time_left, sized=False) is not None

    def _solve(self, time_left: float | None, sized: bool) -> Any:
        import numpy as np
        from scipy.optimize import Bounds, LinearConstraint, milp
        from scipy.sparse import csr_array

        rows = list(self.rows)
        n = len(self.atoms)
        if sized and self.max_size is not None:
            rows.append((list(range(n)), [1.0] * n, -float("inf"), float(self.max_size)))
        options: dict[str, Any] = {"mip_rel_gap": 0.0}
        if time_left is not None:
            if time_left <= 0:
                raise SearchTimeout("excuse search exceeded its time limit")
            options["time_limit"] = time_left
        if n == 0:
            return _Empty(all(lo <= 0 <= up for _, _, lo, up in rows))
        cost = np.array(self.weights, dtype=np.float64)
        if not rows:
            constraints: list[Any] = []
        else:
            data = [c for _, cs, _, _ in rows for c in cs]
            indices = [k for ks, _, _, _ in rows for k in ks]
            indptr = np.cumsum([0] + [len(ks) for ks, _, _, _ in rows])
            matrix = csr_array((data, indices, indptr), shape=(len(rows), n))
            constraints = [LinearConstraint(matrix, [r[2] for r in rows], [r[3] for r in rows])]
        return milp(cost, integrality=np.ones(n), bounds=Bounds(0, 1), constraints=constraints, options=options)


class _Empty:
    """The result of a program without variables: the empty change set, if every row allows it."""

    def __init__(self, feasible: bool) -> None:
        self.status = 0 if feasible else 2
        self.x = [] if feasible else None
        self.fun = 0.0
