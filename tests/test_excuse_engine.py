"""The excuse engine: the paper's examples, the IPC acceptance case, and every
registered strategy against brute force on random small STRIPS tasks."""

from __future__ import annotations

import itertools
import json
from collections import deque

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import BLOCKS, ROOT, kitchen
from guided_lfd.excuse.change import Change
from guided_lfd.excuse.check import check_excuse
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.space import Semantics
from guided_lfd.excuse.strategies import STRATEGIES
from guided_lfd.pddl.model import Atom, Literal
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.planning.validation import PlanStep

ALL_STRATEGIES = sorted(STRATEGIES)


def changes_of(report):
    return [[str(c) for c in e.changes] for e in report.excuses]


def checker_laws(domain, problem, report):
    """The invariants the checker derives itself for ``report``'s semantics (none under the literal one): the
    brute force and the checks below take them from there, not from the engine under test."""
    from guided_lfd.excuse.laws import derive_laws

    return derive_laws(domain, problem) if report.semantics is Semantics.CONSISTENT else None


def assert_checked(domain, problem, report):
    """Re-check every excuse with the independent checker."""
    groups = checker_laws(domain, problem, report)
    for e in report.excuses:
        steps = e.plan
        assert check_excuse(domain, problem, e.changes, steps, groups) == []


@pytest.mark.parametrize("strategy", ALL_STRATEGIES)
@pytest.mark.parametrize("semantics", list(Semantics))
def test_kitchen_1_excuse_is_open_pinkdrawer(strategy, semantics):
    domain, problem = parse_task(*kitchen(1))
    report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, strategy=strategy))
    assert report.status == "excuse-found"
    assert changes_of(report) == [["+(open pinkdrawer)"]]
    assert [str(step) for step in report.excuse.plan] == ["(take redplate table)", "(put_inside redplate pinkdrawer)"]
    assert_checked(domain, problem, report)


@pytest.mark.parametrize("strategy", ALL_STRATEGIES)
@pytest.mark.parametrize("semantics", list(Semantics))
def test_kitchen_2_excuse_is_clear_pinkdrawer(strategy, semantics):
    domain, problem = parse_task(*kitchen(2))
    report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, strategy=strategy))
    assert changes_of(report) == [["+(clear pinkdrawer)"]]
    assert report.excuse.plan[0] == PlanStep("open_drawer", ("pinkdrawer",))


def test_kitchen_2_with_human_invariants_moves_the_chair_consistently():
    domain, problem = parse_task(*kitchen(2))
    human = parse_domain(kitchen(2, "human")[0])
    report = find_excuses(domain, problem, ExcuseOptions(invariants_from=human, all_minimal=True, verify=True))
    assert report.excuse.size == 4
    for e in report.excuses:
        changed = {str(c) for c in e.changes}
        assert {"+(clear pinkdrawer)", "-(blocking chair pinkdrawer)"} <= changed


@pytest.mark.parametrize("strategy", ALL_STRATEGIES)
def test_blocks_without_unstack_literal_has_six_excuses_of_size_two(strategy):
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem, ExcuseOptions(semantics=Semantics.LITERAL, strategy=strategy, all_minimal=True, verify=True))
    assert {e.size for e in report.excuses} == {2}
    assert len(report.excuses) == 6
    assert ["+(clear b)", "+(ontable c)"] in changes_of(report)


@pytest.mark.parametrize("strategy", ALL_STRATEGIES)
def test_blocks_without_unstack_consistent_is_exactly_move_c_to_table(strategy):
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem, ExcuseOptions(strategy=strategy, all_minimal=True, verify=True))
    assert changes_of(report) == [["+(clear b)", "-(on c b)", "+(ontable c)"]]


def test_already_solvable_gives_empty_excuse_and_plan():
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem)
    assert report.status == "already-solvable" and report.excuses == []
    assert len(report.robot_plan) == 6


