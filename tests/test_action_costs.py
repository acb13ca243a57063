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
from guided_lfd.planning.grounding import ground
from guided_lfd.merge import merge_domains
from guided_lfd.pddl import fast_reader, reader
from guided_lfd.pddl.model import Atom
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import domain_to_pddl, problem_to_pddl
from guided_lfd.planning import find_plan
from guided_lfd.symbolic.portfolio import plan_task

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
                        "unsupported: cost 2.5 is not a whole number >= 0"),
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


# -- a review's findings: each input once crashed, was misread, or read differently on the two paths --------


def _variant(tmp_path, domain_edits=(), problem_edits=()) -> tuple[str, str]:
    """The roads fixture with textual edits, written under ``tmp_path``."""
    dtext, ptext = (COSTS / "domain.pddl").read_text(), (COSTS / "problem.pddl").read_text()
    for old, new in domain_edits:
        assert old in dtext, old
        dtext = dtext.replace(old, new)
    for old, new in problem_edits:
        assert old in ptext, old
        ptext = ptext.replace(old, new)
    (tmp_path / "d.pddl").write_text(dtext)
    (tmp_path / "p.pddl").write_text(ptext)
    return str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl")


def _both_ways(monkeypatch, domain: str, problem: str):
    """(outcome with the fast path, outcome with tarski alone): each a model summary or an error line."""
    def outcome():
        try:
            d, p = parse_task(domain, problem)
        except Exception as exc:  # noqa: BLE001 - a crash is an outcome the test rejects
            return (type(exc).__name__, str(exc))
        return ("ok", repr(d.actions), repr(d.functions), repr(d.types), repr(sorted(p.function_values.items())),
                p.metric, repr(p.objects))
    fast = outcome()
    monkeypatch.setattr(fast_reader, "read_domain", lambda *args: None)
    slow = outcome()
    monkeypatch.undo()
    return fast, slow


COST_EDIT = "(increase (total-cost) (road-length ?a ?b))"
REFUSED_COSTS = {
    "arithmetic": ("(increase (total-cost) (+ (road-length ?a ?b) 1))", "unsupported: a cost must be a whole number"),
    "a sum of numbers": ("(increase (total-cost) (+ 1 2))", "unsupported: a cost must be a whole number"),
    "total-cost itself": ("(increase (total-cost) (total-cost))", "unsupported: a cost must be a whole number"),
    "a fraction": ("(increase (total-cost) 3.0)", "unsupported: cost 3.0 is not a whole number >= 0"),
    "wrong arity": ("(increase (total-cost) (road-length ?a))", "semantic error: wrong number of arguments for 'road-length' (expected 2)"),
    "two cost effects": (COST_EDIT + " (increase (total-cost) 1)", "semantic error: an action increases total-cost twice"),
}


@pytest.mark.parametrize("name", REFUSED_COSTS)
def test_cost_forms_the_model_cannot_hold_are_refused_at_their_place(name, tmp_path, monkeypatch, runner, app):
    effect, message = REFUSED_COSTS[name]
    domain, problem = _variant(tmp_path, [(COST_EDIT, effect)])
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and message in fast[1] and f"{domain}:12:" in fast[1], fast  # the drive action's cost
    result = runner.invoke(app, ["plan", domain, problem])
    assert result.exit_code in (32, 33) and "internal error" not in result.stderr


def test_total_cost_with_arguments_is_refused(tmp_path):
    domain, problem = _variant(tmp_path, [("(:functions (total-cost) - number", "(:functions (total-cost ?p - place) - number")])
    with pytest.raises(UnsupportedFeatureError) as info:
        parse_task(domain, problem)
    assert "total-cost takes no arguments" in str(info.value) and ":6:" in str(info.value)


INIT_ERRORS = {
    "wrong arity": ("(= (road-length home shop) 30)", "(= (road-length home) 30)",
                    "semantic error: wrong number of arguments for 'road-length' (expected 2)"),
    "wrong type": ("(:objects home shop mid1 mid2 - place)", "(:objects home shop mid1 mid2 - place other)",
                   None),
    "two values": ("(= (total-cost) 0)", "(= (total-cost) 0) (= (road-length home shop) 31)",
                   "semantic error: two values for (road-length home shop) in :init: 30 and 31"),
    "unknown function": ("(= (total-cost) 0)", "(= (total-cost) 0) (= (width home) 3)", "unknown function 'width'"),
    "a fraction": ("(= (road-length home shop) 30)", "(= (road-length home shop) 2.5)",
                   "unsupported: value 2.5 is not a whole number >= 0"),
}


