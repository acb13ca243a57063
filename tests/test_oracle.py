"""The reachability oracle: the h^2 pair check and the portfolio of searches, against brute force."""

from __future__ import annotations

import itertools
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings

from guided_lfd.excuse import reach
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.excuse.space import Semantics, build_space
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.h2 import PairReachability
from guided_lfd.pddl.reader import parse_task
from test_excuse_engine import _parse_random, brute_force, checker_laws, small_tasks
from test_optimal import _optimal_length

DATA = Path(__file__).parent / "data" / "oracle"


def _oracle(domain, problem) -> ReachabilityOracle:
    task = ground(domain, problem)
    return ReachabilityOracle(build_space(task, Semantics.LITERAL, [], [], []))


def _bfs_reaches_goal(task, state: int) -> bool:
    """Plain breadth-first search over every ground action: the reference."""
    return _optimal_length(task, state) is not None


def _every_state(task):
    for values in itertools.product((0, 1), repeat=len(task.atoms)):
        yield sum(v << i for i, v in enumerate(values))


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_pair_check_never_refutes_a_reachable_goal(tmp_path_factory, pddl):
    """h^2 is admissible: "unreachable" only where no plan exists, from every state of a random task."""
    domain, problem = _parse_random(tmp_path_factory, "h2", pddl)
    oracle = _oracle(domain, problem)
    task, pairs = oracle.space.task, oracle.pairs()
    for state in _every_state(task):
        if not pairs.reachable(state & oracle.mask):
            assert not _bfs_reaches_goal(task, state)


def test_pair_check_refutes_a_calibrated_instrument_that_is_not_powered():
    """switch_on deletes calibrated: calibrated and power_on never hold together (h^1 cannot see it)."""
    domain, problem = parse_task(DATA / "satellite-domain.pddl", DATA / "satellite-problem.pddl")
    oracle = _oracle(domain, problem)
    task = oracle.space.task
    index = {str(a): i for i, a in enumerate(task.atoms)}
    calibrated = task.init | 1 << index["(calibrated cam0)"]
    assert oracle.relaxed_task().relaxed_plan(calibrated & oracle.mask) is not None  # h^1: reachable
    assert not oracle.pairs().reachable(calibrated & oracle.mask)
    assert oracle.solve(calibrated) is None
    assert oracle.stats.pair_proofs == 1 and oracle.stats.expanded == 0  # no search was needed
    powered = calibrated | 1 << index["(power_on cam0)"]
    assert oracle.pairs().reachable(powered & oracle.mask)
    assert oracle.solve(powered) is not None


def test_excuse_search_uses_the_pair_check_and_finds_the_exact_excuse():
    domain, problem = parse_task(DATA / "satellite-domain.pddl", DATA / "satellite-problem.pddl")
    report = find_excuses(domain, problem, ExcuseOptions(semantics=Semantics.LITERAL, all_minimal=True, verify=True))
    assert [sorted(str(c) for c in e.changes) for e in report.excuses] == [
        ["+(calibrated cam0)", "+(power_on cam0)"]]
    assert report.statistics.counters["oracle_pair_proofs"] >= 1


def test_pair_check_cannot_refute_three_slots_and_the_search_does():
    """Two tokens, three slots: every pair of full slots is reachable, all three are not."""
    domain, problem = parse_task(DATA / "tokens-domain.pddl", DATA / "tokens-problem.pddl")
    oracle = _oracle(domain, problem)
    task = oracle.space.task
    assert oracle.pairs().reachable(task.init & oracle.mask)
    assert oracle.solve(task.init) is None
    assert oracle.stats.pair_proofs == 0 and oracle.stats.expanded > 0
    assert not _bfs_reaches_goal(task, task.init)


def _never_decides(*_args):
    while True:
        yield