def test_no_excuse_names_the_goal_no_skill_achieves(tmp_path):
    domain, problem = parse_task(*kitchen(1))
    # Without put_inside nothing makes the plate be inside a drawer.
    from dataclasses import replace

    crippled = replace(domain, actions=[a for a in domain.actions if a.name != "put_inside"])
    report = find_excuses(crippled, problem)
    assert report.status == "no-excuse"
    assert report.unachievable_goals == [Literal(Atom("inside", ("redplate", "pinkdrawer")))]


@pytest.mark.parametrize("strategy", ALL_STRATEGIES)
def test_costs_prefer_cheap_changes_and_fixed_excludes_predicates(strategy):
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    literal = dict(semantics=Semantics.LITERAL, all_minimal=True, verify=True, strategy=strategy)
    cheap = find_excuses(domain, problem, ExcuseOptions(costs=["clear=5", "holding=0"], **literal))
    # holding is free, clear is dear: holding b and holding c (cost 0) win.
    assert changes_of(cheap) == [["+(holding b)", "+(holding c)"]]
    assert cheap.excuse.cost == 0
    fixed = find_excuses(domain, problem, ExcuseOptions(fixed=["holding", "clear"], **literal))
    for e in fixed.excuses:
        assert not {c.atom.predicate for c in e.changes} & {"holding", "clear"}


@pytest.mark.parametrize("strategy", ALL_STRATEGIES)
def test_max_size_too_small_reports_limit(strategy):
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem, ExcuseOptions(max_size=2, strategy=strategy))
    assert report.status == "no-excuse-within-size"


# --- property tests: every strategy == brute force on random small tasks ------------

OBJECTS = ("o1", "o2")


@st.composite
def small_tasks(draw):
    """A random typed STRIPS task as PDDL text: 0/1-ary predicates, 2 domain constants."""
    n_props = draw(st.integers(1, 2))
    n_unary = draw(st.integers(1, 2))
    props = [f"p{i}" for i in range(n_props)]
    unary = [f"u{i}" for i in range(n_unary)]

    def lits(param: str | None):
        atoms = [f"({p})" for p in props]
        atoms += [f"({u} {o})" for u in unary for o in OBJECTS]
        if param:
            atoms += [f"({u} {param})" for u in unary]
        return atoms

    actions = []
    for k in range(draw(st.integers(1, 4))):
        param = draw(st.sampled_from([None, "?x"]))
        pool = lits(param)
        pre = draw(st.lists(st.sampled_from(pool), max_size=2, unique=True))
        neg = draw(st.lists(st.sampled_from([a for a in pool if a not in pre] or pool), max_size=1, unique=True))
        neg = [a for a in neg if a not in pre]
        if len(pool) > 1 and draw(st.booleans()):
            # A "move": consume one atom, produce another (induces mutex invariants).
            src, dst = draw(st.lists(st.sampled_from(pool), min_size=2, max_size=2, unique=True))
            pre = sorted(set(pre) | {src})
            neg = [a for a in neg if a not in (src, dst)]
            add, dele = [dst], [src]
        else:
            add = draw(st.lists(st.sampled_from(pool), min_size=1, max_size=2, unique=True))
            dele = draw(st.lists(st.sampled_from([a for a in pool if a not in add] or pool), max_size=2, unique=True))
            dele = [a for a in dele if a not in add]
        params = "(?x - obj)" if param else "()"
        precondition = " ".join(pre + [f"(not {a})" for a in neg])
        effect = " ".join(add + [f"(not {a})" for a in dele])
        actions.append(f"(:action a{k} :parameters {params} :precondition (and {precondition}) :effect (and {effect}))")
    all_atoms = lits(None)
    init = draw(st.lists(st.sampled_from(all_atoms), max_size=4, unique=True))
    goal = draw(st.lists(st.sampled_from(all_atoms), min_size=1, max_size=3, unique=True))
    preds = " ".join([f"({p})" for p in props] + [f"({u} ?x - obj)" for u in unary])
    domain = (f"(define (domain rnd) (:requirements :strips :typing :negative-preconditions) (:types obj) "
              f"(:constants {' '.join(OBJECTS)} - obj) (:predicates {preds}) {' '.join(actions)})")
    problem = (f"(define (problem r) (:domain rnd) "
               f"(:init {' '.join(init)}) (:goal (and {' '.join(goal)})))")
    return domain, problem


