"""The benchmark summary: markdown tables and plots from the result rows."""

from __future__ import annotations

import statistics
from pathlib import Path
from typing import Any

from guided_lfd.benchmark.results import SOLVED, ResultRow
from guided_lfd.benchmark.analysis import (NONTRIVIAL_S, SIZE_BUCKETS, SIZE_COUNTS, Comparison, compare,
                                           default_strategy, speedups_by_size, size_count_key, suite_part,
                                           whole_run_s)
from guided_lfd.reporting import markdown_table, plots_markdown, pyplot, save_figure

#: Resolution of the benchmark's PNG plots.
DPI = 120

#: How every benchmark plot draws a strategy (colour, marker, legend name); one colour per strategy in all plots.
STRATEGY_STYLE: dict[str, tuple[str, str, str]] = {
    "portfolio": ("tab:green", "s", "portfolio (default)"),
    "landmark": ("tab:orange", "o", "landmark"),
    "symbolic": ("tab:purple", "^", "symbolic"),
    "baseline": ("tab:blue", "x", "baseline (the paper's method)"),
}

#: How every benchmark plot draws a semantics (line style): one line per (strategy, semantics), told apart.
SEMANTICS_STYLE: dict[str, str] = {"literal": "-", "consistent": "--"}


def strategy_style(strategy: str) -> tuple[str | None, str, str]:
    """(colour, marker, name) of a strategy: a strategy without a style of its own gets matplotlib's next colour
    and a plain marker, under its own name."""
    return STRATEGY_STYLE.get(strategy, (None, ".", strategy))


def series_style(strategy: str, semantics: str) -> dict[str, str | None]:
    """Keyword arguments for the line of one (strategy, semantics) series: colour, marker, line style, label.

    A strategy or semantics without a style of its own gets matplotlib's next colour, a plain marker and a
    dotted line, still under its own name.
    """
    colour, marker, name = strategy_style(strategy)
    return {"color": colour, "marker": marker, "linestyle": SEMANTICS_STYLE.get(semantics, ":"),
            "label": f"{name}, {semantics} semantics"}


def plot(rows: list[ResultRow], folder: Path, time_limit: float) -> list[Path]:
    """Cactus plot and time-vs-size plot as PNG files (:class:`~guided_lfd.reporting.PlotsUnavailable` without
    matplotlib: the caller skips them and passes ``plots=None`` to :func:`summary_markdown`)."""
    plt = pyplot()
    folder.mkdir(parents=True, exist_ok=True)
    return [_cactus(plt, rows, folder / "cactus.png", time_limit), _time_vs_size(plt, rows, folder / "time_vs_size.png")]


def _cactus(plt: Any, rows: list[ResultRow], path: Path, time_limit: float) -> Path:
    """Per (strategy, semantics), one step line: the n-th fastest solved task's whole-run time against n."""
    from matplotlib.ticker import MaxNLocator

    fig, ax = plt.subplots(figsize=(6.8, 5.0))
    for st, se in sorted({(r.strategy, r.semantics) for r in rows}):
        times = sorted(whole_run_s(r) for r in rows
                       if r.strategy == st and r.semantics == se and r.status in SOLVED)
        style = series_style(st, se)
        del style["marker"]  # hundreds of steps: markers would hide the line
        ax.step(range(1, len(times) + 1), times, where="post", **style)
    ax.set_yscale("log")
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))  # tasks are counted: no tick at 1.5 tasks
    ax.set_xlabel("tasks solved (fastest first)")
    # whole_run_s: the time the summary's "whole run" columns use (not the search phase alone).
    ax.set_ylabel("whole run per task (s, log scale)")
    ax.axhline(time_limit, color="grey", lw=0.8, ls=":", label=f"time limit ({time_limit:g} s per run)")
    ax.set_title("Cactus plot: whole-run time of the solved tasks\n(further right = more tasks solved; "
                 "lower = faster)", fontsize=10)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)  # below: not over the lines
    return save_figure(fig, path, DPI)


def _time_vs_size(plt: Any, rows: list[ResultRow], path: Path) -> Path:
    """A panel per semantics: each found excuse's whole-run time against its size, a marker per strategy."""
    from matplotlib.ticker import MaxNLocator

    fig, axes = plt.subplots(1, 2, figsize=(9, 4.0), sharey=True)
    for ax, se in zip(axes, sorted({r.semantics for r in rows})):
        for st in sorted({r.strategy for r in rows}):
            pts = [(r.size, whole_run_s(r)) for r in rows
                   if r.strategy == st and r.semantics == se and r.status == "excuse-found"]
            if pts:
                xs, ys = zip(*pts)
                colour, marker, name = strategy_style(st)
                ax.scatter(xs, ys, marker=marker, color=colour, alpha=0.6, label=name)
        ax.set_yscale("log")
        ax.set_xlabel("minimal excuse size (changes)")
        ax.xaxis.set_major_locator(MaxNLocator(integer=True, steps=[1, 2, 5, 10]))
        ax.set_title(f"{se} semantics")
        ax.legend(fontsize=8)
    axes[0].set_ylabel("whole run (s, log scale)")
    fig.suptitle("Whole-run time vs minimal excuse size (one mark per run that found an excuse)")
    return save_figure(fig, path, DPI)


