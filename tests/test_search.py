"""guided-lfd's own optimal planner (guided_lfd.planning.search): pruning keeps every plan, A* is optimal."""

from __future__ import annotations

from collections import deque

import pytest
from hypothesis import HealthCheck, given, settings

from conftest import ROOT
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.optimal import is_plan
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning import find_plan
from guided_lfd.planning.search import astar, planning_actions, reachable_actions
from test_excuse_engine import small_tasks
from test_optimal import _optimal_length, _task_from_text

IPC = ROOT / "data" / "benchmarks" / "ipc"


def _applicable_somewhere(task) -> set[str]:
    """Names of the actions applicable in some state reachable from the initial state (brute force)."""
    seen, queue, used = {task.init}, deque([task.init]), set()
    while queue:
        s = queue.popleft()
        for act in task.actions:
            if act.applicable(s):
                used.add(act.name)
                t = act.apply(s)
                if t not in seen:
                    seen.add(t)
                    queue.append(t)
    return used


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(small_tasks())
def test_reachability_keeps_every_action_a_reachable_state_can_apply(tmp_path, pddl):
    task = _task_from_text(tmp_path, *pddl)
    kept = {a.name for a in reachable_actions(task.actions, task.init)}
    assert _applicable_somewhere(task) <= kept


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(small_tasks())
def test_astar_is_optimal_and_proves_unsolvability(tmp_path, pddl):
    task = _task_from_text(tmp_path, *pddl)
    optimum = _optimal_length(task, task.init)
    plan = astar(planning_actions(task, task.init), task.init, task.goal_pos, task.goal_neg)
    if optimum is None:
        assert plan is None
    else:
        assert plan is not None and len(plan) == optimum
        assert is_plan(plan, task.init, task.goal_pos, task.goal_neg)


@pytest.mark.parametrize("name,length", [("blocks/task04", 12), ("gripper/task01", 11), ("logistics/task01", 20),
                                         ("depot/task01", 10), ("satellite/task02", 13), ("miconic/task03", 10),
                                         ("zenotravel/task03", 6), ("zenotravel/task05", 11)])
def test_ipc_plans_have_pyperplans_optimal_lengths(name, length):
    # Lengths as pyperplan's own `pyperplan -s astar -H lmcut` reports them.
    domain, problem = name.split("/")
    dom, prob = parse_task(IPC / domain / "domain.pddl", IPC / domain / f"{problem}.pddl")
    task = ground(dom, prob, fixed=dom.predicates)
    result = find_plan(task, search="astar-lmcut")
    assert result.optimal and len(result.plan) == length
    assert is_plan(result.plan, task.init, task.goal_pos, task.goal_neg)


def test_reachability_prunes_where_types_allow_more_than_the_world_does():
    # depot task02: 666 type-correct ground actions, 210 reachable (a planner's grounding).
    dom, prob = parse_task(IPC / "depot" / "domain.pddl", IPC / "depot" / "task02.pddl")
    task = ground(dom, prob, fixed=dom.predicates)
    assert (len(task.actions), len(reachable_actions(task.actions, task.init))) == (666, 210)
    assert len(planning_actions(task, task.init)) <= 210
