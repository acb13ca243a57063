"""The reproduced user study: the paper's headline figures, the chain's results, determinism."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from conftest import ROOT, record_figures
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


def test_the_study_plots_name_their_marks_and_leave_p3_out(study, monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    import math

    from guided_lfd.study import report

    _, paper, kitchens = study
    drawn = record_figures(monkeypatch, report)
    assert [p.name for p in report.plot(paper, kitchens, tmp_path)] == ["study-time.png", "study-sizes.png"]
    time_axes = drawn["study-time.png:axes"]
    assert [t.get_text() for t in time_axes[0].get_legend().get_texts()] == [
        "excuse demonstration (guided), paper", "complete demonstration, paper",
        "rendered trace (reproduced), either demonstration"]
    assert time_axes[0].get_ylabel() == "demonstration time (s)"
    sizes = drawn["study-sizes.png:axes"]
    assert [ax.get_ylabel().split(":")[0] for ax in sizes[::2]] == ["P", "O"]
    assert [t.get_text() for t in drawn["study-sizes.png"].legends[0].get_texts()] == [
        label for *_, label in report.SIZE_BARS]
    for ax, (kitchen, row) in zip(sizes, [(k, row) for row in ("P", "O") for k in kitchens]):
        assert ax.get_lines() == []  # bars only: nothing joins two demonstrators
        assert [len(bars) for bars in ax.containers] == [5, 5, 5, 5]  # four bars per demonstrator
        assert all(float(y).is_integer() for y in ax.get_yticks())
        # The reproduced bar stands beside the paper's, not behind it.
        xs = [[bar.get_x() for bar in bars] for bars in ax.containers]
        assert all(len({group[p] for group in xs}) == 4 for p in range(5))
        reproduced_goal = [bar.get_height() for bar in ax.containers[3]]
        expected = ([d.predicted["goal"] for d in kitchen.demonstrators] if row == "P"
                    else [d.demos["complete"].demonstrated_actions for d in kitchen.demonstrators])
        assert reproduced_goal == expected
    for ax in sizes[2:]:  # the paper has no O(G) for P3: no bar, and the gap says so
        paper_goal = [bar.get_height() for bar in ax.containers[2]]
        assert math.isnan(paper_goal[2]) and not any(math.isnan(y) for y in paper_goal[:2] + paper_goal[3:])
        assert [t.get_text() for t in ax.texts if "paper" in t.get_text()] == ["P3: no paper value"]


def test_the_benchmark_plots_label_the_limit_the_time_and_whole_sizes(monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    from guided_lfd.benchmark import read_results
    from guided_lfd.benchmark import report

    drawn = record_figures(monkeypatch, report)
    rows = read_results(ROOT / "benchmarks" / "results" / "results.csv")
    first = [p.read_bytes() for p in report.plot(rows, tmp_path / "one", 60.0)]
    cactus = drawn["cactus.png:axes"][0]
    legend = [t.get_text() for t in cactus.get_legend().get_texts()]
    assert "time limit (60 s per run)" in legend
    assert "whole run" in cactus.get_ylabel() and "whole-run" in cactus.get_title()
    # One line per strategy and semantics, each told apart by its colour and line style.
    series = [line for line in cactus.get_lines() if not line.get_label().startswith("time limit")]
    assert sorted(line.get_label() for line in series) == sorted(label for label in legend
                                                                 if not label.startswith("time limit"))
    assert len(series) == 4 and len({(line.get_color(), line.get_linestyle()) for line in series}) == 4
    for ax in drawn["time_vs_size.png:axes"]:
        assert ax.get_xlabel().startswith("minimal excuse size")
        assert all(float(x).is_integer() for x in ax.get_xticks())
    assert [p.read_bytes() for p in report.plot(rows, tmp_path / "two", 60.0)] == first  # deterministic


def test_a_small_cactus_plot_ticks_whole_tasks(monkeypatch, tmp_path):
    """Two solved tasks: matplotlib's own ticks would stand at 0.5, 1.5, ... tasks."""
    pytest.importorskip("matplotlib")
    from guided_lfd.benchmark import ResultRow
    from guided_lfd.benchmark import report

    drawn = record_figures(monkeypatch, report)
    rows = [ResultRow(tid, "d", "t", "a", "literal", strategy, "excuse-found", size=1, time_s=t)
            for tid, t in (("t1", 0.2), ("t2", 0.4)) for strategy in ("landmark", "baseline")]
    report.plot(rows, tmp_path, 60.0)
    cactus = drawn["cactus.png:axes"][0]
    ticks = [x for x in cactus.get_xticks() if cactus.get_xlim()[0] <= x <= cactus.get_xlim()[1]]
    assert len(ticks) >= 2 and all(float(x).is_integer() for x in ticks)
