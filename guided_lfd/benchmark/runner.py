"""Running the suite: each (task, strategy, semantics) a whole ``guided-lfd excuse`` process, locally or on Dask."""

from __future__ import annotations

import signal
import sys
import threading
import time
from pathlib import Path
from typing import Callable, Iterable

from guided_lfd.errors import EXIT_INTERRUPTED, EXIT_MEMORY, EXIT_TERMINATED
from guided_lfd.memory import cap_memory
from guided_lfd.benchmark.suite import BenchTask, robot_domain_file
from guided_lfd.benchmark.results import SOLVED, ResultRow


#: Runs whose strategy stops on a family (domain, removed action, semantics) after its first
#: unfinished task: later, larger tasks of that family are recorded as ``not-run`` and counted
#: as unsolved at the limit (as the household series does for the baseline).
STOP_AFTER_UNFINISHED = ("baseline",)


#: A run still going this long past its time limit is killed (recorded as ``timeout``).
KILL_GRACE_S = 60.0




def cli_command() -> list[str]:
    """The installed ``guided-lfd`` beside this interpreter (or the same entry point run by it)."""
    exe = Path(sys.executable).with_name("guided-lfd")
    return [str(exe)] if exe.exists() else [sys.executable, "-c", "from cli.main import run; run()"]


def command_line(task: BenchTask, strategy: str, semantics: str, time_limit: float, robot_file: Path) -> list[str]:
    """The ``guided-lfd excuse`` command a user would type for this run."""
    cmd = cli_command()
    cmd += ["excuse", str(robot_file), task.problem_file, "--semantics", semantics, "--strategy", strategy,
            "--time-limit", f"{time_limit:g}", "--json", "--quiet"]
    if task.fixed_from:
        cmd += ["--fixed-from", task.fixed_from]
    return cmd


#: The status of a run the benchmark's own stop interrupted (never written to the results).
INTERRUPTED = "interrupted"
_STOP = threading.Event()
_RUNNING: set = set()  # the guided-lfd processes running now
_RUNNING_LOCK = threading.Lock()


def run_one(task: BenchTask, strategy: str, semantics: str, time_limit: float,
            memory_limit_mb: int | None = None, workdir: Path | None = None) -> ResultRow:
    """One whole run of ``guided-lfd excuse`` in its own process; its result row (never raises).

    ``wall_s`` is the process's wall time as the shell sees it (start-up,
    parsing, grounding, search and the robot's optimal plan); ``time_s`` and
    ``search_time_s`` are the run's own figures.  A run still going 60 s past
    its limit (:data:`KILL_GRACE_S`) is killed and recorded as ``timeout``.
    """
    import json
    import subprocess
    import tempfile

    row = _row(task, strategy, semantics)
    folder = workdir or Path(tempfile.gettempdir()) / "guided-lfd-bench"
    folder.mkdir(parents=True, exist_ok=True)
    try:
        cmd = command_line(task, strategy, semantics, time_limit, robot_domain_file(task, folder))
    except Exception as exc:  # a benchmark row records failures instead of stopping the run
        row.status, row.excuse = "error", f"{type(exc).__name__}: {exc}"[:300]
        return row
    start = time.perf_counter()
    # The memory cap is set on the started process (prlimit), not in a pre-exec hook:
    # those are unsafe while other threads run, and the local executor is threads.
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    with _RUNNING_LOCK:
        _RUNNING.add(proc)
    if memory_limit_mb:
        cap_memory(proc.pid, memory_limit_mb)
    try:
        stdout, stderr = proc.communicate(timeout=time_limit + KILL_GRACE_S)
        code = proc.returncode
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        code, stdout, stderr = None, "", ""
    finally:
        with _RUNNING_LOCK:
            _RUNNING.discard(proc)
    if _STOP.is_set() or code in (EXIT_INTERRUPTED, EXIT_TERMINATED, -signal.SIGINT, -signal.SIGTERM):
        row.status = INTERRUPTED  # the benchmark was stopped under it: no result, not recorded
        return row
    row.wall_s, row.exit_code = round(time.perf_counter() - start, 4), code
    try:
        doc = json.loads(stdout)
    except json.JSONDecodeError:
        doc = None
    if doc is None:
        if code is None:
            status, note = "timeout", f"killed {KILL_GRACE_S:g} s past the limit"
        elif code == EXIT_MEMORY:
            status, note = "memout", ""
        else:
            status = "crashed"
            note = (stderr.strip().splitlines() or [f"process ended with exit code {code}"])[-1]
        row.status, row.excuse = status, note[:300]
        return row
    stats = doc.get("statistics") or {}
    row.status = doc["status"]
    row.time_s, row.search_time_s = stats.get("time_s"), stats.get("search_time_s")
    row.candidates, row.planner_calls = stats.get("candidates", 0), stats.get("planner_calls", 0)
    row.expanded = stats.get("nodes_expanded", 0)
    excuse = doc.get("excuse")
    if excuse:
        row.size, row.cost = excuse["size"], excuse["cost"]
        row.excuse = " ".join(c["change"] for c in excuse["changes"])
    elif doc["status"] not in SOLVED and doc.get("message"):
        row.excuse = str(doc["message"])[:300]
    return row