@pytest.mark.parametrize("name", INIT_ERRORS)
def test_initial_values_are_checked_the_same_way_on_both_paths(name, tmp_path, monkeypatch):
    old, new, message = INIT_ERRORS[name]
    edits = [(old, new)]
    if name == "wrong type":
        edits.append(("(= (total-cost) 0)", "(= (total-cost) 0) (= (road-length other shop) 1)"))
        message = "semantic error: 'other' is a object, expected a place"
    domain, problem = _variant(tmp_path, problem_edits=edits)
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and message in fast[1], fast
    assert ":1:1:" not in fast[1]


def test_values_the_same_twice_and_huge_ones_read_exactly_on_both_paths(tmp_path, monkeypatch):
    huge = 10 ** 23 + 7
    domain, problem = _variant(tmp_path, problem_edits=[
        ("(= (road-length home shop) 30)", f"(= (road-length home shop) {huge}) (= (road-length home shop) {huge})")])
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and fast[0] == "ok" and str(huge) in fast[4]


def test_untyped_function_parameters_read_on_both_paths(tmp_path, monkeypatch, runner, app):
    # 'look' without a precondition sends the domain down tarski's path.
    domain, problem = _variant(tmp_path, [("(road-length ?a ?b - place) - number", "(road-length ?a ?b) - number"),
                                          ("    :precondition (at ?a)\n    :effect (visited ?a)", "    :effect (visited ?a)")])
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and fast[0] == "ok", fast
    assert runner.invoke(app, ["plan", domain, problem]).stdout.splitlines()[-1] == "; cost = 15 (general cost)"


def test_a_type_named_like_an_object_keeps_its_name_in_the_functions(tmp_path, monkeypatch):
    domain, problem = _variant(
        tmp_path, [("(:types place)", "(:types place)\n  (:constants place - place)"),
                   ("    :precondition (at ?a)\n    :effect (visited ?a)", "    :effect (visited ?a)")])
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and fast[0] == "ok", fast
    dom, _ = parse_task(domain, problem)
    assert dom.functions["road-length"].params == (("?x0", "place"), ("?x1", "place"))
    (tmp_path / "w.pddl").write_text(domain_to_pddl(dom))
    assert parse_task(str(tmp_path / "w.pddl"), problem)[0].functions == dom.functions


def test_an_object_named_like_a_function_is_refused_on_both_paths(tmp_path, monkeypatch):
    domain, problem = _variant(tmp_path, problem_edits=[("(:objects home shop mid1 mid2 - place)",
                                                         "(:objects home shop mid1 mid2 road-length - place)")])
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and "declared twice" in fast[1], fast


def test_metric_keywords_in_capitals_read_on_both_paths(tmp_path, monkeypatch):
    domain, problem = _variant(tmp_path, problem_edits=[("(:metric minimize (total-cost))",
                                                         "(:METRIC MINIMIZE (total-cost))")])
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and fast[0] == "ok" and fast[5] is True, fast


def test_an_implicit_constant_in_a_cost_term_takes_the_problems_type(tmp_path, monkeypatch, runner, app):
    domain, problem = _variant(tmp_path, [("(increase (total-cost) 50)", "(increase (total-cost) (road-length ?a mid1))")])
    fast, slow = _both_ways(monkeypatch, domain, problem)
    assert fast == slow and fast[0] == "ok", fast
    result = runner.invoke(app, ["plan", domain, problem])
    assert result.exit_code == 0 and "warning: 'mid1' in action 'teleport' is not a declared constant" in result.stderr


def test_merging_cost_functions_widens_their_types_and_refuses_a_predicate_of_the_name(tmp_path):
    base = (COSTS / "domain.pddl").read_text()
    (tmp_path / "a.pddl").write_text(base)
    (tmp_path / "b.pddl").write_text(base.replace("(:types place)", "(:types place depot - object)").replace(
        "(road-length ?a ?b - place) - number", "(road-length ?a ?b - depot) - number").replace(
        "(increase (total-cost) (road-length ?a ?b))", "(increase (total-cost) 2)"))
    result = merge_domains([parse_domain(str(tmp_path / "a.pddl")), parse_domain(str(tmp_path / "b.pddl"))])
    assert result.domain.functions["road-length"].params == (("?x0", "object"), ("?x1", "object"))
    assert any(line.startswith("function road-length: argument types widened") for line in result.refined)
    (tmp_path / "c.pddl").write_text(base.replace("(visited ?p - place))", "(visited ?p - place) (road-length ?p))"
                                                  ).replace("(:functions (total-cost) - number\n              (road-length ?a ?b - place) - number)", "(:functions (total-cost) - number)").replace(
        "(increase (total-cost) (road-length ?a ?b))", "(increase (total-cost) 2)"))
    from guided_lfd.errors import MergeError

    with pytest.raises(MergeError) as info:
        merge_domains([parse_domain(str(tmp_path / "a.pddl")), parse_domain(str(tmp_path / "c.pddl"))])
    assert "road-length is a function in" in str(info.value)