def _parse_random(tmp_path_factory, name: str, pddl: tuple[str, str]):
    """Write a :func:`small_tasks` example to a fresh folder and read it back."""
    folder = tmp_path_factory.mktemp(name)
    (folder / "d.pddl").write_text(pddl[0])
    (folder / "p.pddl").write_text(pddl[1])
    return parse_task(folder / "d.pddl", folder / "p.pddl")


def excuse_checker(domain, problem, groups):
    """(ground atoms, is_excuse(change atoms)): an independent BFS and consistency check on each excuse state."""
    from guided_lfd.planning.task import ground_atoms

    # What the default options hold fixed (the world's structure) is no change set the search may try.
    atoms = ground_atoms(domain, problem, skip=set(ExcuseOptions().fixed_predicates(domain, problem)))
    ground_actions = []
    for act in domain.actions:
        choices = [OBJECTS] * len(act.params)
        for args in itertools.product(*choices):
            b = {v: a for (v, _), a in zip(act.params, args)}
            ground_actions.append((
                {l.atom.substitute(b) for l in act.precondition if l.positive},
                {l.atom.substitute(b) for l in act.precondition if not l.positive},
                {a.substitute(b) for a in act.add},
                {a.substitute(b) for a in act.delete},
            ))

    def goal_holds(s):
        return all((l.atom in s) == l.positive for l in problem.goal)

    def reachable(s0):
        seen = {s0}
        queue = deque([s0])
        while queue:
            s = queue.popleft()
            if goal_holds(s):
                return True
            for pre, neg, add, dele in ground_actions:
                if pre <= s and not (neg & s):
                    t = frozenset((s - dele) | add)
                    if t not in seen:
                        seen.add(t)
                        queue.append(t)
        return False

    def consistent(s):
        return groups is None or not groups.broken(s)

    init = frozenset(problem.init)

    def is_excuse(combo) -> bool:
        s = frozenset(init.symmetric_difference(combo))
        return (not combo or not goal_holds(s)) and consistent(s) and reachable(s)

    return atoms, is_excuse


def brute_force(domain, problem, groups, max_size=3):
    """All minimal excuses by enumeration, with an independent BFS for reachability."""
    atoms, is_excuse = excuse_checker(domain, problem, groups)
    init = frozenset(problem.init)
    for size in range(0, min(max_size, len(atoms)) + 1):
        found = []
        for combo in itertools.combinations(atoms, size):
            if is_excuse(combo):
                found.append(sorted(str(Change(a, a not in init)) for a in combo))
        if found:
            return size, sorted(found)
    return None, []


@pytest.mark.parametrize("strategy", ALL_STRATEGIES)
@pytest.mark.parametrize("semantics", list(Semantics))
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_strategy_matches_brute_force(tmp_path_factory, strategy, semantics, pddl):
    domain, problem = _parse_random(tmp_path_factory, "rnd", pddl)
    report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, strategy=strategy,
                                                         all_minimal=True, verify=True, max_size=3))
    groups = checker_laws(domain, problem, report)
    size, expected = brute_force(domain, problem, groups)
    if size == 0:
        assert report.status == "already-solvable"
    elif size is None:
        assert report.status in ("no-excuse", "no-excuse-within-size")
        if report.status == "no-excuse":  # a proof: check it over every change set
            assert brute_force(domain, problem, groups, max_size=10**6)[0] is None
    else:
        assert report.status == "excuse-found"
        assert report.statistics.minimality == "verified"  # --verify enumerated every cheaper change set
        assert {e.size for e in report.excuses} == {size}
        assert sorted(sorted(str(c) for c in e.changes) for e in report.excuses) == expected
        for e in report.excuses:
            steps = e.plan
            assert check_excuse(domain, problem, e.changes, steps, groups) == []


