"""A small slice of the excuse benchmark as a regression check on minimal sizes.

Expected statuses and sizes come from a benchmark run in which the baseline
(the paper's method) agreed wherever it finished (column ``baseline_agrees``).
Only sizes are checked here, never times.
"""

from __future__ import annotations

import csv

import pytest

from conftest import ROOT
from guided_lfd import benchmark
from guided_lfd.excuse.strategies import DEFAULT_STRATEGY

SUBSET = list(csv.DictReader(open(ROOT / "benchmarks" / "ci_subset.csv", encoding="utf-8")))
SUITE = {t.id: t for t in benchmark.read_suite(ROOT / "benchmarks" / "suite.csv", ROOT)}
CASES = [(row, se) for row in SUBSET for se in ("literal", "consistent")]


def test_subset_spans_the_benchmark_domains():
    assert len({SUITE[row["id"]].domain for row in SUBSET}) >= 10


@pytest.mark.parametrize("row,semantics", CASES, ids=[f"{r['id']}-{se}" for r, se in CASES])
def test_default_strategy_keeps_minimal_sizes(row, semantics):
    result = benchmark.run_one(SUITE[row["id"]], DEFAULT_STRATEGY, semantics, time_limit=30).to_csv()
    assert result["status"] == row[f"{semantics}_status"]
    assert result["size"] == row[f"{semantics}_size"]


@pytest.mark.parametrize("task_id", ["kitchen-1-problem", "kitchen-2-problem", "gripper-task01-move", "miconic-task04-up"])
def test_baseline_agrees_on_small_tasks(task_id):
    row = next(r for r in SUBSET if r["id"] == task_id)
    result = benchmark.run_one(SUITE[task_id], "baseline", "literal", time_limit=30).to_csv()
    assert (result["status"], result["size"]) == (row["literal_status"], row["literal_size"])


@pytest.mark.slow
@pytest.mark.parametrize("row,semantics", CASES, ids=[f"{r['id']}-{se}" for r, se in CASES])
def test_baseline_agrees_on_the_whole_subset(row, semantics):
    """The paper's method on every subset task (minutes): same status and size wherever it finishes."""
    result = benchmark.run_one(SUITE[row["id"]], "baseline", semantics, time_limit=60).to_csv()
    if result["status"] == "timeout":
        # The baseline may not finish; it must keep its limit, and it must never disagree.
        assert float(result["time_s"]) <= 61.0, result
        pytest.skip(f"the baseline did not finish {row['id']} ({semantics}) in 60 s")
    assert (result["status"], result["size"]) == (row[f"{semantics}_status"], row[f"{semantics}_size"])