@pytest.mark.parametrize("silenced", ["_goal_count_search", "_ff_search", "none"])
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_each_portfolio_member_decides_like_brute_force(tmp_path_factory, monkeypatch, silenced, pddl):
    """With one search silenced (it never decides), the other answers every check alone, and correctly.

    Slices of 0 s make the members take turns step by step, so their
    interleaving is exercised too.
    """
    monkeypatch.setattr(reach, "PORTFOLIO_SLICE_S", 0.0)
    monkeypatch.setattr(reach, "PAIR_CHECK_FIRST_S", 0.0)
    monkeypatch.setattr(reach, "COUNTING_AFTER_S", 0.0)  # the operator-counting member takes turns too
    if silenced != "none":
        monkeypatch.setattr(ReachabilityOracle, silenced, _never_decides)
    domain, problem = _parse_random(tmp_path_factory, "pf", pddl)
    oracle = _oracle(domain, problem)
    task = oracle.space.task
    for state in _every_state(task):
        plan = oracle.solve(state)
        assert (plan is not None) == _bfs_reaches_goal(task, state)
        if plan is not None:
            s = state
            for act in plan:
                assert act.applicable(s)
                s = act.apply(s)
            assert task.satisfies_goal(s)
    for semantics in Semantics:
        report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, all_minimal=True, verify=True, max_size=3))
        size, expected = brute_force(domain, problem, checker_laws(domain, problem, report))
        if size not in (None, 0):
            assert sorted(sorted(str(c) for c in e.changes) for e in report.excuses) == expected


def test_the_ff_search_confirms_when_the_goal_count_search_cannot(monkeypatch):
    """Kitchen-sized check with the goal-count member silenced: the h^FF member finds the plan."""
    from conftest import kitchen

    monkeypatch.setattr(ReachabilityOracle, "_goal_count_search", _never_decides)
    report = find_excuses(*parse_task(*kitchen(1)), ExcuseOptions())
    assert report.status == "excuse-found"
    assert report.statistics.counters["oracle_ff_searches"] >= 1


def test_a_wide_pair_check_is_built_in_its_slices_and_a_stopped_build_goes_on(monkeypatch):
    """Past PAIR_CHECK_EAGER_BYTES the masks are built inside the check's steps: a build stopped midway
    resumes where it stopped and decides as an eager build does."""
    monkeypatch.setattr(reach, "PAIR_CHECK_EAGER_BYTES", 0)
    monkeypatch.setattr("guided_lfd.planning.h2.ACTIONS_PER_STEP", 1)
    domain, problem = parse_task(DATA / "satellite-domain.pddl", DATA / "satellite-problem.pddl")
    oracle = _oracle(domain, problem)
    pairs = oracle.pairs()
    assert pairs.pre_masks == [] and pairs.estimated_bytes() > 0  # nothing built yet
    build = pairs.build()
    next(build), next(build)
    assert 0 < len(pairs.pre_masks) == len(pairs.add_masks) == len(pairs.del_masks) < len(pairs.relaxed.pre)
    build.close()
    task = oracle.space.task
    index = {str(a): i for i, a in enumerate(task.atoms)}
    calibrated = task.init | 1 << index["(calibrated cam0)"]
    assert not pairs.reachable(calibrated & oracle.mask)
    eager = PairReachability(pairs.relaxed)
    for _ in eager.build():
        pass
    assert (pairs.pre_masks, pairs.add_masks, pairs.del_masks) == (eager.pre_masks, eager.add_masks,
                                                                    eager.del_masks)


def test_alternating_queues_take_turns_and_a_boost_gives_the_preferred_queue_its_turns_first():
    """Fast Downward's alternation: turns between the queues, and PREFERRED_BOOST preferred pops after a boost."""
    queues = reach.AlternatingQueues()
    for k in range(reach.PREFERRED_BOOST + 10):
        queues.push(5, ("every", k), False)
        queues.push(5, ("preferred", k), True)
    assert [queues.pop()[0] for _ in range(4)] == ["every", "preferred", "every", "preferred"]
    queues.boost()
    taken = [queues.pop()[0] for _ in range(reach.PREFERRED_BOOST + 2)]
    assert taken[:reach.PREFERRED_BOOST] == ["preferred"] * reach.PREFERRED_BOOST
    assert taken[reach.PREFERRED_BOOST:] == ["every", "preferred"]


