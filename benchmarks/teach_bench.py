#!/usr/bin/env python3
"""Guided-teaching benchmark: `guided-lfd teach --simulate` against the unguided baseline.

    python benchmarks/teach_bench.py --jobs 2        # -> benchmarks/teach_results/{teach.csv,summary.md,teach.png}
    python benchmarks/teach_bench.py --jobs 2 --report   # summary.md and teach.png again from the committed teach.csv
    python benchmarks/teach_bench.py --plot-only     # no runs: teach.png again from teach.csv

For every kitchen task and every household task of the scaling series up to
``--max-items`` (both robots: without the skill that opens, and without the
one that pushes obstacles away), the guided loop runs with the human model
simulating the demonstrator, in three configurations:

* ``guided``: the request is the part of the excuse that suffices (redundancy)
  and the excuse with the shortest predicted demonstration is preferred;
* ``excuse``: the plain minimal excuse (``--no-redundancy``, no preference);
* ``unguided``: the baseline, the human demonstrates the whole task (the human
  model's optimal plan from the initial state to the goal).

Each row: rounds, total demonstrated actions, the ones the robot already had,
misdirected demonstrations (a round whose request the demonstration did not
meet), whether the taught robot then plans the task, and the whole run's wall
time (teaching includes excuse search, simulated rendering, segmentation,
learning, merging and re-planning).  Every run is the installed command line
in its own process.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.benchmark import household  # noqa: E402
from guided_lfd.benchmark import cli_command  # noqa: E402
from guided_lfd.io import write_text  # noqa: E402
from guided_lfd.reporting import PlotsUnavailable, markdown_table, pyplot, save_figure  # noqa: E402
from guided_lfd.study.paper import KITCHEN_NAMES  # noqa: E402

OUT = ROOT / "benchmarks" / "teach_results"
FIELDS = ["task", "robot", "config", "status", "solved", "plans_task", "rounds", "demonstrated", "already_had",
          "misdirected", "request", "wall_s"]


def tasks(max_items: int, folder: Path) -> list[dict]:
    """The kitchen tasks and the household series up to ``max_items`` items, each with its robot and human."""
    domains = ROOT / "data" / "domains"
    out = [{"task": "kitchen-1", "robot": "robot", "robot_file": domains / "kitchen-1" / "robot.pddl",
            "problem": domains / "kitchen-1" / "problem.pddl", "human": domains / "kitchen-1" / "human.pddl"}]
    for robot in ("robot", "robot-no-open"):
        out.append({"task": "kitchen-2", "robot": robot, "robot_file": domains / "kitchen-2" / f"{robot}.pddl",
                    "problem": domains / "kitchen-2" / "problem.pddl", "human": domains / "kitchen-2" / "human.pddl"})
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "human.pddl").write_text(household.domain_pddl())
    for variant in ("no-open", "no-push"):
        (folder / f"robot-{variant}.pddl").write_text(household.domain_pddl(variant))
        for rooms, items, drawers, cupboards, goals in household.SERIES:
            if items > max_items:
                continue
            house = household.House(rooms, items, drawers, cupboards, goals, variant)
            path = folder / f"{house.name}.pddl"
            path.write_text(household.problem_pddl(house))
            out.append({"task": house.name, "robot": f"robot-{variant}", "robot_file": folder / f"robot-{variant}.pddl",
                        "problem": path, "human": folder / "human.pddl"})
    return out


def run_teach(task: dict, config: str, time_limit: float) -> dict:
    """One ``guided-lfd teach --simulate`` run; its row."""
    with tempfile.TemporaryDirectory() as session:
        cmd = [*cli_command(), "teach", str(task["robot_file"]), str(task["problem"]), "--simulate",
               str(task["human"]), "-o", session, "--json", "--quiet", "--time-limit", f"{time_limit:g}"]
        cmd += ["--prefer", "demonstration"] if config == "guided" else ["--no-redundancy"]
        start = time.perf_counter()
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=10 * time_limit + 60)
        wall = time.perf_counter() - start
    row = {"task": task["task"], "robot": task["robot"], "config": config, "wall_s": round(wall, 3)}
    try:
        doc = json.loads(proc.stdout)
    except json.JSONDecodeError:
        return {**row, "status": f"crashed: {proc.stderr.strip()[-120:]}"}
    rounds = doc["rounds"]
    demonstrated = sum(r["demonstration_length"] or 0 for r in rounds)
    new = sum(r["new_actions"] or 0 for r in rounds)
    return {**row, "status": doc["status"], "solved": doc["solved"], "plans_task": doc["plans_original_task"],
            "rounds": len(rounds), "demonstrated": demonstrated, "already_had": demonstrated - new,
            "misdirected": sum(r["request_met"] is False for r in rounds),
            "request": " | ".join(" ".join(r["request"]) for r in rounds)}


def run_unguided(task: dict) -> dict:
    """The baseline: the human demonstrates the whole task (its optimal plan), the robot learns it."""
    from guided_lfd.evaluate import optimal_plan
    from guided_lfd.pddl.reader import parse_domain, parse_task

    start = time.perf_counter()
    robot, problem = parse_task(str(task["robot_file"]), str(task["problem"]))
    human = parse_domain(str(task["human"]))
    plan = optimal_plan(human, problem)
    known = {a.name for a in robot.actions}
    row = {"task": task["task"], "robot": task["robot"], "config": "unguided", "status": "demonstrated",
           "solved": plan is not None, "plans_task": "", "rounds": 1,  # learning it is not simulated
           "demonstrated": len(plan or []), "already_had": sum(s.action in known for s in plan or []),
           "misdirected": 0, "request": "the whole task"}
    return {**row, "wall_s": round(time.perf_counter() - start, 3)}


HEADER = ("task", "robot", "guided", "excuse (no redundancy, no preference)", "unguided (whole task)",
          "guided < unguided", "wall guided (s)")


def _cell(row: dict | None) -> str:
    """One configuration's outcome: demonstrated actions (of which the robot already had), rounds, misdirected."""
    if row is None or row.get("demonstrated", "") == "":
        return "-"
    taught = "" if row.get("plans_task") in (True, "") else ", **not taught**"
    return (f"{row['demonstrated']} ({row['already_had']}), {row['rounds']} round(s), {row['misdirected']} "
            f"misdirected{taught}")


