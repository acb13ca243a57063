"""ADL in the shared model: reading, writing, planning over conditional effects and axioms, validating.

The planner grounds through Fast Downward's normal form; the checks here run
plans and searches with guided-lfd's own lifted semantics
(:mod:`guided_lfd.pddl.semantics`), so neither side confirms itself.
"""

from __future__ import annotations

from collections import deque
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from guided_lfd.errors import UnsupportedFeatureError
from guided_lfd.grounding import AxiomClosure, GroundAxiom, ground
from guided_lfd.pddl.formula import Junction, Quantified, holds
from guided_lfd.pddl.model import Atom, Literal, objects_by_type
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.semantics import derived_atoms, effect_atoms, failed_conditions, strata
from guided_lfd.pddl.writer import domain_to_pddl, problem_to_pddl
from guided_lfd.planning import plan_task
from guided_lfd.validation import PlanStep, validate_plan

ROOT = Path(__file__).resolve().parent.parent
ADL = ROOT / "tests" / "data" / "adl"
HOUSE = ADL / "household"
IPC_ADL = ROOT / "data" / "benchmarks" / "ipc-adl"


def _lifted_bfs(domain, problem, limit: int = 20000) -> int | None:
    """The optimal plan length by breadth-first search with the lifted semantics (None: unsolvable)."""
    from guided_lfd.pddl.formula import bindings_of

    objects = objects_by_type(domain, problem)
    layers = strata(domain)
    goal = problem.goal_condition or Junction("and", problem.goal)
    ground_actions = [(schema, b) for schema in domain.actions for b in bindings_of(schema.params, objects)]

    def world(state):
        return state | derived_atoms(domain, state, objects, layers)

    start = frozenset(problem.init)
    depth = {start: 0}
    queue = deque([start])
    while queue:
        state = queue.popleft()
        here = world(state)
        if holds(goal, here, objects):
            return depth[state]
        for schema, binding in ground_actions:
            if failed_conditions(schema, binding, here, objects):
                continue
            adds, dels = effect_atoms(schema, binding, here, objects)
            nxt = frozenset((state - dels) | adds)
            if nxt not in depth:
                depth[nxt] = depth[state] + 1
                assert len(depth) < limit, "state space larger than the test allows"
                queue.append(nxt)
    return None


def _optimal_length(domain, problem) -> int | None:
    _, result = plan_task(domain, problem)
    if result.plan is None:
        return None
    steps = [PlanStep(a.schema, a.args) for a in result.plan]
    report = validate_plan(domain, problem.init, problem.goal, steps, problem, problem.goal_condition)
    assert report.valid, [str(s.failed) for s in report.steps]
    return len(steps)


# --- reading and writing ------------------------------------------------------------------------------------

def test_the_household_reads_as_formulas_effects_and_rules():
    domain, problem = parse_task(HOUSE / "domain.pddl", HOUSE / "problem.pddl")
    unload = domain.action("unload-all")
    assert isinstance(unload.condition, Junction) and unload.condition.kind == "and"
    assert Literal(Atom("tray-at", ("?t", "?p"))) in unload.precondition  # its top-level literal
    # The translator's normal form: one effect per literal, each with its own variable.
    assert [str(e.literal) for e in unload.effects] == ["(item-at ?i1 ?p)", "(not (on-tray ?i2 ?t))", "(stored ?i3)"]
    assert unload.effects[0].variables == (("?i1", "item"),)
    assert str(unload.effects[2].condition) == "(and (on-tray ?i3 ?t) (cupboard ?p))"
    assert domain.derived_predicates() == {"tidy"}
    assert isinstance(domain.axioms[0].condition, Quantified)
    assert domain.action("carry").condition is None  # plain STRIPS stays plain
    assert problem.goal == (Literal(Atom("tidy", ("kitchen",))),)
    assert isinstance(problem.goal_condition, Junction)
    assert domain.is_adl and not domain.action("open-door").is_adl


