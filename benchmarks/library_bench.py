#!/usr/bin/env python3
"""Skills that carry to the next task: a second task, and a curriculum, on every BYO domain.

    python benchmarks/library_bench.py         # -> benchmarks/library_results/{second_task.csv,curriculum.csv,summary.md}

For every domain under ``tests/data/byo/`` that has a second task (``problem-2.pddl``: a learned skill needed in
a situation its first demonstration did not show), the installed command line, each run in its own process:

* **Second task.** ``teach robot.pddl problem.pddl problem-2.pddl --simulate human.pddl`` (one run over both),
  and the same as two runs (task 1, then task 2 from the robot task 1 left): the second task's demonstrations
  and skill requests (a learned skill shown once more, asked for as a skill excuse), whether the robot plans
  both tasks, and the final learned skills against the human model's actions (precondition and effect
  precision / recall, parameters and static relations included).
* **Curriculum.** A sequence of at least five tasks: ``problem.pddl``, ``problem-2.pddl``,
  ``problem-large.pddl`` and tasks drawn from the larger task's state by seeded random walks of the human model
  (a goal of the fluent facts a walk changed; written to ``library_results/tasks/``).  Demonstrations with the
  growing library (one ``teach`` over the sequence) against demonstrating every task whole (the human's optimal
  plan per task) and against teaching each task from the original robot; the paper's measures: demonstration
  size (demonstrated actions) and F1 savings (the share of the whole-task demonstrations not given).
"""

from __future__ import annotations

import argparse
import json
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.benchmark import cli_command  # noqa: E402
from guided_lfd.benchmark.results import write_csv  # noqa: E402

BYO = ROOT / "tests" / "data" / "byo"
OUT = ROOT / "benchmarks" / "library_results"
SECOND = ["domain", "task1_demonstrations", "task2_demonstrations", "task2_skill_requests", "plans_both",
          "pre_precision", "pre_recall", "eff_precision", "eff_recall", "two_runs_task2_demonstrations",
          "two_runs_plans_both", "two_runs_pre_precision", "two_runs_pre_recall", "two_runs_eff_precision",
          "two_runs_eff_recall", "wall_s"]
CURRICULUM = ["domain", "tasks", "library_demonstrations", "library_actions", "library_solved", "whole_actions",
              "scratch_demonstrations", "scratch_actions", "scratch_solved", "f1_library", "f1_scratch"]


def _teach(robot: Path, problems: list[Path], human: Path, out: Path, time_limit: float) -> tuple[dict | None, float]:
    """``guided-lfd teach`` as a user runs it: its JSON document (a session, or a library for several tasks)."""
    cmd = [*cli_command(), "teach", str(robot), *map(str, problems), "--simulate", str(human), "-o", str(out),
           "--json", "--quiet", "--time-limit", f"{time_limit:g}"]
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=10 * time_limit + 120)
    wall = time.perf_counter() - start
    try:
        return json.loads(proc.stdout), wall
    except json.JSONDecodeError:
        return None, wall


def _quality(library: Path, folder: Path) -> dict:
    """The library's learned skills (actions the robot lacked) against the human model's actions."""
    from guided_lfd.demonstration.quality import skill_quality
    from guided_lfd.pddl.reader import parse_domain

    robot, human = parse_domain(str(folder / "robot.pddl")), parse_domain(str(folder / "human.pddl"))
    known = {a.name for a in robot.actions}
    return skill_quality([a for a in parse_domain(str(library)).actions if a.name not in known], human)


def _demonstrations(session: dict) -> int:
    return sum(r["demonstration_length"] is not None for r in session["rounds"])