def _by_config(rows: list[dict]) -> dict[tuple[str, str, str], dict]:
    """The rows by (task, robot, configuration)."""
    return {(r["task"], r["robot"], r["config"]): r for r in rows}


def summary(rows: list[dict], command: str) -> str:
    """The markdown table: per task and robot, each configuration's demonstration length beside the baseline's."""
    by = _by_config(rows)
    keys = sorted({(r["task"], r["robot"]) for r in rows}, key=lambda k: (not k[0].startswith("kitchen"), k))
    table = []
    for task, robot in keys:
        g, e, u = (by.get((task, robot, c)) for c in ("guided", "excuse", "unguided"))
        cells = [_cell(g), _cell(e), _cell(u)]
        wins = "-" not in (cells[0], cells[2]) and g["solved"] is True and g["demonstrated"] < u["demonstrated"]
        table.append([task, robot, *cells, "yes" if wins else "no", str(g["wall_s"]) if g else "-"])
    better = sum(row[5] == "yes" for row in table)
    return "\n".join(["# Guided teaching vs demonstrating the whole task", "", f"Regenerate with: `{command}`", "",
                      "Demonstrated actions (of which the robot already had), rounds, misdirected demonstrations, "
                      "and whether the taught robot then plans its task; wall time of the whole teaching run.", "",
                      markdown_table(HEADER, table), "",
                      f"Guided teaching needs fewer demonstrated actions than the whole task on {better} of "
                      f"{len(table)} tasks."]) + "\n"


def read_rows(path: Path) -> list[dict]:
    """The rows of a ``teach.csv``, typed as the run made them (counts, flags and wall times)."""
    flags = {"True": True, "False": False, "": ""}
    with open(path, encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(fh))
    for row in rows:
        row.update({k: int(row[k]) for k in ("rounds", "demonstrated", "already_had", "misdirected") if row[k]})
        row.update({k: flags[row[k]] for k in ("solved", "plans_task")})
        row["wall_s"] = float(row["wall_s"])
    return rows


#: What the kitchens' robots cannot do (data/domains/kitchen-*/robot*.pddl).
KITCHEN_ROBOTS = {("kitchen-1", "robot"): "cannot open drawers",
                  ("kitchen-2", "robot"): "cannot move the chair",
                  ("kitchen-2", "robot-no-open"): "cannot open drawers or move the chair"}

#: The plot's bars: (configuration, colour, legend entry).
CONFIGS = (("guided", "tab:green", "guided: the part of the excuse that suffices, shortest demonstration preferred"),
           ("excuse", "tab:orange", "the plain minimal excuse (--no-redundancy)"),
           ("unguided", "tab:grey", "unguided: the human demonstrates the whole task"))


def _task_order(key: tuple[str, str]) -> tuple:
    """Kitchens first, then the houses from small to large, each size's variants together."""
    sizes = household.name_sizes(key[0])
    return (0, key) if sizes is None else (1, sizes, key)


