#!/usr/bin/env python3
"""Demonstrations that go wrong: the teaching loop with a teacher who makes mistakes, checks on and off.

    python benchmarks/mistakes_bench.py --jobs 2   # -> benchmarks/mistakes_results/{mistakes.csv,summary.md}

``teach`` on both kitchens and every BYO domain (its ``problem.pddl``), the simulated teacher making a mistake
in a demonstration at 0, 10, 25 and 50 % (``--mistakes any=RATE``: wrong object, partial, extra steps, wrong
order or misread, drawn evenly; see guided_lfd/teach/mistakes.py), 20 seeds each, at most 5 rounds, the rendered
traces clean (the renderer's default noise) and noisy (a real tracker's: ``--trace-noise`` :data:`NOISY`, a
tracking loss of up to 2 s, a re-grasp, a brief grip, 10 % dropped frames, bursts, duplicates, jitter); the same
sessions with the demonstrations checked against their requests (the loop as it is) and with every
demonstration's skills kept (``checks=False``: the loop before the checks).  Per session: solved (the taught
robot plans the task from its initial state), rounds, demonstrations, mistakes made, and wrong skills merged
(a learned skill whose effects differ from the human model's action of its name).  Sessions run in-process
(the library's ``teach``), one per worker.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.benchmark.results import write_csv  # noqa: E402

OUT = ROOT / "benchmarks" / "mistakes_results"
RATES = (0.0, 0.10, 0.25, 0.50)
NOISY = "loss=2,regrasp=0.28,grip=0.14,drops=0.1,duplicates=0.02,bursts=0.01,jitter=0.002"
FIELDS = ["domain", "rate", "noise", "seed", "checks", "status", "solved", "rounds", "demonstrations", "mistakes",
          "wrong_skills"]


def domains() -> list[Path]:
    """The kitchens and the BYO domains: folders with robot.pddl, human.pddl and problem.pddl."""
    kitchens = [ROOT / "data" / "domains" / k for k in ("kitchen-1", "kitchen-2")]
    byo = sorted(p for p in (ROOT / "tests" / "data" / "byo").iterdir() if (p / "robot.pddl").is_file())
    return kitchens + byo


def session(job: tuple[str, float, str, int, bool]) -> dict:
    """One teaching session (see the module docstring)."""
    from guided_lfd.demonstration.quality import skill_quality
    from guided_lfd.demonstration.render import Noise
    from guided_lfd.pddl.reader import parse_domain, parse_task
    from guided_lfd.teach import SimulatedHuman, teach
    from guided_lfd.teach.mistakes import Mistakes

    folder, rate, noise, seed, checks = Path(job[0]), job[1], job[2], job[3], job[4]
    robot, problem = parse_task(str(folder / "robot.pddl"), str(folder / "problem.pddl"))
    human = parse_domain(str(folder / "human.pddl"))
    teacher = SimulatedHuman(human, robot=robot, seed=seed, mistakes=Mistakes.parse(f"any={rate}"),
                             noise=Noise.parse(NOISY, seed) if noise == "noisy" else None)
    row = {"domain": folder.name, "rate": rate, "noise": noise, "seed": seed, "checks": checks}
    with tempfile.TemporaryDirectory() as tmp:
        try:
            result = teach(robot, problem, teacher, Path(tmp) / "session", max_rounds=5, human=human, checks=checks)
            taught = parse_domain(result.robot_domain)
        except Exception as exc:  # a defect: counted and named in the summary, the sweep goes on
            return {**row, "status": f"crashed: {type(exc).__name__}: {str(exc)[:120]}", "solved": False,
                    "rounds": 0, "demonstrations": 0, "mistakes": 0, "wrong_skills": 0}
    known = {a.name for a in robot.actions}

    def wrong_effects(action) -> bool:
        quality = skill_quality([action], human)
        return quality["eff_precision"] < 1 or quality["eff_recall"] < 1

    wrong = [a.name for a in taught.actions if a.name not in known and wrong_effects(a)]
    return {**row, "status": result.status,
            "solved": bool(result.solved and result.plans_original_task), "rounds": len(result.rounds),
            "demonstrations": sum(r.demonstration_length is not None for r in result.rounds),
            "mistakes": sum(m is not None for m in teacher.made), "wrong_skills": len(wrong)}


def summary(rows: list[dict], command: str) -> str:
    """Per mistake rate, the checked loop beside the unchecked one."""
    lines = ["# Demonstrations that go wrong: a teacher who makes mistakes", "", f"Regenerate with: `{command}`", "",
             "| mistakes per demonstration | traces | loop | sessions | solved within 5 rounds | mean rounds | "
             "demonstrations | mistakes made | sessions with a wrong skill merged |",
             "|---|---|---|---|---|---|---|---|---|"]
    for rate, noise, checks in ((r, n, c) for r in sorted({r["rate"] for r in rows}) for n in ("clean", "noisy")
                                for c in (True, False)):
        group = [r for r in rows if r["rate"] == rate and r["noise"] == noise and r["checks"] == checks]
        if group:
            n = len(group)
            solved = sum(r["solved"] for r in group)
            lines.append(f"| {rate:.0%} | {noise} | {'checked' if checks else 'no checks'} | {n} | "
                         f"{solved} ({solved / n:.1%}) "
                         f"| {sum(r['rounds'] for r in group) / n:.2f} | {sum(r['demonstrations'] for r in group)} "
                         f"| {sum(r['mistakes'] for r in group)} | {sum(r['wrong_skills'] > 0 for r in group)} |")
    unsolved = sorted({(r["domain"], r["noise"], r["status"]) for r in rows if not r["solved"] and r["checks"]})
    if unsolved:
        lines += ["", "Checked sessions not solved, by domain, traces and status: "
                  + ", ".join(f"{d} ({n}, {s})" for d, n, s in unsolved) + "."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    """Run every session and write the CSV and the summary."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--seeds", type=int, default=20)
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    jobs = [(str(folder), rate, noise, seed, checks) for folder in domains() for rate in RATES
            for noise in ("clean", "noisy") for seed in range(args.seeds) for checks in (True, False)]
    with ProcessPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(session, jobs, chunksize=4))
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(args.out / "mistakes.csv", FIELDS, rows)
    (args.out / "summary.md").write_text(summary(rows, "python benchmarks/mistakes_bench.py --jobs 2"))
    print((args.out / "summary.md").read_text())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
