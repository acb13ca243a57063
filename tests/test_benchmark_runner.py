"""The benchmark runner: result rows for runs that fail, and the per-run memory cap."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from conftest import ROOT
from guided_lfd import benchmark
from guided_lfd.benchmark import RESULT_FIELDS, read_suite, run_one


def kitchen_task():
    return next(t for t in read_suite(ROOT / "benchmarks" / "suite.csv", ROOT) if t.id == "kitchen-1-problem")


def test_a_run_that_runs_out_of_memory_is_recorded_as_memout(monkeypatch):
    import guided_lfd.excuse.engine as engine

    def exhausted(*args, **kwargs):
        raise MemoryError

    monkeypatch.setattr(engine, "find_excuses", exhausted)
    row = run_one(kitchen_task(), "baseline", "consistent", 5.0)
    assert list(row) == RESULT_FIELDS
    assert (row["status"], row["size"], row["excuse"]) == ("memout", "", "")


def test_a_run_that_fails_is_recorded_as_error(monkeypatch):
    import guided_lfd.excuse.engine as engine

    def broken(*args, **kwargs):
        raise RuntimeError("internal check failed")

    monkeypatch.setattr(engine, "find_excuses", broken)
    row = run_one(kitchen_task(), "landmark", "literal", 5.0)
    assert row["status"] == "error"
    assert row["excuse"] == "RuntimeError: internal check failed"


def test_memory_limit_turns_a_huge_allocation_into_memory_error():
    code = ("from guided_lfd.benchmark import limit_memory\n"
            "limit_memory(2048)\n"
            "try:\n    bytearray(4 * 1024 ** 3)\nexcept MemoryError:\n    print('memout')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert out.stdout.strip() == "memout", out.stderr


def test_run_suite_records_each_run_in_its_own_process(tmp_path: Path):
    rows = benchmark.run_suite([kitchen_task()], ["landmark"], ["literal"], 30.0, jobs=1, memory_limit_mb=8192)
    assert [(r["status"], r["size"], r["excuse"]) for r in rows] == [("excuse-found", 1, "+(open pinkdrawer)")]
