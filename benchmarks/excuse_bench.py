#!/usr/bin/env python3
"""Excuse benchmark: generate the suite, run it, report.

    python benchmarks/excuse_bench.py generate            # -> benchmarks/suite.csv
    python benchmarks/excuse_bench.py run --jobs 2        # -> benchmarks/results/results.csv
    python benchmarks/excuse_bench.py report              # -> benchmarks/results/summary.md + PNG plots
    python benchmarks/excuse_bench.py all --jobs 2        # run + report

`run --executor dask --scheduler tcp://host:8786` sends the runs to an existing
Dask cluster (extra: pip install 'guided-lfd[dist]').
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from guided_lfd import benchmark  # noqa: E402

HERE = ROOT / "benchmarks"
SUITE = HERE / "suite.csv"
RESULTS = HERE / "results"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=["generate", "run", "report", "all"])
    parser.add_argument("--ipc", type=Path, default=ROOT / "data" / "benchmarks" / "ipc")
    parser.add_argument("--tasks", default=",".join(f"task{i:02d}" for i in range(1, 11)),
                        help="comma-separated IPC task names per domain")
    parser.add_argument("--suite", type=Path, default=SUITE)
    parser.add_argument("--results", type=Path, default=RESULTS)
    parser.add_argument("--time-limit", type=float, default=60.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--memory-limit", type=int, default=8192,
                        help="address-space cap per run in MiB (0 = none); a run past it ends as 'memout'")
    parser.add_argument("--strategies", default="landmark,baseline")
    parser.add_argument("--semantics", default="literal,consistent")
    parser.add_argument("--only", default="", help="comma-separated substrings of task ids to run")
    parser.add_argument("--stop-after-unfinished", default=",".join(benchmark.STOP_AFTER_UNFINISHED),
                        help="strategies that skip a family's (domain, removed action, semantics) later tasks "
                             "after its first unfinished one, counted unsolved at the limit ('' = none)")
    parser.add_argument("--executor", choices=["local", "dask"], default="local")
    parser.add_argument("--scheduler", default=None, help="Dask scheduler address (default: a local cluster)")
    args = parser.parse_args(argv)
    if args.memory_limit < 0:
        parser.error("--memory-limit must be >= 0 (MiB; 0 = no cap)")
    if args.memory_limit and args.executor == "dask":
        print("note: --memory-limit applies to local runs; Dask workers keep their own limits", file=sys.stderr)

    if args.command == "generate":
        suite = benchmark.generate_suite(args.ipc, ROOT / "data" / "domains", args.tasks.split(","),
                                         log=lambda m: print(m, file=sys.stderr))
        benchmark.write_suite(suite, args.suite, ROOT)
        print(f"{len(suite)} tasks over {len({t.domain for t in suite})} domains -> {args.suite}", file=sys.stderr)
        return 0
    results_csv = args.results / "results.csv"
    if args.command in ("run", "all"):
        suite = benchmark.read_suite(args.suite, ROOT)
        if args.only:
            keys = args.only.split(",")
            suite = [t for t in suite if any(k in t.id for k in keys)]
        done = [0]
        total = len(suite) * len(args.strategies.split(",")) * len(args.semantics.split(","))

        log = benchmark.RowLog(args.results / "results.partial.csv")
        if log.done:
            print(f"resuming: {len(log.done)} runs already in {log.path}", file=sys.stderr)

        def progress(row):
            done[0] += 1
            log.append(row)
            print(f"[{done[0]}/{total}] {row['id']} {row['strategy']} {row['semantics']}: "
                  f"{row['status']} size={row['size']} {row['wall_s']}s", file=sys.stderr, flush=True)

        benchmark.run_suite(suite, args.strategies.split(","), args.semantics.split(","), args.time_limit,
                            args.jobs, args.executor, args.scheduler, progress, previous=log.rows,
                            memory_limit_mb=args.memory_limit or None,
                            stop_after_unfinished=[s for s in args.stop_after_unfinished.split(",") if s])
        rows = benchmark.read_results(log.path)
        if args.only and results_csv.exists():
            # A subset run updates its rows in the results; the other runs' rows stay.
            subset = len(rows)
            rows = benchmark.merge_rows(benchmark.read_results(results_csv), rows)
            print(f"{results_csv}: {subset} row(s) replaced or added, {len(rows)} in all", file=sys.stderr)
        rows = sorted(rows, key=lambda r: (r["id"], r["semantics"], r["strategy"]))
        benchmark.write_results(rows, results_csv)
        log.path.unlink()
    if args.command in ("report", "all"):
        args.results.mkdir(parents=True, exist_ok=True)
        rows = benchmark.read_results(results_csv)
        plots = benchmark.plot(rows, args.results, args.time_limit)
        command = "python benchmarks/excuse_bench.py all --jobs 2"
        text = benchmark.summary_markdown(rows, args.time_limit, command, plots, args.results)
        from guided_lfd.io import write_text

        write_text(args.results / "summary.md", text)
        print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
