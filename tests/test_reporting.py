"""guided_lfd.reporting: tables, the rounding rule, relative paths, figures, and plots without matplotlib."""

from __future__ import annotations

import csv
import io
import shutil
import sys
from pathlib import Path

import pytest

from conftest import ROOT
from guided_lfd import reporting
from guided_lfd.reporting import (
    FRACTION_DIGITS, PLOTS_HINT, PlotsUnavailable, csv_text, markdown_cell, markdown_table, plots_markdown, pyplot,
    relative_path, round_fraction, save_figure,
)


# -- rounding -----------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("value,rounded", [(2 / 3, 0.6667), (1 / 3, 0.3333), (7 / 9, 0.7778), (0.25, 0.25),
                                           (1.0, 1.0), (0.0, 0.0), (None, None)])
def test_fractions_are_rounded_to_four_digits(value, rounded):
    assert FRACTION_DIGITS == 4
    assert round_fraction(value) == rounded


def test_evaluate_and_the_study_round_by_the_one_rule():
    from guided_lfd import evaluate
    from guided_lfd.study import paper, report, run

    for module in (evaluate, paper, report, run):
        assert module.round_fraction is reporting.round_fraction
        assert not hasattr(module, "_round")
    misdirection = evaluate.Misdirection(bound=10, explored=3, complete=True, excuse_states=3, misdirected=1)
    assert misdirection.as_dict()["fraction"] == 0.3333


# -- relative paths -----------------------------------------------------------------------------------------------

def test_a_path_under_the_root_is_relative(tmp_path):
    (tmp_path / "data").mkdir()
    assert relative_path(tmp_path / "data" / "x.csv", tmp_path) == "data/x.csv"
    assert relative_path(str(tmp_path / "data" / "x.csv"), tmp_path) == "data/x.csv"
    assert relative_path(tmp_path, tmp_path) == "."


def test_a_path_outside_the_root_is_kept_as_given(tmp_path):
    (tmp_path / "root").mkdir()
    outside = str(tmp_path / "elsewhere" / ".." / "elsewhere" / "x.csv")
    assert relative_path(outside, tmp_path / "root") == outside
    assert relative_path(Path("/somewhere/else.pddl"), tmp_path / "root") == "/somewhere/else.pddl"


def test_relative_paths_resolve_symlinks(tmp_path):
    (tmp_path / "real" / "data").mkdir(parents=True)
    (tmp_path / "link").symlink_to(tmp_path / "real")
    assert relative_path(tmp_path / "link" / "data" / "x.csv", tmp_path / "real") == "data/x.csv"


# -- tables -------------------------------------------------------------------------------------------------------

def test_csv_text():
    text = csv_text(["a", "b", "c"], [[1, None, "x, y"], [0.5, "", 'say "hi"']])
    assert text == 'a,b,c\n1,,"x, y"\n0.5,,"say ""hi"""\n'
    assert list(csv.reader(io.StringIO(text)))[1] == ["1", "", "x, y"]
    assert csv_text(["only"], []) == "only\n"


@pytest.mark.parametrize("value,cell", [(None, "-"), ("", "-"), (0, "0"), (3, "3"), (0.6667, "0.667"),
                                        (3.71, "3.710"), ("yes", "yes"), (True, "True")])
def test_markdown_cells(value, cell):
    assert markdown_cell(value) == cell


def test_markdown_table():
    assert markdown_table(["kitchen", "f1", "note"], [["kitchen-1", 2 / 3, None], ["kitchen-2", 0.75, "ok"]]) == (
        "| kitchen | f1 | note |\n"
        "|---|---|---|\n"
        "| kitchen-1 | 0.667 | - |\n"
        "| kitchen-2 | 0.750 | ok |")
    assert markdown_table(["a"], []) == "| a |\n|---|"


def test_plots_section(tmp_path):
    plots = [tmp_path / "cactus.png", tmp_path / "sub" / "time.png"]
    assert plots_markdown(plots, tmp_path) == ["## Plots", "", "![cactus](cactus.png)", "![time](sub/time.png)"]
    assert plots_markdown(plots) == ["## Plots", "", "![cactus](cactus.png)", "![time](time.png)"]
    assert plots_markdown([]) == ["## Plots", ""]
    assert plots_markdown(None) == ["## Plots", "", f"Not drawn: {PLOTS_HINT}."]
    assert "plots need the plots extra" in PLOTS_HINT