@pytest.mark.parametrize("semantics", list(Semantics))
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks(), costs=st.lists(st.tuples(st.sampled_from(["p0", "p1", "u0", "u1"]), st.integers(0, 4)),
                                          max_size=3))
def test_every_strategy_matches_baseline_with_costs(tmp_path_factory, semantics, pddl, costs):
    domain, problem = _parse_random(tmp_path_factory, "rndc", pddl)
    specs = [f"{p}={c}" for p, c in dict(costs).items() if p in domain.predicates]
    found = {}
    for strategy in ALL_STRATEGIES:
        report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, strategy=strategy, costs=specs,
                                                             all_minimal=True, verify=True, max_size=3))
        found[strategy] = (report.status, sorted((e.cost, e.size, tuple(str(c) for c in e.changes))
                                                for e in report.excuses))
    # The baseline enumerates by weight up to the size bound: the reference.
    if found["baseline"][0] != "no-excuse-within-size":
        for strategy in ALL_STRATEGIES:
            assert found[strategy] == found["baseline"], strategy


@pytest.mark.parametrize("small", [True, False])
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_both_lmcut_implementations_match_brute_force(tmp_path_factory, monkeypatch, small, pddl):
    """LM-cut runs on plain lists for small tasks and on numpy for large ones: test both."""
    from guided_lfd.excuse import lmcut

    monkeypatch.setattr(lmcut, "SMALL_TASK_ACTIONS", 10**9 if small else 0)
    domain, problem = _parse_random(tmp_path_factory, "rndl", pddl)
    for semantics in Semantics:
        report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, all_minimal=True, verify=True, max_size=3))
        size, expected = brute_force(domain, problem, checker_laws(domain, problem, report))
        if size not in (None, 0):
            assert sorted(sorted(str(c) for c in e.changes) for e in report.excuses) == expected


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_hill_climbing_oracle_matches_brute_force(tmp_path_factory, monkeypatch, pddl):
    """Reachability checks hill-climb on h^FF on large tasks: force it on small ones and compare."""
    from guided_lfd.excuse import reach

    monkeypatch.setattr(reach, "GUIDED_MIN_ACTIONS", 0)
    domain, problem = _parse_random(tmp_path_factory, "rndh", pddl)
    for semantics in Semantics:
        report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, all_minimal=True, verify=True, max_size=3))
        size, expected = brute_force(domain, problem, checker_laws(domain, problem, report))
        if size == 0:
            assert report.status == "already-solvable"
        elif size is None:
            assert report.status in ("no-excuse", "no-excuse-within-size")
        else:
            assert sorted(sorted(str(c) for c in e.changes) for e in report.excuses) == expected


def test_hill_climbing_answers_household_checks_and_not_small_ones(tmp_path):
    """It fires on a house (thousands of actions) and stays off on Kitchen I (a handful)."""
    from guided_lfd.benchmark import household

    house = household.House(8, 32, 4, 1, 4, "no-push")
    (tmp_path / "robot.pddl").write_text(household.domain_pddl(house.variant))
    (tmp_path / "house.pddl").write_text(household.problem_pddl(house))
    domain, problem = parse_task(tmp_path / "robot.pddl", tmp_path / "house.pddl")
    report = find_excuses(domain, problem, ExcuseOptions())
    assert report.statistics.counters["oracle_hill_climbs"] >= 1
    assert report.statistics.counters["oracle_expanded"] == 0  # no goal-count search was needed
    assert report.excuse.plan_optimal and len(report.excuse.plan) == 8
    small = find_excuses(*parse_task(*kitchen(1)), ExcuseOptions())
    assert small.statistics.counters["oracle_hill_climbs"] == 0


