"""The reproduced user study: the paper's headline figures, the chain's results, determinism."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from conftest import ROOT
from guided_lfd.study import headline, load_paper_data, reproduce, size_reduction, time_ratios


@pytest.fixture(scope="module")
def paper():
    return load_paper_data(ROOT / "data" / "study")


def test_headline_figures_from_the_shipped_tables(paper):
    h = headline(paper)
    assert h["mean_time_ratio"] == 0.385  # the mean of Table I's printed Ratio row
    assert round(h["less_time"] * 100) == 61
    assert h["mean_time_ratio_from_times"] == pytest.approx(0.3843, abs=1e-4)
    assert round(h["size_reduction_kitchen-1"] * 100) == 68
    assert round(h["size_reduction_kitchen-2"] * 100) == 77


def test_table_one_ratio_row_follows_from_its_times(paper):
    recomputed = time_ratios(paper.times)
    for p, printed in paper.printed_ratio.items():
        assert recomputed[p] == pytest.approx(printed, abs=0.005)


def test_size_reduction_excludes_p3():
    observed = {("k", p): (1, 2) for p in ("P1", "P2", "P4", "P5")}
    observed[("k", "P3")] = (100, 1)
    assert size_reduction(observed, "k") == 0.5


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    out = tmp_path_factory.mktemp("study")
    paper, kitchens = reproduce(ROOT, out)
    return out, paper, kitchens


def test_solvability_after_demonstration_holds_for_everyone(study):
    _, _, kitchens = study
    assert [(k.kitchen, d.demonstrator) for k in kitchens for d in k.demonstrators
            if not d.solvable_after_excuse_demo] == []
    assert {d.excuse_on_merged for k in kitchens for d in k.demonstrators} == {"already-solvable"}


def test_observed_sizes_are_recovered_and_predictions_are_planned(study):
    _, paper, kitchens = study
    for k in kitchens:
        for d in k.demonstrators:
            row = paper.sizes[(k.kitchen, d.demonstrator)]
            assert d.demos["excuse"].demonstrated_actions == row["observed_minimal_excuse"]
            if row["observed_goal"] is not None:
                assert d.demos["complete"].demonstrated_actions == row["observed_goal"]
            # Planned on the learned domains: the excuse is one action away.
            assert d.predicted["minimal_excuse"] == 1
    assert [k.excuse for k in kitchens] == [["+(open pinkdrawer)"], ["+(clear pinkdrawer)"]]


def test_study_report_and_files(study):
    out, _, _ = study
    md = (out / "study.md").read_text()
    assert "| mean time ratio, guided / complete (Table I) | 0.385 (61% less time) | 0.385" in md
    assert "holds for every demonstrator and both kitchens" in md
    tables = {name: list(csv.DictReader(open(out / name, encoding="utf-8")))
              for name in ("study-time.csv", "study-size.csv", "study-measures.csv")}
    # 2 kitchens x 5 demonstrators (x 2 demonstrations for the times).
    assert [len(rows) for rows in tables.values()] == [20, 10, 10]
    assert tables["study-time.csv"][0] == {"kitchen": "kitchen-1", "demonstrator": "P1", "demonstration": "excuse",
                                           "paper_time_s": "3.71", "reproduced_time_s": "3.7"}
    assert {r["excuse_on_merged_domain"] for r in tables["study-measures.csv"]} == {"already-solvable"}
    doc = json.loads((out / "study.json").read_text())
    assert (doc["format"], doc["format_version"]) == ("guided-lfd/study", 1)
    assert doc["reproduced"]["size_reduction_kitchen-1"] == pytest.approx(0.677, abs=1e-3)
    assert [k["excuse"] for k in doc["kitchens"]] == [["+(open pinkdrawer)"], ["+(clear pinkdrawer)"]]
    learned = (out / "study" / "kitchen-1" / "P1-excuse.learned.pddl").read_text()
    assert learned.startswith(";; Learned by guided-lfd from data/demos/kitchen-1/P1-excuse.csv")


def test_the_study_subcommand_writes_what_reproduce_writes(study, runner, app, tmp_path):
    out, _, _ = study
    result = runner.invoke(app, ["study", "--root", str(ROOT), "--out", str(tmp_path), "--quiet"])
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines()[1].startswith("mean time ratio (guided / complete)")
    assert _files(tmp_path) == _files(out)


def _files(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def test_study_is_deterministic(study, tmp_path):
    out, _, _ = study
    reproduce(ROOT, tmp_path)
    first, second = _files(out), _files(tmp_path)
    assert sorted(first) == sorted(second)
    assert [name for name in first if first[name] != second[name]] == []


def test_the_committed_results_are_what_the_study_writes(study):
    """results/ is regenerated with the code: every file but the PNGs (their bytes depend on the matplotlib
    version) is byte-identical to a fresh run."""
    out, _, _ = study
    fresh, committed = _files(out), _files(ROOT / "results")
    assert sorted(fresh) == sorted(committed)
    assert [name for name in fresh if not name.endswith(".png") and fresh[name] != committed[name]] == []


def _figures(monkeypatch, module) -> dict[str, object]:
    """Draw with ``module.save_figure`` recording each figure by file name (and still saving it)."""
    drawn = {}
    save = module.save_figure

    def record(fig, path, dpi):
        drawn[path.name] = fig
        axes = fig.axes  # kept for inspection: save_figure closes the figure, not its artists
        drawn[path.name + ":axes"] = axes
        return save(fig, path, dpi)

    monkeypatch.setattr(module, "save_figure", record)
    return drawn


def test_the_study_plots_name_their_marks_and_leave_p3_out(study, monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    import math

    from guided_lfd.study import report

    _, paper, kitchens = study
    drawn = _figures(monkeypatch, report)
    assert [p.name for p in report.plot(paper, kitchens, tmp_path)] == ["study-time.png", "study-sizes.png"]
    time_axes = drawn["study-time.png:axes"]
    assert [t.get_text() for t in time_axes[0].get_legend().get_texts()] == [
        "excuse demonstration (guided), paper", "complete demonstration, paper",
        "rendered trace (reproduced), either demonstration"]
    assert time_axes[0].get_ylabel() == "demonstration time (s)"
    sizes = drawn["study-sizes.png:axes"]
    assert sizes[0].get_ylabel() == "size (planning actions)"
    assert [t.get_text() for t in sizes[1].get_legend().get_texts()] == [
        "paper (Table II)", "reproduced (planned on the learned domains)"]
    names = [t.get_text() for t in sizes[0].get_legend().get_texts()]
    assert names[3] == "O(G): observed, complete demonstration"
    for ax in sizes:  # the paper's O(G) line has a gap at P3, not a segment from P2 to P4
        og = [line for line in ax.get_lines() if line.get_marker() == "d"]
        assert len(og) == 1
        ys = list(og[0].get_ydata())
        assert math.isnan(ys[2]) and not any(math.isnan(y) for y in ys[:2] + ys[3:])
        assert any(t.get_text() == "P3: no paper value" for t in ax.texts)


def test_the_benchmark_plots_label_the_limit_the_time_and_whole_sizes(monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    from guided_lfd.benchmark import read_results
    from guided_lfd.benchmark import report

    drawn = _figures(monkeypatch, report)
    rows = read_results(ROOT / "benchmarks" / "results" / "results.csv")
    first = [p.read_bytes() for p in report.plot(rows, tmp_path / "one", 60.0)]
    cactus = drawn["cactus.png:axes"][0]
    assert "time limit (60 s per run)" in [t.get_text() for t in cactus.get_legend().get_texts()]
    assert "whole run" in cactus.get_ylabel() and "whole-run" in cactus.get_title()
    for ax in drawn["time_vs_size.png:axes"]:
        assert ax.get_xlabel().startswith("minimal excuse size")
        assert all(float(x).is_integer() for x in ax.get_xticks())
    assert [p.read_bytes() for p in report.plot(rows, tmp_path / "two", 60.0)] == first  # deterministic
