"""``guided-lfd bench``: the excuse benchmark (generate the suite, run it, report), as benchmarks/README.md describes."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from cli.common import QuietOption, command, help_footer, ui, path_name
from guided_lfd import errors
from guided_lfd.errors import OptionError

STEPS = ("generate", "run", "report", "all")


#: The IPC tasks of each family 'bench generate' takes by default.
DEFAULT_TASKS = ",".join(f"task{i:02d}" for i in range(1, 11))


@help_footer(
    example="guided-lfd bench all --jobs 2",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_OUTPUT),
    success="step done (each run's own outcome is a row of the results)",
)
@command
def bench(
    step: Annotated[str, typer.Argument(metavar="STEP", help="generate | run | report | all (run, then report).")],
    root: Annotated[Path | None, typer.Option("--root", parser=path_name, metavar="DIR", help="Repository root (data/, benchmarks/; "
                                                                        "default: the working folder if it has "
                                                                        "them, else the installed checkout).")]
    = None,
    ipc: Annotated[Path | None, typer.Option("--ipc", parser=path_name, metavar="DIR", help="IPC collection (default ROOT/data/benchmarks/ipc).")] = None,
    tasks: Annotated[str, typer.Option("--tasks", metavar="NAMES", help="Comma-separated IPC task names per domain.")]
    = DEFAULT_TASKS,
    suite: Annotated[Path | None, typer.Option("--suite", parser=path_name, metavar="CSV", help="Suite file (default ROOT/benchmarks/suite.csv).")] = None,
    results: Annotated[Path | None, typer.Option("--results", parser=path_name, metavar="DIR", help="Results folder (default ROOT/benchmarks/results).")] = None,
    time_limit: Annotated[float, typer.Option("--time-limit", metavar="SECONDS", help="Per run.")] = 60.0,
    jobs: Annotated[int, typer.Option("--jobs", metavar="N", help="Runs at a time.")] = 2,
    memory_limit: Annotated[int, typer.Option("--memory-limit", metavar="MIB",
                                              help="Address-space cap per run (0 = none); a run past it is 'memout'.")] = 8192,
    strategies: Annotated[str, typer.Option("--strategies", metavar="NAMES", help="Comma-separated strategies.")] = "portfolio,baseline",
    semantics: Annotated[str, typer.Option("--semantics", metavar="NAMES", help="Comma-separated semantics.")] = "literal,consistent",
    only: Annotated[str, typer.Option("--only", metavar="IDS", help="Comma-separated substrings of task ids to run "
                                                      "(their rows replace theirs in the results; the rest stay).")] = "",
    stop_after_unfinished: Annotated[str, typer.Option(
        "--stop-after-unfinished", metavar="NAMES", help="Strategies that skip a family's later tasks after its first unfinished one, "
                                        "counted unsolved at the limit ('' = none).")] = "baseline",
    executor: Annotated[str, typer.Option("--executor", metavar="[local|dask]", help="Where runs execute.")] = "local",
    scheduler: Annotated[str | None, typer.Option("--scheduler", metavar="ADDRESS", help="Dask scheduler address (default: a local cluster).")] = None,
    quiet: QuietOption = False,
) -> None:
    """Run the excuse benchmark (generate, run, report).

    Every strategy and semantics on every task of the suite, each run a whole
    'guided-lfd excuse' process timed from outside; an interrupted run resumes.
    The report writes summary.md and plots into the results folder and prints
    the summary (see benchmarks/README.md).
    """
    from guided_lfd import benchmark

    if step not in STEPS:
        raise OptionError(f"STEP {step}: expected one of: {', '.join(STEPS)}")
    from guided_lfd.memory import MAX_MEMORY_MIB

    if not 0 <= memory_limit <= MAX_MEMORY_MIB:
        raise OptionError(f"--memory-limit {memory_limit}: expected MiB from 0 (no cap) to {MAX_MEMORY_MIB}")
    if executor not in ("local", "dask"):
        raise OptionError(f"--executor {executor}: expected local or dask")
    root, ipc, suite, results = _paths(step, root, ipc, suite, results)
    _check_options(time_limit, jobs, strategies, semantics)
    _check_strategy_names(stop_after_unfinished, "--stop-after-unfinished")
    if step != "generate" and tasks != DEFAULT_TASKS:
        raise OptionError(f"--tasks {tasks!r}: only 'bench generate' reads it (run and report take --only)")
    if step == "generate":
        names = _check_task_names(tasks, ipc)
        tasks_found = benchmark.generate_suite(ipc, root / "data" / "domains", names, log=ui.info_plain)
        benchmark.write_suite(tasks_found, suite, root)
        ui.info(f"{len(tasks_found)} tasks over {len({t.domain for t in tasks_found})} domains -> {suite}")
        return
    results_csv = results / "results.csv"
    if step in ("run", "all"):
        _run(benchmark, root, suite, results, results_csv, time_limit, jobs, memory_limit, strategies, semantics,
             only, stop_after_unfinished, executor, scheduler)
    if step in ("report", "all"):
        results.mkdir(parents=True, exist_ok=True)
        rows = benchmark.read_results(results_csv)
        from guided_lfd.reporting import PLOTS_HINT, PlotsUnavailable

        try:
            plots = benchmark.plot(rows, results, time_limit)
        except PlotsUnavailable:
            plots = None
            ui.info_plain(f"plots skipped: {PLOTS_HINT}")
        # The command the summary names (benchmarks/excuse_bench.py is this subcommand).
        text = benchmark.summary_markdown(rows, time_limit, "python benchmarks/excuse_bench.py all --jobs 2", plots, results)
        from guided_lfd.io import write_text

        write_text(results / "summary.md", text)
        write_text("-", text + "\n")


def _paths(step: str, root: Path | None, ipc: Path | None, suite: Path | None,
           results: Path | None) -> tuple[Path, Path, Path, Path]:
    """The root (see :mod:`guided_lfd.paths`) and the folders and files a step uses, checked before any work."""
    from cli.common import check_apart, check_output_folder
    from guided_lfd.paths import data_root, require

    root = data_root(root, "benchmarks/suite.csv" if step != "generate" else "data/benchmarks/ipc")
    ipc = ipc or root / "data" / "benchmarks" / "ipc"
    suite = suite or root / "benchmarks" / "suite.csv"
    results = results or root / "benchmarks" / "results"
    if step == "generate":
        require(ipc, root / "data" / "domains")
        _not_inside(suite, [ipc, root / "data" / "domains"], "--suite")
    elif step != "report":
        require(suite, hint="give an existing --suite CSV, or --root DIR")
    if step != "generate":
        check_output_folder(results, "--results")
        if step != "report":  # report reads results.csv where it writes: that folder is its own
            check_apart(results, "--results", [root / "data", ipc], root)
        _not_inside(suite, [results], "--suite")
    if step == "report":
        require(results / "results.csv", hint="run the benchmark first (bench run), or give --results DIR")
    return root, ipc, suite, results


def _not_inside(path: Path, folders: list[Path], option: str) -> None:
    """Refuse (exit 37) a file the step reads or writes inside a folder it writes or reads (one would replace
    the other: a suite written over a domain file, results over the suite)."""
    for folder in folders:
        if folder.exists() and path.resolve().is_relative_to(folder.resolve()):
            raise OptionError(f"{option} {path}: lies in {folder}, which this step also uses; expected a file "
                              "elsewhere")


#: More runs at a time than this is no setting for one machine (each run is a process of its own).
MAX_JOBS = 256


def _check_strategy_names(names: str, option: str) -> None:
    """Refuse (exit 37) a list naming a strategy that does not exist ('' names none)."""
    from guided_lfd.excuse.strategies import STRATEGIES

    for name in (n for n in names.split(",") if n):
        if name not in STRATEGIES:
            raise OptionError(f"{option} {names}: unknown strategy '{name}' (expected some of: "
                              f"{', '.join(STRATEGIES)})")


def _check_task_names(tasks: str, ipc: Path) -> list[str]:
    """The --tasks names (spaces around them dropped); refuse (exit 37) a list that is empty or names a task no
    family of the collection has, and (exit 30) an IPC collection that is no folder."""
    from guided_lfd.errors import InputFileError, Location

    names = [t.strip() for t in tasks.split(",") if t.strip()]
    if not names:
        raise OptionError(f"--tasks {tasks!r}: expected comma-separated task names (task01,task02)")
    if not ipc.is_dir():
        raise InputFileError("is a file, expected a folder of IPC domains (one folder per family)", Location(str(ipc)))
    families = [d for d in ipc.iterdir() if d.is_dir()]
    for name in names:
        if not any((d / f"{name}.pddl").is_file() for d in families):
            raise OptionError(f"--tasks {tasks}: no family of {ipc} has a task '{name}'")
    return names


def _check_options(time_limit: float, jobs: int, strategies: str, semantics: str) -> None:
    """Refuse (exit 37) a time limit, job count, strategy or semantics the runs could not use."""
    from guided_lfd.deadline import checked_time_limit
    from guided_lfd.excuse.space import Semantics
    from guided_lfd.excuse.strategies import STRATEGIES

    checked_time_limit(time_limit)
    if not 1 <= jobs <= MAX_JOBS:
        raise OptionError(f"--jobs {jobs}: expected a number of runs at a time from 1 to {MAX_JOBS}")
    for name in strategies.split(","):
        if name not in STRATEGIES:
            raise OptionError(f"--strategies {strategies}: unknown strategy '{name}' (expected some of: "
                              f"{', '.join(STRATEGIES)})")
    for name in semantics.split(","):
        if name not in {s.value for s in Semantics}:
            raise OptionError(f"--semantics {semantics}: unknown semantics '{name}' (expected some of: "
                              f"{', '.join(s.value for s in Semantics)})")


def _run(benchmark, root: Path, suite_file: Path, results: Path, results_csv: Path, time_limit: float, jobs: int,
         memory_limit: int, strategies: str, semantics: str, only: str, stop_after_unfinished: str, executor: str,
         scheduler: str | None) -> None:
    """Run the suite (resuming a partial run), then write the results CSV (a subset run merges its rows)."""
    suite = benchmark.read_suite(suite_file, root)
    if only:
        keys = [k for k in only.split(",") if k.strip()]
        if not keys:
            raise OptionError(f"--only {only!r}: expected comma-separated parts of task ids")
        unmatched = [k for k in keys if not any(k in t.id for t in suite)]
        if unmatched:
            raise OptionError(f"--only {only}: '{unmatched[0]}' matches no task of {suite_file}")
        suite = [t for t in suite if any(k in t.id for k in keys)]
    benchmark.check_removed_actions(suite, suite_file)
    done = [0]
    total = len(suite) * len(strategies.split(",")) * len(semantics.split(","))
    # Each task's digest covers its files' content, the tool's version and the limits, so a resumed run
    # reruns what an edit (or another limit) has made stale instead of reporting it.
    limits = f"time_limit={time_limit:g} memory_limit={memory_limit or 0}"
    inputs = {t.id: benchmark.input_digest(benchmark.task_digest(t), limits) for t in suite}
    log = benchmark.RowLog(results / "results.partial.csv", inputs)
    if log.stale:
        ui.info(f"rerunning {log.stale} run(s) in {log.path} whose inputs changed since they ran")
    if log.done:
        ui.info(f"resuming: {len(log.done)} runs already in {log.path}")

    def progress(row):
        done[0] += 1
        log.append(row)
        cells = row.to_csv()
        ui.info_plain(f"[{done[0]}/{total}] {row.id} {row.strategy} {row.semantics}: "
                      f"{row.status} size={cells['size']} {cells['wall_s']}s")

    benchmark.run_suite(suite, strategies.split(","), semantics.split(","), time_limit, jobs, executor, scheduler,
                        progress, previous=log.rows, memory_limit_mb=memory_limit or None,
                        stop_after_unfinished=[s for s in stop_after_unfinished.split(",") if s])
    rows = benchmark.read_results(log.path)
    if only and results_csv.exists():
        # A subset run updates its rows in the results; the other runs' rows stay.
        subset = len(rows)
        rows = benchmark.merge_rows(benchmark.read_results(results_csv), rows)
        ui.info(f"{results_csv}: {subset} row(s) replaced or added, {len(rows)} in all")
    rows = sorted(rows, key=lambda r: (r.id, r.semantics, r.strategy))
    benchmark.write_results(rows, results_csv)
    log.remove()
