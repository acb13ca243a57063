""":action-costs: read both ways, planned cost-optimally, validated with the cost, kept by excuses and merges.

The fixtures in tests/data/costs/ are a road map where the cheapest route
(three roads of length 5) is not the shortest (one road of length 30).
"""

from __future__ import annotations

import heapq
import json
import os

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import DATA
from guided_lfd.errors import PddlSyntaxError, UnsupportedFeatureError
from guided_lfd.grounding import ground
from guided_lfd.merge import merge_domains
from guided_lfd.pddl import fast_reader, reader
from guided_lfd.pddl.model import Atom
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import domain_to_pddl, problem_to_pddl
from guided_lfd.planning import find_plan, plan_task

COSTS = DATA / "costs"
DOMAIN, PROBLEM = str(COSTS / "domain.pddl"), str(COSTS / "problem.pddl")
ROBOT, NO_FUEL = str(COSTS / "robot.pddl"), str(COSTS / "no-fuel.pddl")


def _without_metric(tmp_path) -> str:
    text = (COSTS / "problem.pddl").read_text().replace("\n  (:metric minimize (total-cost)))", ")")
    path = tmp_path / "no-metric.pddl"
    path.write_text(text)
    return str(path)


def test_the_model_has_the_costs_the_file_declares():
    domain, problem = parse_task(DOMAIN, PROBLEM)
    assert list(domain.functions) == ["total-cost", "road-length"]
    assert {a.name: a.cost for a in domain.actions} == {
        "drive": Atom("road-length", ("?a", "?b")), "teleport": 50, "look": None}
    assert problem.metric
    assert problem.function_values[Atom("road-length", ("home", "shop"))] == 30
    assert Atom("total-cost") not in problem.function_values


def test_the_fast_path_reads_costs_as_tarski_does(monkeypatch):
    fast = parse_task(DOMAIN, PROBLEM)
    dsrc = reader._source_map(DOMAIN, "domain")
    assert fast_reader.read_domain(dsrc, DOMAIN) is not None  # the fast path took it
    monkeypatch.setattr(fast_reader, "read_domain", lambda *args: None)
    slow = parse_task(DOMAIN, PROBLEM)
    assert fast[0].actions == slow[0].actions and fast[0].functions == slow[0].functions
    assert fast[1].function_values == slow[1].function_values and fast[1].metric == slow[1].metric


def test_plan_is_cost_optimal_not_shortest(runner, app):
    result = runner.invoke(app, ["plan", DOMAIN, PROBLEM])
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines() == ["(drive home mid1)", "(drive mid1 mid2)", "(drive mid2 shop)",
                                          "; cost = 15 (general cost)"]
    doc = json.loads(runner.invoke(app, ["plan", DOMAIN, PROBLEM, "--json"]).stdout)
    assert (doc["cost"], doc["optimal"], len(doc["plan"])) == (15, True, 3)


def test_without_a_metric_every_action_costs_one(runner, app, tmp_path):
    result = runner.invoke(app, ["plan", DOMAIN, _without_metric(tmp_path)])
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines() == ["(drive home shop)", "; cost = 1 (unit cost)"]


def test_pyperplan_searches_are_not_called_optimal_when_costs_differ():
    domain, problem = parse_task(DOMAIN, PROBLEM)
    _, result = plan_task(domain, problem, search="pyperplan-astar-lmcut")
    assert result.plan is not None and not result.optimal
    _, unit = plan_task(*parse_task(str(DATA / "blocks/domain.pddl"), str(DATA / "blocks/task01.pddl")),
                        search="pyperplan-astar-lmcut")
    assert unit.optimal


def test_validate_reports_the_cost_and_refuses_a_step_without_one(runner, app, tmp_path):
    plan = tmp_path / "detour.plan"
    plan.write_text("(drive home mid1)\n(drive mid1 mid2)\n(drive mid2 shop)\n")
    result = runner.invoke(app, ["validate", DOMAIN, PROBLEM, str(plan)])
    assert result.stdout == "valid: 3 step(s), goal reached, cost 15 (general cost)\n"
    assert json.loads(runner.invoke(app, ["validate", DOMAIN, PROBLEM, str(plan), "--json"]).stdout)["cost"] == 15
    # A road the map has no length for: the step cannot be applied (PDDL: its effect is undefined).
    problem = tmp_path / "unmeasured.pddl"
    problem.write_text((COSTS / "problem.pddl").read_text().replace("(= (road-length mid2 shop) 5)", ""))
    result = runner.invoke(app, ["validate", DOMAIN, str(problem), str(plan)])
    assert result.exit_code == 12
    assert result.stderr.strip().endswith(
        "detour.plan:3:1: invalid: step 3 (drive mid2 shop) cannot be applied: "
        "its cost (road-length mid2 shop) has no value in the problem's :init")


