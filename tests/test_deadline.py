"""Whole-run time limits: the watchdog, its nesting, and --time-limit on the command line."""

from __future__ import annotations

import json
import signal
import time

import pytest

from guided_lfd import household
from guided_lfd.deadline import check, deadline_after, watchdog
from guided_lfd.errors import EXIT_TIME_LIMIT, SearchTimeout


def _spin(seconds: float) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        pass


def test_watchdog_interrupts_code_without_checks():
    start = time.monotonic()
    with pytest.raises(SearchTimeout, match="spinning exceeded the time limit"):
        with watchdog(deadline_after(0.05), "spinning", grace=0.0):
            _spin(5)
    assert time.monotonic() - start < 1.0
    assert signal.getitimer(signal.ITIMER_REAL)[0] == 0  # disarmed afterwards


def test_inner_watchdog_restores_the_outer_one():
    with pytest.raises(SearchTimeout, match="outer"):
        with watchdog(deadline_after(0.3), "outer", grace=0.0):
            with watchdog(deadline_after(0.05), "inner", grace=0.0):
                time.sleep(0.01)  # ends before the inner limit
            left = signal.getitimer(signal.ITIMER_REAL)[0]
            assert 0 < left <= 0.3
            _spin(5)


def test_outer_watchdog_that_fires_first_keeps_precedence():
    with pytest.raises(SearchTimeout, match="outer"):
        with watchdog(deadline_after(0.05), "outer", grace=0.0):
            with watchdog(deadline_after(10), "inner", grace=0.0):
                _spin(5)


def test_no_deadline_means_no_watchdog_and_check_passes():
    with watchdog(None):
        check(None)
    with pytest.raises(SearchTimeout):
        check(time.monotonic() - 1, "late")


def _house(tmp_path, house: household.House) -> tuple[str, str]:
    dom, prob = tmp_path / "robot.pddl", tmp_path / "house.pddl"
    dom.write_text(household.domain_pddl(house.variant))
    prob.write_text(household.problem_pddl(house))
    return str(dom), str(prob)


def test_excuse_time_limit_bounds_the_whole_run_and_still_writes_json(runner, app, tmp_path):
    # A house whose run takes about a second here: a 0.2 s limit must end it
    # within the limit plus the documented 1 s, in whatever phase it is.
    dom, prob = _house(tmp_path, household.House(16, 64, 4, 1, 4, "no-push"))
    out = tmp_path / "excuse.json"
    start = time.monotonic()
    result = runner.invoke(app, ["excuse", dom, prob, "--time-limit", "0.2", "-o", str(out), "--json"])
    elapsed = time.monotonic() - start
    assert result.exit_code == EXIT_TIME_LIMIT, result.output
    assert elapsed < 0.2 + 1.0
    doc = json.loads(out.read_text())
    assert doc["status"] == "timeout" and doc["excuse"] is None
    assert doc["statistics"]["phase"] in {"grounding", "invariant synthesis", "change space", "relaxed task",
                                          "already solvable?", "searching", "robot plan"}


def test_plan_time_limit_bounds_grounding_too(runner, app, tmp_path):
    dom = tmp_path / "human.pddl"
    dom.write_text(household.domain_pddl())
    _, prob = _house(tmp_path, household.House(32, 128, 4, 1, 4, "no-push"))
    start = time.monotonic()
    result = runner.invoke(app, ["plan", str(dom), prob, "--time-limit", "0.3"])
    assert result.exit_code == EXIT_TIME_LIMIT
    assert time.monotonic() - start < 0.3 + 1.0