def _row(task: BenchTask, strategy: str, semantics: str) -> ResultRow:
    """The row of a run of ``task`` before it has run."""
    return ResultRow(task.id, task.domain, task.task, task.removed_action, semantics, strategy)


Run = tuple[BenchTask, str, str]  # (task, strategy, semantics)


def chains(suite: list[BenchTask], strategies: list[str], semantics: list[str],
           stop_after_unfinished: Iterable[str] = STOP_AFTER_UNFINISHED) -> list[list[Run]]:
    """The runs as chains run in order: one chain per family for a stopping strategy, else one run each.

    A family is (domain, removed action, semantics); its tasks run in task
    order, so that a stopping strategy can give up on it after the first task
    it does not finish.  Chains of stopping strategies come first (they are long).
    """
    stopping = set(stop_after_unfinished)
    families: dict[tuple[str, str, str, str], list[Run]] = {}
    singles: list[list[Run]] = []
    for task in suite:
        for sem in semantics:
            for strategy in strategies:
                if strategy in stopping:
                    families.setdefault((strategy, task.domain, task.removed_action, sem), []).append(
                        (task, strategy, sem))
                else:
                    singles.append([(task, strategy, sem)])
    ordered = [sorted(chain, key=lambda run: run[0].task) for _, chain in sorted(families.items())]
    return ordered + singles


def not_run(task: BenchTask, strategy: str, semantics: str, reason: str) -> ResultRow:
    """The row of a run left out after its family's first unfinished task."""
    row = _row(task, strategy, semantics)
    row.status, row.excuse = "not-run", reason
    return row


def crashed(task: BenchTask, strategy: str, semantics: str, exc: BaseException) -> ResultRow:
    """The row of a run whose worker died under it (Dask's KilledWorker, a crash): counted as crashed."""
    row = _row(task, strategy, semantics)
    row.status, row.excuse = "crashed", f"worker died: {type(exc).__name__}: {exc}"[:300]
    return row


def run_chain(chain: list[Run], time_limit: float, memory_limit_mb: int | None = None,
              previous: dict[tuple[str, str, str], ResultRow] | None = None,
              on_row: Callable[[ResultRow], None] | None = None, stop: bool = False) -> list[ResultRow]:
    """Run a chain in order; with ``stop``, after the first unfinished run the rest are ``not-run``.

    ``previous`` holds rows of an interrupted run (resume): they are not run again.
    """
    rows: list[ResultRow] = []
    stopped_at: str | None = None
    for task, strategy, sem in chain:
        key = (task.id, strategy, sem)
        if previous and key in previous:
            row, fresh = previous[key], False
        elif stopped():
            break  # the benchmark is being stopped (Ctrl-C, SIGTERM): start nothing more
        elif stopped_at is not None:
            row, fresh = not_run(task, strategy, sem, f"not run: {stopped_at} was not finished"), True
        else:
            row, fresh = run_one(task, strategy, sem, time_limit, memory_limit_mb), True
            if row.status == INTERRUPTED:
                break
        if stop and stopped_at is None and row.status not in SOLVED:
            stopped_at = task.task
        rows.append(row)
        if fresh and on_row:
            on_row(row)
    return rows