def test_ground_actions_without_a_cost_value_are_left_out():
    domain, problem = parse_task(DOMAIN, PROBLEM)
    task = ground(domain, problem)  # every type-correct action, as the excuse search grounds
    names = {a.name for a in task.actions}
    assert "(drive home mid1)" in names and "(drive home home)" not in names  # no length for home-home
    assert {a.name: a.cost for a in task.actions}["(teleport home shop)"] == 50
    assert {a.name: a.cost for a in task.actions}["(look home)"] == 0  # no cost effect under a metric


def test_excuse_gives_the_cost_optimal_robot_plan(runner, app):
    for strategy in ("landmark", "baseline"):
        result = runner.invoke(app, ["excuse", ROBOT, NO_FUEL, "--json", "--quiet", "--strategy", strategy])
        assert result.exit_code == 0, result.output
        excuse = json.loads(result.stdout)["excuse"]
        assert [c["change"] for c in excuse["changes"]] == ["+(fuel)"]
        assert (excuse["plan_length"], excuse["plan_cost"], excuse["plan_optimal"]) == (3, 15, True)
    text = runner.invoke(app, ["excuse", ROBOT, NO_FUEL, "--quiet"]).stdout
    assert "then the robot's own plan (3 steps, cost 15, optimal, validated):" in text


