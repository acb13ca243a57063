"""Result rows: their fields, their CSV file, and the row log that survives a crash."""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Any



RESULT_FIELDS = [
    "id", "domain", "task", "removed_action", "semantics", "strategy", "status", "size", "cost",
    "wall_s", "exit_code", "time_s", "search_time_s", "candidates", "planner_calls", "expanded", "excuse",
]


SOLVED = ("excuse-found", "no-excuse")


#: Statuses of a run that gave up within its limits (counted at the limit in whole-run speed-ups).
GAVE_UP = ("timeout", "memout", "not-run")


def _complete(row: dict[str, Any]) -> dict[str, Any]:
    for key in RESULT_FIELDS:
        row.setdefault(key, "")
    return {k: row[k] for k in RESULT_FIELDS}


class RowLog:
    """Appends result rows to a CSV as they arrive, so a long run survives a crash.

    Rows already in the file are skipped when the run is started again (resume).
    """

    def __init__(self, path: Path) -> None:
        self.path = path
        path.parent.mkdir(parents=True, exist_ok=True)
        self.rows: list[dict[str, Any]] = []
        if path.exists():
            self.rows = read_results(path)
        else:
            with open(path, "w", newline="", encoding="utf-8") as fh:
                csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n").writeheader()
        self.done: set[tuple[str, str, str]] = {(r["id"], r["strategy"], r["semantics"]) for r in self.rows}

    def append(self, row: dict[str, Any]) -> None:
        with open(self.path, "a", newline="", encoding="utf-8") as fh:
            csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n", extrasaction="ignore").writerow(row)
            fh.flush()


def merge_rows(kept: list[dict[str, Any]], new: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """``kept`` with each run of ``new`` (same id, strategy, semantics) replaced or added: a subset run's update."""
    key = lambda r: (r["id"], r["strategy"], r["semantics"])  # noqa: E731
    fresh = {key(r): r for r in new}
    return [r for r in kept if key(r) not in fresh] + list(fresh.values())


def write_results(rows: list[dict[str, Any]], path: Path) -> None:
    """Results as CSV (one row per task, strategy and semantics)."""
    import io

    from guided_lfd.io import write_text

    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=RESULT_FIELDS, lineterminator="\n", extrasaction="ignore")
    writer.writeheader()
    writer.writerows(rows)
    write_text(path, buf.getvalue())


def read_results(path: Path) -> list[dict[str, Any]]:
    """Read a results CSV back."""
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))