def test_the_household_writes_as_its_golden_file_and_reads_back_the_same():
    domain, problem = parse_task(HOUSE / "domain.pddl", HOUSE / "problem.pddl")
    text = domain_to_pddl(domain)
    assert text == (ADL / "household-written.pddl").read_text()
    again, again_problem = parse_task("d.pddl", "p.pddl", domain_text=text, problem_text=problem_to_pddl(problem))
    assert again.actions == domain.actions and again.axioms == domain.axioms
    assert again_problem.goal_condition == problem.goal_condition


def _first_task_of_each_domain():
    import sys

    sys.path.insert(0, str(ROOT / "benchmarks"))
    from adl_bench import tasks

    seen: dict[str, tuple[Path, Path]] = {}
    for domain, problem in tasks(IPC_ADL):
        seen.setdefault(problem.parent.name, (domain, problem))
    return list(seen.values())


def test_every_ipc_adl_domain_reads_and_round_trips_through_the_writer():
    pairs = _first_task_of_each_domain()
    assert len(pairs) == 28
    for domain_path, problem_path in pairs:
        domain, problem = parse_task(domain_path, problem_path)
        again, again_problem = parse_task("d.pddl", "p.pddl", domain_text=domain_to_pddl(domain),
                                          problem_text=problem_to_pddl(problem))
        assert (again.actions, again.axioms, again.predicates, again.types) == (
            domain.actions, domain.axioms, domain.predicates, domain.types), problem_path
        assert (again_problem.init, again_problem.goal, again_problem.goal_condition) == (
            problem.init, problem.goal, problem.goal_condition), problem_path


@pytest.mark.parametrize("domain, problem", [
    ("type-twice.pddl", "type-twice-problem.pddl"),
    ("type-and-predicate.pddl", "type-and-predicate-problem.pddl"),
    ("object-among-types.pddl", "object-among-types-problem.pddl"),
    ("domain.pddl", "digit-names.pddl"),
    ("domain.pddl", "object-called-domain.pddl"),
])
def test_valid_pddl_tarski_refuses_reads_and_plans(domain, problem):
    gaps = ADL / "gaps"
    dom, prob = parse_task(gaps / domain, gaps / problem)
    assert _optimal_length(dom, prob) == 1


def test_a_type_declared_twice_with_different_parents_is_still_an_error(tmp_path):
    from guided_lfd.errors import PddlSemanticError

    path = tmp_path / "d.pddl"
    path.write_text("(define (domain d) (:requirements :strips :typing)\n  (:types t - u t - object u)\n"
                    "  (:predicates (p ?x - t)) (:action a :parameters (?x - t) :precondition (p ?x) "
                    ":effect (not (p ?x))))")
    with pytest.raises(PddlSemanticError, match="type 't' is declared twice"):
        parse_domain(path)


def test_a_translator_error_is_one_line_at_the_name_it_is_about(tmp_path):
    from guided_lfd.errors import PddlSyntaxError

    path = tmp_path / "d.pddl"
    path.write_text((HOUSE / "domain.pddl").read_text().replace("(stored ?i)))))))", "(stowed ?i)))))))"))
    with pytest.raises(PddlSyntaxError) as info:
        parse_domain(path)
    assert "\n" not in str(info.value) and "stowed" in str(info.value)
    assert str(info.value).startswith(f"{path}:") and "Fast Downward" in str(info.value)


# --- planning and validating ---------------------------------------------------------------------------------

def test_the_household_plan_is_optimal_and_uses_the_conditional_effects():
    domain, problem = parse_task(HOUSE / "domain.pddl", HOUSE / "problem.pddl")
    assert _optimal_length(domain, problem) == _lifted_bfs(domain, problem) == 7


@pytest.mark.parametrize("folder, name", [
    ("briefcaseworld", "pfile1"), ("briefcaseworld", "pfile3"), ("miconic-simpleadl", "s1-0"),
    ("miconic-fulladl", "f1-0"), ("elevators-00-full", "f1-1"), ("elevators-00-adl", "s1-1"),
    ("blocks-conditional-effect", None),
])
def test_optimal_lengths_equal_a_breadth_first_search_with_the_lifted_semantics(folder, name):
    if name is None:
        domain, problem = parse_task(ADL / f"{folder}.pddl", ROOT / "data/benchmarks/ipc/blocks/task01.pddl")
    else:
        domain, problem = parse_task(IPC_ADL / folder / "domain.pddl", IPC_ADL / folder / f"{name}.pddl")
    assert _optimal_length(domain, problem) == _lifted_bfs(domain, problem)