def test_alternating_queues_order_by_value_then_first_in_and_skip_an_empty_queue():
    queues = reach.AlternatingQueues()
    queues.push(3, "c", False)
    queues.push(1, "a", False)
    queues.push(1, "b", False)
    queues.boost()  # a boost with an empty preferred queue takes nothing from the other
    assert [queues.pop() for _ in range(3)] == ["a", "b", "c"]
    assert not queues


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_helpful_actions_are_the_applicable_achievers_of_every_fact_the_relaxed_plan_needs(tmp_path_factory, pddl):
    """The needed facts are cut to those an applicable action can add (h^add at most the dearest action's cost):
    the helpful actions are still every applicable action adding a precondition or goal fact of the relaxed plan
    that the state lacks, from every state of a random task."""
    domain, problem = _parse_random(tmp_path_factory, "helpful", pddl)
    oracle = _oracle(domain, problem)
    relaxed = oracle.relaxed_task()
    true_fact = 0
    for state in _every_state(oracle.space.task):
        state &= oracle.mask
        found = relaxed.relaxed_plan(state)
        if found is None:
            continue
        plan, needed = found
        holds = set(relaxed._true_facts(state))
        wanted = {f for ai in [*plan, len(relaxed.pre) - 1] for f in relaxed.pre[ai]} - holds - {true_fact}
        reference = {ai for ai, act in enumerate(relaxed.actions)
                     if (state & act.pre_pos) == act.pre_pos and not state & act.pre_neg
                     and wanted & set(relaxed.add[ai])}
        assert set(relaxed.helpful(state, needed)) == reference


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_the_relaxed_plan_lists_each_action_after_those_adding_its_preconditions(tmp_path_factory, pddl):
    """In h^add's order a relaxed plan runs as it stands in the relaxation (unit costs), from every state."""
    domain, problem = _parse_random(tmp_path_factory, "order", pddl)
    oracle = _oracle(domain, problem)
    relaxed = oracle.relaxed_task()
    for state in _every_state(oracle.space.task):
        found = relaxed.relaxed_plan(state & oracle.mask)
        if found is None:
            continue
        holds = set(relaxed._true_facts(state & oracle.mask))
        for ai in [*found[0], len(relaxed.pre) - 1]:
            assert set(relaxed.pre[ai]) <= holds
            holds.update(relaxed.add[ai])


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_the_lookahead_applies_relaxed_plan_actions_until_none_applies(tmp_path_factory, pddl):
    """Its steps chain real transitions, each a relaxed plan action used once, and none of the rest applies after."""
    domain, problem = _parse_random(tmp_path_factory, "ahead", pddl)
    oracle = _oracle(domain, problem)
    for state in _every_state(oracle.space.task):
        state &= oracle.mask
        found = oracle.relaxed_task().relaxed_plan(state)
        if found is None:
            continue
        end, steps = oracle._lookahead(state, found[0])
        s = state
        used = []
        for before, act, after in steps:
            assert before == s and act.applicable(s) and after == act.apply(s) & oracle.mask != s
            used.append(oracle.actions.index(act))
            s = after
        chain = {state, *(after for _, _, after in steps)}
        assert end == s and len(set(used)) == len(used) and set(used) <= set(found[0])
        assert len(chain) == len(steps) + 1  # no state twice: a plan through it would loop
        if not oracle.space.task.satisfies_goal(end):  # it stops at a goal state
            assert not any(oracle.actions[ai].applicable(end) for ai in found[0] if ai not in used
                           and oracle.actions[ai].apply(end) & oracle.mask not in chain)


def _ff_search_to_the_end(oracle: ReachabilityOracle, state: int):
    search = oracle._ff_search(state & oracle.mask)
    while True:
        try:
            next(search)
        except StopIteration as done:
            return done.value


