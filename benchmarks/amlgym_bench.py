"""Score `guided-lfd learn-domain` on AMLGym's trajectories beside SAM and OffLAM, run through AMLGym.

For every domain of AMLGym's learning benchmark (21 IPC learning-track domains,
10 trajectories each) and 1, 3 and 10 trajectories, each learner gets the
domain with empty action bodies (AMLGym's own `empty_domain`) and the first N
trajectories; the learned model is scored with AMLGym's metric functions:
syntactic precision and recall (mean over operators) and, with 10 trajectories,
problem solving on the domain's 10 solving problems (its Fast Downward
configuration through unified-planning, plans validated in the true domain).

Learners: guided-lfd's safe and general models (the `guided-lfd` command of
this environment, timed as a whole run from process start), SAM (n-sam) and
OffLAM (AMLGym's adapters, timed around `learn`).

Set-up (once; AMLGym's metrics and these two learners, not its torch-based
ones): `make amlgym-setup`, then `make amlgym-bench` runs this script in that
environment:

    .venv-amlgym/bin/python benchmarks/amlgym_bench.py --jobs 2 --out benchmarks/amlgym_results
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import importlib
import io
import os
import shutil
import subprocess
import sys
import tempfile
import time
import types
import warnings
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

LEARNERS = ("guided-lfd safe", "guided-lfd general", "SAM", "OffLAM")
COUNTS = (1, 3, 10)
FIELDS = ["domain", "trajectories", "learner", "learn_s", "precision", "recall", "solved", "false_plans",
          "unsolvable", "timed_out", "syntax_errors", "problems", "error"]


def _amlgym_root() -> Path:
    import amlgym

    return Path(amlgym.__file__).parent


def _adapter(name: str):
    """AMLGym's adapter class ``name`` (SAM, OffLAM), imported without the package's registry, which imports
    every algorithm, the torch-based ones included."""
    if "amlgym.algorithms" not in sys.modules:
        package = types.ModuleType("amlgym.algorithms")
        package.__path__ = [str(_amlgym_root() / "algorithms")]
        sys.modules["amlgym.algorithms"] = package
    return getattr(importlib.import_module(f"amlgym.algorithms.{name}"), name)


def _trajectories(domain: str, count: int) -> list[str]:
    folder = _amlgym_root() / "benchmarks" / "trajectories" / "learning" / domain
    files = sorted(folder.iterdir(), key=lambda p: int(p.name.split("_")[0]))
    return [str(p) for p in files[:count]]


def _learn(learner: str, empty: str, trajectories: list[str], out: str) -> float:
    """Learn with ``learner``; the model is written to ``out``; returns the learning time in seconds."""
    start = time.perf_counter()
    if learner.startswith("guided-lfd"):
        command = [str(Path(sys.executable).parent / "guided-lfd"), "learn-domain", "--prior", empty,
                   *trajectories, "--model", learner.split()[1], "-o", out, "--quiet"]
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"exit {done.returncode}")
    else:
        with contextlib.redirect_stdout(io.StringIO()):
            model = _adapter(learner)().learn(empty, trajectories)
        Path(out).write_text(model)
    return time.perf_counter() - start


def run_one(task: tuple[str, int, str, int]) -> dict:
    """One (domain, number of trajectories, learner) cell, in a scratch folder of its own (the adapters and
    the solving metric write ``tmp`` files into the current folder)."""
    domain, count, learner, timeout = task
    from amlgym.metrics import problem_solving, syntactic_precision, syntactic_recall
    from amlgym.util.util import empty_domain

    row: dict = {"domain": domain, "trajectories": count, "learner": learner}
    home = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="amlgym-") as scratch:
        os.chdir(scratch)
        # A copy of the true domain per cell: AMLGym's reader writes a '<file>_clean' beside the file it reads.
        reference = shutil.copy(_amlgym_root() / "benchmarks" / "domains" / f"{domain}.pddl", "reference.pddl")
        reference = os.path.join(scratch, reference)
        try:
            warnings.simplefilter("ignore")
            empty = empty_domain(reference, os.path.join(scratch, "empty.pddl"))
            learned = os.path.join(scratch, "learned.pddl")
            row["learn_s"] = round(_learn(learner, empty, _trajectories(domain, count), learned), 3)
            row["precision"] = float(syntactic_precision(learned, reference)["mean"])
            row["recall"] = float(syntactic_recall(learned, reference)["mean"])
            if count == max(COUNTS):
                folder = _amlgym_root() / "benchmarks" / "problems" / "solving" / domain
                problems = sorted(str(p) for p in folder.glob("*.pddl"))
                with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
                    solving = problem_solving(learned, reference, problems, timeout=timeout, show_progress=False)
                row["problems"] = len(problems)
                for key, name in (("solving_ratio", "solved"), ("false_plans_ratio", "false_plans"),
                                  ("unsolvable_ratio", "unsolvable"), ("timed_out", "timed_out"),
                                  ("syntax_errors", "syntax_errors")):
                    row[name] = round(solving[key] * len(problems))
        except Exception as exc:  # a learner or metric failing is a result to report, not a crash
            row["error"] = " ".join(f"{type(exc).__name__}: {exc}".split())[:200]
        finally:
            os.chdir(home)
    return row


def _mean(rows: list[dict], key: str) -> str:
    values = [r[key] for r in rows if r.get(key) not in (None, "")]
    return f"{sum(values) / len(values):.3f}" if values else "-"


def table(rows: list[dict], domains: list[str]) -> str:
    """The markdown table: per domain and learner, P/R at 1, 3 and 10 trajectories and solving at 10."""
    head = ["domain", "learner", *(f"P/R {n}" for n in COUNTS), "solved (false) of 10"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    by = {(r["domain"], r["learner"], r["trajectories"]): r for r in rows}
    for domain in [*domains, "mean"]:
        for learner in LEARNERS:
            cells = [domain, learner]
            for n in COUNTS:
                if domain == "mean":
                    sel = [r for r in rows if r["learner"] == learner and r["trajectories"] == n]
                    cells.append(f"{_mean(sel, 'precision')} / {_mean(sel, 'recall')}")
                else:
                    r = by.get((domain, learner, n), {})
                    cells.append(f"{r['precision']:.2f} / {r['recall']:.2f}"
                                 if r.get("precision") is not None and r.get("recall") is not None
                                 else f"error: {(r.get('error') or '-')[:40]}")
            sel = [r for r in rows if r["learner"] == learner and r["trajectories"] == max(COUNTS)
                   and (domain == "mean" or r["domain"] == domain) and r.get("solved") not in (None, "")]
            cells.append(f"{sum(r['solved'] for r in sel)} ({sum(r['false_plans'] for r in sel)})" if sel else "-")
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def summary(rows: list[dict], domains: list[str]) -> str:
    """The compact table: one row per domain at 10 trajectories (P / R of each learner, problems solved and
    false plans), then the mean over domains at 1, 3 and 10 trajectories (the learning curve)."""
    by = {(r["domain"], r["learner"], r["trajectories"]): r for r in rows}
    head = ["domain (trajectories)", *(f"{learner} P / R" for learner in LEARNERS), "solved (false plans): "
            + " · ".join(LEARNERS)]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]

    def pr(sel: list[dict]) -> str:
        return f"{_mean(sel, 'precision')} / {_mean(sel, 'recall')}" if sel else "-"

    def solved(sel: list[dict]) -> str:
        sel = [r for r in sel if r.get("solved") not in (None, "")]
        return f"{sum(r['solved'] for r in sel)} ({sum(r['false_plans'] for r in sel)})" if sel else "-"

    top = max(COUNTS)
    for domain in domains:
        cells = [f"{domain} ({top})"]
        cells += [pr([by[k]] if (k := (domain, learner, top)) in by else []) for learner in LEARNERS]
        cells.append(" · ".join(solved([by[k]] if (k := (domain, learner, top)) in by else []) for learner in LEARNERS))
        lines.append("| " + " | ".join(cells) + " |")
    for n in COUNTS:
        sel = {learner: [r for r in rows if r["learner"] == learner and r["trajectories"] == n] for learner in LEARNERS}
        cells = [f"**mean ({n})**", *(pr(sel[learner]) for learner in LEARNERS)]
        cells.append(" · ".join(solved(sel[learner]) for learner in LEARNERS) if n == top else "")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def _read(path: Path) -> list[dict]:
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            for key in ("precision", "recall", "learn_s"):
                row[key] = float(row[key]) if row.get(key) else None
            for key in ("trajectories", "solved", "false_plans", "unsolvable", "timed_out", "syntax_errors", "problems"):
                row[key] = int(row[key]) if row.get(key) else None
            rows.append(row)
    return rows


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark; write results.csv and table.md into --out."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=2, help="Cells run in parallel (default 2).")
    parser.add_argument("--out", default="benchmarks/amlgym_results", help="Output folder.")
    parser.add_argument("--domains", nargs="*", help="Only these domains (default: all 21).")
    parser.add_argument("--learners", nargs="*", default=list(LEARNERS), help="Only these learners.")
    parser.add_argument("--timeout", type=int, default=60, help="Planner time limit per solving problem (s).")
    parser.add_argument("--report", action="store_true", help="Only rewrite the tables from --out's results.csv.")
    args = parser.parse_args(argv)
    out = Path(args.out)
    if args.report:
        rows = _read(out / "results.csv")
        domains = list(dict.fromkeys(r["domain"] for r in rows))
        (out / "table.md").write_text(table(rows, domains))
        (out / "summary.md").write_text(summary(rows, domains))
        return 0
    try:
        folder = _amlgym_root() / "benchmarks" / "trajectories" / "learning"
    except ImportError:
        print("amlgym is not installed: run `make amlgym-setup` first (see the module docstring)", file=sys.stderr)
        return 2
    domains = args.domains or sorted(p.name for p in folder.iterdir() if p.is_dir())
    tasks = [(d, n, learner, args.timeout) for d in domains for n in COUNTS for learner in args.learners]
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    rows: list[dict] = []
    # Rows are written as they come: a long run stopped half-way keeps what it measured.
    with ProcessPoolExecutor(max_workers=args.jobs) as pool, open(out / "results.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        for row in pool.map(run_one, tasks):
            rows.append(row)
            writer.writerow(row)
            f.flush()
            status = row.get("error") or f"P={row.get('precision')} R={row.get('recall')} solved={row.get('solved', '-')}"
            print(f"{row['domain']:12s} {row['trajectories']:2d} {row['learner']:18s} {status}", file=sys.stderr)
    (out / "table.md").write_text(table(rows, domains))
    (out / "summary.md").write_text(summary(rows, domains))
    print(f"{len(rows)} cells in {time.perf_counter() - start:.0f} s; {out / 'table.md'}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
