"""Comparing the default strategy with the baseline: coverage, size agreement, whole-run and search speed-ups."""

from __future__ import annotations

import math
import statistics
from dataclasses import dataclass

from guided_lfd.benchmark.results import GAVE_UP, SOLVED, ResultRow


@dataclass
class Comparison:
    """Default strategy vs baseline on one semantics."""

    semantics: str
    tasks: int
    solved_default: int
    solved_baseline: int
    both: int
    median_speedup: float  # on search time (the engine; setup is shared)
    geomean_speedup: float
    median_total_speedup: float  # on wall time of the whole run
    size_mismatches: list[str]
    large_default: int  # tasks with excuse size >= 3 solved
    large_baseline: int
    nontrivial: int = 0  # tasks the baseline takes >= 1 s on, or does not finish (and one strategy solves)
    median_nontrivial_speedup: float = math.nan  # whole run, wall; an unfinished run counts at the limit


#: Search phases shorter than this (seconds) count as this long in speed-ups.
SEARCH_TIME_FLOOR = 1e-4


#: A task is non-trivial when the baseline's whole run takes at least this long (s) or does not finish.
NONTRIVIAL_S = 1.0


#: Suite parts by task name: the first suite (IPC task01-04 and the kitchens) and its growth.
FIRST_TASKS = ("task01", "task02", "task03", "task04", "problem")


def suite_part(row: ResultRow) -> str:
    """``first`` (IPC task01-04 and the kitchens, the 168 tasks of the first suite) or ``grown``."""
    return "first" if row.task in FIRST_TASKS else "grown"


def whole_run_s(row: ResultRow) -> float | None:
    """The run's whole wall time: ``wall_s`` (from outside the process), else ``time_s`` (older rows)."""
    return row.wall_s if row.wall_s is not None else row.time_s


#: The strategies a report may compare with the baseline: ``excuse``'s default, ``portfolio``, and ``landmark``,
#: the default of results from before it.
DEFAULT_STRATEGIES = ("portfolio", "landmark")


def default_strategy(rows: list[ResultRow]) -> str:
    """The :data:`DEFAULT_STRATEGIES` entry with the most runs in ``rows`` (the first on a tie): a subset run
    of one does not make the other's runs of the rest of the suite count as unsolved."""
    runs = {s: sum(r.strategy == s for r in rows) for s in DEFAULT_STRATEGIES}
    return max(DEFAULT_STRATEGIES, key=lambda s: (runs[s], -DEFAULT_STRATEGIES.index(s)))


def compare(rows: list[ResultRow], default: str | None = None, baseline: str = "baseline",
            time_limit: float = 60.0) -> list[Comparison]:
    """Coverage, speed-up and size agreement per semantics, and over both (a task in each semantics);
    ``default``: the strategy compared with ``baseline`` (None: :func:`default_strategy`)."""
    default = default or default_strategy(rows)
    semantics = sorted({r.semantics for r in rows})
    out = [_compare([r for r in rows if r.semantics == sem], sem, default, baseline, time_limit)
           for sem in semantics]
    if len(semantics) > 1:
        out.append(_compare(rows, "both", default, baseline, time_limit))
    return out


def search_speedup(default_row: ResultRow, baseline_row: ResultRow) -> float | None:
    """Baseline search time / default search time (None when a run has no search time)."""
    d, b = default_row.search_time_s, baseline_row.search_time_s
    if d is None or b is None:
        return None
    # Search times are recorded to the microsecond; below SEARCH_TIME_FLOOR
    # scheduling noise dominates, so shorter phases count as the floor.
    return max(b, SEARCH_TIME_FLOOR) / max(d, SEARCH_TIME_FLOOR)


