"""The default excuse strategy: the landmark search with the symbolic search beside it.

Which member answers depends on the machine's speed; what it answers must not.
So these tests make one member unable to answer and check the other's answer
against the answer of its strategy run alone."""

from __future__ import annotations

import math
import time

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import BLOCKS, ROOT, kitchen
from test_excuse_engine import _parse_random, small_tasks
from guided_lfd.excuse import portfolio
from guided_lfd.excuse import landmark, outcome
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.space import Semantics
from guided_lfd.pddl.reader import parse_task


_LANDMARK_SEARCH = landmark.LandmarkSearch.search


def _waiting_landmark(self, space, limits, progress=None, oracle=None, relaxed=None):
    """A landmark search that never answers: it waits until the portfolio stops it (60 s at most).

    Called outside the portfolio's race (no ``stop``: the engine's own questions, such as whether a goal atom
    any skill achieves is kept out of reach by the world's structure), it is the real search: no symbolic
    member runs beside it there."""
    if limits.stop is None:
        return _LANDMARK_SEARCH(self, space, limits, progress, oracle, relaxed)
    end = time.monotonic() + 60
    while time.monotonic() < end:
        if limits.stop is not None and limits.stop():
            raise outcome.SearchStopped()
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
    monkeypatch.setattr(landmark.LandmarkSearch, "search", _waiting_landmark)


#: Blocks task03 without unstack (C on B; goal A on B on C on D), worked out by hand: literally, B must be
#: clear or held and C held, on D or on the table (2 x 3 excuses of two changes); consistently, C must have
#: been moved from B to the table.
BLOCKS_TASK03_EXCUSES = {
    Semantics.LITERAL: [["+(clear b)", "+(holding c)"], ["+(clear b)", "+(on c d)"], ["+(clear b)", "+(ontable c)"],
                        ["+(holding b)", "+(holding c)"], ["+(holding b)", "+(on c d)"],
                        ["+(holding b)", "+(ontable c)"]],
    Semantics.CONSISTENT: [["+(clear b)", "+(ontable c)", "-(on c b)"]],
}


@pytest.mark.parametrize("semantics", list(Semantics))
def test_the_symbolic_member_gives_every_minimal_excuse_the_baseline_finds(symbolic_answers, semantics):
    """The symbolic member's answer against an independent one: the baseline strategy (breadth-first over change
    sets, a planner call each) and the excuses worked out by hand, not the symbolic strategy run alone."""
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    options = dict(semantics=semantics, all_minimal=True, verify=True)
    report = find_excuses(domain, problem, ExcuseOptions(**options))
    assert report.statistics.answered_by == "symbolic"
    baseline = find_excuses(domain, problem, ExcuseOptions(strategy="baseline", **options))
    assert _excuses(baseline) == ("excuse-found", BLOCKS_TASK03_EXCUSES[semantics])
    assert _excuses(report) == _excuses(baseline)


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


@pytest.mark.parametrize("semantics, answered_by", [(Semantics.LITERAL, "landmark"),
                                                     (Semantics.CONSISTENT, portfolio.WITHOUT_INVARIANTS)])
def test_a_quick_run_is_answered_by_the_landmark_search_alone(monkeypatch, semantics, answered_by):
    monkeypatch.setattr(portfolio, "SYMBOLIC_AFTER_S", 3600.0)  # no worker: the landmark search must answer
    monkeypatch.setattr(portfolio, "WITHOUT_INVARIANTS_UNLIMITED_S", 1e6)  # whatever the machine's speed
    report = find_excuses(*parse_task(*kitchen(1)), ExcuseOptions(semantics=semantics))
    # Consistent: the lightest excuse without the invariants, +(open pinkdrawer), keeps them, so it settles it.
    assert report.statistics.answered_by == answered_by
    assert [str(c) for c in report.excuse.changes] == ["+(open pinkdrawer)"]


DEPOT = ROOT / "data" / "benchmarks" / "ipc" / "depot"


def test_no_excuse_without_the_invariants_is_none_with_them(tmp_path, monkeypatch):
    # Depot without drop: no crate is ever put down, whatever the state.  The search without the invariants
    # proves it in a few expansions; the landmark search with them would enumerate change sets.
    monkeypatch.setattr(portfolio, "WITHOUT_INVARIANTS_UNLIMITED_S", 1e6)  # whatever the machine's speed
    domain_text = (DEPOT / "domain.pddl").read_text()
    start = domain_text.index("(:action drop")
    end = domain_text.index("(:action", start + 1)
    (tmp_path / "domain.pddl").write_text(domain_text[:start] + domain_text[end:])
    domain, problem = parse_task(tmp_path / "domain.pddl", DEPOT / "task01.pddl")
    options = dict(fixed_from=parse_task(DEPOT / "domain.pddl", DEPOT / "task01.pddl")[0])
    report = find_excuses(domain, problem, ExcuseOptions(**options))
    assert report.status == "no-excuse" and report.statistics.answered_by == portfolio.WITHOUT_INVARIANTS
    assert report.statistics.invariants_in_the_way is None  # the literal semantics was not asked again
    alone = find_excuses(domain, problem, ExcuseOptions(strategy="landmark", **options))
    assert alone.status == "no-excuse"


