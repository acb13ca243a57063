"""``plan``'s default: guided-lfd's A* beside a symbolic proof of unsolvability, the first exact answer wins.

A* with LM-cut finds optimal plans and proves small tasks unsolvable by
exhausting them; symbolic bidirectional search (:mod:`guided_lfd.symbolic`)
proves unsolvable tasks whose state spaces are far too large to enumerate one
state at a time.  The symbolic search runs in a forked worker
(:mod:`guided_lfd.symbolic.worker`), so it takes the second core, and a
diagram operation that outlives the run is ended with the worker.  Its
"solvable" answer is not a plan: A* goes on to find the optimal one.  A task
with more variables than :data:`guided_lfd.symbolic.encoding.DEFAULT_MAX_VARIABLES`
gets A* alone.
"""

from __future__ import annotations

import time

from guided_lfd.deadline import deadline_after, seconds_left
from guided_lfd.errors import SearchTimeout
from guided_lfd.planning import DEFAULT_SEARCH, PlanResult, find_plan, time_limit
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.search import SearchStopped, astar, planning_actions
from guided_lfd.planning.task import GroundAction, GroundTask
from guided_lfd.planning.validation import PlanStep, plan_steps, validated


def plan_task(domain, problem, search: str = DEFAULT_SEARCH, time_limit_s: float | None = None) -> tuple[GroundTask, PlanResult]:
    """Ground ``problem`` for planning (static atoms pruned) and plan for it; ``time_limit_s`` bounds both (the
    grounding checks it cooperatively, so the limit holds in a thread too, where no watchdog can run)."""
    deadline = deadline_after(time_limit_s)
    task = ground(domain, problem, fixed=domain.predicates, deadline=deadline)
    if search == DEFAULT_SEARCH and not task.is_adl:
        return task, plan_with_prover(task, deadline)
    return task, find_plan(task, search=search, time_limit_s=seconds_left(deadline, "grounding"))


def validated_plan(domain, problem, search: str = DEFAULT_SEARCH, time_limit_s: float | None = None,
                   what: str = "the planner's plan") -> tuple[PlanResult, list[PlanStep] | None, int | None]:
    """:func:`plan_task`'s answer, its plan as validated steps and the validator's cost (None, None: no plan);
    ``what`` names the plan in the validator's message.

    Raises :class:`RuntimeError` if the plan does not validate or the planner and the validator disagree on
    its cost (a bug, never hidden).
    """
    _, result = plan_task(domain, problem, search, time_limit_s)
    if result.plan is None:
        return result, None, None
    steps = plan_steps(result.plan)
    report = validated(domain, problem, steps, what)
    if report.cost != sum(a.cost for a in result.plan):
        raise RuntimeError("planner and validator disagree on the plan's cost")
    return result, steps, report.cost


def _decide(task: GroundTask, actions: list[GroundAction], deadline: float | None) -> bool:
    """In the worker: whether the task is solvable (raises SearchTimeout past ``deadline``)."""
    from guided_lfd.symbolic.unsolvable import decide

    return decide(task, actions, deadline).solvable


def plan_with_prover(task: GroundTask, deadline: float | None) -> PlanResult:
    """An optimal plan for ``task`` from its initial state, or a proof that none exists, by A* or the prover."""
    # The symbolic engine's modules load only where the prover may run (a STRIPS task, the default search):
    # --search and ADL runs of plan, evaluate and the study never pay for them.
    from guided_lfd.symbolic.encoding import worth_running
    from guided_lfd.symbolic.unsolvable import prover_variables
    from guided_lfd.symbolic.worker import Forked

    start = time.perf_counter()
    usable = planning_actions(task, task.init)
    if not usable and not task.satisfies_goal(task.init):
        return PlanResult(None, DEFAULT_SEARCH, True, time.perf_counter() - start)
    # A task wider than the engine's default limit gets A* alone (no second process).
    wide = not worth_running(len(prover_variables(task, usable)))
    worker = None if wide else Forked(_decide, task, usable, deadline)

    def proved_unsolvable() -> bool:
        return worker is not None and worker.poll() and worker.value() is False

    try:
        with time_limit(seconds_left(deadline), "planner"):  # LM-cut of one state can be long on a big task
            plan = astar(usable, task.init, task.goal_pos, task.goal_neg, deadline=deadline,
                         stop=proved_unsolvable)
    except SearchStopped:
        return PlanResult(None, DEFAULT_SEARCH, True, time.perf_counter() - start, answered_by="symbolic")
    except SearchTimeout:
        if proved_unsolvable():  # answered as time ran out
            return PlanResult(None, DEFAULT_SEARCH, True, time.perf_counter() - start, answered_by="symbolic")
        raise
    finally:
        if worker is not None:
            worker.stop()
    return PlanResult(plan, DEFAULT_SEARCH, True, time.perf_counter() - start)
