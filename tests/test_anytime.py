"""A timed-out excuse search still answers: its proven lower bound, the cheapest excuse it found, and progress.

The searches read their clock through ``guided_lfd.excuse.outcome.clock``;
these tests replace it with one that moves a set step per reading, so a
search times out after the same number of checks on any machine (the real
deadline, 1,000 s away, never comes).
"""

from __future__ import annotations

import itertools
import json
import re
import time
from dataclasses import replace

import pytest

from conftest import BLOCKS, ROOT
from guided_lfd.errors import EXIT_TIME_LIMIT
from guided_lfd.excuse import landmark, outcome
from guided_lfd.excuse.check import check_excuse
from guided_lfd.excuse.laws import derive_laws
from guided_lfd.excuse.lmcut import RelaxedExcuseTask
from guided_lfd.excuse.prepare import prepare
from guided_lfd.excuse.space import Semantics
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.report import ExcuseReport
from guided_lfd.excuse.progress import Progress, ProgressMeter
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.pddl.model import Domain, Problem
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import domain_to_pddl
from guided_lfd.planning.task import bits

LOGISTICS = ROOT / "data" / "benchmarks" / "ipc" / "logistics"
#: Far beyond any test: only the ticking clock ends the searches.
LIMIT = 1000.0
#: Clock step per reading: the landmark search on logistics task11 without drive-truck times out after
#: 10,000 readings, in the middle of the search (a full run takes some 19,800 readings, 3,500 nodes).
STEP = 0.1


def ticking_clock(monkeypatch: pytest.MonkeyPatch, step: float) -> None:
    """Make the searches' clock move ``step`` seconds per reading, from now."""
    base, ticks = time.monotonic(), itertools.count()
    monkeypatch.setattr(outcome, "clock", lambda: base + step * next(ticks))


def logistics_without_driving() -> tuple[Domain, Problem]:
    """Logistics task11 with no drive-truck: the minimal excuse has 12 changes and takes thousands of nodes."""
    full, problem = parse_task(LOGISTICS / "domain.pddl", LOGISTICS / "task11.pddl")
    return replace(full, actions=[a for a in full.actions if a.name != "drive-truck"]), problem


def options(**more) -> ExcuseOptions:
    """The benchmark's options for logistics: the world's static structure fixed; the landmark search alone (the
    portfolio's hitting-set turns answer this task within the first turns: see test_hitting.py)."""
    return ExcuseOptions(strategy="landmark", fixed_from=parse_domain(LOGISTICS / "domain.pddl"), **more)


def assert_checked(report: ExcuseReport, domain: Domain, problem: Problem, opts: ExcuseOptions) -> None:
    """The best candidate passes the independent checker every printed excuse passes."""
    best = report.best_candidate
    assert best is not None
    groups = derive_laws(domain, problem) if report.semantics.value == "consistent" else None
    assert check_excuse(domain, problem, best.changes, best.plan, groups, opts.fixed_predicates(domain),
                        opts.costs, best.cost) == []


def test_a_timed_out_search_reports_a_sound_lower_bound_and_a_checked_best_excuse(monkeypatch):
    domain, problem = logistics_without_driving()
    full = find_excuses(domain, problem, options())
    assert full.status is ExcuseStatus.FOUND and full.excuse is not None
    minimal = full.excuse.cost
    ticking_clock(monkeypatch, STEP)
    opts = options(time_limit=LIMIT)
    report = find_excuses(domain, problem, opts)
    assert report.status is ExcuseStatus.TIMEOUT and report.excuses == []
    bound = report.statistics.lower_bound
    assert bound is not None and 1 <= bound <= minimal
    best = report.best_candidate
    assert best is not None and best.cost >= minimal and not best.proven_minimal
    assert_checked(report, domain, problem, opts)
    assert report.statistics.counters["probe_expanded"] > 0


def blocks_without_unstack() -> tuple[Domain, Problem]:
    """Blocks task03 without unstack: the baseline needs 3,516 candidates for its minimal excuse of 3 changes."""
    return parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")


@pytest.mark.parametrize("strategy, task, opts, limit, steps", [
    ("landmark", logistics_without_driving, options(), LIMIT, (0.5, 0.2, 0.1)),
    ("baseline", blocks_without_unstack, ExcuseOptions(strategy="baseline"), 20.0, (1.0, 0.1, 0.02)),
])
def test_the_lower_bound_never_passes_the_minimum_and_grows_with_the_time(monkeypatch, strategy, task, opts,
                                                                          limit, steps):
    domain, problem = task()
    minimal = find_excuses(domain, problem, opts).excuse.cost
    bounds = []
    for step in steps:
        ticking_clock(monkeypatch, step)
        report = find_excuses(domain, problem, replace(opts, time_limit=limit))
        assert report.status is ExcuseStatus.TIMEOUT
        bounds.append(report.statistics.lower_bound)
    assert bounds == sorted(bounds) and bounds[0] < bounds[-1] <= minimal, (bounds, minimal)