def test_written_cost_domains_and_problems_read_back_equal(tmp_path):
    domain, problem = parse_task(DOMAIN, PROBLEM)
    (tmp_path / "d.pddl").write_text(domain_to_pddl(domain))
    (tmp_path / "p.pddl").write_text(problem_to_pddl(problem))
    again, again_problem = parse_task(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"))
    assert again.actions == domain.actions and again.functions == domain.functions
    assert again_problem.function_values == problem.function_values and again_problem.metric


def test_a_skill_without_cost_merged_into_a_costed_library_costs_one():
    prior = parse_domain(ROBOT)
    learned = parse_domain(str(DATA / "merge/learned.pddl"))
    result = merge_domains([prior, learned])
    assert all(a.cost is not None for a in result.domain.actions)
    assert result.costed and all(line.endswith("has no action cost: it costs 1") for line in result.costed)
    assert ":action-costs" in domain_to_pddl(result.domain)


BAD = {
    "fractional cost": ("(increase (total-cost) 2.5)", UnsupportedFeatureError,
                        "unsupported: the cost of action 'drive' 2.5 is not a non-negative integer"),
    "other fluent": ("(increase (fuel-used) 1)", UnsupportedFeatureError,
                     "unsupported: 'increase' of a fluent other than total-cost"),
    "decrease": ("(decrease (total-cost) 1)", UnsupportedFeatureError, "unsupported: 'decrease' needs :numeric-fluents"),
}


@pytest.mark.parametrize("name", BAD)
def test_numbers_beyond_action_costs_are_refused_with_one_line(name, tmp_path):
    effect, exc, message = BAD[name]
    text = (COSTS / "domain.pddl").read_text().replace("(increase (total-cost) (road-length ?a ?b))", effect)
    path = tmp_path / "domain.pddl"
    path.write_text(text)
    with pytest.raises(exc) as info:
        parse_task(str(path), PROBLEM)
    assert "\n" not in str(info.value) and message in str(info.value), str(info.value)
    assert str(info.value).startswith(f"{path}:")


@pytest.mark.parametrize("metric,message", [
    ("(:metric maximize (total-cost))", "a metric other than '(:metric minimize (total-cost))'"),
    ("(:metric minimize (total-time))", "a metric other than '(:metric minimize (total-cost))'"),
])
def test_other_metrics_are_refused(metric, message, tmp_path):
    path = tmp_path / "problem.pddl"
    path.write_text((COSTS / "problem.pddl").read_text().replace("(:metric minimize (total-cost))", metric))
    with pytest.raises(UnsupportedFeatureError) as info:
        parse_task(DOMAIN, str(path))
    assert message in str(info.value)


def test_numeric_preconditions_are_refused(tmp_path):
    path = tmp_path / "domain.pddl"
    path.write_text((COSTS / "domain.pddl").read_text().replace(
        ":precondition (at ?a)\n", ":precondition (and (at ?a) (> (road-length ?a ?b) 3))\n"))
    with pytest.raises(UnsupportedFeatureError) as info:
        parse_task(str(path), PROBLEM)
    assert "'>' needs :numeric-fluents" in str(info.value) or "numeric comparison" in str(info.value)


def _dijkstra(task, actions) -> float:
    """The cheapest plan's cost by uniform-cost search over the whole state space (the reference)."""
    best = {task.init: 0}
    heap = [(0, task.init)]
    while heap:
        g, state = heapq.heappop(heap)
        if g > best[state]:
            continue
        if task.satisfies_goal(state):
            return g
        for act in actions:
            if act.applicable(state):
                nxt = act.apply(state)
                if g + act.cost < best.get(nxt, float("inf")):
                    best[nxt] = g + act.cost
                    heapq.heappush(heap, (g + act.cost, nxt))
    return float("inf")


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 3), st.integers(0, 3), st.integers(0, 9)), min_size=1, max_size=9))
def test_astar_cost_equals_uniform_cost_search(roads):
    """On random road maps with random lengths (zero included), A* + LM-cut finds the cheapest plan."""
    places = [f"p{i}" for i in range(4)]
    init = ["(at p0)"] + [f"(road p{a} p{b})" for a, b, _ in roads]
    lengths = {(a, b): w for a, b, w in roads}
    init += [f"(= (road-length p{a} p{b}) {w})" for (a, b), w in lengths.items()]
    text = (f"(define (problem r) (:domain roads) (:objects {' '.join(places)} - place) "
            f"(:init {' '.join(init)}) (:goal (and (at p3) (visited p3))) (:metric minimize (total-cost)))")
    import tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".pddl", delete=False) as fh:
        fh.write(text)
    try:
        domain, problem = parse_task(DOMAIN, fh.name)
    finally:
        os.unlink(fh.name)
    task = ground(domain, problem, fixed=domain.predicates)
    result = find_plan(task)
    reference = _dijkstra(task, task.actions)
    if result.plan is None:
        assert reference == float("inf")
    else:
        assert sum(a.cost for a in result.plan) == reference


def test_a_cost_domain_with_syntax_error_still_names_the_place(tmp_path):
    path = tmp_path / "domain.pddl"
    path.write_text((COSTS / "domain.pddl").read_text().replace("(increase (total-cost) 50)", "(increase (total-cost) 50"))
    with pytest.raises(PddlSyntaxError) as info:
        parse_task(str(path), PROBLEM)
    assert str(info.value).startswith(f"{path}:")


def test_costs_either_types_shared_names_and_implicit_constants_together(runner, app, monkeypatch):
    """Every reader extension in one task: the same model both ways, and the cheapest plan."""
    domain, problem = str(DATA / "grammar/all-together/domain.pddl"), str(DATA / "grammar/all-together/problem.pddl")
    fast = parse_task(domain, problem)
    assert fast[0].predicates["at"].params[0][1] == "(either tool cart)"
    assert "cart" in fast[0].types and fast[1].objects["cart"] == "cart"
    assert fast[0].implicit_constants == ("wrench",) and fast[1].metric
    monkeypatch.setattr(fast_reader, "read_domain", lambda *args: None)
    slow = parse_task(domain, problem)
    monkeypatch.undo()
    assert (repr(slow[0].actions), slow[0].functions, slow[0].types) == (repr(fast[0].actions), fast[0].functions,
                                                                        fast[0].types)
    assert slow[1].function_values == fast[1].function_values and slow[1].objects == fast[1].objects
    result = runner.invoke(app, ["plan", domain, problem])
    assert result.stdout.splitlines()[-1] == "; cost = 6 (general cost)"  # via the yard (2 + 3 + 1), not 9 + 1
    assert "warning: 'wrench' in action 'grab' is not a declared constant" in result.stderr