@pytest.mark.parametrize("literal_answer", ["timeout", "inconsistent"])
def test_without_invariants_settles_nothing_it_cannot(literal_answer, monkeypatch):
    # Blocks without unstack: the lightest excuse without invariants puts a block in the hand and keeps it on
    # the table too; that breaks an invariant, so the consistent search must answer.
    if literal_answer == "timeout":
        monkeypatch.setattr(portfolio, "WITHOUT_INVARIANTS_LEAST_S", 0.0)
        monkeypatch.setattr(portfolio, "WITHOUT_INVARIANTS_SHARE", 0.0)
    else:
        monkeypatch.setattr(portfolio, "WITHOUT_INVARIANTS_UNLIMITED_S", 1e6)
    monkeypatch.setattr(portfolio, "SYMBOLIC_AFTER_S", 3600.0)
    firsts = []
    real = portfolio.without_invariants

    def recording(*args):
        answer, first = real(*args)
        firsts.append(first)
        return answer, first

    monkeypatch.setattr(portfolio, "without_invariants", recording)
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem, ExcuseOptions())
    assert report.statistics.answered_by == "landmark"
    [first] = firsts
    if literal_answer == "timeout":
        assert first.status.value == "timeout"
    else:
        assert first.status.value == "excuse-found" and first.solutions
    assert "literal_expanded" in report.statistics.counters
    alone = find_excuses(domain, problem, ExcuseOptions(strategy="landmark"))
    assert [e.size for e in report.excuses] == [e.size for e in alone.excuses]


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
        patch.setattr(landmark.LandmarkSearch, "search", _waiting_landmark)
        got = find_excuses(domain, problem, ExcuseOptions(**options))
    assert _excuses(got) == expected


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks(), costs=st.lists(st.tuples(st.sampled_from(["p0", "p1", "u0", "u1"]), st.integers(0, 4)),
                                          max_size=3))
def test_the_search_without_invariants_gives_the_consistent_answer(tmp_path_factory, monkeypatch, pddl, costs):
    # One excuse (no --all): the shortcut may answer; status and weight must be the consistent search's own.
    domain, problem = _parse_random(tmp_path_factory, "lit", pddl)
    specs = [f"{p}={c}" for p, c in dict(costs).items() if p in domain.predicates]
    options = dict(semantics=Semantics.CONSISTENT, max_size=3, costs=specs)
    expected = find_excuses(domain, problem, ExcuseOptions(strategy="landmark", **options))
    with monkeypatch.context() as patch:
        patch.setattr(portfolio, "SYMBOLIC_AFTER_S", 3600.0)
        patch.setattr(portfolio, "WITHOUT_INVARIANTS_UNLIMITED_S", 1e6)
        got = find_excuses(domain, problem, ExcuseOptions(**options))
    assert _excuses(got)[0] == _excuses(expected)[0]
    assert [(e.size, e.cost) for e in got.excuses] == [(e.size, e.cost) for e in expected.excuses]


def test_without_a_time_limit_the_search_without_invariants_still_has_one(monkeypatch):
    # It may never finish (depot's literal candidates) where the consistent search would: it gets a share of
    # WITHOUT_INVARIANTS_UNLIMITED_S, and the oracle's own deadline is restored after it.
    seen = []
    real = landmark.LandmarkSearch.search

    def recording(self, space, limits, progress=None, oracle=None, relaxed=None):
        seen.append((space.semantics, limits.deadline, oracle.deadline if oracle is not None else None))
        return real(self, space, limits, progress, oracle, relaxed)

    monkeypatch.setattr(landmark.LandmarkSearch, "search", recording)
    monkeypatch.setattr(portfolio, "SYMBOLIC_AFTER_S", 3600.0)
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem, ExcuseOptions())
    assert report.excuses and [s for s, _, _ in seen] == [Semantics.LITERAL, Semantics.CONSISTENT]
    (_, literal_until, literal_oracle), (_, consistent_until, consistent_oracle) = seen
    most = time.monotonic() + portfolio.WITHOUT_INVARIANTS_SHARE * portfolio.WITHOUT_INVARIANTS_UNLIMITED_S
    assert math.isfinite(literal_until) and literal_until <= most
    assert math.isfinite(literal_oracle) and literal_oracle <= most
    assert consistent_until is None and consistent_oracle is None