def second_task(folder: Path, time_limit: float) -> dict:
    """One domain's second-task row (see the module docstring)."""
    row: dict = {"domain": folder.name}
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        doc, _ = _teach(folder / "robot.pddl", [folder / "problem.pddl", folder / "problem-2.pddl"],
                        folder / "human.pddl", Path(tmp) / "one", time_limit)
        if doc is None:
            return {**row, "plans_both": "crashed"}
        first, second = doc["tasks"]
        row.update(task1_demonstrations=first["demonstrations"], task2_demonstrations=second["demonstrations"],
                   task2_skill_requests=len(second["skill_requests"]),
                   plans_both=bool(first["plans_original_task"] and second["plans_original_task"]))
        row.update(_quality(Path(tmp) / "one" / "robot.pddl", folder))
        one, _ = _teach(folder / "robot.pddl", [folder / "problem.pddl"], folder / "human.pddl", Path(tmp) / "a",
                        time_limit)
        two, _ = _teach(Path(tmp) / "a" / "robot.pddl", [folder / "problem-2.pddl"], folder / "human.pddl",
                        Path(tmp) / "b", time_limit)
        row["wall_s"] = round(time.perf_counter() - start, 2)
        if one is None or two is None:
            return {**row, "two_runs_plans_both": "crashed"}
        row.update(two_runs_task2_demonstrations=_demonstrations(two),
                   two_runs_plans_both=bool(one["plans_original_task"] and two["plans_original_task"]))
        row.update({f"two_runs_{k}": v for k, v in _quality(Path(tmp) / "b" / "robot.pddl", folder).items()})
    return row


def _walk_task(folder: Path, seed: int, steps: int, out: Path) -> Path | None:
    """A task from the larger task's state: the fluent facts a seeded random walk of the human model changed."""
    from dataclasses import replace

    from guided_lfd.pddl.model import Literal
    from guided_lfd.pddl.reader import parse_task
    from guided_lfd.pddl.writer import problem_to_pddl
    from guided_lfd.planning.grounding import ground
    from guided_lfd.planning.task import bits

    human, problem = parse_task(str(folder / "human.pddl"), str(folder / "problem-large.pddl"))
    task = ground(human, problem)
    rng, state = random.Random(seed), task.init
    for _ in range(steps):
        moves = [a for a in task.actions if state & a.pre_pos == a.pre_pos and not state & a.pre_neg]
        if not moves:
            break
        act = rng.choice(moves)
        state = (state & ~act.delete) | act.add
    hand = {"holding", "hand-empty", "handempty", "gripper-free", "carrying", "grasped", "free"}
    made = [task.atoms[i] for i in bits(state & ~task.init) if task.atoms[i].predicate not in hand]
    if not made:
        return None
    goal = tuple(Literal(a) for a in sorted(rng.sample(made, min(len(made), 3))))
    name = f"{problem.name}-walk-{seed}"
    path = out / folder.name / f"{name}.pddl"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(problem_to_pddl(replace(problem, name=name, goal=goal)))
    return path


def _whole_actions(folder: Path, task: Path, time_limit: float) -> int | None:
    """The human's optimal plan length for the task: the size of demonstrating it whole."""
    proc = subprocess.run([*cli_command(), "plan", str(folder / "human.pddl"), str(task), "--json", "--quiet",
                           "--time-limit", f"{time_limit:g}"], capture_output=True, text=True,
                          timeout=10 * time_limit + 60)
    try:
        plan = json.loads(proc.stdout).get("plan")
    except json.JSONDecodeError:
        return None
    return None if plan is None else len(plan)


def curriculum(folder: Path, time_limit: float, walks: int, tasks_out: Path) -> dict:
    """One domain's curriculum row (see the module docstring)."""
    tasks = [folder / "problem.pddl", folder / "problem-2.pddl", folder / "problem-large.pddl"]
    seed = 0
    while len(tasks) < 3 + walks and seed < 50:
        walk = _walk_task(folder, seed, 8 + 4 * seed % 12, tasks_out)
        seed += 1
        if walk is not None and _whole_actions(folder, walk, time_limit):
            tasks.append(walk)
    row: dict = {"domain": folder.name, "tasks": len(tasks)}
    sizes = [_whole_actions(folder, t, time_limit) for t in tasks]
    row["whole_actions"] = sum(s or 0 for s in sizes)
    with tempfile.TemporaryDirectory() as tmp:
        doc, _ = _teach(folder / "robot.pddl", tasks, folder / "human.pddl", Path(tmp) / "seq", time_limit)
        if doc is not None:
            row.update(library_demonstrations=sum(t["demonstrations"] for t in doc["tasks"]),
                       library_actions=sum(t["demonstrated_actions"] for t in doc["tasks"]),
                       library_solved=sum(bool(t["plans_original_task"]) for t in doc["tasks"]))
        scratch = [_teach(folder / "robot.pddl", [t], folder / "human.pddl", Path(tmp) / f"s{k}", time_limit)[0]
                   for k, t in enumerate(tasks)]
    done = [s for s in scratch if s is not None]
    row.update(scratch_demonstrations=sum(_demonstrations(s) for s in done),
               scratch_actions=sum(sum(r["demonstration_length"] or 0 for r in s["rounds"]) for s in done),
               scratch_solved=sum(bool(s["plans_original_task"]) for s in done))
    whole = row["whole_actions"] or 1
    row["f1_library"] = round(1 - row.get("library_actions", whole) / whole, 3)
    row["f1_scratch"] = round(1 - row["scratch_actions"] / whole, 3)
    return row


