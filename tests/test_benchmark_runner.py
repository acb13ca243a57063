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


def printed_by(code: str) -> list[str]:
    """Words a fresh interpreter prints running ``code`` (limits must not leak into the test process)."""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert out.returncode == 0, out.stderr
    return out.stdout.split()


def test_memory_limit_caps_the_soft_limit_and_a_huge_allocation_fails():
    code = ("import resource\nfrom guided_lfd.benchmark import limit_memory\n"
            "limit_memory(2048)\n"
            "print(resource.getrlimit(resource.RLIMIT_AS)[0] == 2048 * 2 ** 20)\n"
            "try:\n    bytearray(4 * 1024 ** 3)\nexcept MemoryError:\n    print('memout')\n")
    assert printed_by(code) == ["True", "memout"]


def test_memory_limit_stays_below_a_hard_limit_already_in_force():
    code = ("import resource\nfrom guided_lfd.benchmark import limit_memory\n"
            "resource.setrlimit(resource.RLIMIT_AS, (3 * 2 ** 30, 3 * 2 ** 30))\n"
            "limit_memory(8192)\n"
            "print(resource.getrlimit(resource.RLIMIT_AS) == (3 * 2 ** 30, 3 * 2 ** 30))\n")
    assert printed_by(code) == ["True"]


def test_a_process_that_dies_is_recorded_as_crashed_with_its_exit_code(monkeypatch):
    import os

    def dies(*args, **kwargs):
        os._exit(3)

    monkeypatch.setattr(benchmark, "run_one", dies)  # the forked child sees the patched module
    rows = benchmark.run_suite([kitchen_task()], ["landmark"], ["literal"], 30.0, jobs=1)
    assert [(r["status"], r["excuse"]) for r in rows] == [("crashed", "process ended with exit code 3")]


def test_memout_during_invariant_synthesis_stays_a_memout(monkeypatch):
    from fast_downward.translate import invariant_finder

    def exhausted(*args, **kwargs):
        raise MemoryError

    monkeypatch.setattr(invariant_finder, "find_invariants", exhausted)
    assert run_one(kitchen_task(), "landmark", "consistent", 5.0)["status"] == "memout"


def test_run_suite_records_each_run_in_its_own_process(tmp_path: Path):
    rows = benchmark.run_suite([kitchen_task()], ["landmark"], ["literal"], 30.0, jobs=1, memory_limit_mb=8192)
    assert [(r["status"], r["size"], r["excuse"]) for r in rows] == [("excuse-found", 1, "+(open pinkdrawer)")]
