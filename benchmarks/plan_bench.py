#!/usr/bin/env python3
"""`guided-lfd plan` against pyperplan's own optimal planner, whole runs from the shell.

    python benchmarks/plan_bench.py --jobs 2      # -> benchmarks/plan_results/{plan.csv,summary.md}

For every shipped IPC task (data/benchmarks/ipc/<domain>/taskNN.pddl) both
commands run as fresh processes with the same time limit:

* `guided-lfd plan DOMAIN PROBLEM --json --quiet --time-limit T`
* `pyperplan -s astar -H lmcut DOMAIN PROBLEM` (killed at T; it writes its
  plan next to the problem, so it gets a copy of the problem in a scratch folder)

Whole-run wall time is measured around each process (start-up, parsing,
grounding, search, writing the plan), the order of the two alternates from
task to task, and the plan lengths are compared (both planners are optimal:
they must agree).  The summary gives the median ratio over the tasks both solve.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IPC = ROOT / "data" / "benchmarks" / "ipc"
OUT = ROOT / "benchmarks" / "plan_results"
FIELDS = ["domain", "task", "guided_status", "guided_length", "guided_wall_s", "guided_search_s",
          "pyperplan_status", "pyperplan_length", "pyperplan_wall_s", "ratio"]


def _exe(name: str) -> str:
    path = Path(sys.executable).with_name(name)
    return str(path) if path.exists() else name


def guided_run(domain: Path, problem: Path, limit: float, command: str = "plan",
               extra: tuple[str, ...] = ()) -> tuple[str, dict | None, float]:
    """(status, the --json document when it answered, wall s) of one `guided-lfd plan` (or ``command``) process."""
    cmd = [_exe("guided-lfd"), command, str(domain), str(problem), "--json", "--quiet", "--time-limit", f"{limit:g}",
           *extra]
    start = time.perf_counter()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=limit + 30)
    except subprocess.TimeoutExpired:
        return "killed", None, time.perf_counter() - start
    wall = time.perf_counter() - start
    if proc.returncode == 20:
        return "timeout", None, wall
    try:
        doc = json.loads(proc.stdout)
    except json.JSONDecodeError:
        return f"exit {proc.returncode}", None, wall
    return doc["status"], doc, wall


def run_guided(domain: Path, problem: Path, limit: float) -> tuple[str, int | None, float, float | None]:
    """(status, plan length, wall s, search s) of one `guided-lfd plan` process."""
    status, doc, wall = guided_run(domain, problem, limit)
    if doc is None:
        return status, None, wall, None
    if status != "solved":
        return status, None, wall, doc.get("time_s")
    return "solved", len(doc["plan"]), wall, doc.get("time_s")


def run_pyperplan(domain: Path, problem: Path, limit: float) -> tuple[str, int | None, float]:
    """(status, plan length, wall s) of one `pyperplan -s astar -H lmcut` process."""
    with tempfile.TemporaryDirectory() as scratch:
        copy = Path(scratch) / problem.name
        shutil.copyfile(problem, copy)
        cmd = [_exe("pyperplan"), "-s", "astar", "-H", "lmcut", str(domain), str(copy)]
        start = time.perf_counter()
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=limit)
        except subprocess.TimeoutExpired:
            return "timeout", None, time.perf_counter() - start
        wall = time.perf_counter() - start
        soln = copy.with_name(copy.name + ".soln")
        if proc.returncode != 0 or not soln.exists():
            return f"exit {proc.returncode}", None, wall
        steps = [line for line in soln.read_text().splitlines() if line.strip().startswith("(")]
        return "solved", len(steps), wall


def run_task(domain: Path, problem: Path, limit: float, guided_first: bool) -> dict:
    """Both planners on one task (in the given order); its CSV row."""
    if guided_first:
        g = run_guided(domain, problem, limit)
        p = run_pyperplan(domain, problem, limit)
    else:
        p = run_pyperplan(domain, problem, limit)
        g = run_guided(domain, problem, limit)
    row = {"domain": domain.parent.name, "task": problem.stem, "guided_status": g[0], "guided_length": g[1] or "",
           "guided_wall_s": round(g[2], 4), "guided_search_s": "" if g[3] is None else g[3],
           "pyperplan_status": p[0], "pyperplan_length": p[1] or "", "pyperplan_wall_s": round(p[2], 4), "ratio": ""}
    if g[0] == p[0] == "solved":
        row["ratio"] = round(g[2] / p[2], 4)
    return row


def _read(row: dict) -> bool:
    """Whether guided-lfd read the task (exits 30-39 are input errors: missing, syntax, unsupported ...)."""
    status = row["guided_status"]
    return not (status.startswith("exit 3") and len(status) == len("exit 30"))


def summary(rows: list[dict], limit: float, command: str) -> str:
    """Markdown: median whole-run ratio on the tasks both solve, length agreement, per domain."""
    both = [r for r in rows if r["ratio"] != ""]
    ratios = [float(r["ratio"]) for r in both]
    differ = [r for r in both if str(r["guided_length"]) != str(r["pyperplan_length"])]
    g_only = [r for r in rows if r["guided_status"] == "solved" and r["pyperplan_status"] != "solved"]
    p_only = [r for r in rows if r["pyperplan_status"] == "solved" and r["guided_status"] != "solved"]
    lines = ["# `guided-lfd plan` vs `pyperplan -s astar -H lmcut`", "", f"Regenerate with: `{command}`", "",
             f"{len(rows)} IPC tasks, {limit:g} s per run; whole-process wall time as the shell sees it. "
             "Ratio = guided-lfd / pyperplan (below 1: guided-lfd is faster).", "",
             "| tasks | both solve | only guided-lfd | only pyperplan | median ratio | geo-mean ratio "
             "| median wall guided-lfd | median wall pyperplan | different lengths |", "|---|---|---|---|---|---|---|---|---|"]
    if ratios:
        import math

        geo = math.exp(statistics.fmean(math.log(r) for r in ratios))
        lines.append(f"| {len(rows)} | {len(both)} | {len(g_only)} | {len(p_only)} | {statistics.median(ratios):.2f} "
                     f"| {geo:.2f} | {statistics.median(float(r['guided_wall_s']) for r in both):.2f} s "
                     f"| {statistics.median(float(r['pyperplan_wall_s']) for r in both):.2f} s | {len(differ)} |")
    lines += ["", "| domain | tasks | read | both solve | same length | median ratio | only guided-lfd "
              "| only pyperplan |", "|---|---|---|---|---|---|---|---|"]
    for dom in sorted({r["domain"] for r in rows}):
        mine = [r for r in rows if r["domain"] == dom]
        sub = [r for r in both if r["domain"] == dom]
        ratio = f"{statistics.median(float(r['ratio']) for r in sub):.2f}" if sub else "-"
        same = sum(str(r["guided_length"]) == str(r["pyperplan_length"]) for r in sub)
        lines.append(f"| {dom} | {len(mine)} | {sum(_read(r) for r in mine)} | {len(sub)} | {same} | {ratio} "
                     f"| {sum(r in g_only for r in mine)} | {sum(r in p_only for r in mine)} |")
    refused = [r for r in rows if not _read(r)]
    if refused:
        lines += ["", f"Refused by the reader ({len(refused)}; the exit code says why, see the README's table):", ""]
        lines += [f"- {r['domain']} {r['task']}: {r['guided_status']}" for r in refused]
    if differ:
        lines += ["", "Different plan lengths (a bug in one of them):", ""]
        lines += [f"- {r['domain']} {r['task']}: {r['guided_length']} vs {r['pyperplan_length']}" for r in differ]
    else:
        lines += ["", "Every task both solve has the same (optimal) plan length."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tasks", default=",".join(f"task{i:02d}" for i in range(1, 11)),
                        help="comma-separated task names, or 'all': every task of the collection")
    parser.add_argument("--domains", default="", help="comma-separated domain names (default: all shipped)")
    parser.add_argument("--time-limit", type=float, default=30.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", type=Path, default=OUT)
    parser.add_argument("--ipc", type=Path, default=IPC, help="the collection: one folder per domain")
    args = parser.parse_args(argv)
    wanted = set(args.domains.split(",")) if args.domains else None
    domains = [d for d in sorted(args.ipc.iterdir())
               if (d / "domain.pddl").is_file() and (wanted is None or d.name in wanted)]
    if args.tasks == "all":
        work = [(d / "domain.pddl", p) for d in domains for p in sorted(d.glob("task*.pddl"))]
    else:
        work = [(d / "domain.pddl", d / f"{t}.pddl") for d in domains
                for t in args.tasks.split(",") if (d / f"{t}.pddl").is_file()]
    rows: list[dict] = []
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(run_task, dom, prob, args.time_limit, k % 2 == 0) for k, (dom, prob) in enumerate(work)]
        for fut in futures:
            row = fut.result()
            rows.append(row)
            print(f"{row['domain']} {row['task']}: guided {row['guided_status']} {row['guided_length']} "
                  f"{row['guided_wall_s']} s | pyperplan {row['pyperplan_status']} {row['pyperplan_length']} "
                  f"{row['pyperplan_wall_s']} s", file=sys.stderr, flush=True)
    args.out.mkdir(parents=True, exist_ok=True)
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=FIELDS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    (args.out / "plan.csv").write_text(buf.getvalue(), encoding="utf-8")
    command = "python benchmarks/plan_bench.py " + " ".join(argv if argv is not None else sys.argv[1:])
    text = summary(rows, args.time_limit, command.strip())
    (args.out / "summary.md").write_text(text, encoding="utf-8")
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
