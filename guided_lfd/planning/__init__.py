"""Planning on guided-lfd's ground tasks: guided-lfd's A* with LM-cut, and pyperplan's searches.

The default, ``astar-lmcut``, is :func:`guided_lfd.planning.search.astar` over the
actions reachable from the initial state and relevant to the goal.  The
``pyperplan-*`` configurations (and ``bfs``, ``gbfs-hff``: the baseline's
planner calls) hand the ground task to pyperplan as a
:class:`pyperplan.task.Task`; negative preconditions and goals, which
pyperplan does not support, are compiled into complement atoms
``(not-<atom>)`` kept up to date by every action.
"""

from __future__ import annotations

import math
import time
from contextlib import contextmanager
from dataclasses import dataclass, replace
from typing import Callable, Iterator

from guided_lfd.deadline import deadline_after, watchdog
from guided_lfd.planning.task import GroundAction, GroundTask, bits

#: Registered configurations: name -> (search, heuristic or None, optimal?).  ``guided`` is
#: guided-lfd's own A*; the other searches are pyperplan's (imported when used).
SEARCHES: dict[str, tuple[str, str | None, bool]] = {
    "astar-lmcut": ("guided", "lmcut", True),
    "pyperplan-astar-lmcut": ("astar", "lmcut", True),
    "astar-hmax": ("astar", "hmax", True),
    "bfs": ("bfs", None, True),
    "gbfs-hff": ("gbfs", "hff", False),
}
DEFAULT_SEARCH = "astar-lmcut"


@contextmanager
def time_limit(seconds: float | None, what: str = "search") -> Iterator[None]:
    """Raise :class:`SearchTimeout` if the block runs longer than ``seconds``.

    Pyperplan's searches cannot be interrupted otherwise; this is a
    :func:`guided_lfd.deadline.watchdog` (main thread only, nests with the
    whole run's watchdog).
    """
    if seconds is None or not math.isfinite(seconds) or seconds > 1e6:
        yield
        return
    with watchdog(deadline_after(seconds), f"{what}", grace=0.0):
        yield


def to_pyperplan(task: GroundTask, init: int | None = None, actions: list[GroundAction] | None = None):
    """Build a pyperplan ``Task`` (with complement atoms for negative conditions)."""
    from pyperplan.task import Operator, Task

    init = task.init if init is None else init
    actions = task.actions if actions is None else actions
    negated = task.goal_neg
    for act in actions:
        negated |= act.pre_neg
    names = [str(a) for a in task.atoms]

    def neg_name(i: int) -> str:
        return f"(not-{names[i][1:]}"

    operators = []
    for act in actions:
        pre = {names[i] for i in bits(act.pre_pos)} | {neg_name(i) for i in bits(act.pre_neg)}
        add = {names[i] for i in bits(act.add)}
        dele = {names[i] for i in bits(act.delete & ~act.add)}
        add |= {neg_name(i) for i in bits(act.delete & ~act.add & negated)}
        dele |= {neg_name(i) for i in bits(act.add & negated)}
        operators.append(Operator(act.name, frozenset(pre), frozenset(add), frozenset(dele)))
    state = {names[i] for i in bits(init)} | {neg_name(i) for i in bits(negated & ~init)}
    goals = {names[i] for i in bits(task.goal_pos)} | {neg_name(i) for i in bits(task.goal_neg)}
    facts = set(names) | {neg_name(i) for i in bits(negated)}
    return Task(task.problem.name, facts, frozenset(state), frozenset(goals), operators)


@dataclass
class PlanResult:
    """Outcome of a planner call: ``plan`` is None when the task is unsolvable."""

    plan: list[GroundAction] | None
    search: str
    optimal: bool
    time_s: float
    #: What found the plan or proved there is none: the search, or ``symbolic`` (the portfolio's prover).
    answered_by: str = ""

    def __post_init__(self) -> None:
        self.answered_by = self.answered_by or self.search


