#!/usr/bin/env python3
"""Are the default excuses ones a person would accept?  Judged against the complete domain, whole runs from the shell.

    python benchmarks/plausibility_bench.py --jobs 2 --time-limit 20   # -> benchmarks/plausibility_results/

Each task of the excuse suite (``benchmarks/suite.csv``: an IPC task whose robot
lacks one action schema its plan needs; tasks task01-task03 of every family by
default) runs twice as a fresh process, with the same time limit:

* the default: `guided-lfd excuse ROBOT PROBLEM --json --quiet --time-limit T`
  (consistent semantics, no model of what can change: the world's structure and
  the one-place rule are the tool's own guesses);
* the reference: the same with `--fixed-from COMPLETE --invariants-from COMPLETE`
  (the complete domain says what can change and which invariants hold).

A default excuse is *plausible* when each change is to a predicate some action
of the complete domain changes, and the excuse state keeps every invariant of
the complete domain (derived by the independent checker,
:func:`guided_lfd.excuse.laws.derive_laws`, without the one-place rule: these
are the complete domain's own laws).  A run is *answered* when it ends within
the limit with an excuse, a proof that none exists, or "already solvable".

Writes ``plausibility.csv`` (one row per task) and ``summary.md`` (per family:
runs, answered, plausible, sizes against the reference).
"""

from __future__ import annotations

import argparse
import csv
import statistics
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plan_bench import guided_run  # noqa: E402  (one guided-lfd process, timed from outside, as everywhere)

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "benchmarks" / "plausibility_results"
FIELDS = ["id", "domain", "task", "removed_action", "status", "size", "wall_s", "plausible", "implausible_because",
          "excuse", "reference_status", "reference_size", "reference_wall_s", "reference_excuse"]
ANSWERED = ("excuse-found", "no-excuse", "already-solvable")


def _changes(doc: dict | None) -> list[str]:
    excuse = (doc or {}).get("excuse") or {}
    return [c["change"] for c in excuse.get("changes", [])]


def judge(changes: list[str], complete, problem, laws) -> str:
    """Why the excuse ``changes`` is implausible against the complete domain ('' = plausible)."""
    from guided_lfd.pddl.model import Atom

    fluent = complete.fluent_predicates()
    state = set(problem.init)
    reasons = []
    for change in changes:
        name, *args = change[1:].strip("()").lower().split()
        atom = Atom(name, tuple(args))
        if name not in fluent:
            reasons.append(f"{change}: no action of the complete domain changes {name}")
        (state.add if change.startswith("+") else state.discard)(atom)
    reasons += [f"breaks {law}" for law in laws.broken(frozenset(state))]
    return "; ".join(reasons)


def run_task(task, robots: Path, limit: float) -> dict:
    """Both runs of one suite task, and the default excuse judged."""
    from guided_lfd.benchmark import robot_domain_file
    from guided_lfd.excuse.laws import derive_laws
    from guided_lfd.pddl.reader import parse_task

    robot = robot_domain_file(task, robots)
    status, doc, wall = guided_run(robot, Path(task.problem_file), limit, "excuse")
    ref_status, ref, ref_wall = guided_run(robot, Path(task.problem_file), limit, "excuse",
                                           ("--fixed-from", task.domain_file, "--invariants-from", task.domain_file))
    changes = _changes(doc)
    why = ""
    if changes:
        complete, problem = parse_task(task.domain_file, task.problem_file)
        why = judge(changes, complete, problem, derive_laws(complete, problem, one_place=False))
    size = (doc or {}).get("excuse", {}) or {}
    ref_size = (ref or {}).get("excuse", {}) or {}
    return {"id": task.id, "domain": task.domain, "task": task.task, "removed_action": task.removed_action,
            "status": status, "size": size.get("size", ""), "wall_s": f"{wall:.2f}",
            "plausible": "" if not changes else ("yes" if not why else "no"), "implausible_because": why,
            "excuse": " ".join(changes), "reference_status": ref_status, "reference_size": ref_size.get("size", ""),
            "reference_wall_s": f"{ref_wall:.2f}", "reference_excuse": " ".join(_changes(ref))}


