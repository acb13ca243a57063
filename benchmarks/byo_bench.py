#!/usr/bin/env python3
"""Bring your own robot: the whole loop on domains in vocabularies unlike the kitchens'.

    python benchmarks/byo_bench.py            # -> benchmarks/byo_results/{byo.csv,summary.md}

For every domain under ``tests/data/byo/`` (a robot missing one or two skills,
the human model with all of them, a task and a larger task), the installed
command line runs ``guided-lfd teach robot.pddl problem.pddl --simulate
human.pddl`` in its own process (whole-run wall time, set-up included).  Then,
with the taught ``robot.pddl``:

* the original task and the larger task are planned (``guided-lfd plan``), and
  the larger plan's uses of the learned skills are counted;
* every learned skill (an action the taught robot has and the robot had not)
  is compared with the human model's action of the same name (or, unnamed,
  the best-matching one): precision and recall of its preconditions and of its
  effects under the best parameter mapping, pooled over the domain's skills.
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
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.benchmark import cli_command  # noqa: E402

BYO = ROOT / "tests" / "data" / "byo"
OUT = ROOT / "benchmarks" / "byo_results"
FIELDS = ["domain", "hand_facts", "missing", "status", "rounds", "learned", "plans_task", "plans_larger",
          "learned_uses_larger", "pre_precision", "pre_recall", "eff_precision", "eff_recall", "teach_wall_s"]


def _plan(domain: Path, problem: Path, time_limit: float) -> list[str] | None:
    """The validated plan ``guided-lfd plan`` prints (None: none found)."""
    proc = subprocess.run([*cli_command(), "plan", str(domain), str(problem), "--json", "--quiet", "--time-limit",
                           f"{time_limit:g}"], capture_output=True, text=True, timeout=10 * time_limit + 60)
    try:
        doc = json.loads(proc.stdout)
    except json.JSONDecodeError:
        return None
    return doc.get("plan")


def run(folder: Path, time_limit: float) -> dict:
    """One domain's row (see the module docstring)."""
    from guided_lfd.demonstration.quality import skill_quality
    from guided_lfd.pddl.reader import parse_domain

    robot, human = parse_domain(str(folder / "robot.pddl")), parse_domain(str(folder / "human.pddl"))
    row: dict = {"domain": folder.name,
                 "missing": " ".join(sorted({a.name for a in human.actions} - {a.name for a in robot.actions}))}
    with tempfile.TemporaryDirectory() as tmp:
        session = Path(tmp) / "session"
        cmd = [*cli_command(), "teach", str(folder / "robot.pddl"), str(folder / "problem.pddl"), "--simulate",
               str(folder / "human.pddl"), "-o", str(session), "--json", "--quiet", "--time-limit", f"{time_limit:g}"]
        start = time.perf_counter()
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=10 * time_limit + 60)
        row["teach_wall_s"] = round(time.perf_counter() - start, 3)
        try:
            doc = json.loads(proc.stdout)
        except json.JSONDecodeError:
            return {**row, "status": f"crashed: {proc.stderr.strip()[-120:]}"}
        rounds = doc["rounds"]
        row.update(status=doc["status"], rounds=len(rounds), plans_task=doc["plans_original_task"],
                   hand_facts=(rounds[0].get("vocabulary") or "").split(" (")[0] if rounds else "")
        taught = parse_domain(str(session / "robot.pddl"))
        known = {a.name for a in robot.actions}
        learned = [a for a in taught.actions if a.name not in known]
        row["learned"] = " ".join(a.name for a in learned)
        larger = _plan(session / "robot.pddl", folder / "problem-large.pddl", time_limit)
        row["plans_larger"] = larger is not None
        names = {a.name for a in learned}
        row["learned_uses_larger"] = sum(step.strip("()").split()[0] in names for step in larger or [])
        row.update(skill_quality(learned, human))
    return row


def summary(rows: list[dict], command: str) -> str:
    """The markdown table of the rows."""
    lines = ["# Bring your own robot: teaching on other vocabularies", "", f"Regenerate with: `{command}`", "",
             "`teach --simulate` per domain of `tests/data/byo/`; the taught robot then plans the task and a larger "
             "one; learned skills against the human model's actions (precision / recall).", "",
             "| domain | hand facts | robot lacks | status | rounds | learned | plans task | plans larger (learned "
             "skills used) | pre P / R | eff P / R | teach wall (s) |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['domain']} | {r.get('hand_facts', '')} | {r['missing']} | {r['status']} | "
                     f"{r.get('rounds', '-')} | {r.get('learned', '')} | {r.get('plans_task')} | "
                     f"{r.get('plans_larger')} ({r.get('learned_uses_larger', 0)}) | "
                     f"{r.get('pre_precision', '-')} / {r.get('pre_recall', '-')} | "
                     f"{r.get('eff_precision', '-')} / {r.get('eff_recall', '-')} | {r['teach_wall_s']} |")
    taught = sum(r.get("status") == "solved" and r.get("plans_larger") for r in rows)
    lines += ["", f"Taught, and the taught robot plans the larger task: {taught} of {len(rows)} domains."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run every domain (or those named) and write the CSV and summary."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("domains", nargs="*", help="domain folders under tests/data/byo (default: all)")
    parser.add_argument("--time-limit", type=float, default=60.0, help="per teach/plan run (s)")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    folders = [BYO / d for d in args.domains] or sorted(p for p in BYO.iterdir() if (p / "robot.pddl").is_file())
    rows = [run(folder, args.time_limit) for folder in folders]
    args.out.mkdir(parents=True, exist_ok=True)
    buf = io.StringIO()
    writer = csv.DictWriter(buf, FIELDS, extrasaction="ignore", lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    (args.out / "byo.csv").write_text(buf.getvalue())
    (args.out / "summary.md").write_text(summary(rows, "python benchmarks/byo_bench.py"))
    print((args.out / "summary.md").read_text())
    return 0 if all(r.get("status") == "solved" and r.get("plans_larger") for r in rows) else 1


if __name__ == "__main__":
    raise SystemExit(main())
