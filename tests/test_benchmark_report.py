"""The benchmark report: coverage, speed-ups and agreement computed from result rows."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from guided_lfd.benchmark import ResultRow, compare, size_bucket, speedups_by_size, summary_markdown


def row(tid, semantics, strategy, status, size=None, search=0.01, total=0.1, domain="d"):
    return ResultRow(tid, domain, "t", "a", semantics, strategy, status, size=size,
                     time_s=None if total == "" else total, search_time_s=None if search == "" else search)


ROWS = [
    # t1: both solve, size 1, 100x on search (landmark below the 0.1 ms floor: counts as 0.1 ms)
    row("t1", "literal", "landmark", "excuse-found", 1, search=0.00002, total=0.05),
    row("t1", "literal", "baseline", "excuse-found", 1, search=0.01, total=0.06),
    # t2: both solve, size 4, 20x
    row("t2", "literal", "landmark", "excuse-found", 4, search=0.05, total=0.1),
    row("t2", "literal", "baseline", "excuse-found", 4, search=1.0, total=1.05),
    # t3: only the landmark search solves it (size 6)
    row("t3", "literal", "landmark", "excuse-found", 6, search=2.0, total=2.1),
    row("t3", "literal", "baseline", "timeout", total=61.0),
    # t1 consistent: both prove that no excuse exists, 4x
    row("t1", "consistent", "landmark", "no-excuse", search=0.001, total=0.05),
    row("t1", "consistent", "baseline", "no-excuse", search=0.004, total=0.06),
    # t2 consistent: sizes disagree (a bug either way), and the landmark run crashed on t3
    row("t2", "consistent", "landmark", "excuse-found", 3, search=0.01),
    row("t2", "consistent", "baseline", "excuse-found", 2, search=0.5),
    row("t3", "consistent", "landmark", "error", search=""),
    row("t3", "consistent", "baseline", "timeout", search=""),
]


def by_label(rows):
    return {c.semantics: c for c in compare(rows)}


def test_coverage_speedups_and_large_tasks_per_semantics():
    lit = by_label(ROWS)["literal"]
    assert (lit.tasks, lit.solved_default, lit.solved_baseline, lit.both) == (3, 3, 2, 2)
    assert lit.median_speedup == pytest.approx((100 + 20) / 2)
    assert lit.geomean_speedup == pytest.approx(math.sqrt(100 * 20))
    assert (lit.large_default, lit.large_baseline) == (2, 1)
    assert lit.size_mismatches == []


def test_disagreeing_sizes_are_reported_and_both_pools_the_semantics():
    comps = by_label(ROWS)
    assert comps["consistent"].size_mismatches == ["t2: landmark excuse-found 3 vs baseline excuse-found 2"]
    both = comps["both"]
    assert both.tasks == 6 and both.both == 4
    assert both.median_speedup == pytest.approx((20 + 50) / 2)  # ratios 100, 20, 4, 50


@pytest.mark.parametrize("size,bucket", [(1, "1"), (2, "2"), (3, "3-5"), (5, "3-5"), (6, "6+"), (11, "6+")])
def test_size_buckets(size, bucket):
    assert size_bucket(row("t", "literal", "landmark", "excuse-found", size)) == bucket


def test_speedups_by_size_bucket():
    assert size_bucket(ROWS[6]) == "none"
    table = speedups_by_size(ROWS)
    assert table["literal"] == {"1": [pytest.approx(100)], "3-5": [pytest.approx(20)]}
    assert table["consistent"] == {"none": [pytest.approx(4)], "3-5": [pytest.approx(50)]}


def test_summary_shows_tables_disagreements_and_errors(tmp_path: Path):
    text = summary_markdown(ROWS, 60, "python benchmarks/excuse_bench.py all --jobs 2", [tmp_path / "cactus.png"],
                            tmp_path)
    assert "| literal | 3 | 3 (100%) | 2 (67%) | 2 | 60x | 45x |" in text
    assert "| literal | 100x (1) | - | 20x (1) | - | - |" in text
    assert "- t2: landmark excuse-found 3 vs baseline excuse-found 2" in text
    assert "Runs that returned an excuse: 7; runs that ended in an error or crash: 1." in text
    assert "- t3 landmark consistent: error\n" in text
    assert "![cactus](cactus.png)" in text


def test_summary_of_a_clean_run_says_sizes_agree(tmp_path: Path):
    clean = [r for r in ROWS if r.semantics == "literal"]
    text = summary_markdown(clean, 60, "cmd", [], tmp_path)
    assert "Every task both strategies solved has the same status and minimal size." in text
    assert "runs that ended in an error or crash: 0." in text


def test_summary_lists_memouts(tmp_path: Path):
    rows = ROWS[:4] + [row("t9", "literal", "baseline", "memout"), row("t9", "literal", "landmark", "no-excuse")]
    text = summary_markdown(rows, 60, "cmd", [], tmp_path)
    assert "Runs that exceeded the memory cap (memout, counted as unsolved): 1." in text
    assert "- t9 baseline literal" in text


def test_nontrivial_whole_run_speedup_counts_unfinished_runs_at_the_limit():
    rows = [
        row("t1", "literal", "landmark", "excuse-found", 1, total=0.5),   # trivial: baseline 0.6 s
        row("t1", "literal", "baseline", "excuse-found", 1, total=0.6),
        row("t2", "literal", "landmark", "excuse-found", 2, total=0.5),   # baseline 5 s: 10x
        row("t2", "literal", "baseline", "excuse-found", 2, total=5.0),
        row("t3", "literal", "landmark", "excuse-found", 3, total=2.0),   # baseline timeout: 60 / 2 = 30x
        row("t3", "literal", "baseline", "timeout", total=61.5),
        row("t4", "literal", "landmark", "excuse-found", 3, total=1.0),   # baseline not run: 60x
        row("t4", "literal", "baseline", "not-run", total=""),
        row("t5", "literal", "landmark", "timeout", total=60.2),          # neither: left out
        row("t5", "literal", "baseline", "timeout", total=60.4),
        row("t6", "literal", "landmark", "excuse-found", 1, total=0.5),   # baseline crashed: says nothing
        row("t6", "literal", "baseline", "crashed", total=3.0),
    ]
    for r in rows:
        r.wall_s = r.time_s
    lit = by_label(rows)["literal"]
    assert lit.nontrivial == 3
    assert lit.median_nontrivial_speedup == pytest.approx(30)


def test_summary_reports_overruns_of_the_time_limit_and_runs_not_made(tmp_path: Path):
    rows = [row("a-task05-x", "literal", "landmark", "excuse-found", 1, total=0.5),
            row("a-task05-x", "literal", "baseline", "timeout", total=61.7),
            row("a-task06-x", "literal", "landmark", "timeout", total=60.3),
            row("a-task06-x", "literal", "baseline", "not-run", total="")]
    for r in rows:
        r.wall_s = r.time_s
        r.task = r.id.split("-")[1]
    text = summary_markdown(rows, 60, "cmd", [], tmp_path)
    assert ("longest whole run 61.70 s (a-task05-x baseline literal: timeout), +1.70 s against the 60 s limit; "
            "runs more than 1 s past it: 1.") in text
    assert "- a-task05-x baseline literal: 61.70 s (timeout)" in text
    assert "Runs not made: 1." in text
    assert "| grown | literal | 2 | 1 (50.0%) | 0 (0.0%) | 1 |" in text


def test_the_default_is_the_portfolio_where_the_results_have_it(tmp_path):
    # The same runs under the portfolio's name, beside older landmark rows that solved less: the report
    # compares the portfolio with the baseline and names it.
    renamed = [ResultRow(**{**r.__dict__, "strategy": "portfolio"}) for r in ROWS if r.strategy == "landmark"]
    stale = [row("t1", "literal", "landmark", "timeout", total=60.0)]
    rows = renamed + stale + [r for r in ROWS if r.strategy == "baseline"]
    lit = by_label(rows)["literal"]
    assert (lit.solved_default, lit.solved_baseline) == (3, 2)
    text = summary_markdown(rows, 60.0, "cmd", None, tmp_path)
    assert "## Default (portfolio) vs baseline" in text and "solved: portfolio" in text
    assert "## Minimal excuse sizes found (portfolio)" in text
    assert "| literal | 3 | 3 (100%) | 2 (67%) |" in text


def test_a_subset_run_of_the_portfolio_leaves_the_landmark_rows_the_default():
    rows = ROWS + [row("t1", "literal", "portfolio", "excuse-found", 1)]
    assert by_label(rows)["literal"].solved_default == 3  # landmark's: 4 rows against 1