def test_one_lookahead_reaches_the_goal_where_every_relaxed_plan_is_a_plan(monkeypatch):
    """Six independent errands: the start and the lookahead's state (the goal) are all the h^FF search meets;
    without the lookahead it steps one action at a time."""
    domain, problem = parse_task(DATA / "errands-domain.pddl", DATA / "errands-problem.pddl")
    oracle = _oracle(domain, problem)
    kind, (steps, _end) = _ff_search_to_the_end(oracle, oracle.space.task.init)
    assert kind == "plan" and len(steps) == 12 and oracle.stats.expanded == 2
    monkeypatch.setattr(ReachabilityOracle, "_lookahead", lambda self, s, plan: (s, ()))
    oracle = _oracle(domain, problem)
    kind, (steps, _end) = _ff_search_to_the_end(oracle, oracle.space.task.init)
    assert kind == "plan" and len(steps) == 12 and oracle.stats.expanded == 13


def test_the_lookahead_takes_an_action_harmless_to_the_rest_of_the_plan_first():
    """The courier takes p1 (every take and walk deletes what another needs; the first in order goes), walks to
    h1 and puts it down at once (harmless), before anything else."""
    domain, problem = parse_task(DATA / "parcels-domain.pddl", DATA / "parcels-problem.pddl")
    oracle = _oracle(domain, problem)
    start = oracle.space.task.init & oracle.mask
    _end, steps = oracle._lookahead(start, oracle.relaxed_task().relaxed_plan(start)[0])
    assert [act.name for _, act, _ in steps] == ["(take p1 depot)", "(walk depot h1)", "(put p1 h1)"]


def test_a_path_that_comes_back_to_a_state_is_remembered_without_the_loop():
    """A lookahead may step back to where the search came from: the loop is cut before the states are remembered
    as alive (kept, it made the remaining plan of every later call endless)."""
    oracle = _oracle(*parse_task(DATA / "errands-domain.pddl", DATA / "errands-problem.pddl"))
    a, b = oracle.actions[0], oracle.actions[1]
    path = [(1, a, 2), (2, b, 1), (1, b, 3), (3, a, 4), (4, a, 3), (3, b, 5)]
    assert reach._without_loops(path) == [(1, b, 3), (3, b, 5)]
    assert oracle._record(path, 5) == [b, b]
    assert oracle.alive == {1: (b, 3), 3: (b, 5), 5: None}
    assert oracle._record([], 1) == [b, b]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_paused_checks_resume_and_decide_like_brute_force(tmp_path_factory, monkeypatch, pddl):
    """Every check pauses after each turn (0 s slices, a pause time already past) and the checks of all the
    states are resumed in rotation, more of them than are kept (a dropped one starts afresh): each still ends
    in the right answer; the excuse search with 0 s candidate slices finds brute force's excuses."""
    from guided_lfd.excuse import landmark

    monkeypatch.setattr(reach, "PORTFOLIO_SLICE_S", 0.0)
    monkeypatch.setattr(reach, "PAIR_CHECK_FIRST_S", 0.0)
    monkeypatch.setattr(reach, "COUNTING_AFTER_S", 0.0)
    monkeypatch.setattr(reach, "MAX_PAUSED", 2)
    domain, problem = _parse_random(tmp_path_factory, "pz", pddl)
    oracle = _oracle(domain, problem)
    task = oracle.space.task
    pending, pauses = list(_every_state(task))[:8], 0
    while pending:
        state = pending.pop(0)
        try:
            plan = oracle.solve(state, pause_at=0.0)
        except reach.CheckPaused:
            pauses += 1
            pending.append(state)
            continue
        assert (plan is not None) == _bfs_reaches_goal(task, state)
    assert len(oracle._paused) <= 2
    monkeypatch.setattr(landmark, "CHECK_SLICE_S", 0.0)
    for semantics in Semantics:
        report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics, strategy="landmark",
                                                             all_minimal=True, verify=True, max_size=3))
        size, expected = brute_force(domain, problem, checker_laws(domain, problem, report))
        if size not in (None, 0):
            assert sorted(sorted(str(c) for c in e.changes) for e in report.excuses) == expected


