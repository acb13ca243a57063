"""Committed outputs are what the code makes: a restructure that changed one would show here."""

from __future__ import annotations

import shutil

from conftest import ROOT


def test_the_benchmark_summary_is_regenerated_byte_for_byte_from_its_csv(tmp_path):
    from guided_lfd import benchmark

    results = tmp_path / "results"
    shutil.copytree(ROOT / "benchmarks" / "results", results)
    rows = benchmark.read_results(results / "results.csv")
    plots = benchmark.plot(rows, results, 60.0)
    text = benchmark.summary_markdown(rows, 60.0, "python benchmarks/excuse_bench.py all --jobs 2", plots, results)
    assert text == (ROOT / "benchmarks" / "results" / "summary.md").read_text()
