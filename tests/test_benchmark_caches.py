"""Every cache the benchmark keeps is keyed by the content of what it caches: an edited file is never served stale.

The benchmark keeps two things between runs: the robot domains it builds (a domain without one action, under
``$TMPDIR/guided-lfd-bench``) and the rows of an interrupted run (``results.partial.csv``, resumed).  Each test
edits a file between two runs and checks that the second run answers for the edited file.
"""

from __future__ import annotations

import csv
import os
import subprocess
import sys
from pathlib import Path

from conftest import DOMAINS, ROOT
from guided_lfd import benchmark
from guided_lfd.benchmark import BenchTask, ResultRow, RowLog, input_digest, task_digest

KITCHEN = DOMAINS / "kitchen-1"
#: put_inside edited to need a drawer that is *not* clear, and the chair made immovable: the robot without
#: open_drawer then needs -(clear pinkdrawer) beside +(open pinkdrawer) (literal semantics).
EDITS = ((":precondition (and (in_hand ?i) (open ?d) (clear ?d))",
          ":precondition (and (in_hand ?i) (open ?d) (not (clear ?d)))"),
         (":precondition (and (blocking ?c ?from) (clear ?to) (hand_free))",
          ":precondition (and (blocking ?c ?from) (clear ?to) (hand_free) (not (hand_free)))"))


def kitchen_without_open_drawer(folder: Path) -> tuple[BenchTask, Path]:
    """A suite task of the user's own: Kitchen I's human domain without open_drawer, copied into ``folder``."""
    domain = folder / "kitchen.pddl"
    domain.write_text((KITCHEN / "human.pddl").read_text())
    task = BenchTask("kitchen-open", "kitchen", "problem", "open_drawer", str(domain),
                     str(KITCHEN / "problem.pddl"), str(domain))
    return task, domain


def edit(domain: Path) -> None:
    text = domain.read_text()
    for old, new in EDITS:
        assert text.count(old) == 1
        text = text.replace(old, new)
    domain.write_text(text)


def test_a_robot_domain_is_built_again_after_its_domain_file_is_edited(tmp_path):
    task, domain = kitchen_without_open_drawer(tmp_path)
    cache = tmp_path / "cache"
    cache.mkdir()
    first = benchmark.robot_domain_file(task, cache)
    assert "(:action open_drawer" not in first.read_text() and "(not (clear ?d))" not in first.read_text()
    assert benchmark.robot_domain_file(task, cache) == first  # unchanged content: built once
    edit(domain)
    second = benchmark.robot_domain_file(task, cache)
    assert second != first and "(not (clear ?d))" in second.read_text()


def test_the_key_changes_with_every_input_and_the_tools_version(tmp_path, monkeypatch):
    task, domain = kitchen_without_open_drawer(tmp_path)
    base = task_digest(task)
    assert task_digest(task) == base
    assert task_digest(BenchTask(**{**task.__dict__, "removed_action": "take"})) != base
    monkeypatch.setattr("guided_lfd.__version__", "99.0")
    assert task_digest(task) != base
    monkeypatch.undo()
    edit(domain)
    assert task_digest(task) != base
    # Text and a file of the same bytes are different inputs; so are ("ab", "c") and ("a", "bc").
    assert input_digest("ab", "c") != input_digest("a", "bc")
    assert input_digest(str(domain)) != input_digest(domain)


def bench_run(task: BenchTask, folder: Path) -> dict[str, str]:
    """``excuse_bench.py run`` on a one-task suite as a user types it, with its own TMPDIR; the results row."""
    suite = folder / "suite.csv"
    with open(suite, "w", newline="", encoding="utf-8") as fh:  # absolute paths: read from any --root
        writer = csv.DictWriter(fh, fieldnames=benchmark.SUITE_FIELDS)
        writer.writeheader()
        writer.writerow(task.__dict__)
    proc = subprocess.run([sys.executable, str(ROOT / "benchmarks/excuse_bench.py"), "run", "--suite", str(suite),
                           "--results", str(folder / "results"), "--strategies", "landmark", "--semantics",
                           "literal", "--time-limit", "30"], capture_output=True, text=True, timeout=180, cwd=ROOT,
                          env={**os.environ, "TMPDIR": str(folder / "tmp")})
    assert proc.returncode == 0, proc.stderr
    with open(folder / "results" / "results.csv", encoding="utf-8") as fh:
        return next(csv.DictReader(fh))


def test_bench_answers_for_the_edited_domain_on_its_second_run(tmp_path):
    (tmp_path / "tmp").mkdir()
    task, domain = kitchen_without_open_drawer(tmp_path)
    assert bench_run(task, tmp_path)["excuse"] == "+(open pinkdrawer)"
    edit(domain)
    assert bench_run(task, tmp_path)["excuse"] == "-(clear pinkdrawer) +(open pinkdrawer)"


def test_a_resumed_run_reruns_the_rows_whose_files_were_edited(tmp_path):
    (tmp_path / "tmp").mkdir()
    task, domain = kitchen_without_open_drawer(tmp_path)
    # An interrupted run left its row for the unedited domain (with the digests the CLI records) ...
    results = tmp_path / "results"
    limits = "time_limit=30 memory_limit=0"
    log = RowLog(results / "results.partial.csv", {task.id: input_digest(task_digest(task), limits)})
    log.append(ResultRow(task.id, task.domain, task.task, task.removed_action, "literal", "landmark",
                         "excuse-found", size=1, cost=1, excuse="+(open pinkdrawer)"))
    # ... then the domain is edited and the run resumed: the row is run again, not reported.
    edit(domain)
    assert bench_run(task, tmp_path)["excuse"] == "-(clear pinkdrawer) +(open pinkdrawer)"
    assert not (results / "results.partial.csv").exists()
    assert not (results / "results.partial.csv.inputs.json").exists()


def test_a_row_log_keeps_only_rows_whose_inputs_are_unchanged(tmp_path):
    path = tmp_path / "results.partial.csv"
    row = ResultRow("t1", "d", "task01", "a", "literal", "landmark", "excuse-found", size=1)
    other = ResultRow("t2", "d", "task02", "a", "literal", "landmark", "timeout")
    log = RowLog(path, {"t1": "one", "t2": "two"})
    log.append(row)
    log.append(other)
    assert RowLog(path, {"t1": "one", "t2": "two"}).rows == [row, other]
    resumed = RowLog(path, {"t1": "one", "t2": "edited"})
    assert (resumed.rows, resumed.stale, resumed.done) == ([row], 1, {row.key})
    assert benchmark.read_results(path) == [row]  # the stale row left the log itself


def test_a_row_log_without_recorded_inputs_trusts_none_of_its_rows(tmp_path):
    """A partial log from a release that kept no digests (or whose digest file is damaged) is run again."""
    path = tmp_path / "results.partial.csv"
    benchmark.write_results([ResultRow("t1", "d", "task01", "a", "literal", "landmark", "excuse-found")], path)
    assert RowLog(path, {"t1": "one"}).rows == []
    benchmark.write_results([ResultRow("t1", "d", "task01", "a", "literal", "landmark", "excuse-found")], path)
    (tmp_path / "results.partial.csv.inputs.json").write_text("{not json")
    assert RowLog(path, {"t1": "one"}).stale == 1
