#!/usr/bin/env python3
"""Household scaling run: whole-run wall time and peak memory of `guided-lfd excuse` against task size.

    python benchmarks/household/scaling.py generate          # -> benchmarks/household/tasks/
    python benchmarks/household/scaling.py run --jobs 2      # -> benchmarks/household/results/scaling.csv
    python benchmarks/household/scaling.py report            # -> results/scaling.md + scaling.png
    python benchmarks/household/scaling.py all --jobs 2      # all three

Every run is the installed command line in its own process, timed from the
shell's point of view (start-up, parsing, grounding, search, the robot's
plan, printing); its peak resident memory is the largest of the process and
the processes it waited for (``wait4``).  The houses are the series of
``guided_lfd.benchmark.household.SERIES`` and the wide house ``WIDE_HOUSE``.  The
default strategy runs on every task under both semantics; the symbolic
strategy alone and the baseline (the paper's breadth-first search with a
planner call per candidate) run from the smallest task up and stop at the
first size they do not finish, per semantics and variant.  Sizes found by
two strategies are compared: they must agree.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.benchmark import household  # noqa: E402
from guided_lfd.benchmark import cli_command, limit_section  # noqa: E402
from guided_lfd.benchmark.report import series_style  # noqa: E402
from guided_lfd.reporting import PlotsUnavailable, pyplot, save_figure  # noqa: E402

TASKS = HERE / "tasks"
RESULTS = HERE / "results"
VARIANTS = ("no-push", "no-open")
FIELDS = ["task", "variant", "rooms", "items", "drawers", "cupboards", "goals", "semantics", "strategy", "status",
          "exit_code", "size", "plan_length", "plan_optimal", "wall_s", "peak_mb", "time_s", "search_time_s",
          "answered_by", "ground_atoms", "ground_actions", "relevant_atoms"]
#: The default strategy (``guided-lfd excuse`` without ``--strategy``), and those run up to their first
#: unfinished size beside it.
DEFAULT = "portfolio"
UP_TO_FIRST_MISS = ("symbolic", "baseline")


def generate(series=household.SERIES) -> list[dict]:
    """Write the robot domains and the series' problems; return the task list."""
    TASKS.mkdir(parents=True, exist_ok=True)
    (TASKS / "human.pddl").write_text(household.domain_pddl())
    out = []
    for variant in VARIANTS:
        (TASKS / f"robot-{variant}.pddl").write_text(household.domain_pddl(variant))
        for rooms, items, drawers, cupboards, goals in series:
            house = household.House(rooms, items, drawers, cupboards, goals, variant)
            path = TASKS / f"{house.name}.pddl"
            path.write_text(household.problem_pddl(house))
            out.append({"task": house.name, "variant": variant, "rooms": rooms, "items": items,
                        "drawers": house.drawers, "cupboards": rooms * cupboards, "goals": goals,
                        "domain": TASKS / f"robot-{variant}.pddl", "problem": path})
    return out


def run_one(task: dict, semantics: str, strategy: str, time_limit: float) -> dict:
    """One whole run of the command line; its row."""
    cmd = [*cli_command(), "excuse", str(task["domain"]), str(task["problem"]), "--semantics", semantics,
           "--strategy", strategy, "--time-limit", f"{time_limit:g}", "--json", "--quiet"]
    code, stdout, wall, peak_kb = _timed(cmd, time_limit + 30)
    row = {k: task[k] for k in ("task", "variant", "rooms", "items", "drawers", "cupboards", "goals")}
    row.update(semantics=semantics, strategy=strategy, exit_code=code, wall_s=round(wall, 3),
               peak_mb=round(peak_kb / 1024))
    try:
        doc = json.loads(stdout)
    except json.JSONDecodeError:
        row.update(status="crashed" if code != -9 else "killed")
        return row
    stats = doc.get("statistics", {})
    excuse = doc.get("excuse") or {}
    row.update(status=doc["status"], size=excuse.get("size", ""), plan_length=excuse.get("plan_length", ""),
               plan_optimal=excuse.get("plan_optimal", ""), time_s=stats.get("time_s", ""),
               search_time_s=stats.get("search_time_s", ""), answered_by=stats.get("answered_by", ""),
               ground_atoms=stats.get("ground_atoms", ""), ground_actions=stats.get("ground_actions", ""),
               relevant_atoms=stats.get("relevant_atoms", ""))
    return row