def run_suite(
    suite: list[BenchTask],
    strategies: list[str],
    semantics: list[str],
    time_limit: float,
    jobs: int = 2,
    executor: str = "local",
    scheduler: str | None = None,
    on_row: Callable[[ResultRow], None] | None = None,
    previous: list[ResultRow] | None = None,
    memory_limit_mb: int | None = None,
    stop_after_unfinished: Iterable[str] = STOP_AFTER_UNFINISHED,
) -> list[ResultRow]:
    """Run every (task, strategy, semantics), ``jobs`` command-line processes at a time.

    ``executor`` is ``local`` (a thread per job, each starting ``guided-lfd``
    processes) or ``dask`` (each chain a task on the cluster, whose workers
    need guided-lfd installed; ``scheduler`` is its address or a
    ``distributed.Client``).  A chain whose Dask worker dies gives
    ``crashed`` rows, and the run goes on.  Each run's address space is capped at
    ``memory_limit_mb`` (a run that needs more ends as ``memout``).
    ``previous`` rows (an interrupted run's) are kept and not run again.
    """
    stopping = set(stop_after_unfinished)
    work = chains(suite, strategies, semantics, stopping)
    done = {r.key: r for r in previous or []}
    if executor == "dask":
        return _run_dask(work, time_limit, scheduler, on_row, memory_limit_mb, done, stopping)
    from concurrent.futures import ThreadPoolExecutor

    lock = threading.Lock()

    def report(row: ResultRow) -> None:
        if on_row:
            with lock:
                on_row(row)

    rows: list[ResultRow] = []
    _STOP.clear()
    pool = ThreadPoolExecutor(max_workers=max(1, jobs))
    try:
        futures = [pool.submit(run_chain, chain, time_limit, memory_limit_mb, done, report,
                               chain[0][1] in stopping) for chain in work]
        for fut in futures:
            rows.extend(fut.result())
    except KeyboardInterrupt:
        stop_running()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    return sorted(rows, key=lambda r: (r.id, r.semantics, r.strategy))


def stopped() -> bool:
    """Whether :func:`stop_running` was called (a function, so that a chain pickled for Dask names it)."""
    return _STOP.is_set()


def stop_running() -> None:
    """Stop the benchmark at once (Ctrl-C, SIGTERM): no run starts any more, the running ones are terminated,
    and their rows are not recorded (a resumed run makes them again)."""
    _STOP.set()
    with _RUNNING_LOCK:
        for proc in _RUNNING:
            proc.terminate()


def _run_dask(work, time_limit, scheduler, on_row, memory_limit_mb, done, stopping):
    try:
        from dask.distributed import Client, as_completed
    except ImportError:
        raise ImportError("the dask executor needs the 'dist' extra: pip install 'guided-lfd[dist]'") from None
    client = scheduler if isinstance(scheduler, Client) else Client(scheduler) if scheduler else Client(processes=True)
    try:
        # No retries: a run is timed, and a rerun on another worker would not be the same run.
        futures, chain_of = [], {}
        for chain in work:
            fut = client.submit(run_chain, chain, time_limit, memory_limit_mb, done, None,
                                chain[0][1] in stopping, pure=False, retries=0)
            futures.append(fut)
            chain_of[fut.key] = chain
        rows = []
        for fut in as_completed(futures):
            try:
                chain_rows = fut.result()
            except Exception as exc:  # noqa: BLE001 - KilledWorker, a worker's crash: rows, not a traceback
                # Resumed rows stay as they were; the chain's other runs are lost with the worker.
                chain_rows = [done.get((task.id, strategy, sem)) or crashed(task, strategy, sem, exc)
                              for task, strategy, sem in chain_of[fut.key]]
            for row in chain_rows:
                rows.append(row)
                if on_row and row.key not in done:
                    on_row(row)
    finally:
        if not isinstance(scheduler, Client):
            client.close()
    return sorted(rows, key=lambda r: (r.id, r.semantics, r.strategy))