def _parts_table(rows: list[ResultRow], default: str) -> list[str]:
    """Default coverage per suite part (the first 168 tasks, the grown ones) and semantics."""
    parts = sorted({suite_part(r) for r in rows})
    if parts == ["first"]:
        return []
    out = ["", "## Coverage by suite part", "",
           "*first*: IPC task01-04 and the kitchens (the smaller tasks); *grown*: IPC task05-10.", ""]
    table = []
    for part in parts:
        for se in sorted({r.semantics for r in rows}):
            sub = [r for r in rows if suite_part(r) == part and r.semantics == se]
            n = len({r.id for r in sub})
            lm = sum(r.status in SOLVED for r in sub if r.strategy == default)
            bl = sum(r.status in SOLVED for r in sub if r.strategy == "baseline")
            skipped = sum(r.status == "not-run" for r in sub if r.strategy == "baseline")
            table.append([part, se, n, f"{lm} ({100 * lm / max(n, 1):.1f}%)", f"{bl} ({100 * bl / max(n, 1):.1f}%)",
                          skipped])
    out.append(markdown_table(["part", "semantics", "tasks", f"solved: {default}", "solved: baseline",
                               "baseline not run"], table))
    return out


def limit_section(runs: list[tuple[float, str, str]], time_limit: float) -> list[str]:
    """Markdown lines: how far whole runs went past the time limit (``--time-limit`` bounds the whole run).

    ``runs``: each run's (whole wall time, name, status); the household series has its own rows.
    """
    if not runs:
        return []
    worst, worst_name, worst_status = max(runs, key=lambda run: run[0])
    over = [run for run in runs if run[0] > time_limit + 1.0]
    out = ["", "## Time limit", "",
           f"Runs: {len(runs)}; longest whole run {worst:.2f} s ({worst_name}: {worst_status}), "
           f"{worst - time_limit:+.2f} s against the {time_limit:g} s limit; runs more than 1 s past it: {len(over)}."]
    out += [f"- {name}: {wall:.2f} s ({status})" for wall, name, status in over]
    return out


def _limit_section(rows: list[ResultRow], time_limit: float) -> list[str]:
    out = limit_section([(r.wall_s, f"{r.id} {r.strategy} {r.semantics}", r.status) for r in rows
                         if r.wall_s is not None], time_limit)
    skipped = sum(r.status == "not-run" for r in rows)
    if skipped:
        out += ["", f"Runs not made: {skipped}. A baseline run is not made on the later tasks of a family "
                "(domain, removed action, semantics) after the first task of that family it does not finish "
                "(tasks in order, as in the household series); such a run counts as unsolved at the limit."]
    return out


def summary_markdown(rows: list[ResultRow], time_limit: float, command: str, plots: list[Path] | None,
                     base: Path) -> str:
    """The markdown summary: coverage table, speed-ups, agreement, plots (None: skipped, the section says so)."""
    default = default_strategy(rows)  # counted once: every section compares the same strategy
    comps = compare(rows, time_limit=time_limit, default=default)
    domains = sorted({r.domain for r in rows})
    lines = _overview_section(rows, comps, domains, time_limit, command, default)
    lines += _parts_table(rows, default) + _limit_section(rows, time_limit)
    lines += _domain_coverage_section(rows, domains, default)
    lines += _size_speedup_section(rows, default)
    lines += _sizes_found_section(rows, default)
    lines += _agreement_section(comps)
    lines += _validation_section(rows)
    lines += [""] + plots_markdown(plots, base)
    return "\n".join(lines) + "\n"


def _overview_section(rows: list[ResultRow], comps: list[Comparison], domains: list[str], time_limit: float,
                      command: str, default: str) -> list[str]:
    """Title, how to regenerate, what the numbers mean, and the default-vs-baseline table per semantics."""
    return [
        "# Excuse benchmark",
        "",
        f"Regenerate with: `{command}`",
        "",
        f"{len({r.id for r in rows})} tasks over {len(domains)} domains; time limit {time_limit:g} s per task "
        "and run; each run is one `guided-lfd excuse ... --json` process, as a user would start it. *Solved* = "
        "a minimal excuse found, or proved that none exists.",
        "",
        f"## Default ({default}) vs baseline (the paper's method)",
        "",
        f"Speed-ups are baseline time / {default} time. *search* is the excuse search itself (the engine), on "
        "the tasks both solve; the setup before it is the same code for both strategies and is excluded: "
        "parsing, grounding, invariant synthesis, compiling the relaxed excuse task and the \"already "
        "solvable?\" check (whose reachability memory the landmark search then reuses). *whole run* is the "
        "wall time of the whole process as the shell sees it: start-up, parsing, grounding, search and the "
        "robot's optimal plan. *Non-trivial* tasks are those where the baseline's whole run takes "
        f">= {NONTRIVIAL_S:g} s or does not finish (counted at the limit; an unfinished default run too). "
        "The baseline is generous to the paper's method: each candidate is one in-memory pyperplan call on "
        "the already-grounded task (no re-parsing or re-grounding per candidate). Search phases shorter than "
        "0.1 ms count as 0.1 ms.",
        "",
        markdown_table(
            ["semantics", "tasks", f"solved: {default}", "solved: baseline", "both", "median speed-up (search)",
             "geo-mean speed-up (search)", "median speed-up (whole run)", "non-trivial tasks",
             "median speed-up (whole run, non-trivial)", f"size >= 3 solved: {default}", "size >= 3 solved: baseline",
             "size disagreements"],
            [[c.semantics, c.tasks, f"{c.solved_default} ({100 * c.solved_default / c.tasks:.0f}%)",
              f"{c.solved_baseline} ({100 * c.solved_baseline / c.tasks:.0f}%)", c.both, f"{c.median_speedup:.0f}x",
              f"{c.geomean_speedup:.0f}x", f"{c.median_total_speedup:.1f}x", c.nontrivial,
              f"{c.median_nontrivial_speedup:.1f}x", c.large_default, c.large_baseline, len(c.size_mismatches)]
             for c in comps]),
    ]


