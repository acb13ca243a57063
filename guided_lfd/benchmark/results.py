"""Result rows: their fields, their CSV file, and the row log that survives a crash."""

from __future__ import annotations

import csv
from pathlib import Path
from dataclasses import dataclass, fields
from typing import Any, Sequence



RESULT_FIELDS = [
    "id", "domain", "task", "removed_action", "semantics", "strategy", "status", "size", "cost",
    "wall_s", "exit_code", "time_s", "search_time_s", "candidates", "planner_calls", "expanded", "excuse",
]


SOLVED = ("excuse-found", "no-excuse")


#: Statuses of a run that gave up within its limits (counted at the limit in whole-run speed-ups).
GAVE_UP = ("timeout", "memout", "not-run")


@dataclass
class ResultRow:
    """One run of the benchmark (task, strategy, semantics): how it ended, what it found, its times and effort.

    Numbers are numbers (None where the run has none: a crashed run has no
    size); :meth:`from_csv` and :meth:`to_csv` are the CSV's text, an empty
    cell for None.
    """

    id: str
    domain: str
    task: str
    removed_action: str
    semantics: str
    strategy: str
    status: str = ""
    size: int | None = None
    cost: int | None = None
    wall_s: float | None = None  # the process as the shell sees it
    exit_code: int | None = None
    time_s: float | None = None  # the run's own clock
    search_time_s: float | None = None
    candidates: int | None = None
    planner_calls: int | None = None
    expanded: int | None = None
    excuse: str = ""  # the excuse's changes, or why there is none

    @property
    def key(self) -> tuple[str, str, str]:
        """(id, strategy, semantics): what a run is, in a resumed or merged run."""
        return self.id, self.strategy, self.semantics

    @classmethod
    def from_csv(cls, record: dict[str, str]) -> "ResultRow":
        """A row from a results CSV record (cells as text)."""
        values: dict[str, Any] = {}
        for f in fields(cls):
            text = record.get(f.name, "") or ""
            kind = _KINDS.get(f.name, str)
            values[f.name] = text if kind is str else (kind(text) if text != "" else None)
        return cls(**values)

    def to_csv(self) -> dict[str, str]:
        """The row as CSV cells, in :data:`RESULT_FIELDS` order."""
        return {name: "" if (value := getattr(self, name)) is None else str(value) for name in RESULT_FIELDS}


#: The numeric fields and their types (the rest are text).
_KINDS: dict[str, type] = {"size": int, "cost": int, "exit_code": int, "candidates": int, "planner_calls": int,
                           "expanded": int, "wall_s": float, "time_s": float, "search_time_s": float}


class RowLog:
    """Appends result rows to a CSV as they arrive, so a long run survives a crash.

    Rows already in the file are skipped when the run is started again (resume), but only those whose inputs
    are unchanged: ``inputs`` maps each task id to the digest of what its runs read and how they run (files'
    content, the tool's version, the limits; see :func:`~guided_lfd.benchmark.suite.input_digest`), kept in
    a file beside the log.  A row whose task's digest differs, or that no digest vouches for (a log from an
    older release), is dropped from the log and run again: a resumed run never reports a result computed
    from a file that has since been edited.
    """

    def __init__(self, path: Path, inputs: dict[str, str] | None = None) -> None:
        self.path = path
        self.inputs_path = path.with_name(path.name + ".inputs.json")
        self.inputs = dict(inputs or {})
        self.stale = 0  # rows dropped on resume because their inputs changed
        path.parent.mkdir(parents=True, exist_ok=True)
        self.rows: list[ResultRow] = []
        if path.exists():
            recorded = self._recorded_inputs()
            rows = read_results(path)
            self.rows = [r for r in rows if r.id in self.inputs and recorded.get(r.id) == self.inputs[r.id]]
            self.stale = len(rows) - len(self.rows)
            if self.stale:
                write_results(self.rows, path)
        else:
            with open(path, "w", newline="", encoding="utf-8") as fh:
                csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n").writeheader()
        self._write_inputs()
        self.done: set[tuple[str, str, str]] = {r.key for r in self.rows}

    def _recorded_inputs(self) -> dict[str, str]:
        """The digests the log's rows were computed from ({} where the file is missing or unreadable)."""
        import json

        try:
            doc = json.loads(self.inputs_path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return {}
        inputs = doc.get("inputs") if isinstance(doc, dict) else None
        return {str(k): str(v) for k, v in inputs.items()} if isinstance(inputs, dict) else {}

    def _write_inputs(self) -> None:
        import json

        from guided_lfd.io import write_text

        write_text(self.inputs_path, json.dumps({"format": 1, "inputs": self.inputs}, indent=1, sort_keys=True))

    def append(self, row: ResultRow) -> None:
        """Add ``row`` to the file (flushed: it survives the run)."""
        with open(self.path, "a", newline="", encoding="utf-8") as fh:
            csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n").writerow(row.to_csv())
            fh.flush()

    def remove(self) -> None:
        """Delete the log and its digests (the run is complete and its results written)."""
        self.path.unlink(missing_ok=True)
        self.inputs_path.unlink(missing_ok=True)


def merge_rows(kept: list[ResultRow], new: list[ResultRow]) -> list[ResultRow]:
    """``kept`` with each run of ``new`` (same id, strategy, semantics) replaced or added: a subset run's update."""
    fresh = {r.key: r for r in new}
    return [r for r in kept if r.key not in fresh] + list(fresh.values())


def write_results(rows: list[ResultRow], path: Path) -> None:
    """Results as CSV (one row per task, strategy and semantics)."""
    write_csv(path, RESULT_FIELDS, [row.to_csv() for row in rows])


def write_csv(path: Path, fields: Sequence[str], rows: list[dict], ignore_extra: bool = False) -> None:
    """``rows`` as a CSV with the columns ``fields``, written atomically (a benchmark's table of runs);
    ``ignore_extra``: keys beyond ``fields`` are left out instead of refused."""
    import io

    from guided_lfd.io import write_text

    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(fields), lineterminator="\n",
                            extrasaction="ignore" if ignore_extra else "raise")
    writer.writeheader()
    writer.writerows(rows)
    write_text(path, buf.getvalue())