def _task_label(task: str, robot: str) -> str:
    """A row's label: the task (a house by its sizes, without the 'house-' and variant) and what its robot lacks."""
    sizes = household.name_sizes(task)
    if sizes is None:
        return f"{KITCHEN_NAMES.get(task, task)}: robot {KITCHEN_ROBOTS.get((task, robot), robot)}"
    return f"{household.size_tag(sizes[0])}: robot {household.VARIANT_TEXT.get(sizes[1], sizes[1])}"


def _name_caption(tasks: list[str]) -> str:
    """What a house's name says, spelt out on the last (largest) house of ``tasks``."""
    houses = [(t, sizes) for t in tasks if (sizes := household.name_sizes(t)) is not None]
    if not houses:
        return ""
    pattern = "-".join(f"{letter}<{what.split()[0]}>" for letter, what in household.NAME_PARTS)
    task, (numbers, _) = houses[-1]
    example = household.size_tag(numbers)
    spelt = ", ".join(f"{n} {what}" for (_, what), n in zip(household.NAME_PARTS, numbers))
    return f"House tasks are named {pattern}:\ne.g. {example} has {spelt}."


def plot(rows: list[dict], path: Path) -> Path | None:
    """Demonstrated actions per task: guided, the plain excuse, and the whole task (None without matplotlib)."""
    try:
        plt = pyplot()
    except PlotsUnavailable as exc:
        print(f"plot skipped: {exc}", file=sys.stderr)
        return None
    from matplotlib.ticker import MaxNLocator

    by = _by_config(rows)
    keys = sorted({(r["task"], r["robot"]) for r in rows}, key=_task_order)
    fig, ax = plt.subplots(figsize=(10, 1.5 + 0.5 * len(keys)), layout="constrained")
    height = 0.27
    for j, (config, colour, label) in enumerate(CONFIGS):
        values = [int(by.get((t, r, config), {}).get("demonstrated") or 0) for t, r in keys]
        bars = ax.barh([k + (j - 1) * height for k in range(len(keys))], values, height, color=colour, label=label)
        ax.bar_label(bars, fontsize=7, padding=2)
    ax.set_yticks(range(len(keys)), [_task_label(t, r) for t, r in keys], fontsize=8)
    ax.invert_yaxis()  # the first task on top
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))  # actions are counted
    ax.set_xlabel("demonstrated actions (all rounds of teaching)")
    fig.suptitle("What the human demonstrates: guided teaching vs the whole task (fewer is better)")
    ax.legend(fontsize=8, loc="upper right")  # the kitchens' bars are short: room beside them
    fig.supxlabel(_name_caption([t for t, _ in keys]), fontsize=8)
    return save_figure(fig, path, 110)


def run_all(args: argparse.Namespace) -> list[dict]:
    """Every task in every configuration; the rows, also written to ``--out``'s ``teach.csv``."""
    with tempfile.TemporaryDirectory() as scratch:
        work = tasks(args.max_items, Path(scratch))
        with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            taught = list(pool.map(lambda job: run_teach(*job, args.time_limit),
                                   [(t, c) for t in work for c in ("guided", "excuse")]))
        rows = taught + [run_unguided(t) for t in work]
    args.out.mkdir(parents=True, exist_ok=True)
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=FIELDS, lineterminator="\n", restval="")
    writer.writeheader()
    writer.writerows(sorted(rows, key=lambda r: (r["task"], r["robot"], r["config"])))
    write_text(args.out / "teach.csv", buf.getvalue())
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--max-items", type=int, default=32, help="largest household task (items)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--time-limit", type=float, default=60.0, help="per excuse search, in seconds")
    parser.add_argument("--out", type=Path, default=OUT)
    parser.add_argument("--report", action="store_true", help="only rewrite summary.md and the plot from --out's "
                        "teach.csv (give the run's other options to keep its 'Regenerate with' line)")
    parser.add_argument("--plot-only", action="store_true", help="no runs: redraw teach.png from --out's teach.csv")
    args = parser.parse_args(argv)
    if args.plot_only:
        return 0 if plot(read_rows(args.out / "teach.csv"), args.out / "teach.png") else 1
    rows = read_rows(args.out / "teach.csv") if args.report else run_all(args)
    given = [a for a in (argv if argv is not None else sys.argv[1:]) if a != "--report"]
    text = summary(rows, " ".join(["python benchmarks/teach_bench.py", *given]))
    picture = plot(rows, args.out / "teach.png")
    if picture is not None:
        text += f"\n![demonstrated actions]({picture.name})\n"
    write_text(args.out / "summary.md", text)
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