def test_the_baseline_has_no_best_excuse_and_says_so(monkeypatch):
    domain, problem = blocks_without_unstack()
    ticking_clock(monkeypatch, 1.0)
    report = find_excuses(domain, problem, ExcuseOptions(strategy="baseline", time_limit=20.0))
    assert report.status is ExcuseStatus.TIMEOUT and report.best_candidate is None
    assert report.statistics.lower_bound == 1
    assert report.to_dict()["message"] == ("time limit reached before a minimal excuse was found; "
                                           "no excuse smaller than 1 change (proven); none found so far")
    assert report.to_dict()["best_candidate"] is None


@pytest.mark.parametrize("more, words", [
    ({"costs": ["clear=2"]}, "no excuse cheaper than 2 (proven)"),
    ({"max_size": 3}, "no excuse smaller than 2 changes within --max-size 3 (proven)"),
])
def test_the_bound_speaks_of_costs_under_cost_and_of_the_size_limit(monkeypatch, more, words):
    domain, problem = blocks_without_unstack()
    opts = ExcuseOptions(strategy="baseline", **more)
    minimal = find_excuses(domain, problem, opts).excuse.cost
    ticking_clock(monkeypatch, 0.1)
    report = find_excuses(domain, problem, replace(opts, time_limit=20.0))
    assert report.statistics.lower_bound <= minimal
    message = report.to_dict()["message"]
    assert message == f"time limit reached before a minimal excuse was found; {words}; none found so far"


def test_a_search_that_ends_in_time_drops_the_probes_excuse(monkeypatch):
    # The probe runs (at 3/4 of the time), the search then finds the minimal excuse before its deadline.
    domain, problem = logistics_without_driving()
    ticking_clock(monkeypatch, 0.045)
    report = find_excuses(domain, problem, options(time_limit=LIMIT))
    assert report.status is ExcuseStatus.FOUND and report.best_candidate is None
    assert report.statistics.lower_bound is None and report.statistics.counters["probe_expanded"] > 0
    assert report.to_dict()["best_candidate"] is None


def test_a_minimal_excuse_from_the_probe_ends_the_run_when_the_bound_meets_it(monkeypatch):
    # At 0.07 s per reading the probe (at 3/4 of the time) finds a 12-change excuse, then the bound reaches 12.
    domain, problem = logistics_without_driving()
    ticking_clock(monkeypatch, 0.07)
    report = find_excuses(domain, problem, options(time_limit=LIMIT))
    assert report.status is ExcuseStatus.FOUND and report.excuse.cost == 12 and report.best_candidate is None
    assert report.statistics.counters["probe_adopted"] == 1


def test_progress_reports_the_phases_then_a_growing_bound(monkeypatch):
    from guided_lfd.excuse import progress as progress_module

    monkeypatch.setattr(progress_module, "REPORTS_PER_SECOND", float("inf"))  # every node reports
    domain, problem = logistics_without_driving()
    reports: list[Progress] = []
    report = find_excuses(domain, problem, options(), reports.append)
    phases = [p.phase for p in reports]
    assert phases[:2] == ["grounding", "invariant synthesis"] and "searching" in phases
    searching = [p for p in reports if p.phase == "searching" and p.lower_bound is not None]
    assert len(searching) >= report.statistics.nodes_expanded
    bounds = [p.lower_bound for p in searching]
    assert bounds == sorted(bounds) and bounds[-1] == report.excuse.cost
    assert [p.nodes for p in searching] == sorted(p.nodes for p in searching)
    assert all(p.oracle_calls <= report.statistics.planner_calls for p in searching)


def test_the_meter_reports_a_few_times_a_second(monkeypatch):
    from guided_lfd.excuse import progress as progress_module

    now = [100.0]
    monkeypatch.setattr(progress_module.time, "monotonic", lambda: now[0])
    reports: list[Progress] = []
    meter = ProgressMeter(reports.append, started=99.0)
    meter.phase("searching")
    assert [(p.phase, p.elapsed_s) for p in reports] == [("searching", 1.0)]
    now[0] += 0.2
    assert not meter.due()
    now[0] += 0.06
    assert meter.due()
    meter.search(nodes=7, oracle_calls=2, candidates=1, lower_bound=3)
    meter.found(9)
    assert reports[-1] == Progress("searching", 1.26, lower_bound=3, nodes=7, oracle_calls=2, candidates=1,
                                   best_cost=9)


# -- the command line ---------------------------------------------------------------------------------------------


@pytest.fixture
def logistics_files(tmp_path):
    domain, _ = logistics_without_driving()
    path = tmp_path / "robot.pddl"
    path.write_text(domain_to_pddl(domain))
    return [str(path), str(LOGISTICS / "task11.pddl"), "--fixed-from", str(LOGISTICS / "domain.pddl"),
            "--time-limit", str(LIMIT), "--strategy", "landmark"]