def test_one_status_type_from_the_strategies_to_the_exit_code(runner, app):
    """Every strategy ends in an ExcuseStatus; the report keeps it; the command line exits with its code."""
    from guided_lfd.excuse.status import ExcuseStatus
    from guided_lfd.excuse.strategies import STRATEGIES

    assert {s.exit_code for s in ExcuseStatus} == {0, 11, 13, 20}
    domain, problem = kitchen(2)
    dom, prob = parse_task(domain, problem)
    for name in STRATEGIES:
        for max_size, expected in ((None, ExcuseStatus.FOUND), (0, ExcuseStatus.NONE_WITHIN_SIZE)):
            report = find_excuses(dom, prob, ExcuseOptions(strategy=name, max_size=max_size))
            assert report.status is expected, name
            args = ["excuse", domain, problem, "--strategy", name, "--quiet", "--json"]
            result = runner.invoke(app, args + ([] if max_size is None else ["--max-size", "0"]))
            assert result.exit_code == expected.exit_code
            assert json.loads(result.stdout)["status"] == expected.value


def test_statistics_are_typed_and_written_in_the_documented_order():
    from guided_lfd.excuse.statistics import ExcuseStatistics

    stats = ExcuseStatistics(ground_atoms=3, candidates=2, counters={"evaluations": 5}, phase="searching", time_s=0.1)
    assert list(stats.to_dict()) == ["ground_atoms", "candidates", "evaluations", "phase", "time_s"]
    report = find_excuses(*parse_task(*kitchen(1)))
    assert isinstance(report.statistics, ExcuseStatistics) and report.statistics.candidates >= 1
    assert report.excuse.plan and all(isinstance(step, PlanStep) for step in report.excuse.plan)


@pytest.mark.parametrize("strategy", [n for n, s in STRATEGIES.items() if getattr(s, "lists_slack", False)])
@pytest.mark.parametrize("semantics", list(Semantics))
@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_slack_lists_every_excuse_up_to_one_more_change_that_extends_none(tmp_path_factory, strategy, semantics, pddl):
    """--slack 1 (unit costs): the minimal excuses and every excuse one change larger that contains none of them."""
    domain, problem = _parse_random(tmp_path_factory, "rnds", pddl)
    report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, strategy=strategy, all_minimal=True,
                                                         verify=True, slack=1, max_size=3))
    if report.status != "excuse-found":
        return  # already solvable or no excuse: the plain brute-force test covers those
    groups = checker_laws(domain, problem, report)
    size, minimal = brute_force(domain, problem, groups)
    atoms, is_excuse = excuse_checker(domain, problem, groups)
    init = frozenset(problem.init)
    valid_bigger = []
    minimal_sets = [set(m) for m in minimal]
    for combo in itertools.combinations(atoms, size + 1) if size + 1 <= 3 else ():  # within --max-size 3
        changes = sorted(str(Change(a, a not in init)) for a in combo)
        if any(m <= set(changes) for m in minimal_sets):
            continue
        if is_excuse(combo):
            valid_bigger.append(changes)
    expected = sorted(minimal) + sorted(valid_bigger)
    got = [sorted(str(c) for c in e.changes) for e in report.excuses]
    assert sorted(got) == sorted(expected)
    assert all(check_excuse(domain, problem, e.changes, e.plan, groups) == [] for e in report.excuses)


def test_a_fixed_atom_of_an_invariant_group_pins_its_group():
    """Review finding: --fixed on a predicate whose true atom is in a mutex group crashed LM-cut (KeyError)."""
    domain, problem = parse_task(*kitchen(2))
    for fixed in (["hand_free"], ["on_top"]):
        report = find_excuses(domain, problem, ExcuseOptions(fixed=fixed))
        assert [str(c) for c in report.excuse.changes] == ["+(clear pinkdrawer)"]


def test_the_checker_rejects_a_change_to_a_fixed_predicate_and_a_cost_its_changes_do_not_have():
    """The checker reads --fixed and --cost itself (issue #25: it ignored both): Kitchen I's excuse passes with
    the options it was found under, and fails when the predicate it changes is fixed or its cost is misstated."""
    from guided_lfd.excuse.check import change_cost

    domain, problem = parse_task(*kitchen(1))
    report = find_excuses(domain, problem, ExcuseOptions(costs=["open=3"]))
    excuse = report.excuse
    args = (domain, problem, excuse.changes, excuse.plan, checker_laws(domain, problem, report))
    assert excuse.cost == 3 and change_cost(excuse.changes, ["open=3"]) == 3
    assert check_excuse(*args, fixed=[], costs=["open=3"], cost=3) == []
    assert check_excuse(*args, fixed=["open"]) == ["+(open pinkdrawer) changes open, which is fixed"]
    assert check_excuse(*args, costs=["(open pinkdrawer)=5", "open=3"], cost=3) == [
        "the excuse's cost is 3, but its changes cost 5"]


