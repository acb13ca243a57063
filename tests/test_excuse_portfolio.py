"""The default excuse strategy: the landmark search with the symbolic search beside it.

Which member answers depends on the machine's speed; what it answers must not.
So these tests make one member unable to answer and check the other's answer
against the answer of its strategy run alone."""

from __future__ import annotations

import time

import pytest
from hypothesis import HealthCheck, given, settings

from conftest import BLOCKS, kitchen
from test_excuse_engine import _parse_random, small_tasks
from guided_lfd.excuse import portfolio
from guided_lfd.excuse import strategies
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.space import Semantics
from guided_lfd.pddl.reader import parse_task


def _waiting_landmark(self, space, limits, progress=None, oracle=None, relaxed=None):
    """A landmark search that never answers: it waits until the portfolio stops it (60 s at most)."""
    end = time.monotonic() + 60
    while time.monotonic() < end:
        if limits.stop is not None and limits.stop():
            raise strategies.SearchStopped()
        time.sleep(0.005)
    raise AssertionError("the symbolic search never answered")


def _excuses(report):
    """Status and excuses; the two "none" statuses alike (with --max-size, a search that proved none at all may
    say either)."""
    status = "none" if report.status in ("no-excuse", "no-excuse-within-size") else report.status
    return status, sorted(sorted(str(c) for c in e.changes) for e in report.excuses)


@pytest.fixture
def symbolic_answers(monkeypatch):
    """The symbolic member starts at once and the landmark member cannot answer."""
    monkeypatch.setattr(portfolio, "SYMBOLIC_AFTER_S", 0.0)
    monkeypatch.setattr(strategies.LandmarkSearch, "search", _waiting_landmark)


@pytest.mark.parametrize("semantics", list(Semantics))
def test_the_symbolic_member_answers_as_the_symbolic_strategy_does(symbolic_answers, semantics):
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    options = dict(semantics=semantics, all_minimal=True, verify=True)
    report = find_excuses(domain, problem, ExcuseOptions(**options))
    assert report.statistics.answered_by == "symbolic"
    alone = find_excuses(domain, problem, ExcuseOptions(strategy="symbolic", **options))
    assert _excuses(report) == _excuses(alone) and report.excuses


def test_a_task_wider_than_the_engines_limit_is_searched_by_the_landmark_search_alone(monkeypatch):
    from guided_lfd.symbolic import encoding, worker

    monkeypatch.setattr(portfolio, "SYMBOLIC_AFTER_S", 0.0)  # the worker would start at once ...
    monkeypatch.setattr(encoding, "DEFAULT_MAX_VARIABLES", 3)  # ... but the task has more relevant atoms
    monkeypatch.setattr(worker, "Forked", _never_forked)  # no second process at all
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem, ExcuseOptions(all_minimal=True))
    assert report.statistics.answered_by == "landmark" and report.excuses
    assert report.statistics.relevant_atoms > 3


def _never_forked(*_):
    raise AssertionError("the symbolic search started on a task past its limit")


def test_a_quick_run_is_answered_by_the_landmark_search_alone(monkeypatch):
    monkeypatch.setattr(portfolio, "SYMBOLIC_AFTER_S", 3600.0)  # no worker: the landmark search must answer
    report = find_excuses(*parse_task(*kitchen(1)))
    assert report.statistics.answered_by == "landmark"
    assert [str(c) for c in report.excuse.changes] == ["+(open pinkdrawer)"]


@pytest.mark.parametrize("semantics", list(Semantics))
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_either_member_gives_the_landmark_strategys_answer(tmp_path_factory, monkeypatch, semantics, pddl):
    domain, problem = _parse_random(tmp_path_factory, "port", pddl)
    options = dict(semantics=semantics, all_minimal=True, max_size=3)
    expected = _excuses(find_excuses(domain, problem, ExcuseOptions(strategy="landmark", **options)))
    with monkeypatch.context() as patch:
        patch.setattr(portfolio, "SYMBOLIC_AFTER_S", 0.0)
        patch.setattr(strategies.LandmarkSearch, "search", _waiting_landmark)
        got = find_excuses(domain, problem, ExcuseOptions(**options))
    assert _excuses(got) == expected