def test_cli_json_on_timeout_has_the_bound_and_the_best_excuse(runner, app, monkeypatch, logistics_files):
    ticking_clock(monkeypatch, STEP)
    result = runner.invoke(app, ["excuse", *logistics_files, "--json"])
    assert result.exit_code == EXIT_TIME_LIMIT, result.stderr
    doc = json.loads(result.stdout)
    assert doc["status"] == "timeout" and doc["excuse"] is None
    bound, best = doc["statistics"]["lower_bound"], doc["best_candidate"]
    assert best["proven_minimal"] is False and best["validated"] is True and best["size"] == len(best["changes"])
    assert best["cost"] > bound and best["plan"] and best["plan_optimal"] is False
    message = (f"time limit reached before a minimal excuse was found; no excuse smaller than {bound} changes "
               f"(proven); best excuse found so far (not proven minimal): size {best['size']}, cost {best['cost']}")
    assert doc["message"] == message
    assert result.stderr.splitlines()[0] == message


def test_cli_text_on_timeout_prints_the_best_excuse_on_stdout_and_the_bound_on_stderr(runner, app, monkeypatch,
                                                                                        logistics_files):
    ticking_clock(monkeypatch, STEP)
    result = runner.invoke(app, ["excuse", *logistics_files])
    assert result.exit_code == EXIT_TIME_LIMIT, result.stderr
    lines = result.stdout.splitlines()
    title = re.fullmatch(r"Best excuse found so far \(not proven minimal; size (\d+), cost (\d+)\): "
                         r"demonstrate how to reach", lines[0])
    assert title is not None, lines[0]
    size = int(title.group(1))
    assert all(re.fullmatch(r"  .+   [+-]\(.+\)", line) for line in lines[1:1 + size])
    assert re.fullmatch(r"then the robot's own plan \(\d+ steps?, validated\):", lines[1 + size])
    assert "time limit reached" not in result.stdout  # the reason is on stderr only
    bound = re.search(r"no excuse smaller than (\d+) changes \(proven\)", result.stderr.splitlines()[0])
    assert bound is not None and int(bound.group(1)) < size


def test_cli_progress_line_words():
    from cli.excuse import progress_line

    assert progress_line(Progress("grounding", 0.5)) == "grounding"
    line = progress_line(Progress("searching", 3.0, lower_bound=4, nodes=12345, oracle_calls=67, candidates=60))
    assert line == "searching: lower bound 4, 12,345 nodes, 67 reachability checks"
    line = progress_line(Progress("searching", 3.0, lower_bound=4, nodes=1, oracle_calls=2, best_cost=9))
    assert line.endswith(", best excuse so far costs 9")


def landmark_run(incumbent_of=None, all_minimal: bool = False) -> landmark._LandmarkRun:
    """The landmark search on logistics task11 without drive-truck, run to its end; ``incumbent_of(run)``, if
    given, hands it a probe's excuse (change set, plan, weight) before it starts."""
    domain, problem = logistics_without_driving()
    prepared = prepare(domain, problem, Semantics.LITERAL, fixed=options().fixed_predicates(domain))
    space = prepared.space
    run = landmark._LandmarkRun(space, outcome.SearchLimits(all_minimal=all_minimal),
                                  RelaxedExcuseTask(space), prepared.oracle)
    if incumbent_of is not None:
        run.incumbent = incumbent_of(run)
    run.loop(None)
    return run


@pytest.fixture(scope="module")
def full_run() -> landmark._LandmarkRun:
    return landmark_run()


def test_the_probes_excuse_ends_the_search_once_the_bound_meets_its_weight(full_run):
    (minimal,) = full_run.solutions
    weight = full_run.space.weight(minimal)
    run = landmark_run(lambda r: (minimal, full_run.plans[minimal], weight))
    assert run.solutions == [minimal] and run.adopted and run.bound >= weight
    # The nodes of the minimal weight before the excuse, and the excuse itself, are never taken up.
    assert run.expanded < full_run.expanded
    assert run.outcome().extra["probe_adopted"] == 1


def test_a_heavier_probe_excuse_is_not_taken_for_a_minimal_one(full_run):
    (minimal,) = full_run.solutions
    space = full_run.space
    extra = next(i for i in bits(space.changeable & ~minimal))
    heavier = minimal | 1 << extra
    run = landmark_run(lambda r: (heavier, full_run.plans[minimal], space.weight(heavier)))
    assert run.solutions == [minimal] and not run.adopted


def test_every_minimal_excuse_wanted_the_probes_excuse_ends_nothing(full_run):
    (minimal,) = full_run.solutions
    weight = full_run.space.weight(minimal)
    every = landmark_run(all_minimal=True)
    run = landmark_run(lambda r: (minimal, full_run.plans[minimal], weight), all_minimal=True)
    assert sorted(run.solutions) == sorted(every.solutions) and not run.adopted