def _timed(cmd: list[str], kill_after: float) -> tuple[int, str, float, int]:
    """Run ``cmd``: its exit code (-9 when killed past ``kill_after`` s), stdout, wall time and peak memory (KiB)."""
    import os
    import tempfile
    import threading

    with tempfile.TemporaryFile("w+") as out:
        start = time.perf_counter()
        proc = subprocess.Popen(cmd, stdout=out, stderr=subprocess.DEVNULL, text=True)
        killer = threading.Timer(kill_after, proc.kill)
        killer.start()
        try:
            _, status, usage = os.wait4(proc.pid, 0)
        finally:
            killer.cancel()
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        return proc.returncode, out.read(), wall, usage.ru_maxrss


def run(tasks: list[dict], time_limit: float, jobs: int, log=print) -> list[dict]:
    """The default strategy everywhere; the symbolic strategy and the baseline up to their first unfinished size."""
    rows: list[dict] = []

    def note(row: dict) -> None:
        log(f"{row['task']} {row['semantics']} {row['strategy']}: {row['status']} size={row.get('size', '')} "
            f"{row['wall_s']} s {row.get('peak_mb', '')} MiB")

    jobs_list = [(t, sem, DEFAULT) for t in tasks for sem in ("literal", "consistent")]
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for row in pool.map(lambda job: run_one(job[0], job[1], job[2], time_limit), jobs_list):
            note(row)
            rows.append(row)

    # Size by size per (strategy, variant, semantics), until a run does not finish.
    def up_to_first_miss(strategy: str, variant: str, semantics: str) -> list[dict]:
        out = []
        for t in sorted((t for t in tasks if t["variant"] == variant), key=lambda t: (t["items"], t["goals"])):
            row = run_one(t, semantics, strategy, time_limit)
            note(row)
            out.append(row)
            if row["status"] not in ("excuse-found", "no-excuse"):
                break
        return out

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for series in pool.map(lambda key: up_to_first_miss(*key),
                               [(st, v, s) for st in UP_TO_FIRST_MISS for v in VARIANTS
                                for s in ("literal", "consistent")]):
            rows.extend(series)
    return sorted(rows, key=lambda r: (r["variant"], int(r["items"]), int(r["goals"]), r["semantics"],
                                       r["strategy"]))


