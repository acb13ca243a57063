#!/usr/bin/env python3
"""`guided-lfd plan` on the IPC's ADL domains beside Fast Downward's optimal search, whole runs from the shell.

    python benchmarks/adl_bench.py --jobs 2 --time-limit 60   # -> benchmarks/adl_results/{adl.csv,summary.md}

For every task of data/benchmarks/ipc-adl (28 domains, 6 small tasks each;
the domain file is ``domain.pddl`` or the one named after the task) both
commands run as fresh processes with the same time limit:

* `guided-lfd plan DOMAIN PROBLEM --json --quiet --time-limit T`
* Fast Downward (the binary of the optional `up-fast-downward` package, or
  ``--fast-downward PATH`` to its ``fast-downward.py``) with
  ``astar(lmcut())``, or ``astar(blind())`` where LM-cut refuses the task's
  conditional effects or axioms.

It records whether guided-lfd read the task, each side's status, optimal
cost and whole-run wall time, and whether the costs agree (both are optimal:
they must).  Without Fast Downward only guided-lfd's columns are filled.
"""

from __future__ import annotations

import argparse
import csv
import re
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plan_bench import guided_run  # noqa: E402  (the same guided-lfd process as the STRIPS comparison)

ROOT = Path(__file__).resolve().parent.parent
ADL = ROOT / "data" / "benchmarks" / "ipc-adl"
OUT = ROOT / "benchmarks" / "adl_results"
FIELDS = ["domain", "task", "guided_status", "guided_cost", "guided_wall_s", "guided_search_s",
          "fd_search", "fd_status", "fd_cost", "fd_wall_s"]


def tasks(root: Path = ADL) -> list[tuple[Path, Path]]:
    """(domain, problem) pairs of the collection: ``domain.pddl``, else the domain file named after the task."""
    out = []
    for folder in sorted(p for p in root.iterdir() if p.is_dir()):
        files = sorted(folder.glob("*.pddl"))
        domains = [f for f in files if "domain" in f.name]
        for problem in (f for f in files if f not in domains):
            own = [d for d in domains if problem.stem in d.stem.replace("domain", "")]
            domain = own[0] if own else folder / "domain.pddl"
            out.append((domain, problem))
    return out


def fast_downward_script() -> Path | None:
    """Fast Downward's driver script from the `up-fast-downward` package, if installed."""
    try:
        import up_fast_downward
    except ImportError:
        return None
    script = Path(up_fast_downward.__file__).parent / "downward" / "fast-downward.py"
    return script if script.exists() else None


#: Fast Downward configurations (options before the files, options after them), tried in turn where the task
#: uses what one refuses: A* with LM-cut, else blind A*.
OPTIMAL = [((), ("--search", "astar(lmcut())")), ((), ("--search", "astar(blind())"))]


def run_fd(script: Path, domain: Path, problem: Path, limit: float,
           configs=OPTIMAL) -> tuple[str, str, int | None, float]:
    """(configuration, status, cost, wall s) of Fast Downward with the first of ``configs`` the task allows;
    status ``unsolvable`` only where Fast Downward proves it (its exit codes 10 and 11)."""
    for before, after in configs:
        search = " ".join((*before, *after))
        with tempfile.TemporaryDirectory() as scratch:
            cmd = [sys.executable, str(script), *before, "--overall-time-limit", f"{int(limit)}s", str(domain),
                   str(problem), *after]
            start = time.perf_counter()
            try:
                proc = subprocess.run(cmd, capture_output=True, text=True, timeout=limit + 30, cwd=scratch)
            except subprocess.TimeoutExpired:
                return search, "timeout", None, time.perf_counter() - start
            wall = time.perf_counter() - start
        out = proc.stdout + proc.stderr
        if "not supported" in out.lower() or "unsupported" in out.lower():
            continue
        cost = re.search(r"Plan cost: (\d+)", out)
        if cost:
            return search, "solved", int(cost.group(1)), wall
        if proc.returncode in (10, 11):  # the translator or a complete search proved it
            return search, "unsolvable", None, wall
        if proc.returncode == 12:  # an incomplete search ended without a plan: no proof
            return search, "unsolved-incomplete", None, wall
        if proc.returncode in (21, 23, 24) or "Time limit" in out:  # translator or search out of time
            return search, "timeout", None, wall
        if proc.returncode in (20, 22):  # translator or search out of memory
            return search, "memout", None, wall
        return search, f"exit {proc.returncode}", None, wall
    return "-", "unsupported", None, 0.0