def summary(second: list[dict], course: list[dict], command: str) -> str:
    """The two markdown tables."""
    lines = ["# Skills that carry to the next task", "", f"Regenerate with: `{command}`", "",
             "## A second task", "",
             "`teach robot.pddl problem.pddl problem-2.pddl --simulate human.pddl` (one run), and task 1 then task 2 "
             "as two runs; the second task needs a learned skill where its first demonstration did not show it. "
             "Final learned skills against the human model's actions.", "",
             "| domain | task 1 demos | task 2 demos (skill requests) | plans both | pre P / R | eff P / R | "
             "two runs: task 2 demos, plans both, pre P / R, eff P / R |", "|---|---|---|---|---|---|---|"]
    for r in second:
        lines.append(
            f"| {r['domain']} | {r.get('task1_demonstrations', '-')} | {r.get('task2_demonstrations', '-')} "
            f"({r.get('task2_skill_requests', '-')}) | {r.get('plans_both')} | {r.get('pre_precision', '-')} / "
            f"{r.get('pre_recall', '-')} | {r.get('eff_precision', '-')} / {r.get('eff_recall', '-')} | "
            f"{r.get('two_runs_task2_demonstrations', '-')}, {r.get('two_runs_plans_both')}, "
            f"{r.get('two_runs_pre_precision', '-')} / {r.get('two_runs_pre_recall', '-')}, "
            f"{r.get('two_runs_eff_precision', '-')} / {r.get('two_runs_eff_recall', '-')} |")
    lines += ["", "## A curriculum", "",
              "Per domain a sequence of tasks (the first, the second, the larger, and tasks drawn by seeded random "
              "walks of the human model from the larger one's state). Demonstrated actions with the growing "
              "library (one `teach` over the sequence), teaching each task from the original robot, and "
              "demonstrating every task whole; F1 savings = the share of the whole-task demonstrations not given.",
              "", "| domain | tasks | library: demos, actions, solved | from the original robot: demos, actions, "
              "solved | whole tasks: actions | F1 library | F1 from the original robot |",
              "|---|---|---|---|---|---|---|"]
    for r in course:
        lines.append(f"| {r['domain']} | {r['tasks']} | {r.get('library_demonstrations', '-')}, "
                     f"{r.get('library_actions', '-')}, {r.get('library_solved', '-')} | "
                     f"{r['scratch_demonstrations']}, {r['scratch_actions']}, {r['scratch_solved']} | "
                     f"{r['whole_actions']} | {r['f1_library']} | {r['f1_scratch']} |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run every domain with a second task (or those named) and write the CSVs and the summary."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("domains", nargs="*", help="domain folders under tests/data/byo (default: all with a "
                                                   "problem-2.pddl)")
    parser.add_argument("--time-limit", type=float, default=60.0, help="per teach/plan run (s)")
    parser.add_argument("--walks", type=int, default=2, help="random-walk tasks per curriculum (default 2)")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    folders = ([BYO / d for d in args.domains] or
               sorted(p for p in BYO.iterdir() if (p / "problem-2.pddl").is_file()))
    args.out.mkdir(parents=True, exist_ok=True)
    second = [second_task(folder, args.time_limit) for folder in folders]
    course = [curriculum(folder, args.time_limit, args.walks, args.out / "tasks") for folder in folders]
    write_csv(args.out / "second_task.csv", SECOND, second, ignore_extra=True)
    write_csv(args.out / "curriculum.csv", CURRICULUM, course, ignore_extra=True)
    (args.out / "summary.md").write_text(summary(second, course, "python benchmarks/library_bench.py"))
    print((args.out / "summary.md").read_text())
    ok = all(r.get("plans_both") is True and r.get("two_runs_plans_both") is True for r in second)
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