def test_validate_names_the_failing_disjunction_and_runs_conditional_effects():
    domain, problem = parse_task(HOUSE / "domain.pddl", HOUSE / "problem.pddl")
    steps = [PlanStep("load", ("cup", "tray1", "counter")), PlanStep("carry", ("tray1", "counter", "pantry")),
             PlanStep("unload-all", ("tray1", "pantry"))]
    report = validate_plan(domain, problem.init, problem.goal, steps, problem, problem.goal_condition)
    failure = report.first_failure
    assert failure is not None and failure.index == 3
    assert [str(f) for f in failure.failed] == [
        "(or (not (cupboard pantry)) (not (has-door pantry)) (door-open pantry))"]
    opened = [PlanStep("open-door", ("pantry",)), *steps]
    report = validate_plan(domain, problem.init, problem.goal, opened, problem, problem.goal_condition)
    assert report.first_failure is None
    assert Atom("stored", ("cup",)) in report.final_state  # the nested conditional effect (a cupboard)
    assert Atom("item-at", ("cup", "pantry")) in report.final_state
    assert [str(g) for g in report.unsatisfied_goal] == ["(tidy kitchen)"]  # plate and spoon are not stored


def test_the_cli_plans_and_validates_an_adl_task(runner, app, tmp_path):
    out = tmp_path / "plan.txt"
    result = runner.invoke(app, ["plan", str(HOUSE / "domain.pddl"), str(HOUSE / "problem.pddl"), "-o", str(out),
                                 "--quiet"])
    assert result.exit_code == 0, result.output
    assert out.read_text().endswith("; cost = 7 (unit cost)\n")
    result = runner.invoke(app, ["validate", str(HOUSE / "domain.pddl"), str(HOUSE / "problem.pddl"), str(out)])
    assert result.exit_code == 0, result.output


def test_excuses_on_adl_domains_are_refused_in_one_line_for_now(runner, app):
    result = runner.invoke(app, ["excuse", str(HOUSE / "domain.pddl"), str(HOUSE / "problem.pddl")])
    assert result.exit_code == 33
    assert "excuses on domains with ADL" in result.stderr and len(result.stderr.strip().splitlines()) == 1


def test_grounding_for_excuses_refuses_adl_instead_of_dropping_its_effects():
    domain, problem = parse_task(HOUSE / "domain.pddl", HOUSE / "problem.pddl")
    with pytest.raises(UnsupportedFeatureError):
        ground(domain, problem)  # excuses change static atoms too: not in Fast Downward's normal form yet


def test_axiom_layers_close_a_state_with_negation_as_failure():
    # layer 0: d1 <- a ; d2 <- d1 and b (same layer, chained) ; layer 1: d3 <- not d2
    a, b, d1, d2, d3 = range(5)
    closure = AxiomClosure([[GroundAxiom(d1, 1 << a, 0), GroundAxiom(d2, (1 << d1) | (1 << b), 0)],
                            [GroundAxiom(d3, 0, 1 << d2)]], derived=(1 << d1) | (1 << d2) | (1 << d3))
    assert closure.close(1 << a) == (1 << a) | (1 << d1) | (1 << d3)
    assert closure.close((1 << a) | (1 << b)) == (1 << a) | (1 << b) | (1 << d1) | (1 << d2)
    assert closure.close(1 << d2) == 1 << d3  # stale derived atoms are recomputed, not kept


# --- random ADL tasks against the lifted breadth-first search ----------------------------------------------

_ATOMS = ["(p ?x)", "(p a)", "(p b)", "(q ?x)", "(q a)", "(r)"]