def run_guided(domain: Path, problem: Path, limit: float) -> tuple[str, int | None, float, float | None]:
    """(status, plan cost, wall s, search s) of one `guided-lfd plan` process."""
    status, doc, wall = guided_run(domain, problem, limit)
    return status, None if doc is None else doc.get("cost"), wall, None if doc is None else doc.get("time_s")


def run_task(domain: Path, problem: Path, limit: float, script: Path | None) -> dict:
    """Both planners on one task; its CSV row."""
    g = run_guided(domain, problem, limit)
    row = {"domain": problem.parent.name, "task": problem.stem, "guided_status": g[0],
           "guided_cost": "" if g[1] is None else g[1],
           "guided_wall_s": round(g[2], 4), "guided_search_s": "" if g[3] is None else g[3],
           "fd_search": "", "fd_status": "", "fd_cost": "", "fd_wall_s": ""}
    if script is not None:
        search, status, cost, wall = run_fd(script, domain, problem, limit)
        row.update(fd_search=search, fd_status=status, fd_cost="" if cost is None else cost,
                   fd_wall_s=round(wall, 4))
    return row


def summary(rows: list[dict], limit: float, command: str, fd: bool) -> str:
    """Markdown: read / solved / same optimal cost, per domain and in total."""
    def read(r: dict) -> bool:
        return not re.fullmatch(r"exit 3\d", r["guided_status"])

    both = [r for r in rows if r["guided_status"] == "solved" and r["fd_status"] == "solved"]
    differ = [r for r in both if str(r["guided_cost"]) != str(r["fd_cost"])]
    lines = ["# `guided-lfd plan` on IPC ADL domains" + (" beside Fast Downward" if fd else ""), "",
             f"Regenerate with: `{command}`", "",
             f"{len(rows)} tasks, {limit:g} s per run, whole-process wall time as the shell sees it. Fast Downward: "
             "`astar(lmcut())`, or `astar(blind())` where LM-cut refuses conditional effects or axioms.", "",
             "| domain | tasks | read | guided-lfd solved | FD solved | both | same cost | median wall guided-lfd "
             "| median wall FD |", "|---|---|---|---|---|---|---|---|---|"]
    groups = sorted({r["domain"] for r in rows})
    for dom in [*groups, None]:
        mine = [r for r in rows if dom is None or r["domain"] == dom]
        sub = [r for r in both if r in mine]
        g_wall = f"{statistics.median(float(r['guided_wall_s']) for r in sub):.2f} s" if sub else "-"
        f_wall = f"{statistics.median(float(r['fd_wall_s']) for r in sub):.2f} s" if sub else "-"
        name = dom or "**all**"
        lines.append(f"| {name} | {len(mine)} | {sum(read(r) for r in mine)} "
                     f"| {sum(r['guided_status'] == 'solved' for r in mine)} "
                     f"| {sum(r['fd_status'] == 'solved' for r in mine)} | {len(sub)} "
                     f"| {len(sub) - sum(r in differ for r in sub)} | {g_wall} | {f_wall} |")
    if differ:
        lines += ["", "Different optimal costs (a bug in one of them):", ""]
        lines += [f"- {r['domain']} {r['task']}: guided-lfd {r['guided_cost']}, FD {r['fd_cost']}" for r in differ]
    else:
        lines += ["", "Every task both solve has the same optimal cost."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run the comparison and write the CSV and the summary."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--time-limit", type=float, default=60.0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", default=None, help="domains whose name contains this")
    ap.add_argument("--fast-downward", type=Path, default=None, help="path to fast-downward.py")
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args(argv)
    script = args.fast_downward or fast_downward_script()
    todo = [(d, p) for d, p in tasks() if args.only is None or args.only in p.parent.name]
    with ThreadPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(lambda dp: run_task(dp[0], dp[1], args.time_limit, script), todo))
    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "adl.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    command = "python benchmarks/adl_bench.py " + " ".join(sys.argv[1:] if argv is None else argv)
    text = summary(rows, args.time_limit, command.strip(), script is not None)
    (args.out / "summary.md").write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