def write_csv(rows: list[dict], path: Path) -> None:
    """The rows as CSV (written to a temporary file, then renamed)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".tmp")
    with tmp.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS, lineterminator="\n", extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    tmp.replace(path)


def read_csv(path: Path) -> list[dict]:
    """Rows written by :func:`write_csv`."""
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


def slope(points: list[tuple[float, float]]) -> float | None:
    """Least-squares slope of log(time) over log(ground actions)."""
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    var = sum((x - mx) ** 2 for x, _ in pts)
    return None if var == 0 else sum((x - mx) * (y - my) for x, y in pts) / var


def _solved(row: dict) -> bool:
    return row["status"] in ("excuse-found", "no-excuse")


def report(rows: list[dict], time_limit: float, out_dir: Path) -> str:
    """Markdown summary and a log-log plot of wall time against ground actions."""
    actions = {r["task"]: int(r["ground_actions"]) for r in rows if r.get("ground_actions")}
    relevant = {r["task"]: r["relevant_atoms"] for r in rows if r.get("relevant_atoms")}
    lines = [
        "# Household scaling run",
        "",
        f"Command: `python benchmarks/household/scaling.py all --jobs 2` (time limit {time_limit:g} s per run; "
        "wall = the whole `guided-lfd excuse` process as the shell sees it; peak = its largest resident memory, "
        "the process or a worker it started).",
        "",
        "| task | ground actions | relevant atoms | semantics | default: status, size, wall s, peak MiB (answered by) "
        "| symbolic alone: status, wall s | baseline: status, size, wall s |",
        "|---|---|---|---|---|---|---|",
    ]
    by_key = {(r["task"], r["semantics"], r["strategy"]): r for r in rows}
    disagreements = 0
    for task in sorted({r["task"] for r in rows}, key=lambda t: (t.split("-")[-1], actions.get(t, 0), t)):
        for sem in ("literal", "consistent"):
            default = by_key.get((task, sem, DEFAULT))
            if default is None:
                continue
            cells = [f"{default['status']}, {default.get('size') or '-'}, {float(default['wall_s']):.2f}, "
                     f"{default.get('peak_mb') or '-'} ({default.get('answered_by') or '-'})"]
            for strategy, with_size in (("symbolic", False), ("baseline", True)):
                other = by_key.get((task, sem, strategy))
                if other is None:
                    cells.append("not run")
                    continue
                cell = f"{other['status']}, " + (f"{other.get('size') or '-'}, " if with_size else "")
                cell += f"{float(other['wall_s']):.2f}"
                if _solved(other) and _solved(default) and other.get("size") != default.get("size"):
                    disagreements += 1
                    cell += " **size differs**"
                cells.append(cell)
            lines.append(f"| {task} | {actions.get(task, '-')} | {relevant.get(task, '-')} | {sem} | "
                         + " | ".join(cells) + " |")
    lines += ["", f"Size disagreements between the strategies where both finish: {disagreements}."]
    lines += limit_section([(float(r["wall_s"]), f"{r['task']} {r['strategy']} {r['semantics']}", r["status"])
                            for r in rows if r.get("wall_s") not in ("", None)], time_limit) + [""]
    # The slope of a strategy and semantics is over both variants' runs.
    series: dict[str, list[tuple[float, float]]] = {}
    for r in rows:
        if _solved(r) and r["task"] in actions:
            series.setdefault(f"{r['strategy']} ({r['semantics']})", []).append(
                (actions[r["task"]], float(r["wall_s"])))
    lines.append("| series | runs finished | log-log slope of wall time vs ground actions |")
    lines.append("|---|---|---|")
    for name in sorted(series):
        s = slope(series[name])
        lines.append(f"| {name} | {len(series[name])} | {'-' if s is None else f'{s:.2f}'} |")
    plot = _plot(rows, actions, out_dir / "scaling.png", time_limit)
    if plot:
        lines += ["", f"![scaling]({plot.name})"]
    return "\n".join(lines) + "\n"


def _plot(rows: list[dict], actions: dict[str, int], path: Path, time_limit: float) -> Path | None:
    """A panel per robot variant: one line per (strategy, semantics), wall time against ground actions.

    The variants' tasks differ in size, so a line never joins two variants; a run that did not finish is a
    marker at its wall time (the time limit), outside the line.
    """
    try:
        plt = pyplot()
    except PlotsUnavailable as exc:
        print(f"no plot: {exc}", file=sys.stderr)
        return None
    from matplotlib.lines import Line2D

    fig, axes = plt.subplots(1, len(VARIANTS), figsize=(11, 4.8), sharey=True, layout="constrained")
    for ax, variant in zip(axes, VARIANTS):
        mine = [r for r in rows if r["variant"] == variant and r["task"] in actions]
        for strategy, semantics in sorted({(r["strategy"], r["semantics"]) for r in mine}):
            runs = sorted((actions[r["task"]], float(r["wall_s"]), _solved(r)) for r in mine
                          if r["strategy"] == strategy and r["semantics"] == semantics)
            style = series_style(strategy, semantics)
            ax.plot([x for x, _, ok in runs if ok], [y for _, y, ok in runs if ok], **style)
            ax.plot([x for x, _, ok in runs if not ok], [y for _, y, ok in runs if not ok], ls="",
                    marker="v", markersize=9, markerfacecolor="none", color=style["color"])
        ax.axhline(time_limit, color="grey", linestyle=":", linewidth=1)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("ground actions of the task (log scale)")
        ax.set_title(f"robot {household.VARIANT_TEXT[variant]} ({variant})", fontsize=10)
    axes[0].set_ylabel("whole-run wall time (s, log scale)")
    handles, labels = axes[0].get_legend_handles_labels()
    handles += [Line2D([], [], ls="", marker="v", markerfacecolor="none", color="black"),
                Line2D([], [], color="grey", ls=":")]
    labels += ["not finished within the limit (the baseline is not run on larger tasks)",
               f"time limit ({time_limit:g} s per run)"]
    fig.legend(handles, labels, loc="outside lower center", ncol=2, fontsize=8)
    fig.suptitle("guided-lfd excuse on the household series: one line per strategy and semantics")
    path.parent.mkdir(parents=True, exist_ok=True)
    return save_figure(fig, path, 120)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=["generate", "run", "report", "all"])
    parser.add_argument("--time-limit", type=float, default=60.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--max-items", type=int, default=None, help="only houses with at most this many items")
    args = parser.parse_args(argv)
    series = [s for s in [*household.SERIES, household.WIDE_HOUSE] if args.max_items is None or s[1] <= args.max_items]
    tasks = generate(series)
    if args.command == "generate":
        print(f"{len(tasks)} tasks -> {TASKS}", file=sys.stderr)
        return 0
    csv_path = RESULTS / "scaling.csv"
    if args.command in ("run", "all"):
        rows = run(tasks, args.time_limit, args.jobs, log=lambda m: print(m, file=sys.stderr, flush=True))
        write_csv(rows, csv_path)
    if args.command in ("report", "all"):
        text = report(read_csv(csv_path), args.time_limit, RESULTS)
        (RESULTS / "scaling.md").write_text(text)
        print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
