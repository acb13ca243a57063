#!/usr/bin/env python3
"""Excuse benchmark: generate the suite, run it, report.

    python benchmarks/excuse_bench.py generate            # -> benchmarks/suite.csv
    python benchmarks/excuse_bench.py run --jobs 2        # -> benchmarks/results/results.csv
    python benchmarks/excuse_bench.py report              # -> benchmarks/results/summary.md + PNG plots
    python benchmarks/excuse_bench.py all --jobs 2        # run + report

`run --executor dask --scheduler tcp://host:8786` sends the runs to an existing
Dask cluster (extra: pip install 'guided-lfd[dist]').

This script is `guided-lfd bench` (cli/bench.py) run from the repository root;
`guided-lfd bench --help` lists the options.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))


def main(argv: list[str] | None = None) -> int:
    """``guided-lfd bench ARGS --root <this repository>``; returns its exit code."""
    from cli.main import app

    args = list(sys.argv[1:] if argv is None else argv)
    if "--root" not in args:
        args += ["--root", str(ROOT)]
    try:
        app(["bench", *args], prog_name="excuse_bench.py")
    except SystemExit as exc:
        return int(exc.code or 0)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