def _domain_coverage_section(rows: list[ResultRow], domains: list[str], default: str) -> list[str]:
    """Solved tasks per domain, for each semantics and strategy (the default's first)."""
    strategies = [default, "baseline"] + sorted({r.strategy for r in rows} - {default, "baseline"})
    columns = [(se, st) for se in ("literal", "consistent") for st in strategies]
    coverage = []
    for dom in domains:
        ids = {r.id for r in rows if r.domain == dom}
        coverage.append([dom, len(ids)] + [
            sum(1 for r in rows if r.domain == dom and r.semantics == se and r.strategy == st
                and r.status in SOLVED) for se, st in columns])
    return ["", "## Coverage per domain", "",
            markdown_table(["domain", "tasks"] + [f"{st} {se}" for se, st in columns], coverage)]


def _size_speedup_section(rows: list[ResultRow], default: str) -> list[str]:
    """Median search speed-up per minimal excuse size bucket and semantics."""
    by_size = speedups_by_size(rows, default)
    return ["", "## Median search speed-up by minimal excuse size", "",
            "On the tasks both strategies solve; each cell is the median and, in brackets, the number of tasks.",
            "", markdown_table(
                ["semantics"] + [f"size {b}" if b != "none" else "no excuse" for b in SIZE_BUCKETS],
                [[se] + [f"{statistics.median(v):.0f}x ({len(v)})" if (v := by_size[se].get(b)) else "-"
                         for b in SIZE_BUCKETS] for se in sorted(by_size)])]


def _sizes_found_section(rows: list[ResultRow], default: str) -> list[str]:
    """How many minimal excuses of each size (1 to 6+) the default strategy found, per semantics."""
    sizes: dict[str, int] = {}
    for r in rows:
        if r.strategy == default and r.status == "excuse-found":
            key = size_count_key(r.size or 0)
            sizes[f"{r.semantics} {key}"] = sizes.get(f"{r.semantics} {key}", 0) + 1
    keys = list(SIZE_COUNTS)
    return ["", f"## Minimal excuse sizes found ({default})", "",
            markdown_table(["semantics"] + keys,
                           [[se] + [sizes.get(f"{se} {k}", 0) for k in keys] for se in ("literal", "consistent")])]


def _agreement_section(comps: list[Comparison]) -> list[str]:
    """Whether both strategies agree on status and minimal size, or the list of disagreements."""
    mism = [m for c in comps if c.semantics != "both" for m in c.size_mismatches]
    return ["", "## Size agreement", "",
            "Every task both strategies solved has the same status and minimal size."
            if not mism else "Disagreements:\n\n" + "\n".join(f"- {m}" for m in mism)]


def _validation_section(rows: list[ResultRow]) -> list[str]:
    """The independent check of every excuse, the runs that ended in an error or crash, and the memouts."""
    errors = [r for r in rows if r.status in ("error", "crashed")]
    found = sum(r.status == "excuse-found" for r in rows)
    lines = ["", "## Validation", "",
             f"Every run re-checks each excuse it returns with the independent checker "
             f"(`guided_lfd.excuse.check`: the excuse state does not already satisfy the goal, keeps the invariants under the "
             f"consistent semantics, and the robot's plan from it validates); a failed check ends the run "
             f"as an error. Runs that returned an excuse: {found}; runs that ended in an error or crash: {len(errors)}."]
    if errors:
        lines += [""] + [f"- {r.id} {r.strategy} {r.semantics}: {r.status}"
                         + (f" ({r.excuse})" if r.excuse else "") for r in errors]
    memouts = [r for r in rows if r.status == "memout"]
    if memouts:
        lines += ["", f"Runs that exceeded the memory cap (memout, counted as unsolved): {len(memouts)}.", ""]
        lines += [f"- {r.id} {r.strategy} {r.semantics}" for r in memouts]
    return lines
