"""Whole-run time limits: the watchdog, its nesting, and --time-limit on the command line."""

from __future__ import annotations

import json
import signal
import time

import pytest

from conftest import fresh_interpreter
from guided_lfd.benchmark import household
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
    # The whole run as a user waits for it, start-up included, in a process of its own: in-process, freeing
    # the grounded task and earlier tests' garbage fell inside the timed window (3.7 s once, under xdist),
    # which no user of the command ever waits for (the command ends its process without freeing).
    import subprocess
    import sys

    start = time.monotonic()
    result = subprocess.run([sys.executable, "-c", "from cli.main import run; run()", "plan", str(dom), prob,
                             "--time-limit", "0.3"], capture_output=True, text=True, timeout=60)
    elapsed = time.monotonic() - start
    assert result.returncode == EXIT_TIME_LIMIT, (result.returncode, result.stderr)
    assert elapsed < 0.3 + 2.5, elapsed  # grounding alone takes seconds; the margin is for a loaded machine


def test_linger_keeps_objects_only_when_the_process_will_not_free_them():
    code = ("import weakref\nfrom guided_lfd import deadline\nclass Big: pass\n"
            "a = Big(); ra = weakref.ref(a); deadline.linger(a); del a\n"
            "deadline.keep_until_exit()\n"
            "b = Big(); rb = weakref.ref(b); deadline.linger(b); del b\n"
            "print(ra() is None, rb() is not None, deadline.lingering())\n")
    assert fresh_interpreter(code).strip() == "True True True"


def test_the_console_script_ends_with_its_exit_code_and_all_its_output(tmp_path):
    import subprocess
    import sys
    from pathlib import Path

    from conftest import ROOT, kitchen

    exe = Path(sys.executable).with_name("guided-lfd")
    domain, problem = kitchen(1)
    ok = subprocess.run([str(exe), "excuse", str(domain), str(problem), "--json", "--quiet"], capture_output=True,
                        text=True, cwd=ROOT, timeout=60)
    assert ok.returncode == 0 and json.loads(ok.stdout)["status"] == "excuse-found" and ok.stderr == ""
    missing = subprocess.run([str(exe), "plan", str(tmp_path / "none.pddl"), str(problem)], capture_output=True,
                             text=True, cwd=ROOT, timeout=60)
    assert missing.returncode == 30 and "file not found" in missing.stderr
    # A reader that stops early: no complaint at exit, the command's own exit code.
    piped = subprocess.run(f"'{exe}' excuse '{domain}' '{problem}' --json --quiet | head -c 1", shell=True,
                           capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert piped.stdout == "{" and "Exception ignored" not in piped.stderr


def test_a_timed_out_search_ends_within_the_limit_from_the_shell(tmp_path):
    # blocks task01 without stack: the baseline does not finish; the process ends near its limit.
    import subprocess
    import sys
    from dataclasses import replace
    from pathlib import Path

    from conftest import ROOT
    from guided_lfd.pddl.reader import parse_domain
    from guided_lfd.pddl.writer import domain_to_pddl

    exe = Path(sys.executable).with_name("guided-lfd")
    blocks = ROOT / "data" / "benchmarks" / "ipc" / "blocks"
    full = parse_domain(blocks / "domain.pddl")
    robot = tmp_path / "robot.pddl"
    robot.write_text(domain_to_pddl(replace(full, actions=[a for a in full.actions if a.name != "stack"])))
    start = time.monotonic()
    out = subprocess.run([str(exe), "excuse", str(robot), str(blocks / "task01.pddl"), "--strategy", "baseline",
                          "--time-limit", "2", "--json", "--quiet"], capture_output=True, text=True, cwd=ROOT,
                         timeout=60)
    wall = time.monotonic() - start
    assert out.returncode == EXIT_TIME_LIMIT and json.loads(out.stdout)["status"] == "timeout"
    assert wall < 3.0


def test_plan_past_its_deadline_after_reading_is_a_time_limit_not_an_option_error(runner, app, monkeypatch):
    # Reading ends after the deadline but before the watchdog's grace (a loaded machine): the planner's time
    # left is negative. Without the watchdog and with a start 10 s ago, that moment is the same on any machine.
    import contextlib

    import cli.plan
    from conftest import kitchen

    monkeypatch.setattr(cli.plan, "watchdog", lambda *args, **kwargs: contextlib.nullcontext())
    monkeypatch.setattr(cli.plan, "started_at", lambda: time.monotonic() - 10)
    result = runner.invoke(app, ["plan", *kitchen(1, "human"), "--time-limit", "5"])
    assert result.exit_code == EXIT_TIME_LIMIT, result.output
    assert result.stderr == "time limit: plan exceeded the time limit\n"