def test_a_paused_check_keeps_its_members_time_and_resumes_them(monkeypatch):
    """Two tokens, three slots (the goal unreachable; the pair check cannot see it): paused after every
    turn, the check resumes the same searches until the h^FF search exhausts the states (the goal-count
    search, which would exhaust them in its first turn, silenced)."""
    monkeypatch.setattr(reach, "PORTFOLIO_SLICE_S", 0.0)
    monkeypatch.setattr(ReachabilityOracle, "_goal_count_search", _never_decides)
    domain, problem = parse_task(DATA / "tokens-domain.pddl", DATA / "tokens-problem.pddl")
    oracle = _oracle(domain, problem)
    start = oracle.space.task.init
    pauses, members = 0, None
    while True:
        try:
            assert oracle.solve(start, pause_at=0.0) is None
            break
        except reach.CheckPaused:
            turns = oracle._paused[start & oracle.mask]
            assert members is None or turns.members is members  # the same searches, resumed
            members = turns.members
            pauses += 1
    assert pauses >= 2 and not oracle._paused and start & oracle.mask in oracle.dead


def test_interleaved_pair_check_builds_keep_the_masks_aligned(monkeypatch):
    """Two checks whose lazy h^2 builds interleave (one paused mid-build and resumed after another built
    more) leave every action's masks at its own index, and a check in rotation with another still decides
    like the check built alone: before, the resumed build appended from where it had stopped, so the masks
    slid, and gripper's solvable initial state was proved dead."""
    from guided_lfd.planning import h2
    from guided_lfd.planning.h2 import _mask

    root = Path(__file__).parent.parent / "data" / "benchmarks" / "ipc" / "gripper"
    domain, problem = parse_task(root / "domain.pddl", root / "task01.pddl")
    monkeypatch.setattr(h2, "ACTIONS_PER_STEP", 1)
    oracle = _oracle(domain, problem)
    relaxed, start = oracle.relaxed_task(), oracle.space.task.init & oracle.mask
    pairs = PairReachability(relaxed)
    first, second = pairs.steps(start), pairs.steps(start)
    for generator, turns in ((first, 4), (second, 4), (first, 3)):
        for _ in range(turns):
            next(generator)
    assert all(pairs.pre_masks[i] == _mask(relaxed.pre[i]) for i in range(len(pairs.pre_masks)))
    assert len(pairs.pre_masks) == len(pairs.add_masks) == len(pairs.del_masks) <= len(relaxed.pre)

    monkeypatch.setattr(h2, "ACTIONS_PER_STEP", 64)
    monkeypatch.setattr(reach, "PAIR_CHECK_EAGER_BYTES", -1)  # a wide task's lazy build
    monkeypatch.setattr(reach, "PAIR_CHECK_FIRST_S", 0.0)
    monkeypatch.setattr(reach, "PORTFOLIO_SLICE_S", 0.0)
    monkeypatch.setattr(reach, "COUNTING_AFTER_S", 1e9)
    for silenced in ("_goal_count_search", "_ff_search"):  # only the pair check decides
        monkeypatch.setattr(ReachabilityOracle, silenced, _never_decides)
    oracle = _oracle(domain, problem)
    oracle.guided = False
    task = oracle.space.task
    index = {str(a): i for i, a in enumerate(task.atoms)}
    refuted = task.init ^ 1 << index["(at ball1 rooma)"]  # ball1 nowhere: h^2 refutes it
    pending, decided = [task.init, refuted], []
    for _ in range(2000):  # the initial state's check never ends here (only the pair check can decide)
        state = pending.pop(0)
        try:
            plan = oracle.solve(state, pause_at=time.monotonic() + 0.002)
        except reach.CheckPaused:
            pending.append(state)
            continue
        decided.append((state, plan))
        if state == refuted:
            break
    assert decided == [(refuted, None)]
