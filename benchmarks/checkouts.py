#!/usr/bin/env python3
"""Two checkouts of guided-lfd side by side: whole-run wall times and answers of `plan` and `excuse`.

    git worktree add /tmp/reference <rev>
    python benchmarks/checkouts.py /tmp/reference .          # -> benchmarks/checkouts_results/{runs.csv,summary.md}
    python benchmarks/checkouts.py /tmp/reference . --rounds 3 --time-limit 60

For a restructure that must not change behaviour or speed.  Each command runs
as a fresh process of the interpreter running this script, with the checkout's
folder first on PYTHONPATH (so the same installed libraries serve both), on:

* `plan`: the shipped IPC tasks named in ``--plan-tasks`` (default: those the
  planning benchmark's results solve in 0.5 to 8 s);
* `excuse`: the excuse suite's CI subset (benchmarks/ci_subset.csv, the robot
  domain being the domain without one action), both semantics, with
  ``--fixed-from`` the complete domain as the suite runs it.

Runs of the two checkouts alternate task by task (A B, then B A on the next
round), so a drift in machine load affects both alike; each figure is the
median over ``--rounds``.  Answers are compared: plan costs must agree, excuse
sizes and statuses must agree (which of several minimal excuses is printed may
differ between runs of one checkout when the portfolio's members race).  The
summary gives each command's total median time per checkout and their ratio.
Measure on a quiet machine: nothing else running.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IPC = ROOT / "data" / "benchmarks" / "ipc"
RUNNER = "import sys; from cli.main import run; sys.argv[0] = 'guided-lfd'; run()"


def plan_jobs(tasks: str) -> list[tuple[str, list[str]]]:
    """(name, arguments) of each `plan` run: ``tasks`` as comma-separated ``domain/taskNN``, or ``searched``:
    the tasks the planning benchmark's last results (plan_results/plan.csv) solve in 0.5 to 8 s, where search
    rather than start-up is most of a run and a run is short enough to repeat."""
    if tasks == "searched":
        rows = csv.DictReader((ROOT / "benchmarks" / "plan_results" / "plan.csv").open())
        pairs = [(r["domain"], r["task"]) for r in rows
                 if r["guided_status"] == "solved" and 0.5 <= float(r["guided_wall_s"]) <= 8]
    else:
        pairs = [tuple(t.split("/", 1)) for t in tasks.split(",")]
    return [(f"plan {domain}-{task}", ["plan", str(IPC / domain / "domain.pddl"), str(IPC / domain / f"{task}.pddl"),
                                       "--json", "--quiet"]) for domain, task in pairs]


def excuse_jobs(robots: Path) -> list[tuple[str, list[str]]]:
    """(name, arguments) of each `excuse` run: the CI subset, both semantics (robot domains written to ``robots``)."""
    sys.path.insert(0, str(ROOT))
    from guided_lfd.benchmark.suite import read_suite, robot_domain_file

    wanted = {row["id"] for row in csv.DictReader((ROOT / "benchmarks" / "ci_subset.csv").open())}
    jobs = []
    for task in read_suite(ROOT / "benchmarks" / "suite.csv", ROOT):
        if task.id not in wanted:
            continue
        robot = robot_domain_file(task, robots)
        for semantics in ("literal", "consistent"):
            args = ["excuse", str(robot), str(task.problem_file), "--semantics", semantics, "--json", "--quiet"]
            if task.fixed_from:
                args += ["--fixed-from", str(task.fixed_from)]
            jobs.append((f"excuse {task.id} {semantics}", args))
    return jobs


def run(checkout: Path, args: list[str], time_limit: float) -> tuple[float, str]:
    """Wall seconds of one run and its answer (plan cost, or excuse status and size)."""
    env = {**os.environ, "PYTHONPATH": str(checkout)}
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", RUNNER, *args, "--time-limit", str(time_limit)], cwd=ROOT,
                          env=env, capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    try:
        doc = json.loads(done.stdout)
    except json.JSONDecodeError:
        return elapsed, f"exit {done.returncode}"
    if args[0] == "plan":
        return elapsed, f"{doc.get('status')} cost {doc.get('cost')}"
    excuse = doc.get("excuse") or {}
    return elapsed, f"{doc.get('status')} size {len(excuse.get('changes', []))}"


def label(checkout: Path) -> str:
    """The checkout's commit (with '+ changes' when its tree differs from it), or its path outside git."""
    rev = subprocess.run(["git", "-C", str(checkout), "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    if rev.returncode != 0:
        return str(checkout)
    dirty = subprocess.run(["git", "-C", str(checkout), "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    return rev.stdout.strip() + (" + changes" if dirty else "")


def main() -> None:
    """Run both checkouts on every job, alternating, and write the runs and a summary."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("reference", type=Path, help="the checkout to compare against")
    parser.add_argument("candidate", type=Path, help="the checkout measured against it")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--time-limit", type=float, default=60)
    parser.add_argument("--plan-tasks", default="searched", help="domain/taskNN,... or 'searched'")
    parser.add_argument("--only", choices=("plan", "excuse"), help="one command only")
    parser.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "checkouts_results")
    opts = parser.parse_args()
    checkouts = (opts.reference.resolve(), opts.candidate.resolve())
    with tempfile.TemporaryDirectory() as robots:
        jobs = []
        if opts.only in (None, "plan"):
            jobs += plan_jobs(opts.plan_tasks)
        if opts.only in (None, "excuse"):
            jobs += excuse_jobs(Path(robots))
        times: dict[tuple[str, int], list[float]] = {}
        answers: dict[tuple[str, int], set[str]] = {}
        for r in range(opts.rounds):
            for n, (name, args) in enumerate(jobs):
                order = (0, 1) if (n + r) % 2 == 0 else (1, 0)
                for which in order:
                    elapsed, answer = run(checkouts[which], args, opts.time_limit)
                    times.setdefault((name, which), []).append(elapsed)
                    answers.setdefault((name, which), set()).add(answer)
                print(f"round {r + 1}/{opts.rounds} {n + 1}/{len(jobs)} {name}: "
                      f"{times[(name, 0)][-1]:.2f} s, {times[(name, 1)][-1]:.2f} s", file=sys.stderr)
    opts.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for name, _ in jobs:
        a, b = (statistics.median(times[(name, w)]) for w in (0, 1))
        rows.append({"job": name, "reference_s": round(a, 3), "candidate_s": round(b, 3), "ratio": round(b / a, 3),
                     "reference": " | ".join(sorted(answers[(name, 0)])), "candidate": " | ".join(sorted(answers[(name, 1)])),
                     "same_answer": answers[(name, 0)] == answers[(name, 1)]})
    with (opts.out / "runs.csv").open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    lines = [f"# {label(checkouts[0])} against {label(checkouts[1])}", "",
             f"{opts.rounds} rounds, medians, time limit {opts.time_limit:g} s, Python {sys.version.split()[0]}", "",
             "| command | jobs | reference (s) | candidate (s) | candidate / reference | same answers |", "|---|---|---|---|---|---|"]
    for command in ("plan", "excuse"):
        mine = [row for row in rows if row["job"].startswith(command)]
        if not mine:
            continue
        a, b = sum(row["reference_s"] for row in mine), sum(row["candidate_s"] for row in mine)
        same = sum(row["same_answer"] for row in mine)
        lines.append(f"| {command} | {len(mine)} | {a:.2f} | {b:.2f} | {b / a:.3f} | {same} of {len(mine)} |")
    (opts.out / "summary.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