def _formula(draw, depth: int) -> str:
    kind = draw(st.sampled_from(["lit", "lit", "and", "or", "exists", "forall", "imply"] if depth else ["lit"]))
    if kind == "lit":
        atom = draw(st.sampled_from(_ATOMS + ["(d ?x)", "(e)"]))
        return atom if draw(st.booleans()) else f"(not {atom})"
    if kind in ("and", "or"):
        parts = [_formula(draw, depth - 1) for _ in range(draw(st.integers(1, 3)))]
        return f"({kind} {' '.join(parts)})"
    if kind == "imply":
        return f"(imply {_formula(draw, depth - 1)} {_formula(draw, depth - 1)})"
    body = _formula(draw, depth - 1).replace("?x", "?y")
    return f"({kind} (?y - obj) {body})"


@st.composite
def _adl_tasks(draw) -> tuple[str, str]:
    actions = []
    for k in range(draw(st.integers(1, 3))):
        pre = _formula(draw, 2)
        effects = [draw(st.sampled_from(["(p ?x)", "(not (p ?x))", "(q ?x)", "(not (q ?x))", "(r)", "(not (r))"]))]
        if draw(st.booleans()):
            cond = _formula(draw, 1).replace("?x", "?z")
            literal = draw(st.sampled_from(["(p ?z)", "(not (p ?z))", "(q ?z)", "(not (r))"]))
            effects.append(f"(forall (?z - obj) (when {cond} {literal}))")
        if draw(st.booleans()):
            effects.append(f"(when {_formula(draw, 1)} {draw(st.sampled_from(['(r)', '(not (q ?x))', '(p a)']))})")
        actions.append(f"(:action act{k} :parameters (?x - obj) :precondition {pre} "
                       f":effect (and {' '.join(effects)}))")
    derived_d = _formula(draw, 1).replace("(d ", "(p ").replace("(e)", "(r)")  # d uses no derived predicate
    derived_e = _formula(draw, 1).replace("(e)", "(r)")
    domain = ("(define (domain rnd) (:requirements :adl :derived-predicates) (:types obj) (:constants a b - obj) "
              "(:predicates (p ?x - obj) (q ?x - obj) (r) (d ?x - obj) (e)) "
              f"(:derived (d ?x - obj) {derived_d}) (:derived (e) (exists (?x - obj) {derived_e})) "
              + " ".join(actions) + ")")
    init = " ".join(draw(st.lists(st.sampled_from(["(p a)", "(p b)", "(q a)", "(q b)", "(r)"]), unique=True)))
    goal = _formula(draw, 2).replace("?x", "a")
    problem = f"(define (problem rp) (:domain rnd) (:init {init}) (:goal {goal}))"
    return domain, problem


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_adl_tasks())
def test_random_adl_tasks_plan_as_the_lifted_semantics_search(task):
    domain_text, problem_text = task
    domain, problem = parse_task("d.pddl", "p.pddl", domain_text=domain_text, problem_text=problem_text)
    assert _optimal_length(domain, problem) == _lifted_bfs(domain, problem)


def test_merge_keeps_a_prior_domains_adl_actions_and_rules(runner, app, tmp_path):
    out = tmp_path / "merged.pddl"
    kitchen = ROOT / "data" / "domains" / "kitchen-1" / "robot.pddl"
    result = runner.invoke(app, ["merge", str(HOUSE / "domain.pddl"), str(kitchen), "-o", str(out)])
    assert result.exit_code == 0, result.output
    merged = parse_domain(out)
    house = parse_domain(HOUSE / "domain.pddl")
    assert merged.axioms == house.axioms
    for act in house.actions:
        assert merged.action(act.name).condition == act.condition and merged.action(act.name).effects == act.effects
    _, problem = parse_task(HOUSE / "domain.pddl", HOUSE / "problem.pddl")
    from guided_lfd.pddl.reader import parse_problem_for

    assert _optimal_length(merged, parse_problem_for(merged, HOUSE / "problem.pddl")) == 7
    # The same ADL action twice is one action (compared with its formulas and effects).
    twice = runner.invoke(app, ["merge", str(HOUSE / "domain.pddl"), str(HOUSE / "domain.pddl"), "-o", str(out)])
    assert twice.exit_code == 0 and len(parse_domain(out).actions) == 4