def summary(rows: list[dict], limit: float, command: str) -> str:
    """Per family: runs, answered, plausible, sizes against the reference."""
    lines = [f"# Plausibility of the default excuses ({limit:g} s per run)", "", f"`{command}`", "",
             "| family | runs | answered | excuses | plausible | reference answered | same size | larger | smaller "
             "| median wall s |", "|---|---|---|---|---|---|---|---|---|---|"]
    families = sorted({r["domain"] for r in rows})
    total = {k: 0 for k in ("runs", "answered", "excuses", "plausible", "ref", "same", "larger", "smaller")}
    for family in families + ["all"]:
        group = [r for r in rows if family in ("all", r["domain"])]
        both = [r for r in group if r["size"] != "" and r["reference_size"] != ""]
        counts = {"runs": len(group), "answered": sum(r["status"] in ANSWERED for r in group),
                  "excuses": sum(r["plausible"] != "" for r in group),
                  "plausible": sum(r["plausible"] == "yes" for r in group),
                  "ref": sum(r["reference_status"] in ANSWERED for r in group),
                  "same": sum(int(r["size"]) == int(r["reference_size"]) for r in both),
                  "larger": sum(int(r["size"]) > int(r["reference_size"]) for r in both),
                  "smaller": sum(int(r["size"]) < int(r["reference_size"]) for r in both)}
        if family != "all":
            total = {k: total[k] + counts[k] for k in total}
        wall = statistics.median(float(r["wall_s"]) for r in group) if group else 0.0
        name = "**all**" if family == "all" else family
        lines.append(f"| {name} | {counts['runs']} | {counts['answered']} | {counts['excuses']} | "
                     f"{counts['plausible']} | {counts['ref']} | {counts['same']} | {counts['larger']} | "
                     f"{counts['smaller']} | {wall:.2f} |")
    odd = [r for r in rows if r["plausible"] == "no"]
    lines += ["", f"Implausible default excuses: {len(odd)}."]
    lines += [f"- {r['id']}: {r['excuse']} ({r['implausible_because']})" for r in odd]
    differ = [r for r in rows if r["size"] != "" and r["reference_size"] != "" and r["size"] != r["reference_size"]]
    lines += ["", f"Sizes that differ from the reference: {len(differ)}."]
    lines += [f"- {r['id']}: default {r['size']} `{r['excuse']}`, reference {r['reference_size']} "
              f"`{r['reference_excuse']}`" for r in differ]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run the table and write it (see the module's docstring)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time-limit", type=float, default=20.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--tasks", default="task01,task02,task03", help="comma-separated task names per family")
    parser.add_argument("--only", default="", help="comma-separated parts of task ids")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    from guided_lfd.benchmark import read_suite
    from guided_lfd.io import write_text

    wanted = set(args.tasks.split(","))
    suite = [t for t in read_suite(ROOT / "benchmarks" / "suite.csv", ROOT) if t.task in wanted
             and (not args.only or any(k in t.id for k in args.only.split(",")))]
    args.out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as robots, ThreadPoolExecutor(args.jobs) as pool:
        rows = []
        for k, row in enumerate(pool.map(lambda t: run_task(t, Path(robots), args.time_limit), suite), 1):
            rows.append(row)
            print(f"[{k}/{len(suite)}] {row['id']}: {row['status']} {row['size']} plausible={row['plausible'] or '-'}"
                  f" reference {row['reference_status']} {row['reference_size']}", file=sys.stderr, flush=True)
    with open(args.out / "plausibility.csv", "w", newline="", encoding="utf-8") as fh:
        writer = csv.DictWriter(fh, fieldnames=FIELDS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    command = f"python benchmarks/plausibility_bench.py --jobs {args.jobs} --time-limit {args.time_limit:g}"
    write_text(args.out / "summary.md", summary(rows, args.time_limit, command))
    print(summary(rows, args.time_limit, command))
    return 0


if __name__ == "__main__":
    sys.exit(main())