def _compare(rows: list[ResultRow], label: str, default: str, baseline: str,
             time_limit: float = 60.0) -> Comparison:
    """Coverage, speed-up and size agreement over ``rows`` (``label``: a semantics, or "both")."""
    by_task: dict[str, dict[str, dict]] = {}
    for r in rows:
        key = r.id if label != "both" else f"{r.id} ({r.semantics})"
        by_task.setdefault(key, {})[r.strategy] = r
    solved_d = solved_b = large_d = large_b = 0
    ratios: list[float] = []
    total_ratios: list[float] = []
    nontrivial: list[float] = []
    mismatches: list[str] = []
    for tid, runs in sorted(by_task.items()):
        d, b = runs.get(default), runs.get(baseline)
        ok_d = d is not None and d.status in SOLVED
        ok_b = b is not None and b.status in SOLVED
        solved_d += ok_d
        solved_b += ok_b
        size = next((r.size for r in (d, b) if r is not None and r.status == "excuse-found"), None)
        if size is not None and size >= 3:
            large_d += ok_d
            large_b += ok_b
        if (ok_d or ok_b) and d is not None and b is not None:
            # A run that gave up counts at the limit; a crashed or failed one says nothing.
            d_wall = whole_run_s(d) if ok_d else time_limit if d.status in GAVE_UP else None
            b_wall = whole_run_s(b) if ok_b else time_limit if b.status in GAVE_UP else None
            if d_wall is not None and b_wall is not None and (not ok_b or b_wall >= NONTRIVIAL_S):
                nontrivial.append(b_wall / max(d_wall, 1e-4))
        if ok_d and ok_b:
            if (d.status, d.size) != (b.status, b.size):
                mismatches.append(f"{tid}: {default} {d.status} {d.size} vs {baseline} {b.status} {b.size}")
            total_ratios.append(whole_run_s(b) / max(whole_run_s(d), 1e-4))
            ratio = search_speedup(d, b)
            if ratio is not None:
                ratios.append(ratio)
    return Comparison(
        label, len(by_task), solved_d, solved_b, len(ratios),
        statistics.median(ratios) if ratios else math.nan,
        math.exp(statistics.fmean(math.log(r) for r in ratios)) if ratios else math.nan,
        statistics.median(total_ratios) if total_ratios else math.nan,
        mismatches, large_d, large_b, len(nontrivial),
        statistics.median(nontrivial) if nontrivial else math.nan,
    )


#: Excuse-size buckets of the speed-up table ("none" = proved that no excuse exists).
SIZE_BUCKETS = ("1", "2", "3-5", "6+", "none")


def size_bucket(row: ResultRow) -> str:
    """The :data:`SIZE_BUCKETS` entry of a solved result row."""
    if row.status != "excuse-found":
        return "none"
    size = row.size or 0
    return str(size) if size <= 2 else ("3-5" if size <= 5 else "6+")


#: Excuse sizes one by one, the last open-ended: the sizes-found table's columns.
SIZE_COUNTS = ("1", "2", "3", "4", "5", "6+")


def size_count_key(size: int) -> str:
    """The :data:`SIZE_COUNTS` column of an excuse of ``size`` changes."""
    return str(size) if size < 6 else "6+"


def speedups_by_size(rows: list[ResultRow], default: str | None = None,
                     baseline: str = "baseline") -> dict[str, dict[str, list[float]]]:
    """Search speed-ups on the tasks both strategies solve, per semantics and excuse-size bucket (``default``:
    None for :func:`default_strategy`)."""
    default = default or default_strategy(rows)
    runs: dict[tuple[str, str], dict[str, dict]] = {}
    for r in rows:
        runs.setdefault((r.id, r.semantics), {})[r.strategy] = r
    out: dict[str, dict[str, list[float]]] = {}
    for (_, sem), pair in sorted(runs.items()):
        d, b = pair.get(default), pair.get(baseline)
        if d is None or b is None or d.status not in SOLVED or b.status not in SOLVED:
            continue
        ratio = search_speedup(d, b)
        if ratio is not None:
            out.setdefault(sem, {}).setdefault(size_bucket(d), []).append(ratio)
    return out
