"""``plan``'s default portfolio (A* beside the symbolic prover) and the forked worker it runs the prover in."""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import pytest

from conftest import BLOCKS
from guided_lfd.symbolic.portfolio import plan_task
from guided_lfd.symbolic import portfolio
from guided_lfd.pddl.reader import parse_task
from guided_lfd.symbolic.worker import Forked

TRACK = Path(__file__).resolve().parent.parent / "data" / "benchmarks" / "unsolvability-ipc2016"


def _slow_astar(actions, init, goal_pos, goal_neg, deadline=None, stop=None, **_):
    """An A* that never finishes: it only waits for the portfolio to stop it (60 s at most)."""
    end = time.monotonic() + 60
    while time.monotonic() < end:
        if stop is not None and stop():
            raise portfolio.SearchStopped()
        time.sleep(0.01)
    raise AssertionError("the prover never answered")


def test_the_prover_answers_when_astar_cannot(monkeypatch):
    monkeypatch.setattr(portfolio, "astar", _slow_astar)
    domain, problem = parse_task(TRACK / "bottleneck" / "domain.pddl", TRACK / "bottleneck" / "prob01.pddl")
    _, result = plan_task(domain, problem)
    assert result.plan is None and result.answered_by == "symbolic"


def test_a_task_wider_than_the_engines_limit_starts_no_prover(monkeypatch):
    from guided_lfd.symbolic import encoding, worker

    monkeypatch.setattr(encoding, "DEFAULT_MAX_VARIABLES", 10)  # bottleneck prob01's actions touch 49 atoms
    monkeypatch.setattr(worker, "Forked", _never_forked)  # no second process at all
    domain, problem = parse_task(TRACK / "bottleneck" / "domain.pddl", TRACK / "bottleneck" / "prob01.pddl")
    _, result = plan_task(domain, problem)
    assert result.plan is None and result.answered_by == "astar-lmcut"  # A* alone proved it


def _never_forked(*_):
    raise AssertionError("the prover started on a task past its limit")


def test_a_solvable_task_is_planned_by_astar_whatever_the_prover_says():
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task03.pddl")
    _, result = plan_task(domain, problem)
    assert result.plan is not None and result.optimal and result.answered_by == "astar-lmcut"


def test_plan_json_names_who_answered(runner, app):
    out = runner.invoke(app, ["plan", str(TRACK / "bottleneck" / "domain.pddl"),
                              str(TRACK / "bottleneck" / "prob01.pddl"), "--json"])
    assert out.exit_code == 10
    document = json.loads(out.stdout)
    assert document["status"] == "unsolvable" and document["answered_by"] in ("astar-lmcut", "symbolic")


def _fails():
    raise ValueError("no")


def _dies():
    os._exit(3)


def test_the_worker_reports_a_value_an_error_and_a_death():
    for target, args, kind in ((pow, (2, 10), "ok"), (_fails, (), "error"), (_dies, (), "error")):
        worker = Forked(target, *args)
        try:
            assert worker.poll(timeout=30)
            assert worker.answer is not None and worker.answer[0] == kind
        finally:
            worker.stop()
    worker = Forked(pow, 2, 10)
    worker.poll(30)
    assert worker.value() == 1024
    worker.stop()


def test_stopping_a_worker_ends_it():
    worker = Forked(time.sleep, 60)
    worker.stop()
    assert not worker.process.is_alive()
    assert not worker.poll() or worker.value() is None
