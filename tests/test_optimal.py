"""Plan shortening and the LM-cut certificate of optimality (guided_lfd.planning.optimal)."""

from __future__ import annotations

from collections import deque

import pytest
from hypothesis import HealthCheck, given, settings

from guided_lfd.planning.grounding import ground
from guided_lfd.planning.optimal import certified_optimal, is_plan, shorten_plan
from guided_lfd.planning.relaxation import INF, RelaxedTask
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning import find_plan
from conftest import BLOCKS, kitchen
from test_excuse_engine import small_tasks


def _optimal_length(task, state: int) -> int | None:
    """Breadth-first optimal plan length (None = unsolvable): the reference."""
    seen = {state}
    queue = deque([(state, 0)])
    while queue:
        s, d = queue.popleft()
        if task.satisfies_goal(s):
            return d
        for act in task.actions:
            if act.applicable(s):
                t = act.apply(s)
                if t not in seen:
                    seen.add(t)
                    queue.append((t, d + 1))
    return None


def _task_from_text(tmp_path, domain_text: str, problem_text: str):
    (tmp_path / "d.pddl").write_text(domain_text)
    (tmp_path / "p.pddl").write_text(problem_text)
    return ground(*parse_task(tmp_path / "d.pddl", tmp_path / "p.pddl"))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(small_tasks())
def test_lmcut_is_admissible_and_detects_unsolvable_tasks(tmp_path, pddl):
    task = _task_from_text(tmp_path, *pddl)
    h = RelaxedTask(task.actions, task.goal_pos, task.goal_neg).lmcut(task.init)
    optimum = _optimal_length(task, task.init)
    if optimum is None:
        assert h <= INF  # relaxed-solvable tasks may still be unsolvable
    else:
        assert h <= optimum


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(small_tasks())
def test_shortened_plans_stay_plans_and_never_grow(tmp_path, pddl):
    task = _task_from_text(tmp_path, *pddl)
    result = find_plan(task, search="gbfs-hff")
    if result.plan is None:
        return
    plan = list(result.plan)
    short = shorten_plan(plan, task.init, task.goal_pos, task.goal_neg)
    assert is_plan(short, task.init, task.goal_pos, task.goal_neg)
    assert len(short) <= len(plan)
    optimum = _optimal_length(task, task.init)
    if certified_optimal(short, task.init, RelaxedTask(task.actions, task.goal_pos, task.goal_neg)):
        assert len(short) == optimum


def test_lmcut_matches_optimum_on_kitchen_1_and_certifies_its_plan():
    domain, problem = parse_task(*kitchen(1, "human"))
    task = ground(domain, problem)
    plan = find_plan(task).plan
    assert RelaxedTask(task.actions, task.goal_pos, task.goal_neg).lmcut(task.init) == len(plan) == 3
    assert certified_optimal(plan, task.init, RelaxedTask(task.actions, task.goal_pos, task.goal_neg))


def test_shorten_plan_cuts_loops_and_useless_steps():
    domain, problem = parse_task(*kitchen(1, "human"))
    task = ground(domain, problem)
    by_name = {a.name: a for a in task.actions}
    plan = [by_name[n] for n in ("(open_drawer pinkdrawer)", "(close_drawer pinkdrawer)", "(open_drawer bluedrawer)",
                                 "(open_drawer pinkdrawer)", "(take redplate table)",
                                 "(put_inside redplate pinkdrawer)")]
    assert is_plan(plan, task.init, task.goal_pos, task.goal_neg)
    short = shorten_plan(plan, task.init, task.goal_pos, task.goal_neg)
    assert [a.name for a in short] == ["(open_drawer pinkdrawer)", "(take redplate table)",
                                       "(put_inside redplate pinkdrawer)"]


def test_lmcut_on_blocks_tasks_never_exceeds_the_optimum():
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task02.pddl")
    task = ground(domain, problem)
    h = RelaxedTask(task.actions, task.goal_pos, task.goal_neg).lmcut(task.init)
    assert 0 < h <= _optimal_length(task, task.init)


def test_lmcut_unreachable_goal_is_infinite(tmp_path):
    domain = ("(define (domain d) (:requirements :strips) (:predicates (p) (q)) "
              "(:action a :parameters () :precondition (and (p)) :effect (and (p))))")
    task = _task_from_text(tmp_path, domain, "(define (problem x) (:domain d) (:init (p)) (:goal (and (q))))")
    assert RelaxedTask(task.actions, task.goal_pos, task.goal_neg).lmcut(task.init) == INF
