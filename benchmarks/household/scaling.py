#!/usr/bin/env python3
"""Household scaling run: whole-run wall time of `guided-lfd excuse` against task size.

    python benchmarks/household/scaling.py generate          # -> benchmarks/household/tasks/
    python benchmarks/household/scaling.py run --jobs 2      # -> benchmarks/household/results/scaling.csv
    python benchmarks/household/scaling.py report            # -> results/scaling.md + scaling.png
    python benchmarks/household/scaling.py all --jobs 2      # all three

Every run is the installed command line in its own process, timed from the
shell's point of view (start-up, parsing, grounding, search, the robot's
plan, printing).  The default strategy runs on every task under both
semantics; the baseline (the paper's breadth-first search with a planner
call per candidate) runs from the smallest task up and stops at the first
size it does not finish, per semantics and variant.  Sizes found by both are
compared: they must agree.
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

from guided_lfd import household  # noqa: E402
from guided_lfd.benchmark import cli_command, limit_section  # noqa: E402

TASKS = HERE / "tasks"
RESULTS = HERE / "results"
VARIANTS = ("no-push", "no-open")
FIELDS = ["task", "variant", "rooms", "items", "drawers", "cupboards", "goals", "semantics", "strategy", "status",
          "exit_code", "size", "plan_length", "plan_optimal", "wall_s", "time_s", "search_time_s",
          "ground_atoms", "ground_actions"]


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
    start = time.perf_counter()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=time_limit + 30)
        code, stdout = proc.returncode, proc.stdout
    except subprocess.TimeoutExpired:
        code, stdout = -9, ""
    wall = time.perf_counter() - start
    row = {k: task[k] for k in ("task", "variant", "rooms", "items", "drawers", "cupboards", "goals")}
    row.update(semantics=semantics, strategy=strategy, exit_code=code, wall_s=round(wall, 3))
    try:
        doc = json.loads(stdout)
    except json.JSONDecodeError:
        row.update(status="crashed" if code != -9 else "killed")
        return row
    stats = doc.get("statistics", {})
    excuse = doc.get("excuse") or {}
    row.update(status=doc["status"], size=excuse.get("size", ""), plan_length=excuse.get("plan_length", ""),
               plan_optimal=excuse.get("plan_optimal", ""), time_s=stats.get("time_s", ""),
               search_time_s=stats.get("search_time_s", ""), ground_atoms=stats.get("ground_atoms", ""),
               ground_actions=stats.get("ground_actions", ""))
    return row


def run(tasks: list[dict], time_limit: float, jobs: int, log=print) -> list[dict]:
    """The default strategy everywhere, the baseline up to its first unfinished size."""
    rows: list[dict] = []
    jobs_list = [(t, sem, "landmark") for t in tasks for sem in ("literal", "consistent")]
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for row in pool.map(lambda job: run_one(job[0], job[1], job[2], time_limit), jobs_list):
            log(f"{row['task']} {row['semantics']} landmark: {row['status']} size={row.get('size', '')} "
                f"{row['wall_s']} s")
            rows.append(row)
    # The baseline, size by size per (variant, semantics), until it does not finish.
    def baseline_series(variant: str, semantics: str) -> list[dict]:
        out = []
        for t in [t for t in tasks if t["variant"] == variant]:
            row = run_one(t, semantics, "baseline", time_limit)
            log(f"{row['task']} {semantics} baseline: {row['status']} size={row.get('size', '')} {row['wall_s']} s")
            out.append(row)
            if row["status"] not in ("excuse-found", "no-excuse"):
                break
        return out

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for series in pool.map(lambda vs: baseline_series(*vs),
                               [(v, s) for v in VARIANTS for s in ("literal", "consistent")]):
            rows.extend(series)
    return sorted(rows, key=lambda r: (r["variant"], int(r["items"]), r["goals"], r["semantics"], r["strategy"]))


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
    lines = [
        "# Household scaling run",
        "",
        f"Command: `python benchmarks/household/scaling.py all --jobs 2` (time limit {time_limit:g} s per run; "
        "wall = the whole `guided-lfd excuse` process as the shell sees it).",
        "",
        "| task | ground actions | semantics | landmark: status, size, wall s (search s) | baseline: status, size, wall s |",
        "|---|---|---|---|---|",
    ]
    by_key = {(r["task"], r["semantics"], r["strategy"]): r for r in rows}
    disagreements = 0
    for task in sorted({r["task"] for r in rows}, key=lambda t: (t.split("-")[-1], actions.get(t, 0), t)):
        for sem in ("literal", "consistent"):
            lm = by_key.get((task, sem, "landmark"))
            bl = by_key.get((task, sem, "baseline"))
            if lm is None:
                continue
            lm_cell = f"{lm['status']}, {lm.get('size') or '-'}, {float(lm['wall_s']):.2f} ({lm.get('search_time_s') or '-'})"
            bl_cell = (f"{bl['status']}, {bl.get('size') or '-'}, {float(bl['wall_s']):.2f}" if bl else "not run")
            if bl and _solved(bl) and _solved(lm) and bl.get("size") != lm.get("size"):
                disagreements += 1
                bl_cell += " **size differs**"
            lines.append(f"| {task} | {actions.get(task, '-')} | {sem} | {lm_cell} | {bl_cell} |")
    lines += ["", f"Size disagreements between the strategies where both finish: {disagreements}."]
    lines += limit_section([(float(r["wall_s"]), f"{r['task']} {r['strategy']} {r['semantics']}", r["status"])
                            for r in rows if r.get("wall_s") not in ("", None)], time_limit) + [""]
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
    plot = _plot(series, out_dir / "scaling.png", time_limit)
    if plot:
        lines += ["", f"![scaling]({plot.name})"]
    return "\n".join(lines) + "\n"


def _plot(series: dict[str, list[tuple[float, float]]], path: Path, time_limit: float) -> Path | None:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing (pip install 'guided-lfd[plots]'): no plot", file=sys.stderr)
        return None
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name in sorted(series):
        pts = sorted(series[name])
        ax.plot([x for x, _ in pts], [y for _, y in pts], marker="o", label=name)
    ax.axhline(time_limit, color="grey", linestyle=":", linewidth=1, label=f"time limit ({time_limit:g} s)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("ground actions")
    ax.set_ylabel("whole-run wall time (s)")
    ax.set_title("guided-lfd excuse on household tasks")
    ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120, metadata={"Software": None})
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=["generate", "run", "report", "all"])
    parser.add_argument("--time-limit", type=float, default=60.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--max-items", type=int, default=None, help="only houses with at most this many items")
    args = parser.parse_args(argv)
    series = [s for s in household.SERIES if args.max_items is None or s[1] <= args.max_items]
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
