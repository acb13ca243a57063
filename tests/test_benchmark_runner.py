"""The benchmark runner: whole command-line runs, rows for runs that fail, the memory cap, chains."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from conftest import ROOT, fresh_interpreter, kitchen
from guided_lfd import benchmark
from guided_lfd.benchmark import RESULT_FIELDS, BenchTask, ResultRow, read_suite, run_one


def kitchen_task():
    return next(t for t in read_suite(ROOT / "benchmarks" / "suite.csv", ROOT) if t.id == "kitchen-1-problem")


def fake_run(monkeypatch, script: str) -> None:
    """Make every run execute ``script`` in a fresh interpreter instead of guided-lfd."""
    monkeypatch.setattr(benchmark.runner, "command_line", lambda *args: [sys.executable, "-c", script])


def test_a_run_is_the_command_line_with_its_wall_time():
    row = run_one(kitchen_task(), "landmark", "consistent", 30.0)
    assert isinstance(row, ResultRow) and list(row.to_csv()) == RESULT_FIELDS
    assert (row.status, row.size, row.excuse, row.exit_code) == ("excuse-found", 1, "+(open pinkdrawer)", 0)
    # The whole process (start-up included) takes longer than the run's own clock.
    assert row.wall_s > row.time_s > row.search_time_s >= 0


def test_the_command_is_what_a_user_types(tmp_path):
    task = next(t for t in read_suite(ROOT / "benchmarks" / "suite.csv", ROOT) if t.id == "gripper-task01-move")
    robot = benchmark.robot_domain_file(task, tmp_path)
    cmd = benchmark.command_line(task, "baseline", "literal", 60.0, robot)
    assert cmd[1:] == ["excuse", str(robot), task.problem_file, "--semantics", "literal", "--strategy", "baseline",
                       "--time-limit", "60", "--json", "--quiet", "--fixed-from", task.fixed_from]
    from guided_lfd.pddl.reader import parse_domain

    assert [a.name for a in parse_domain(robot).actions] == ["pick", "drop"]


def test_a_run_that_runs_out_of_memory_is_recorded_as_memout(monkeypatch):
    fake_run(monkeypatch, "raise SystemExit(22)")
    row = run_one(kitchen_task(), "baseline", "consistent", 5.0)
    assert (row.status, row.size, row.excuse, row.exit_code) == ("memout", None, "", 22)


def test_a_process_that_dies_is_recorded_as_crashed_with_its_last_words(monkeypatch):
    fake_run(monkeypatch, "import sys; print('boom', file=sys.stderr); raise SystemExit(3)")
    row = run_one(kitchen_task(), "landmark", "literal", 5.0)
    assert (row.status, row.excuse, row.exit_code) == ("crashed", "boom", 3)


def test_a_run_far_past_its_limit_is_killed_as_a_timeout(monkeypatch):
    fake_run(monkeypatch, "import time; time.sleep(30)")
    monkeypatch.setattr(benchmark.runner, "KILL_GRACE_S", 0.5)
    row = run_one(kitchen_task(), "landmark", "literal", 0.5)
    assert row.status == "timeout" and row.excuse == "killed 0.5 s past the limit"
    assert 1.0 <= row.wall_s < 10


def printed_by(code: str) -> list[str]:
    """Words a fresh interpreter prints running ``code`` (limits must not leak into the test process)."""
    return fresh_interpreter(code).split()


def test_memory_limit_caps_the_soft_limit_and_a_huge_allocation_fails():
    code = ("import os, resource\nfrom guided_lfd.memory import cap_memory\n"
            "cap_memory(os.getpid(), 2048)\n"
            "print(resource.getrlimit(resource.RLIMIT_AS)[0] == 2048 * 2 ** 20)\n"
            "try:\n    bytearray(4 * 1024 ** 3)\nexcept MemoryError:\n    print('memout')\n")
    assert printed_by(code) == ["True", "memout"]


def test_memory_limit_stays_below_a_hard_limit_already_in_force():
    code = ("import os, resource\nfrom guided_lfd.memory import cap_memory\n"
            "resource.setrlimit(resource.RLIMIT_AS, (3 * 2 ** 30, 3 * 2 ** 30))\n"
            "cap_memory(os.getpid(), 8192)\n"
            "print(resource.getrlimit(resource.RLIMIT_AS) == (3 * 2 ** 30, 3 * 2 ** 30))\n")
    assert printed_by(code) == ["True"]


def test_the_memory_cap_reaches_the_run(monkeypatch):
    fake_run(monkeypatch, "import resource, sys, time\ntime.sleep(0.3)\n"
                          "sys.exit(0 if resource.getrlimit(resource.RLIMIT_AS)[0] == 3000 * 2 ** 20 else 5)")
    assert run_one(kitchen_task(), "landmark", "literal", 5.0, memory_limit_mb=3000).exit_code == 0


def test_memout_during_invariant_synthesis_is_the_memout_exit(runner, app, monkeypatch):
    from fast_downward.translate import invariant_finder

    def exhausted(*args, **kwargs):
        raise MemoryError

    monkeypatch.setattr(invariant_finder, "find_invariants", exhausted)
    domain, problem = kitchen(1)
    assert runner.invoke(app, ["excuse", str(domain), str(problem), "--semantics", "consistent"]).exit_code == 22


def family(n: int) -> list[BenchTask]:
    return [BenchTask(f"d-task0{i}-a", "d", f"task0{i}", "a", "", "", "") for i in range(1, n + 1)]


def test_a_stopping_strategy_gives_up_on_a_family_after_its_first_unfinished_task(monkeypatch):
    statuses = {"task01": "excuse-found", "task02": "timeout", "task03": "excuse-found"}
    ran = []

    def fake(task, strategy, semantics, *args):
        ran.append((task.task, strategy))
        return ResultRow(task.id, task.domain, task.task, task.removed_action, semantics, strategy,
                         statuses[task.task] if strategy == "baseline" else "excuse-found")

    monkeypatch.setattr(benchmark.runner, "run_one", fake)
    rows = benchmark.run_suite(list(reversed(family(3))), ["landmark", "baseline"], ["literal"], 60.0, jobs=2)
    assert sorted(ran) == [("task01", "baseline"), ("task01", "landmark"), ("task02", "baseline"),
                           ("task02", "landmark"), ("task03", "landmark")]
    by = {(r.task, r.strategy): r for r in rows}
    assert by["task03", "baseline"].status == "not-run"
    assert by["task03", "baseline"].excuse == "not run: task02 was not finished"


def test_a_resumed_run_keeps_its_rows_and_its_stops(monkeypatch):
    ran = []

    def fake(task, strategy, semantics, *args):
        ran.append(task.task)
        return ResultRow(task.id, task.domain, task.task, task.removed_action, semantics, strategy, "excuse-found")

    monkeypatch.setattr(benchmark.runner, "run_one", fake)
    previous = [ResultRow("d-task01-a", "d", "task01", "a", "literal", "baseline", "timeout")]
    rows = benchmark.run_suite(family(2), ["baseline"], ["literal"], 60.0, jobs=1, previous=previous)
    assert ran == []
    assert [r.status for r in rows] == ["timeout", "not-run"]


@pytest.mark.parametrize("jobs", [1, 2])
def test_run_suite_records_each_run_in_its_own_process(jobs):
    rows = benchmark.run_suite([kitchen_task()], ["landmark", "baseline"], ["literal"], 30.0, jobs=jobs,
                               memory_limit_mb=8192)
    assert [(r.strategy, r.status, r.size, r.excuse) for r in rows] == [
        ("baseline", "excuse-found", 1, "+(open pinkdrawer)"), ("landmark", "excuse-found", 1, "+(open pinkdrawer)")]


def test_a_subset_run_updates_its_rows_and_keeps_the_others(tmp_path):
    """`excuse_bench.py run --only ...` must not replace the full results with its few rows."""
    import csv
    import subprocess

    results = tmp_path / "results"
    results.mkdir()
    full = [ResultRow(f"t{i}", "d", "task01", "a", "consistent", "landmark", "excuse-found", size=1) for i in range(5)]
    full.append(ResultRow("kitchen-1-problem", "kitchen", "problem", "", "consistent", "landmark", "timeout"))
    benchmark.write_results(full, results / "results.csv")
    proc = subprocess.run([sys.executable, str(ROOT / "benchmarks/excuse_bench.py"), "run", "--only",
                           "kitchen-1-problem", "--strategies", "landmark", "--semantics", "consistent",
                           "--results", str(results), "--time-limit", "30"], capture_output=True, text=True,
                          timeout=120, cwd=ROOT)
    assert proc.returncode == 0, proc.stderr
    with open(results / "results.csv") as fh:
        rows = {r["id"]: r for r in csv.DictReader(fh)}
    assert set(rows) == {"t0", "t1", "t2", "t3", "t4", "kitchen-1-problem"}
    assert rows["kitchen-1-problem"]["status"] == "excuse-found"  # rerun: replaced
    assert rows["t3"]["status"] == "excuse-found"  # not rerun: kept


def test_result_rows_read_back_from_csv_as_they_were_written(tmp_path):
    """Numbers stay numbers (a size is an int whether the row is fresh or read back), None an empty cell."""
    rows = [ResultRow("t1", "d", "task01", "a", "literal", "landmark", "excuse-found", size=2, cost=3, wall_s=0.1234,
                      exit_code=0, time_s=0.0959, search_time_s=1e-05, candidates=4, planner_calls=5, expanded=6,
                      excuse="+(p a) -(q b)"),
            ResultRow("t1", "d", "task01", "a", "literal", "baseline", "timeout", excuse="time limit")]
    benchmark.write_results(rows, tmp_path / "r.csv")
    assert benchmark.read_results(tmp_path / "r.csv") == rows
    assert rows[1].to_csv()["size"] == "" and rows[0].to_csv()["search_time_s"] == "1e-05"