@pytest.mark.parametrize("semantics", list(Semantics))
def test_the_landmark_search_queues_no_change_set_twice_and_pins_what_its_branches_left(semantics, monkeypatch):
    """The children of a node split its extensions (the k-th adds the k-th atom of the branch and pins the ones
    before it): no change set is ever queued as a child twice, and no child flips an atom its parent pinned.
    Depot task03 without drive under the consistent semantics took 2,618 nodes before this split, 372 with it."""
    from dataclasses import replace as replace_

    from guided_lfd.excuse import landmark as module

    ipc = ROOT / "data" / "benchmarks" / "ipc" / "depot"
    full, problem = parse_task(ipc / "domain.pddl", ipc / "task03.pddl")
    robot = replace_(full, actions=[a for a in full.actions if a.name != "drive"])
    children: list[tuple[int, int, int]] = []  # (parent's pins, child, child's pins)
    push, expand = module._LandmarkRun.push, module._LandmarkRun.expand

    def expanding(self, f, g, changes, landmarks, branch, pinned):
        self.parent_pins = pinned
        self.expanding = True
        try:
            expand(self, f, g, changes, landmarks, branch, pinned)
        finally:
            self.expanding = False

    def pushing(self, f, g, changes, landmarks, pinned):
        if getattr(self, "expanding", False) and not self.greedy:
            children.append((self.parent_pins, changes, pinned))
        push(self, f, g, changes, landmarks, pinned)

    monkeypatch.setattr(module._LandmarkRun, "expand", expanding)
    monkeypatch.setattr(module._LandmarkRun, "push", pushing)
    report = find_excuses(robot, problem, ExcuseOptions(semantics=semantics, strategy="landmark",
                                                        fixed_from=parse_domain(ipc / "domain.pddl")))
    assert report.status == "excuse-found" and report.excuse.size == (8 if semantics is Semantics.CONSISTENT else 2)
    assert len(children) > 10
    assert len({child for _, child, _ in children}) == len(children)
    assert all(parent & ~pins == 0 and not child & pins for parent, child, pins in children)


def test_a_paused_candidate_resumes_when_its_turn_comes_and_always_before_a_higher_f(monkeypatch):
    """paused_due: not before its time while the heap has nodes of its f; at its time if no node of a lower f
    waits; at once when every node left has a higher f (or none is left); never ahead of a lower f."""
    from types import SimpleNamespace

    from guided_lfd.excuse import landmark as module
    from guided_lfd.excuse import outcome

    now = [0.0]
    monkeypatch.setattr(outcome, "clock", lambda: now[0])
    entry = (3, -1, 1, 0b1)
    run = SimpleNamespace(heap=[(3, -2, 2, 0b10)], paused=[(5.0, entry)])
    due = module._LandmarkRun.paused_due
    assert due(run) is None  # a node of its f waits and its time has not come
    now[0] = 5.0
    assert due(run) == entry and run.paused == []
    run.paused, now[0] = [(9.0, entry)], 0.0
    run.heap = [(4, -2, 2, 0b10)]
    assert due(run) == entry  # every node left has a higher f: decided first
    run.paused, run.heap = [(9.0, entry)], []
    assert due(run) == entry
    later = (5, -1, 3, 0b100)
    run.paused, run.heap, now[0] = [(1.0, later)], [(4, -2, 2, 0b10)], 2.0
    assert due(run) is None  # its time has come, but a node of a lower f waits
    run.paused = [(1.0, later), (7.0, entry)]
    assert due(run) == entry and run.paused == [(1.0, later)]  # the lowest f first when the heap has no f as low
