"""The operator-counting program: sound against brute force, and what it refutes that h^2 cannot."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings

from guided_lfd.excuse import reach
from guided_lfd.excuse.reach import ReachabilityOracle
from guided_lfd.planning.counting import OperatorCounting
from guided_lfd.pddl.reader import parse_task
from test_excuse_engine import _parse_random, small_tasks
from test_oracle import _bfs_reaches_goal, _every_state, _never_decides, _oracle

DATA = Path(__file__).parent / "data" / "oracle"


def _cameras() -> ReachabilityOracle:
    return _oracle(*parse_task(DATA / "cameras-domain.pddl", DATA / "cameras-problem.pddl"))


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_the_program_has_no_solution_only_where_no_plan_exists(tmp_path_factory, pddl):
    """From every state of a random task: "dead" implies that breadth-first search finds no plan."""
    domain, problem = _parse_random(tmp_path_factory, "counting", pddl)
    oracle = _oracle(domain, problem)
    task = oracle.space.task
    counting = OperatorCounting(oracle.relaxed_task(), task.goal_pos)
    for state in _every_state(task):
        if counting.dead(state & oracle.mask):
            assert not _bfs_reaches_goal(task, state)


def test_two_calibrations_take_no_three_images_and_h2_cannot_tell():
    oracle = _cameras()
    start = oracle.space.task.init & oracle.mask
    assert oracle.pairs().reachable(start)
    assert OperatorCounting(oracle.relaxed_task(), oracle.space.task.goal_pos).dead(start)
    index = {str(a): i for i, a in enumerate(oracle.space.task.atoms)}
    with_image = start | 1 << index["(have-image t3)"]
    assert not OperatorCounting(oracle.relaxed_task(), oracle.space.task.goal_pos).dead(with_image)


def test_the_program_answers_as_a_portfolio_member_when_the_searches_cannot(monkeypatch):
    """Both searches silenced: the member refutes the candidate, and the oracle remembers it dead."""
    monkeypatch.setattr(reach, "COUNTING_AFTER_S", 0.0)
    monkeypatch.setattr(ReachabilityOracle, "_goal_count_search", _never_decides)
    monkeypatch.setattr(ReachabilityOracle, "_ff_search", _never_decides)
    oracle = _cameras()
    start = oracle.space.task.init
    assert oracle.solve(start) is None
    assert oracle.stats.counting_proofs == 1 and oracle.stats.pair_proofs == 0
    assert start & oracle.mask in oracle.dead


def test_the_program_waits_its_portfolio_time(monkeypatch):
    """Before COUNTING_AFTER_S of the searches' time the member gets no turn: the goal-count search refutes
    the small candidate first."""
    monkeypatch.setattr(reach, "COUNTING_AFTER_S", 3600.0)
    oracle = _cameras()
    assert oracle.solve(oracle.space.task.init) is None
    assert oracle.stats.counting_proofs == 0 and oracle.stats.expanded > 0
