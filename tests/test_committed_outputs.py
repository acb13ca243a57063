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


def test_the_guided_teaching_table_is_regenerated_from_its_csv_and_is_the_one_the_docs_show():
    """benchmarks/teach_results/summary.md is what teach_bench.py makes from the committed teach.csv, its table
    has the header separator that makes it render as a table, and docs/commands.md shows the same table."""
    import sys

    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        import teach_bench
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    results = ROOT / "benchmarks" / "teach_results"
    rows = teach_bench.read_rows(results / "teach.csv")
    text = teach_bench.summary(rows, "python benchmarks/teach_bench.py --jobs 2")
    assert text + "\n![demonstrated actions](teach.png)\n" == (results / "summary.md").read_text()
    table = [line for line in text.splitlines() if line.startswith("|")]
    assert table[0].startswith("| task | robot | guided |") and table[1] == "|" + "---|" * 7
    assert all(line.count(" | ") == 6 for line in table[2:]), "a cell with a | in it would split the row"
    assert "\n".join(table) in (ROOT / "docs" / "commands.md").read_text()
