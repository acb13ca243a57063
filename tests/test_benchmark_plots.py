"""The household scaling and guided-teaching plots, drawn from their committed results without running anything."""

from __future__ import annotations

import shutil

import pytest

from conftest import ROOT, load_script, record_figures


@pytest.fixture(scope="module")
def scaling():
    return load_script(ROOT / "benchmarks" / "household" / "scaling.py", "scaling_under_test")


@pytest.fixture(scope="module")
def teach():
    return load_script(ROOT / "benchmarks" / "teach_bench.py", "teach_bench_under_test")


def test_the_scaling_report_draws_one_line_per_variant_strategy_and_semantics(scaling, monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    drawn = record_figures(monkeypatch, scaling)
    results = ROOT / "benchmarks" / "household" / "results"
    rows = scaling.read_csv(results / "scaling.csv")
    # The markdown stays what is committed: only the picture changes with the plot.
    assert scaling.report(rows, 60.0, tmp_path) == (results / "scaling.md").read_text()
    axes = drawn["scaling.png:axes"]
    assert [ax.get_title() for ax in axes] == ["robot cannot push obstacles aside (no-push)",
                                               "robot cannot open drawers (no-open)"]
    for ax, variant in zip(axes, scaling.VARIANTS):
        sizes = {int(r["ground_actions"]) for r in rows if r["variant"] == variant}
        lines = [line for line in ax.get_lines() if not line.get_label().startswith("_")]
        names = ("baseline (the paper's method)", "portfolio (default)", "symbolic")
        assert sorted(line.get_label() for line in lines) == [
            f"{name}, {se} semantics" for name in names for se in ("consistent", "literal")]
        assert len({(line.get_color(), line.get_linestyle()) for line in lines}) == 6
        for line in lines:  # only this variant's tasks, left to right: no zigzag between variants
            xs = list(line.get_xdata())
            assert set(xs) <= sizes and xs == sorted(set(xs))
    unfinished = [line for line in axes[0].get_lines() if line.get_marker() == "v" and len(line.get_xdata())]
    assert unfinished and all(line.get_linestyle() == "None" for line in unfinished)
    legend = [t.get_text() for t in drawn["scaling.png"].legends[0].get_texts()]
    assert legend[-2:] == ["not finished within the limit (the baseline is not run on larger tasks)",
                           "time limit (60 s per run)"]


def test_the_teach_plot_spells_out_its_task_names(teach, monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    drawn = record_figures(monkeypatch, teach)
    out = tmp_path / "out"
    out.mkdir()
    shutil.copy(ROOT / "benchmarks" / "teach_results" / "teach.csv", out)
    assert teach.main(["--plot-only", "--out", str(out)]) == 0  # no runs: only the picture
    assert sorted(p.name for p in out.iterdir()) == ["teach.csv", "teach.png"]
    fig, (ax,) = drawn["teach.png"], drawn["teach.png:axes"]
    labels = [t.get_text() for t in ax.get_yticklabels()]
    assert labels[:3] == ["Kitchen I: robot cannot open drawers", "Kitchen II: robot cannot move the chair",
                          "Kitchen II: robot cannot open drawers or move the chair"]
    assert labels.index("r4-i8-d8-c4-g2: robot cannot open drawers") < labels.index(
        "r4-i16-d16-c4-g2: robot cannot open drawers")  # houses by size, not by spelling
    assert not any(label.startswith("house-") for label in labels)
    assert fig.get_supxlabel() == (
        "House tasks are named r<rooms>-i<items>-d<drawers>-c<cupboards>-g<goals>:\n"
        "e.g. r8-i32-d32-c8-g4 has 8 rooms, 32 items, 32 drawers, 8 cupboards, 4 goals (items to put into a goal "
        "container).")
    assert [len(bars) for bars in ax.containers] == [len(labels)] * 3
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [label for *_, label in teach.CONFIGS]
    assert all(float(x).is_integer() for x in ax.get_xticks())


def test_house_names_give_back_their_sizes():
    from guided_lfd.benchmark import household

    house = household.House(4, 16, 4, 1, 2, "no-open")
    assert household.name_sizes(house.name) == ((4, 16, 16, 4, 2), "no-open")
    assert household.name_sizes("kitchen-1") is None
    assert len(household.NAME_PARTS) == 5 and set(household.VARIANT_TEXT) == set(household.VARIANTS)