# -- figures ------------------------------------------------------------------------------------------------------

def test_figures_are_saved_without_metadata_and_byte_identical(tmp_path):
    pytest.importorskip("matplotlib")
    plt = pyplot()
    paths = []
    for name in ("one.png", "two.png"):
        fig, ax = plt.subplots(figsize=(2, 2))
        ax.plot([0, 1], [1, 0])
        paths.append(save_figure(fig, tmp_path / name, 50))
        assert not plt.get_fignums()  # closed
    first, second = (p.read_bytes() for p in paths)
    assert first.startswith(b"\x89PNG") and first == second
    assert b"Software" not in first and b"matplotlib" not in first


# -- without matplotlib -------------------------------------------------------------------------------------------

@pytest.fixture
def no_matplotlib(monkeypatch):
    """Make ``import matplotlib`` fail, as without the plots extra (a None entry in sys.modules)."""
    for name in [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.")]:
        monkeypatch.delitem(sys.modules, name)
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)


def test_pyplot_without_matplotlib(no_matplotlib):
    with pytest.raises(PlotsUnavailable, match=r"plots need the plots extra: pip install 'guided-lfd\[plots\]'"):
        pyplot()
    assert issubclass(PlotsUnavailable, ImportError)


def test_both_plot_functions_raise_plots_unavailable(no_matplotlib, tmp_path):
    from guided_lfd.benchmark import plot as bench_plot
    from guided_lfd.study.report import plot as study_plot

    with pytest.raises(PlotsUnavailable):
        bench_plot([], tmp_path, 60.0)
    with pytest.raises(PlotsUnavailable):
        study_plot(None, [], tmp_path)  # type: ignore[arg-type]
    assert list(tmp_path.iterdir()) == []


def _pngs(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.rglob("*.png"))


def test_the_study_without_matplotlib_skips_its_plots_and_says_so(no_matplotlib, runner, app, tmp_path):
    result = runner.invoke(app, ["study", "--root", str(ROOT), "--out", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert [line for line in result.stderr.splitlines() if "plots" in line] == [f"plots skipped: {PLOTS_HINT}"]
    assert _pngs(tmp_path) == []
    md = (tmp_path / "study.md").read_text()
    assert md.endswith(f"## Plots\n\nNot drawn: {PLOTS_HINT}.\n")
    assert "![" not in md
    # The tables are written as usual.
    assert (tmp_path / "study-measures.csv").read_text() == (ROOT / "results" / "study-measures.csv").read_text()


def test_the_study_library_without_matplotlib(no_matplotlib, tmp_path):
    from guided_lfd.study import reproduce

    reproduce(ROOT, tmp_path)
    assert _pngs(tmp_path) == []
    assert f"Not drawn: {PLOTS_HINT}." in (tmp_path / "study.md").read_text()


def test_quiet_silences_the_skipped_plots_line(no_matplotlib, runner, app, tmp_path):
    result = runner.invoke(app, ["study", "--root", str(ROOT), "--out", str(tmp_path), "--quiet"])
    assert result.exit_code == 0 and result.stderr == ""


def test_the_benchmark_report_without_matplotlib_skips_its_plots_and_says_so(no_matplotlib, runner, app, tmp_path):
    results = tmp_path / "results"
    results.mkdir()
    shutil.copy(ROOT / "benchmarks" / "results" / "results.csv", results / "results.csv")
    result = runner.invoke(app, ["bench", "report", "--root", str(ROOT), "--results", str(results)])
    assert result.exit_code == 0, result.output
    assert result.stderr.splitlines() == [f"plots skipped: {PLOTS_HINT}"]
    assert _pngs(results) == []
    summary = (results / "summary.md").read_text()
    assert summary.endswith(f"## Plots\n\nNot drawn: {PLOTS_HINT}.\n")
    # Everything but the plots section is as with the plots drawn.
    from guided_lfd.benchmark import read_results, summary_markdown

    drawn = summary_markdown(read_results(results / "results.csv"), 60.0,
                             "python benchmarks/excuse_bench.py all --jobs 2",
                             [results / "cactus.png", results / "time_vs_size.png"], results)
    assert summary.split("## Plots")[0] == drawn.split("## Plots")[0]
    assert drawn.endswith("## Plots\n\n![cactus](cactus.png)\n![time_vs_size](time_vs_size.png)\n")
