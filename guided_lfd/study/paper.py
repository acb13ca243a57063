"""The paper's own study data (Tables I and II, ``data/study``) and its headline figures."""

from __future__ import annotations

import csv

import statistics
from dataclasses import dataclass
from pathlib import Path

from guided_lfd.reporting import round_fraction




KITCHENS = ("kitchen-1", "kitchen-2")


KITCHEN_NAMES = {"kitchen-1": "Kitchen I", "kitchen-2": "Kitchen II"}


DEMONSTRATORS = ("P1", "P2", "P3", "P4", "P5")


#: The demonstrator whose complete demonstrations the paper's tool could not
#: process (parallel hand activities); the paper excludes them from sizes.
UNPROCESSED_BY_PAPER = "P3"


@dataclass
class PaperData:
    """Tables I and II as shipped in ``data/study``."""

    times: dict[tuple[str, str, str], float]  # (kitchen, demonstrator, excuse|complete) -> s
    printed_ratio: dict[str, float]  # Table I's bottom row, as printed
    sizes: dict[tuple[str, str], dict[str, int | None]]  # (kitchen, demonstrator) -> column -> value


def _rows(path: Path) -> list[dict[str, str]]:
    with open(path, encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


def load_paper_data(folder: Path) -> PaperData:
    """Read ``table1-*.csv`` and ``table2-*.csv`` from ``folder``."""
    times = {(r["kitchen"], r["demonstrator"], r["demonstration"]): float(r["time_s"])
             for r in _rows(folder / "table1-demonstration-time.csv")}
    ratio = {r["demonstrator"]: float(r["ratio"]) for r in _rows(folder / "table1-ratio.csv")}
    sizes = {}
    for r in _rows(folder / "table2-demonstration-size.csv"):
        sizes[(r["kitchen"], r["demonstrator"])] = {k: (int(v) if v else None) for k, v in r.items()
                                                    if k not in ("kitchen", "demonstrator")}
    return PaperData(times, ratio, sizes)


def time_ratios(times: dict[tuple[str, str, str], float]) -> dict[str, float]:
    """Per demonstrator: excuse-guided over complete time, both kitchens pooled (Table I's Ratio row)."""
    out = {}
    for p in DEMONSTRATORS:
        guided = sum(times[(k, p, "excuse")] for k in KITCHENS)
        complete = sum(times[(k, p, "complete")] for k in KITCHENS)
        out[p] = guided / complete
    return out


def size_reduction(observed: dict[tuple[str, str], tuple[int | None, int | None]], kitchen: str) -> float:
    """1 - mean over demonstrators (P3 excluded) of observed excuse size / observed complete size."""
    ratios = []
    for p in DEMONSTRATORS:
        if p == UNPROCESSED_BY_PAPER:
            continue
        excuse, complete = observed[(kitchen, p)]
        if excuse is None or not complete:
            continue
        ratios.append(excuse / complete)
    return 1 - statistics.fmean(ratios)


def headline(paper: PaperData) -> dict[str, float]:
    """The paper's headline figures, computed from the shipped tables as the paper describes."""
    printed = statistics.fmean(paper.printed_ratio[p] for p in DEMONSTRATORS)
    from_times = statistics.fmean(time_ratios(paper.times).values())
    observed = {key: (v["observed_minimal_excuse"], v["observed_goal"]) for key, v in paper.sizes.items()}
    return {
        # The paper's own figure at the paper's precision (its printed ratios have three digits): the one
        # value not rounded by guided_lfd.reporting.round_fraction.
        "mean_time_ratio": round(printed, 3),
        "less_time": round_fraction(1 - printed),  # 0.6148: "61% less time"
        "mean_time_ratio_from_times": round_fraction(from_times),
        **{f"size_reduction_{k}": round_fraction(size_reduction(observed, k)) for k in KITCHENS},
    }
