#!/usr/bin/env python3
"""Start-up time of ``guided-lfd excuse`` against the bare imports it cannot avoid.

    python benchmarks/startup.py            # 5 runs of each, medians and their ratio
    python benchmarks/startup.py --runs 11 --check

Times, as subprocesses, (a) the installed console script
``guided-lfd excuse data/domains/kitchen-1/robot.pddl data/domains/kitchen-1/problem.pddl``
(its search takes well under a millisecond: the wall time is start-up) and
(b) ``python -c "import typer, rich, tarski.io"``, the libraries every
``excuse`` run needs.  Both use the interpreter running this script and the
``guided-lfd`` script beside it (so run it with the project's venv python).
The target is a ratio (a)/(b) of at most 1.5.

Runs of (a) and (b) alternate, after one untimed warm-up of each (which
writes byte-code caches, even under PYTHONDONTWRITEBYTECODE, and fills the
file cache), so that a change in machine load affects both alike.
Figures are wall-clock times: on a busy machine they are indicative only.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
KITCHEN = ROOT / "data" / "domains" / "kitchen-1"
TARGET_RATIO = 1.5
BASELINE_IMPORTS = "import typer, rich, tarski.io"


def console_script() -> Path:
    """The ``guided-lfd`` script installed in the venv of ``sys.executable``."""
    script = Path(sys.executable).parent / "guided-lfd"
    if not script.exists():
        raise SystemExit(f"{script} not found: run this with the python of the venv guided-lfd is installed in")
    return script


def wall_time(argv: list[str], env: dict[str, str] | None = None) -> float:
    """Seconds one run of ``argv`` takes; its output is discarded, a failure is fatal."""
    start = time.perf_counter()
    done = subprocess.run(argv, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    elapsed = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} exited {done.returncode}: {done.stderr.strip()}")
    return elapsed


def measure(runs: int) -> tuple[list[float], list[float]]:
    """Wall times of ``runs`` excuse runs and ``runs`` baseline imports, interleaved."""
    excuse = [str(console_script()), "excuse", str(KITCHEN / "robot.pddl"), str(KITCHEN / "problem.pddl")]
    baseline = [sys.executable, "-c", BASELINE_IMPORTS]
    # Warm-up, not counted.  It may write byte-code caches even where PYTHONDONTWRITEBYTECODE
    # is set: the libraries were compiled when installed, and guided-lfd's own modules must
    # not be timed compiling from source each run (no user's machine does that either).
    warm = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    wall_time(excuse, warm), wall_time(baseline, warm)
    excuse_times, baseline_times = [], []
    for _ in range(runs):
        excuse_times.append(wall_time(excuse))
        baseline_times.append(wall_time(baseline))
    return excuse_times, baseline_times


def main(argv: list[str] | None = None) -> int:
    """Print the medians and their ratio; with ``--check``, exit 1 above the target ratio."""
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=5, help="timed runs of each command (default 5)")
    parser.add_argument("--check", action="store_true", help=f"exit 1 if the ratio is above {TARGET_RATIO}")
    args = parser.parse_args(argv)
    if args.runs < 1:
        parser.error("--runs: expected at least 1")
    excuse_times, baseline_times = measure(args.runs)
    excuse_s, baseline_s = statistics.median(excuse_times), statistics.median(baseline_times)
    ratio = excuse_s / baseline_s
    print(f"guided-lfd excuse (kitchen-1):    median {excuse_s * 1000:7.1f} ms of {args.runs} runs")
    print(f"python -c '{BASELINE_IMPORTS}': median {baseline_s * 1000:7.1f} ms of {args.runs} runs")
    verdict = "within" if ratio <= TARGET_RATIO else "above"
    print(f"ratio: {ratio:.2f} ({verdict} the target of {TARGET_RATIO})")
    return 1 if args.check and ratio > TARGET_RATIO else 0


if __name__ == "__main__":
    sys.exit(main())
