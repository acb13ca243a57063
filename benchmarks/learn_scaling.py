#!/usr/bin/env python3
"""`learn-domain` on long trajectories: whole-run wall time against the number of steps, and --time-limit.

    python benchmarks/learn_scaling.py            # -> benchmarks/learn_scaling_results/{runs.csv,summary.md}
    python benchmarks/learn_scaling.py --steps 1000,5000,20000 --rounds 3

A trajectory of N steps is a seeded random walk of blocksworld's true domain
(tests/data/trajectories/blocksworld: eight blocks), written as a PDDL
trajectory file; `guided-lfd learn-domain TRAJ --prior prior.pddl` learns its
four operators from it as a fresh process, timed from the outside (start-up,
reading, learning, writing), the median over ``--rounds``.  Then the largest
trajectory three times over runs with ``--time-limit 5``: it must end with
exit 20 within 6 s and write nothing.  Measure on a quiet machine.
"""

from __future__ import annotations

import argparse
import csv
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd.pddl.reader import parse_task  # noqa: E402
from guided_lfd.planning.grounding import ground  # noqa: E402
from guided_lfd.planning.task import bits  # noqa: E402

BLOCKS = ROOT / "tests" / "data" / "trajectories" / "blocksworld"


def trajectory(steps: int, seed: int = 0) -> str:
    """A random walk of ``steps`` actions of the true blocksworld domain from its problem, as a trajectory."""
    task = ground(*parse_task(BLOCKS / "true.pddl", BLOCKS / "problem.pddl"))
    rng = random.Random(seed)

    def state(s: int) -> str:
        return "(:state " + " ".join(sorted(str(task.atoms[i]) for i in bits(s))) + ")"

    s, lines = task.init, ["(:trajectory", state(task.init)]
    for _ in range(steps):
        act = rng.choice([a for a in task.actions if a.applicable(s)])
        s = act.apply(s)
        lines += [f"(:action {act.name})", state(s)]
    return "\n".join([*lines, ")"]) + "\n"


def run(path: Path, out: Path, *extra: str) -> tuple[float, int]:
    """Wall seconds and exit code of one `learn-domain` run."""
    script = Path(sys.executable).parent / "guided-lfd"
    start = time.perf_counter()
    done = subprocess.run([str(script), "learn-domain", str(path), "--prior", str(BLOCKS / "prior.pddl"), "-q",
                           "-o", str(out), *extra], capture_output=True, text=True)
    return time.perf_counter() - start, done.returncode


def main() -> None:
    """Time each size, then the time limit, and write the results."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--steps", default="1000,5000,20000")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "learn_scaling_results")
    opts = parser.parse_args()
    sizes = [int(n) for n in opts.steps.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for n in sizes:
            path = folder / f"walk-{n}.traj"
            path.write_text(trajectory(n))
            times = []
            for _ in range(opts.rounds):
                seconds, code = run(path, folder / "learned.pddl")
                if code != 0:
                    raise SystemExit(f"learn-domain on {n} steps exited {code}")
                times.append(seconds)
            rows.append({"steps": n, "median_s": round(statistics.median(times), 3),
                         "ms_per_step": round(1000 * statistics.median(times) / n, 3)})
            print(f"{n} steps: {rows[-1]['median_s']} s", file=sys.stderr)
        big = folder / "walk-long.traj"
        big.write_text(trajectory(3 * max(sizes), seed=1))
        target = folder / "limited.pddl"
        seconds, code = run(big, target, "--time-limit", "5")
        limited = {"steps": 3 * max(sizes), "time_limit_s": 5, "wall_s": round(seconds, 3), "exit": code,
                   "wrote": target.exists()}
    opts.out.mkdir(parents=True, exist_ok=True)
    with (opts.out / "runs.csv").open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    lines = ["# learn-domain on trajectories", "", f"{opts.rounds} rounds, medians, Python {sys.version.split()[0]}", "",
             "| steps | whole run (s) | ms per step |", "|---|---|---|"]
    lines += [f"| {r['steps']} | {r['median_s']} | {r['ms_per_step']} |" for r in rows]
    lines += ["", f"`--time-limit 5` on {limited['steps']} steps: exit {limited['exit']} after {limited['wall_s']} s, "
                  f"output written: {'yes' if limited['wrote'] else 'no'}"]
    (opts.out / "summary.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
