"""The paper's own study data (Tables I and II, ``data/study``) and its headline figures."""

from __future__ import annotations

import csv
import io
import statistics
from dataclasses import dataclass
from pathlib import Path

from guided_lfd.errors import InputFileError, Location
from guided_lfd.io import read_text
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


#: Each table's columns (as shipped in ``data/study``).
_COLUMNS = {
    "table1-demonstration-time.csv": ("kitchen", "demonstrator", "demonstration", "time_s"),
    "table1-ratio.csv": ("demonstrator", "ratio"),
    "table2-demonstration-size.csv": ("kitchen", "demonstrator", "predicted_minimal_excuse", "observed_minimal_excuse",
                                      "predicted_nonminimal_excuse", "predicted_goal", "observed_goal"),
}


def _rows(path: Path) -> list[tuple[Location, dict[str, str]]]:
    """The rows of one table, each with its place in the file; a column the table lacks is an input error."""
    columns = _COLUMNS[path.name]
    reader = csv.DictReader(io.StringIO(read_text(path, "a table of the paper's study (CSV)")))
    missing = [c for c in columns if c not in (reader.fieldnames or [])]
    if missing:
        raise InputFileError(f"no column '{missing[0]}' (expected the columns {', '.join(columns)})",
                             Location(str(path), 1))
    try:
        return [(Location(str(path), reader.line_num), row) for row in reader]
    except csv.Error as exc:
        raise InputFileError(f"not a CSV table ({exc})", Location(str(path), reader.line_num)) from None


def _number(row: dict[str, str], column: str, where: Location, kind: type = float):
    """The table's value in ``column`` (an empty cell is None where ``kind`` is int: Table II's blanks)."""
    text = (row.get(column) or "").strip()
    if not text and kind is int:
        return None
    try:
        return kind(text)
    except ValueError:
        expected = "a whole number or an empty cell" if kind is int else "a number"
        raise InputFileError(f"'{text}' in column {column} is not a number (expected {expected})", where) from None


def _require(found, wanted, path: Path, what: str) -> None:
    """Every key of ``wanted`` has a row (the study needs each kitchen and demonstrator the paper has)."""
    for key in wanted:
        if key not in found:
            raise InputFileError(f"no row for {' '.join(key) if isinstance(key, tuple) else key} (expected {what}: "
                                 f"kitchens {', '.join(KITCHENS)}, demonstrators {', '.join(DEMONSTRATORS)})",
                                 Location(str(path)))


def load_paper_data(folder: Path) -> PaperData:
    """Read ``table1-*.csv`` and ``table2-*.csv`` from ``folder``; a table without a row the study needs, or with a
    value that is not a number, is an :class:`~guided_lfd.errors.InputFileError` naming the file (and line)."""
    path = folder / "table1-demonstration-time.csv"
    times = {(r["kitchen"], r["demonstrator"], r["demonstration"]): _number(r, "time_s", where)
             for where, r in _rows(path)}
    _require(times, [(k, p, kind) for k in KITCHENS for p in DEMONSTRATORS for kind in ("excuse", "complete")], path,
             "a time for each kitchen, demonstrator and demonstration")
    path = folder / "table1-ratio.csv"
    ratio = {r["demonstrator"]: _number(r, "ratio", where) for where, r in _rows(path)}
    _require(ratio, DEMONSTRATORS, path, "a ratio for each demonstrator")
    path = folder / "table2-demonstration-size.csv"
    sizes = {}
    for where, r in _rows(path):
        sizes[(r["kitchen"], r["demonstrator"])] = {k: _number(r, k, where, int) for k in _COLUMNS[path.name][2:]}
    _require(sizes, [(k, p) for k in KITCHENS for p in DEMONSTRATORS], path, "sizes for each kitchen and demonstrator")
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
