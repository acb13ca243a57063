#!/usr/bin/env python3
"""Proving "the robot cannot": `guided-lfd plan` on the IPC 2016 unsolvability track beside Fast Downward.

    python benchmarks/unsolvability_bench.py --jobs 1 --time-limit 60 --smallest 2   # -> benchmarks/unsolvability_results/

For the smallest ``--smallest`` tasks (by file size) of each of the track's 20
domain folders in data/benchmarks/unsolvability-ipc2016 (8 tasks each; every
task there is unsolvable), three whole runs from the shell, each with the same
time limit:

* `guided-lfd plan DOMAIN PROBLEM --json --quiet --time-limit T`;
* Fast Downward's LAMA first iteration (``--alias lama-first``) and its A* with
  LM-cut (``--search "astar(lmcut())"``), from the optional `up-fast-downward`
  package (or ``--fast-downward PATH`` to its ``fast-downward.py``).

A proof counts only where the planner says so: guided-lfd's ``unsolvable``,
Fast Downward's exit codes 10 and 11 (an incomplete search that ends without a
plan, 12, is no proof).  A plan found on this track would be a claim against
the track's own label; the summary counts such runs separately.

guided-lfd's default runs two processes (A* and the symbolic prover beside
it), so one run at a time (``--jobs 1``) keeps both of its cores its own.
"""

from __future__ import annotations

import argparse
import csv
import statistics
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from adl_bench import fast_downward_script, run_fd, tasks  # noqa: E402  (the same Fast Downward runs)
from plan_bench import guided_run  # noqa: E402  (one guided-lfd process, timed from outside)

ROOT = Path(__file__).resolve().parent.parent
TRACK = ROOT / "data" / "benchmarks" / "unsolvability-ipc2016"
OUT = ROOT / "benchmarks" / "unsolvability_results"
FIELDS = ["domain", "task", "guided_status", "guided_answered_by", "guided_wall_s", "lama_status", "lama_wall_s", "lmcut_status",
          "lmcut_wall_s"]
LAMA = [(("--alias", "lama-first"), ())]
LMCUT = [((), ("--search", "astar(lmcut())"))]


def smallest(k: int, root: Path = TRACK) -> list[tuple[Path, Path]]:
    """(domain, problem) of the ``k`` smallest problem files of each domain folder."""
    by_folder: dict[Path, list[tuple[Path, Path]]] = {}
    for domain, problem in tasks(root):
        by_folder.setdefault(problem.parent, []).append((domain, problem))
    return [pair for pairs in by_folder.values() for pair in sorted(pairs, key=lambda p: p[1].stat().st_size)[:k]]


def run_task(domain: Path, problem: Path, limit: float, script: Path | None) -> dict:
    """The three runs of one task, as a CSV row."""
    status, doc, wall = guided_run(domain, problem, limit)
    row = {"domain": problem.parent.name, "task": problem.stem, "guided_status": status,
           "guided_answered_by": (doc or {}).get("answered_by", ""), "guided_wall_s": f"{wall:.2f}", "lama_status": "", "lama_wall_s": "", "lmcut_status": "",
           "lmcut_wall_s": ""}
    if script is not None:
        for name, configs in (("lama", LAMA), ("lmcut", LMCUT)):
            _, fd_status, _, fd_wall = run_fd(script, domain, problem, limit, configs)
            row[f"{name}_status"], row[f"{name}_wall_s"] = fd_status, f"{fd_wall:.2f}"
    return row


def summary(rows: list[dict], limit: float, command: str) -> str:
    """Proofs per planner and domain, and the median whole-run time where both guided-lfd and LAMA prove it."""
    planners = [("guided-lfd", "guided"), ("FD lama-first", "lama"), ("FD A* LM-cut", "lmcut")]
    lines = [f"# IPC 2016 unsolvability track ({limit:g} s per run)", "", f"`{command}`", "",
             "| domain | tasks | " + " | ".join(f"proved: {n}" for n, _ in planners) + " |",
             "|---|---|" + "---|" * len(planners)]
    for family in sorted({r["domain"] for r in rows}) + ["all"]:
        group = [r for r in rows if family in ("all", r["domain"])]
        cells = [str(sum(r[f"{key}_status"] == "unsolvable" for r in group)) for _, key in planners]
        lines.append(f"| {'**all**' if family == 'all' else family} | {len(group)} | " + " | ".join(cells) + " |")
    both = [r for r in rows if r["guided_status"] == r["lama_status"] == "unsolvable"]
    if both:
        ratio = statistics.median(float(r["guided_wall_s"]) / max(float(r["lama_wall_s"]), 1e-3) for r in both)
        lines += ["", f"Where both guided-lfd and LAMA prove it ({len(both)} tasks), guided-lfd's whole run takes "
                      f"{ratio:.1f}x LAMA's (median)."]
    symbolic = sum(r["guided_status"] == "unsolvable" and r.get("guided_answered_by") == "symbolic" for r in rows)
    lines += ["", f"guided-lfd's proofs by its symbolic prover (the rest by A*): {symbolic}."]
    wrong = [r for r in rows if "solved" in (r["guided_status"], r["lama_status"], r["lmcut_status"])]
    lines += ["", f"Runs that found a plan on a task labelled unsolvable: {len(wrong)}."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run the comparison and write ``unsolvability.csv`` and ``summary.md``."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--time-limit", type=float, default=60.0)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--smallest", type=int, default=2, help="tasks per domain folder, smallest first")
    parser.add_argument("--fast-downward", type=Path, default=None, help="fast-downward.py (default: up-fast-downward's)")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    script = args.fast_downward or fast_downward_script()
    pairs = smallest(args.smallest)
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    with ThreadPoolExecutor(args.jobs) as pool:
        for k, row in enumerate(pool.map(lambda p: run_task(*p, args.time_limit, script), pairs), 1):
            rows.append(row)
            print(f"[{k}/{len(pairs)}] {row['domain']}/{row['task']}: guided {row['guided_status']} "
                  f"{row['guided_wall_s']} s, lama {row['lama_status'] or '-'}, lmcut {row['lmcut_status'] or '-'}",
                  file=sys.stderr, flush=True)
    command = (f"python benchmarks/unsolvability_bench.py --jobs {args.jobs} --time-limit {args.time_limit:g} "
               f"--smallest {args.smallest}")
    write_results(args.out, "unsolvability.csv", FIELDS, rows, summary(rows, args.time_limit, command))
    return 0


def write_results(out: Path, name: str, fields: list[str], rows: list[dict], text: str) -> None:
    """``rows`` as ``out/name`` (CSV) and ``text`` as ``out/summary.md``, also printed."""
    from guided_lfd.io import write_text

    out.mkdir(parents=True, exist_ok=True)
    with open(out / name, "w", newline="", encoding="utf-8") as fh:
        writer = csv.DictWriter(fh, fieldnames=fields, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    write_text(out / "summary.md", text)
    print(text)


if __name__ == "__main__":
    sys.exit(main())