def find_plan(
    task: GroundTask,
    init: int | None = None,
    search: str = DEFAULT_SEARCH,
    time_limit_s: float | None = None,
    actions: list[GroundAction] | None = None,
) -> PlanResult:
    """Plan with a registered configuration (see :data:`SEARCHES`).

    A ``None`` plan is a proof of unsolvability: all searches registered here
    are complete and exhaust the reachable state space before giving up.
    """
    kind, heuristic, optimal = SEARCHES[search]
    start = time.perf_counter()
    if kind == "guided":
        return _guided_astar(task, init, actions, time_limit_s, search, start)
    if task.is_adl:
        from guided_lfd.errors import UnsupportedFeatureError

        raise UnsupportedFeatureError(f"search '{search}' plans STRIPS tasks only; ADL tasks need "
                                      f"'{DEFAULT_SEARCH}'")
    from pyperplan.heuristics.blind import BlindHeuristic
    from pyperplan.heuristics.lm_cut import LmCutHeuristic
    from pyperplan.heuristics.relaxation import hFFHeuristic, hMaxHeuristic
    from pyperplan.search import astar_search, breadth_first_search, greedy_best_first_search

    ptask = to_pyperplan(task, init, actions)
    _check_each_expansion(ptask, time_limit_s)
    heuristics: dict[str, Callable] = {"lmcut": LmCutHeuristic, "hmax": hMaxHeuristic, "hff": hFFHeuristic}
    with time_limit(time_limit_s, "planner"):
        if kind == "bfs":
            ops = breadth_first_search(ptask)
        else:
            h = heuristics[heuristic](ptask) if heuristic else BlindHeuristic(ptask)
            ops = astar_search(ptask, h) if kind == "astar" else greedy_best_first_search(ptask, h)
    elapsed = time.perf_counter() - start
    pool = task.actions if actions is None else actions
    # Pyperplan's searches count steps: optimal only where every action costs 1.
    optimal = optimal and all(a.cost == 1 for a in pool)
    if ops is None:
        return PlanResult(None, search, optimal, elapsed)
    by_name = {a.name: a for a in pool}
    return PlanResult([by_name[op.name] for op in ops], search, optimal, elapsed)


def _check_each_expansion(ptask, time_limit_s: float | None) -> None:
    """Make ``ptask`` raise :class:`SearchTimeout` when a search past ``time_limit_s`` expands a state: the
    watchdog cannot interrupt pyperplan outside the main thread (a library call in a worker thread)."""
    if time_limit_s is None or not math.isfinite(time_limit_s):
        return
    from guided_lfd.errors import SearchTimeout

    deadline = time.monotonic() + time_limit_s
    successors = ptask.get_successor_states

    def checked(state):
        if time.monotonic() > deadline:
            raise SearchTimeout("time limit reached in the planner")
        return successors(state)

    ptask.get_successor_states = checked


def _guided_astar(task: GroundTask, init: int | None, actions: list[GroundAction] | None,
                  time_limit_s: float | None, search: str, start: float) -> PlanResult:
    """guided-lfd's A* with LM-cut over the reachable, relevant actions."""
    from guided_lfd.planning.search import astar, planning_actions

    init = task.init if init is None else init
    deadline = None if time_limit_s is None else time.monotonic() + time_limit_s
    if task.is_adl:
        from guided_lfd.planning import adl

        with time_limit(time_limit_s, "planner"):
            plan = adl.astar(task if actions is None else replace(task, actions=list(actions)), init, deadline)
        return PlanResult(plan, search, True, time.perf_counter() - start)
    usable = planning_actions(task, init, actions)
    with time_limit(time_limit_s, "planner"):  # LM-cut of one state can be long on a big task
        plan = astar(usable, init, task.goal_pos, task.goal_neg, deadline=deadline)
    return PlanResult(plan, search, True, time.perf_counter() - start)
