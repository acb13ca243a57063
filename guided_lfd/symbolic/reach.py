"""Symbolic reachability: breadth-first over sets of states, backward from the goal or forward from a state.

Backward search keeps its layers (the states exactly k steps from the goal),
so a plan from any state of the reached set is read off them one step at a
time, with no search.  :func:`prove_unsolvable` runs both directions in turns
(the cheaper last step goes next, as symbolic planners do) until one runs
dry (unsolvable) or they meet (solvable).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any

from guided_lfd.deadline import check
from guided_lfd.errors import SearchTimeout
from guided_lfd.planning.task import GroundAction
from guided_lfd.symbolic.encoding import SymbolicTask


class StepAbandoned(Exception):
    """A step of :meth:`Reachability.step` ran past the time it was given (the search is as before it)."""


@dataclass
class Layers:
    """A breadth-first search's layers: ``layers[k]`` holds the states first reached in step k; ``reached`` their
    union; ``complete`` once no new state is left (a fixpoint)."""

    layers: list[Any]
    reached: Any
    complete: bool = False
    seconds: list[float] = field(default_factory=list)

    @property
    def frontier(self) -> Any:
        """The states of the last layer."""
        return self.layers[-1]


class Reachability:
    """Breadth-first search over sets of states in one direction, a layer per :meth:`step`."""

    def __init__(self, sym: SymbolicTask, start: Any, backward: bool, constraint: Any | None = None,
                 deadline: float | None = None) -> None:
        self.sym, self.backward, self.deadline = sym, backward, deadline
        self.constraint = constraint
        start = start if constraint is None else start & constraint
        self.result = Layers([start], start, complete=start == sym.dd.false)

    def step(self, give_up: float | None = None) -> Any:
        """Reach one layer further; returns the new layer (false when the search is complete).

        Past ``give_up`` (a ``time.monotonic()`` value) the step is abandoned (:class:`StepAbandoned`) and
        the search is as before it.
        """
        sym, dd, result = self.sym, self.sym.dd, self.result
        began = time.monotonic()
        images = self._images(result.frontier, give_up)
        new = images & ~result.reached
        if self.constraint is not None:
            new = new & self.constraint
        result.seconds.append(time.monotonic() - began)
        if new == dd.false:
            result.complete = True
            return new
        result.layers.append(new)
        result.reached = result.reached | new
        return new

    def _images(self, states: Any, give_up: float | None) -> Any:
        deadline = self.deadline
        if give_up is not None and (deadline is None or give_up < deadline):
            deadline, abandon = give_up, True
        else:
            abandon = False
        try:
            return self._union_of_images(states, deadline)
        except SearchTimeout:
            if abandon and (self.deadline is None or time.monotonic() <= self.deadline):
                raise StepAbandoned() from None
            raise

    def _union_of_images(self, states: Any, deadline: float | None) -> Any:
        sym, dd = self.sym, self.sym.dd
        parts = []
        for k, a in enumerate(sym.actions):
            if k % 64 == 0:
                check(deadline, "symbolic search")
            if self.backward:
                part = dd.and_exists(states, a.effect, a.effect_vars)
                if part != dd.false:
                    parts.append(a.pre & part)
            else:
                part = dd.and_exists(states, a.pre, a.effect_vars)
                if part != dd.false:
                    parts.append(a.effect & part)
        return _balanced_or(dd, parts, deadline)

    def run(self) -> Layers:
        """Step until the fixpoint."""
        while not self.result.complete:
            self.step()
        return self.result


def _balanced_or(dd: Any, parts: list[Any], deadline: float | None) -> Any:
    """The disjunction of ``parts`` pairwise, level by level (intermediate diagrams stay small)."""
    if not parts:
        return dd.false
    while len(parts) > 1:
        check(deadline, "symbolic search")
        parts = [parts[i] | parts[i + 1] if i + 1 < len(parts) else parts[i] for i in range(0, len(parts), 2)]
    return parts[0]


def backward_layers(sym: SymbolicTask, constraint: Any | None = None, deadline: float | None = None) -> Layers:
    """Every state from which the goal can be reached (within ``constraint``, if given), by layers."""
    return Reachability(sym, sym.goal(), backward=True, constraint=constraint, deadline=deadline).run()


def plan_from(sym: SymbolicTask, layers: Layers, state: int) -> list[GroundAction] | None:
    """A shortest plan (in steps) from ``state`` read off backward ``layers`` (None: ``state`` is in none).

    Each step takes an action whose successor lies one layer nearer the goal:
    the layers are exact, so one always exists.
    """
    depth = next((k for k, layer in enumerate(layers.layers) if sym.contains(layer, state)), None)
    if depth is None:
        return None
    plan: list[GroundAction] = []
    for k in range(depth, 0, -1):
        nearer = layers.layers[k - 1]
        for sa in sym.actions:
            act = sa.action
            if act.applicable(state):
                nxt = act.apply(state)
                if sym.contains(nearer, nxt):
                    plan.append(act)
                    state = nxt
                    break
        else:
            raise RuntimeError("symbolic layers inconsistent: no step towards the goal")
    return plan


@dataclass
class Proof:
    """What :func:`prove_unsolvable` found: ``solvable`` (the searches met) or not (one ran dry)."""

    solvable: bool
    direction: str  # which search ran dry or met the other: "forward" or "backward"
    layers: int  # steps taken, both directions together
    seconds: float


def prove_unsolvable(sym: SymbolicTask, init: int, deadline: float | None = None,
                     constraint: Any | None = None) -> Proof:
    """Bidirectional breadth-first search between ``init`` and the goal, until it decides solvability.

    Each turn extends the direction expected to be cheaper (its last step's time); a step is given at most
    twice the dearest step so far (at least a second) and abandoned beyond that, which then counts as its
    cost: a direction whose sets blow up (backward search in tetris) waits while the other goes on, and
    is tried again with twice the time later.  ``constraint``: a set holding every state reachable from
    ``init`` (invariants); the backward search stays inside it.
    """
    began = time.monotonic()
    searches = {"forward": Reachability(sym, sym.state(init), backward=False, deadline=deadline),
                "backward": Reachability(sym, sym.goal(), backward=True, constraint=constraint, deadline=deadline)}
    estimate = {"forward": 0.0, "backward": 0.0}
    dd = sym.dd
    steps = 0
    while True:
        if (searches["forward"].result.reached & searches["backward"].result.reached) != dd.false:
            return Proof(True, "both", steps, time.monotonic() - began)
        for name, search in searches.items():
            if search.result.complete:
                return Proof(False, name, steps, time.monotonic() - began)
        name = min(estimate, key=lambda n: estimate[n])
        cap = max(1.0, 2 * max(estimate.values()))
        try:
            searches[name].step(time.monotonic() + cap)
        except StepAbandoned:
            estimate[name] = cap
            continue
        estimate[name] = searches[name].result.seconds[-1]
        steps += 1