def read_results(path: Path) -> list[ResultRow]:
    """Read a results CSV back.  A file without the runs' key columns, a row with another number of cells, an
    unknown status or a cell that is no number where one is expected (``nan``, ``-1`` seconds) is
    :class:`~guided_lfd.errors.InputFileError` at its line: a report drawn from it would mean nothing."""
    records = checked_records(path, _REQUIRED, "the results of 'guided-lfd bench run'", "results")
    return [_checked_row(record, where) for record, where in records]


def checked_records(path: Path, required: Sequence[str], expected: str, what: str) -> list[tuple[dict, Any]]:
    """The records of a CSV file (a spreadsheet's byte-order mark skipped), each with its Location.  A file
    missing or unreadable, without a ``required`` column, or with a row of another number of cells is
    :class:`~guided_lfd.errors.InputFileError` at its line (``expected`` says what the file should be, ``what``
    names it)."""
    from guided_lfd.errors import InputFileError, Location

    out = []
    try:
        with open(path, newline="", encoding="utf-8-sig") as fh:
            reader = csv.DictReader(fh)
            missing = [c for c in required if c not in (reader.fieldnames or [])]
            if missing:
                raise InputFileError(f"missing column(s) {', '.join(missing)} (expected {expected})",
                                     Location(str(path), 1))
            for record in reader:
                where = Location(str(path), reader.line_num)
                if None in record or None in record.values():
                    raise InputFileError(f"expected {len(reader.fieldnames or [])} cells in the row", where)
                out.append((record, where))
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise InputFileError(f"cannot read the {what} ({getattr(exc, 'strerror', None) or exc})",
                             Location(str(path))) from None
    return out


#: Columns a results CSV must have (the others may be missing: an empty cell).
_REQUIRED = ("id", "strategy", "semantics", "status")
#: Statuses a run can end with: the excuse document's, and the runner's own.
STATUSES = ("excuse-found", "already-solvable", "no-excuse", "no-excuse-within-size", "timeout", "memout",
            "not-run", "crashed")


def _checked_row(record: dict[str, str], where: Any) -> ResultRow:
    """``record`` as a row, each number a finite one (seconds and counts at least 0), the status a known one."""
    import math

    from guided_lfd.errors import InputFileError

    if record["status"] not in STATUSES:
        raise InputFileError(f"status {record['status']!r}: expected one of {', '.join(STATUSES)}", where)
    try:
        row = ResultRow.from_csv(record)
    except ValueError:
        bad = next(f for f, kind in _KINDS.items() if not _parses(record.get(f) or "", kind))
        raise InputFileError(f"{bad} {record[bad]!r}: expected {_EXPECTED[_KINDS[bad]]}", where) from None
    for name, kind in _KINDS.items():
        value = getattr(row, name)
        if value is not None and name != "exit_code" and (not math.isfinite(value) or value < 0):
            raise InputFileError(f"{name} {record[name]!r}: expected {_EXPECTED[kind]} (at least 0)", where)
    return row


_EXPECTED = {int: "a whole number", float: "a number"}


def _parses(text: str, kind: type) -> bool:
    try:
        text == "" or kind(text)
    except ValueError:
        return False
    return True
