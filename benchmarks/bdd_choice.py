#!/usr/bin/env python3
"""Which decision-diagram library: CUDD (``dd.cudd``) against OxiDD, on the same symbolic searches.

    pip install -e '.[oxidd]'
    python benchmarks/bdd_choice.py --time-limit 30 --smallest 1   # -> benchmarks/bdd_choice_results/

For the smallest ``--smallest`` tasks of each folder of the IPC 2016
unsolvability track (data/benchmarks/unsolvability-ipc2016), the same
bidirectional symbolic decision (:func:`guided_lfd.symbolic.unsolvable.decide`:
the same variables, order, invariants and steps) with each library, one
fresh process per run, timed inside (the search, after grounding) and from
outside (the whole process), with the process's peak memory.  A run the limit
ends counts as unanswered.  Every answer must be "unsolvable": the track's
label.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from unsolvability_bench import smallest, write_results  # noqa: E402  (the same tasks, the same files)

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "benchmarks" / "bdd_choice_results"
LIBRARIES = ("cudd", "oxidd")
FIELDS = ["domain", "task", "library", "answer", "search_s", "wall_s", "peak_mib"]

#: What one run does, in a fresh interpreter: ground, decide, report.
_CHILD = """
import json, resource, sys, time
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.search import planning_actions
from guided_lfd.symbolic.unsolvable import decide
domain, problem = parse_task(sys.argv[1], sys.argv[2])
task = ground(domain, problem, fixed=domain.predicates)
actions = planning_actions(task, task.init)
began = time.monotonic()
proof = decide(task, actions, deadline=began + float(sys.argv[4]), library=sys.argv[3])
print(json.dumps({"solvable": proof.solvable, "search_s": time.monotonic() - began,
                  "peak_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""


def run(domain: Path, problem: Path, library: str, limit: float) -> dict:
    """One decision in a fresh process, as a CSV row."""
    row = {"domain": problem.parent.name, "task": problem.stem, "library": library, "answer": "",
           "search_s": "", "wall_s": "", "peak_mib": ""}
    start = time.perf_counter()
    try:
        proc = subprocess.run([sys.executable, "-c", _CHILD, str(domain), str(problem), library, f"{limit:g}"],
                              capture_output=True, text=True, timeout=limit + 30)
    except subprocess.TimeoutExpired:
        row.update(answer="killed", wall_s=f"{time.perf_counter() - start:.2f}")
        return row
    row["wall_s"] = f"{time.perf_counter() - start:.2f}"
    try:
        doc = json.loads(proc.stdout.strip().splitlines()[-1])
    except (json.JSONDecodeError, IndexError):
        row["answer"] = "timeout" if "SearchTimeout" in proc.stderr else f"exit {proc.returncode}"
        return row
    row.update(answer="solvable" if doc["solvable"] else "unsolvable", search_s=f"{doc['search_s']:.2f}",
               peak_mib=f"{doc['peak_mib']:.0f}")
    return row


def summary(rows: list[dict], limit: float, command: str) -> str:
    """Answers per library and the median ratio of search times where both answer."""
    lines = [f"# Diagram libraries on the unsolvability track ({limit:g} s per run)", "", f"`{command}`", "",
             "| library | answered | solvable answers (wrong) | median search s | median peak MiB |", "|---|---|---|---|---|"]
    for lib in LIBRARIES:
        mine = [r for r in rows if r["library"] == lib]
        answered = [r for r in mine if r["answer"] in ("unsolvable", "solvable")]
        wrong = sum(r["answer"] == "solvable" for r in mine)
        med = statistics.median(float(r["search_s"]) for r in answered) if answered else float("nan")
        peak = statistics.median(float(r["peak_mib"]) for r in answered) if answered else float("nan")
        lines.append(f"| {lib} | {len(answered)} of {len(mine)} | {wrong} | {med:.2f} | {peak:.0f} |")
    by_task: dict[tuple[str, str], dict[str, dict]] = {}
    for r in rows:
        by_task.setdefault((r["domain"], r["task"]), {})[r["library"]] = r
    both = [(t["cudd"], t["oxidd"]) for t in by_task.values()
            if all(lib in t and t[lib]["answer"] == "unsolvable" for lib in LIBRARIES)]
    if both:
        ratio = statistics.median(float(o["search_s"]) / max(float(c["search_s"]), 1e-3) for c, o in both)
        lines += ["", f"Where both answer ({len(both)} tasks), OxiDD's search takes {ratio:.2f}x CUDD's (median)."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run both libraries on the tasks, one run at a time; write ``bdd_choice.csv`` and ``summary.md``."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time-limit", type=float, default=30.0)
    parser.add_argument("--smallest", type=int, default=1, help="tasks per domain folder, smallest first")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    rows = []
    for domain, problem in smallest(args.smallest):
        for lib in LIBRARIES:
            rows.append(run(domain, problem, lib, args.time_limit))
            r = rows[-1]
            print(f"{r['domain']}/{r['task']} {lib}: {r['answer']} {r['search_s']} s", file=sys.stderr, flush=True)
    command = f"python benchmarks/bdd_choice.py --time-limit {args.time_limit:g} --smallest {args.smallest}"
    write_results(args.out, "bdd_choice.csv", FIELDS, rows, summary(rows, args.time_limit, command))
    return 0


if __name__ == "__main__":
    sys.exit(main())
