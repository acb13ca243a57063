"""The excuse benchmark: tasks made unsolvable by removing a skill, and their runs.

A benchmark task is an IPC (or kitchen) task whose robot domain lacks one
action schema, kept if the robot can no longer solve it.  The excuse space
fixes the predicates no action of the *complete* domain changes (roads, floor
order, type predicates): what no agent in that world can change
(``--fixed-from`` the complete domain).  Every strategy and semantics runs
on every task in its own process with the same time limit; rows go to a CSV
and a markdown summary with plots is written from it.
"""

from __future__ import annotations

import csv
import math
import statistics
import sys
import time
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any, Callable, Iterable

from guided_lfd.memory import cap_memory

SUITE_FIELDS = ["id", "domain", "task", "removed_action", "domain_file", "problem_file", "fixed_from"]
RESULT_FIELDS = [
    "id", "domain", "task", "removed_action", "semantics", "strategy", "status", "size", "cost",
    "wall_s", "exit_code", "time_s", "search_time_s", "candidates", "planner_calls", "expanded", "excuse",
]
SOLVED = ("excuse-found", "no-excuse")
#: Statuses of a run that gave up within its limits (counted at the limit in whole-run speed-ups).
GAVE_UP = ("timeout", "memout", "not-run")


@dataclass(frozen=True)
class BenchTask:
    """One benchmark task: a problem and the robot domain without ``removed_action``."""

    id: str
    domain: str
    task: str
    removed_action: str
    domain_file: str
    problem_file: str
    fixed_from: str  # the complete domain ("" = none)

    def load(self):
        """(robot domain, problem, complete domain or None)."""
        from guided_lfd.pddl.reader import parse_domain, parse_task

        full, problem = parse_task(self.domain_file, self.problem_file)
        robot = full
        if self.removed_action:
            robot = replace(full, actions=[a for a in full.actions if a.name != self.removed_action])
        complete = parse_domain(self.fixed_from) if self.fixed_from else None
        return robot, problem, complete


def _robot_solves(robot, problem, complete, time_limit: float) -> bool | None:
    """Whether the robot can solve the task (None = undecided in time)."""
    from guided_lfd.errors import SearchTimeout
    from guided_lfd.excuse.engine import ExcuseOptions
    from guided_lfd.excuse.reach import ReachabilityOracle
    from guided_lfd.excuse.space import Semantics, build_space
    from guided_lfd.grounding import ground

    options = ExcuseOptions(fixed_from=complete)
    fixed = options.fixed_predicates(robot)
    task = ground(robot, problem, fixed=fixed)
    space = build_space(task, Semantics.LITERAL, fixed)
    oracle = ReachabilityOracle(space, time.monotonic() + time_limit)
    try:
        return oracle.solve(task.init) is not None
    except SearchTimeout:
        return None


def generate_suite(ipc_root: Path, kitchen_root: Path | None, tasks: Iterable[str],
                   check_time: float = 20.0, log: Callable[[str], None] = print) -> list[BenchTask]:
    """Every (domain, task, removed action) whose robot domain cannot solve the task."""
    from guided_lfd.pddl.reader import parse_task

    out: list[BenchTask] = []
    for domain_dir in sorted(p for p in ipc_root.iterdir() if (p / "domain.pddl").is_file()):
        for name in tasks:
            problem_file = domain_dir / f"{name}.pddl"
            if not problem_file.is_file():
                continue
            full, _ = parse_task(domain_dir / "domain.pddl", problem_file)
            for action in full.actions:
                bt = BenchTask(f"{domain_dir.name}-{name}-{action.name}", domain_dir.name, name, action.name,
                               str(domain_dir / "domain.pddl"), str(problem_file), str(domain_dir / "domain.pddl"))
                robot, problem, complete = bt.load()
                solvable = _robot_solves(robot, problem, complete, check_time)
                log(f"{bt.id}: {'solvable' if solvable else 'undecided' if solvable is None else 'UNSOLVABLE'}")
                if solvable is False:
                    out.append(bt)
    if kitchen_root is not None:
        for kdir in sorted(p for p in kitchen_root.iterdir() if (p / "robot.pddl").is_file()):
            out.append(BenchTask(f"{kdir.name}-problem", kdir.name, "problem", "", str(kdir / "robot.pddl"),
                                 str(kdir / "problem.pddl"), str(kdir / "human.pddl")))
    return out


def _relative(path: str, root: Path) -> str:
    try:
        return str(Path(path).resolve().relative_to(root.resolve()))
    except ValueError:
        return path


def write_suite(suite: list[BenchTask], path: Path, root: Path) -> None:
    """Write the suite as CSV with paths relative to ``root``."""
    from guided_lfd.io import write_text
    import io

    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=SUITE_FIELDS, lineterminator="\n")
    writer.writeheader()
    for t in suite:
        row = asdict(t)
        for key in ("domain_file", "problem_file", "fixed_from"):
            row[key] = _relative(row[key], root) if row[key] else ""
        writer.writerow(row)
    write_text(path, buf.getvalue())


def read_suite(path: Path, root: Path) -> list[BenchTask]:
    """Read a suite CSV; relative paths are taken from ``root``."""
    out = []
    with open(path, newline="", encoding="utf-8") as fh:
        for row in csv.DictReader(fh):
            for key in ("domain_file", "problem_file", "fixed_from"):
                if row[key] and not Path(row[key]).is_absolute():
                    row[key] = str(root / row[key])
            out.append(BenchTask(**row))
    return out


#: Runs whose strategy stops on a family (domain, removed action, semantics) after its first
#: unfinished task: later, larger tasks of that family are recorded as ``not-run`` and counted
#: as unsolved at the limit (as the household series does for the baseline).
STOP_AFTER_UNFINISHED = ("baseline",)
#: A run still going this long past its time limit is killed (recorded as ``timeout``).
KILL_GRACE_S = 60.0
#: Exit code of a run whose memory ran out (see guided_lfd.errors.EXIT_MEMORY).
_EXIT_MEMORY = 22


def robot_domain_file(task: BenchTask, folder: Path) -> Path:
    """The robot's domain file for ``task`` (the domain without ``removed_action``), written once."""
    if not task.removed_action:
        return Path(task.domain_file)
    path = folder / f"{task.domain}-without-{task.removed_action}.pddl"
    if not path.exists():
        from guided_lfd.io import write_text
        from guided_lfd.pddl.reader import parse_domain
        from guided_lfd.pddl.writer import domain_to_pddl

        full = parse_domain(task.domain_file)
        robot = replace(full, actions=[a for a in full.actions if a.name != task.removed_action])
        write_text(path, domain_to_pddl(robot, header=f"{task.domain} without {task.removed_action}"))
    return path


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


def run_one(task: BenchTask, strategy: str, semantics: str, time_limit: float,
            memory_limit_mb: int | None = None, workdir: Path | None = None) -> dict[str, Any]:
    """One whole run of ``guided-lfd excuse`` in its own process; its result row (never raises).

    ``wall_s`` is the process's wall time as the shell sees it (start-up,
    parsing, grounding, search and the robot's optimal plan); ``time_s`` and
    ``search_time_s`` are the run's own figures.  A run still going 60 s past
    its limit (:data:`KILL_GRACE_S`) is killed and recorded as ``timeout``.
    """
    import json
    import subprocess
    import tempfile

    row: dict[str, Any] = {"id": task.id, "domain": task.domain, "task": task.task,
                           "removed_action": task.removed_action, "semantics": semantics, "strategy": strategy}
    folder = workdir or Path(tempfile.gettempdir()) / "guided-lfd-bench"
    folder.mkdir(parents=True, exist_ok=True)
    try:
        cmd = command_line(task, strategy, semantics, time_limit, robot_domain_file(task, folder))
    except Exception as exc:  # a benchmark row records failures instead of stopping the run
        row.update(status="error", excuse=f"{type(exc).__name__}: {exc}"[:300])
        return _complete(row)
    start = time.perf_counter()
    # The memory cap is set on the started process (prlimit), not in a pre-exec hook:
    # those are unsafe while other threads run, and the local executor is threads.
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if memory_limit_mb:
        cap_memory(proc.pid, memory_limit_mb)
    try:
        stdout, stderr = proc.communicate(timeout=time_limit + KILL_GRACE_S)
        code = proc.returncode
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        code, stdout, stderr = None, "", ""
    row.update(wall_s=round(time.perf_counter() - start, 4), exit_code="" if code is None else code)
    try:
        doc = json.loads(stdout)
    except json.JSONDecodeError:
        doc = None
    if doc is None:
        if code is None:
            status, note = "timeout", f"killed {KILL_GRACE_S:g} s past the limit"
        elif code == _EXIT_MEMORY:
            status, note = "memout", ""
        else:
            status = "crashed"
            note = (stderr.strip().splitlines() or [f"process ended with exit code {code}"])[-1]
        row.update(status=status, excuse=note[:300])
        return _complete(row)
    stats = doc.get("statistics") or {}
    row.update(status=doc["status"], time_s=stats.get("time_s", ""), search_time_s=stats.get("search_time_s", ""),
               candidates=stats.get("candidates", 0), planner_calls=stats.get("planner_calls", 0),
               expanded=stats.get("nodes_expanded", 0))
    excuse = doc.get("excuse")
    if excuse:
        row.update(size=excuse["size"], cost=excuse["cost"], excuse=" ".join(c["change"] for c in excuse["changes"]))
    elif doc["status"] not in SOLVED and doc.get("message"):
        row.update(excuse=str(doc["message"])[:300])
    return _complete(row)


def _complete(row: dict[str, Any]) -> dict[str, Any]:
    for key in RESULT_FIELDS:
        row.setdefault(key, "")
    return {k: row[k] for k in RESULT_FIELDS}


class RowLog:
    """Appends result rows to a CSV as they arrive, so a long run survives a crash.

    Rows already in the file are skipped when the run is started again (resume).
    """

    def __init__(self, path: Path) -> None:
        self.path = path
        path.parent.mkdir(parents=True, exist_ok=True)
        self.rows: list[dict[str, Any]] = []
        if path.exists():
            self.rows = read_results(path)
        else:
            with open(path, "w", newline="", encoding="utf-8") as fh:
                csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n").writeheader()
        self.done: set[tuple[str, str, str]] = {(r["id"], r["strategy"], r["semantics"]) for r in self.rows}

    def append(self, row: dict[str, Any]) -> None:
        with open(self.path, "a", newline="", encoding="utf-8") as fh:
            csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n", extrasaction="ignore").writerow(row)
            fh.flush()


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


def not_run(task: BenchTask, strategy: str, semantics: str, reason: str) -> dict[str, Any]:
    """The row of a run left out after its family's first unfinished task."""
    return _complete({"id": task.id, "domain": task.domain, "task": task.task, "removed_action": task.removed_action,
                      "semantics": semantics, "strategy": strategy, "status": "not-run", "excuse": reason})


def crashed(task: BenchTask, strategy: str, semantics: str, exc: BaseException) -> dict[str, Any]:
    """The row of a run whose worker died under it (Dask's KilledWorker, a crash): counted as crashed."""
    reason = f"worker died: {type(exc).__name__}: {exc}"
    return _complete({"id": task.id, "domain": task.domain, "task": task.task, "removed_action": task.removed_action,
                      "semantics": semantics, "strategy": strategy, "status": "crashed", "excuse": reason[:300]})


def run_chain(chain: list[Run], time_limit: float, memory_limit_mb: int | None = None,
              previous: dict[tuple[str, str, str], dict[str, Any]] | None = None,
              on_row: Callable[[dict[str, Any]], None] | None = None, stop: bool = False) -> list[dict[str, Any]]:
    """Run a chain in order; with ``stop``, after the first unfinished run the rest are ``not-run``.

    ``previous`` holds rows of an interrupted run (resume): they are not run again.
    """
    rows: list[dict[str, Any]] = []
    stopped_at: str | None = None
    for task, strategy, sem in chain:
        key = (task.id, strategy, sem)
        if previous and key in previous:
            row, fresh = previous[key], False
        elif stopped_at is not None:
            row, fresh = not_run(task, strategy, sem, f"not run: {stopped_at} was not finished"), True
        else:
            row, fresh = run_one(task, strategy, sem, time_limit, memory_limit_mb), True
        if stop and stopped_at is None and row["status"] not in SOLVED:
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
    on_row: Callable[[dict[str, Any]], None] | None = None,
    previous: list[dict[str, Any]] | None = None,
    memory_limit_mb: int | None = None,
    stop_after_unfinished: Iterable[str] = STOP_AFTER_UNFINISHED,
) -> list[dict[str, Any]]:
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
    done = {(r["id"], r["strategy"], r["semantics"]): r for r in previous or []}
    if executor == "dask":
        return _run_dask(work, time_limit, scheduler, on_row, memory_limit_mb, done, stopping)
    import threading
    from concurrent.futures import ThreadPoolExecutor

    lock = threading.Lock()

    def report(row: dict[str, Any]) -> None:
        if on_row:
            with lock:
                on_row(row)

    rows: list[dict[str, Any]] = []
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = [pool.submit(run_chain, chain, time_limit, memory_limit_mb, done, report,
                               chain[0][1] in stopping) for chain in work]
        for fut in futures:
            rows.extend(fut.result())
    return sorted(rows, key=lambda r: (r["id"], r["semantics"], r["strategy"]))


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
                chain_rows = [crashed(task, strategy, sem, exc) for task, strategy, sem in chain_of[fut.key]]
            for row in chain_rows:
                rows.append(row)
                if on_row and (row["id"], row["strategy"], row["semantics"]) not in done:
                    on_row(row)
    finally:
        if not isinstance(scheduler, Client):
            client.close()
    return sorted(rows, key=lambda r: (r["id"], r["semantics"], r["strategy"]))


def merge_rows(kept: list[dict[str, Any]], new: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """``kept`` with each run of ``new`` (same id, strategy, semantics) replaced or added: a subset run's update."""
    key = lambda r: (r["id"], r["strategy"], r["semantics"])  # noqa: E731
    fresh = {key(r): r for r in new}
    return [r for r in kept if key(r) not in fresh] + list(fresh.values())


def write_results(rows: list[dict[str, Any]], path: Path) -> None:
    """Results as CSV (one row per task, strategy and semantics)."""
    import io

    from guided_lfd.io import write_text

    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=RESULT_FIELDS, lineterminator="\n", extrasaction="ignore")
    writer.writeheader()
    writer.writerows(rows)
    write_text(path, buf.getvalue())


def read_results(path: Path) -> list[dict[str, Any]]:
    """Read a results CSV back."""
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@dataclass
class Comparison:
    """Default strategy vs baseline on one semantics."""

    semantics: str
    tasks: int
    solved_default: int
    solved_baseline: int
    both: int
    median_speedup: float  # on search time (the engine; setup is shared)
    geomean_speedup: float
    median_total_speedup: float  # on wall time of the whole run
    size_mismatches: list[str]
    large_default: int  # tasks with excuse size >= 3 solved
    large_baseline: int
    nontrivial: int = 0  # tasks the baseline takes >= 1 s on, or does not finish (and one strategy solves)
    median_nontrivial_speedup: float = math.nan  # whole run, wall; an unfinished run counts at the limit


#: Search phases shorter than this (seconds) count as this long in speed-ups.
SEARCH_TIME_FLOOR = 1e-4


#: A task is non-trivial when the baseline's whole run takes at least this long (s) or does not finish.
NONTRIVIAL_S = 1.0
#: Suite parts by task name: the first suite (IPC task01-04 and the kitchens) and its growth.
FIRST_TASKS = ("task01", "task02", "task03", "task04", "problem")


def suite_part(row: dict[str, Any]) -> str:
    """``first`` (IPC task01-04 and the kitchens, the 168 tasks of the first suite) or ``grown``."""
    return "first" if row["task"] in FIRST_TASKS else "grown"


def whole_run_s(row: dict[str, Any]) -> float | None:
    """The run's whole wall time: ``wall_s`` (from outside the process), else ``time_s`` (older rows)."""
    for key in ("wall_s", "time_s"):
        if row.get(key) not in ("", None):
            return float(row[key])
    return None


def compare(rows: list[dict[str, Any]], default: str = "landmark", baseline: str = "baseline",
            time_limit: float = 60.0) -> list[Comparison]:
    """Coverage, speed-up and size agreement per semantics, and over both (a task in each semantics)."""
    semantics = sorted({r["semantics"] for r in rows})
    out = [_compare([r for r in rows if r["semantics"] == sem], sem, default, baseline, time_limit)
           for sem in semantics]
    if len(semantics) > 1:
        out.append(_compare(rows, "both", default, baseline, time_limit))
    return out


def search_speedup(default_row: dict[str, Any], baseline_row: dict[str, Any]) -> float | None:
    """Baseline search time / default search time (None when a run has no search time)."""
    d, b = default_row.get("search_time_s"), baseline_row.get("search_time_s")
    if d in ("", None) or b in ("", None):
        return None
    # Search times are recorded to the microsecond; below SEARCH_TIME_FLOOR
    # scheduling noise dominates, so shorter phases count as the floor.
    return max(float(b), SEARCH_TIME_FLOOR) / max(float(d), SEARCH_TIME_FLOOR)


def _compare(rows: list[dict[str, Any]], label: str, default: str, baseline: str,
             time_limit: float = 60.0) -> Comparison:
    """Coverage, speed-up and size agreement over ``rows`` (``label``: a semantics, or "both")."""
    by_task: dict[str, dict[str, dict]] = {}
    for r in rows:
        key = r["id"] if label != "both" else f"{r['id']} ({r['semantics']})"
        by_task.setdefault(key, {})[r["strategy"]] = r
    solved_d = solved_b = large_d = large_b = 0
    ratios: list[float] = []
    total_ratios: list[float] = []
    nontrivial: list[float] = []
    mismatches: list[str] = []
    for tid, runs in sorted(by_task.items()):
        d, b = runs.get(default), runs.get(baseline)
        ok_d = d is not None and d["status"] in SOLVED
        ok_b = b is not None and b["status"] in SOLVED
        solved_d += ok_d
        solved_b += ok_b
        size = next((int(r["size"]) for r in (d, b) if r is not None and r["status"] == "excuse-found"), None)
        if size is not None and size >= 3:
            large_d += ok_d
            large_b += ok_b
        if (ok_d or ok_b) and d is not None and b is not None:
            # A run that gave up counts at the limit; a crashed or failed one says nothing.
            d_wall = whole_run_s(d) if ok_d else time_limit if d["status"] in GAVE_UP else None
            b_wall = whole_run_s(b) if ok_b else time_limit if b["status"] in GAVE_UP else None
            if d_wall is not None and b_wall is not None and (not ok_b or b_wall >= NONTRIVIAL_S):
                nontrivial.append(b_wall / max(d_wall, 1e-4))
        if ok_d and ok_b:
            if (d["status"], str(d["size"])) != (b["status"], str(b["size"])):
                mismatches.append(f"{tid}: {default} {d['status']} {d['size']} vs {baseline} {b['status']} {b['size']}")
            total_ratios.append(whole_run_s(b) / max(whole_run_s(d), 1e-4))
            ratio = search_speedup(d, b)
            if ratio is not None:
                ratios.append(ratio)
    return Comparison(
        label, len(by_task), solved_d, solved_b, len(ratios),
        statistics.median(ratios) if ratios else math.nan,
        math.exp(statistics.fmean(math.log(r) for r in ratios)) if ratios else math.nan,
        statistics.median(total_ratios) if total_ratios else math.nan,
        mismatches, large_d, large_b, len(nontrivial),
        statistics.median(nontrivial) if nontrivial else math.nan,
    )


#: Excuse-size buckets of the speed-up table ("none" = proved that no excuse exists).
SIZE_BUCKETS = ("1", "2", "3-5", "6+", "none")


def size_bucket(row: dict[str, Any]) -> str:
    """The :data:`SIZE_BUCKETS` entry of a solved result row."""
    if row["status"] != "excuse-found":
        return "none"
    size = int(row["size"])
    return str(size) if size <= 2 else ("3-5" if size <= 5 else "6+")


def speedups_by_size(rows: list[dict[str, Any]], default: str = "landmark",
                     baseline: str = "baseline") -> dict[str, dict[str, list[float]]]:
    """Search speed-ups on the tasks both strategies solve, per semantics and excuse-size bucket."""
    runs: dict[tuple[str, str], dict[str, dict]] = {}
    for r in rows:
        runs.setdefault((r["id"], r["semantics"]), {})[r["strategy"]] = r
    out: dict[str, dict[str, list[float]]] = {}
    for (_, sem), pair in sorted(runs.items()):
        d, b = pair.get(default), pair.get(baseline)
        if d is None or b is None or d["status"] not in SOLVED or b["status"] not in SOLVED:
            continue
        ratio = search_speedup(d, b)
        if ratio is not None:
            out.setdefault(sem, {}).setdefault(size_bucket(d), []).append(ratio)
    return out


def plot(rows: list[dict[str, Any]], folder: Path, time_limit: float) -> list[Path]:
    """Cactus plot and time-vs-size plot as PNG files."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise ImportError("plots need the 'plots' extra: pip install 'guided-lfd[plots]'") from None
    folder.mkdir(parents=True, exist_ok=True)
    configs = sorted({(r["strategy"], r["semantics"]) for r in rows})
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for st, se in configs:
        times = sorted(whole_run_s(r) for r in rows
                       if r["strategy"] == st and r["semantics"] == se and r["status"] in SOLVED)
        ax.step(range(1, len(times) + 1), times, where="post", label=f"{st} ({se})")
    ax.set_yscale("log")
    ax.set_xlabel("tasks solved")
    ax.set_ylabel("time per task (s, log)")
    ax.axhline(time_limit, color="grey", lw=0.8, ls="--")
    ax.set_title("Excuse search: cactus plot")
    ax.legend(fontsize=8)
    fig.tight_layout()
    cactus = folder / "cactus.png"
    fig.savefig(cactus, dpi=120, metadata={"Software": None})
    plt.close(fig)
    fig, axes = plt.subplots(1, 2, figsize=(9, 4.0), sharey=True)
    for ax, se in zip(axes, sorted({r["semantics"] for r in rows})):
        for st, marker in (("baseline", "x"), ("landmark", "o")):
            pts = [(int(r["size"]), whole_run_s(r)) for r in rows
                   if r["strategy"] == st and r["semantics"] == se and r["status"] == "excuse-found"]
            if pts:
                xs, ys = zip(*pts)
                ax.scatter(xs, ys, marker=marker, alpha=0.6, label=st)
        ax.set_yscale("log")
        ax.set_xlabel("minimal excuse size")
        ax.set_title(f"{se} semantics")
        ax.legend(fontsize=8)
    axes[0].set_ylabel("time (s, log)")
    fig.suptitle("Time vs excuse size (solved tasks)")
    fig.tight_layout()
    scatter = folder / "time_vs_size.png"
    fig.savefig(scatter, dpi=120, metadata={"Software": None})
    plt.close(fig)
    return [cactus, scatter]


def _parts_table(rows: list[dict[str, Any]]) -> list[str]:
    """Default coverage per suite part (the first 168 tasks, the grown ones) and semantics."""
    parts = sorted({suite_part(r) for r in rows})
    if parts == ["first"]:
        return []
    out = ["", "## Coverage by suite part", "",
           "*first*: IPC task01-04 and the kitchens (the first suite); *grown*: IPC task05-10.", "",
           "| part | semantics | tasks | solved: landmark | solved: baseline | baseline not run |", "|---|---|---|---|---|---|"]
    for part in parts:
        for se in sorted({r["semantics"] for r in rows}):
            sub = [r for r in rows if suite_part(r) == part and r["semantics"] == se]
            n = len({r["id"] for r in sub})
            lm = sum(r["status"] in SOLVED for r in sub if r["strategy"] == "landmark")
            bl = sum(r["status"] in SOLVED for r in sub if r["strategy"] == "baseline")
            skipped = sum(r["status"] == "not-run" for r in sub if r["strategy"] == "baseline")
            out.append(f"| {part} | {se} | {n} | {lm} ({100 * lm / max(n, 1):.1f}%) | {bl} ({100 * bl / max(n, 1):.1f}%) "
                       f"| {skipped} |")
    return out


def limit_section(rows: list[dict[str, Any]], time_limit: float,
                  label: Callable[[dict[str, Any]], str] | None = None) -> list[str]:
    """Markdown lines: how far whole runs went past the time limit (``--time-limit`` bounds the whole run).

    ``label`` names a row (default: its id, strategy and semantics).
    """
    label = label or (lambda r: f"{r['id']} {r['strategy']} {r['semantics']}")
    walls = [(float(r["wall_s"]), r) for r in rows if r.get("wall_s") not in ("", None)]
    if not walls:
        return []
    worst, worst_row = max(walls, key=lambda item: item[0])
    over = [(w, r) for w, r in walls if w > time_limit + 1.0]
    out = ["", "## Time limit", "",
           f"Runs: {len(walls)}; longest whole run {worst:.2f} s ({label(worst_row)}: {worst_row['status']}), "
           f"{worst - time_limit:+.2f} s against the {time_limit:g} s limit; runs more than 1 s past it: {len(over)}."]
    out += [f"- {label(r)}: {w:.2f} s ({r['status']})" for w, r in over]
    return out


def _limit_section(rows: list[dict[str, Any]], time_limit: float) -> list[str]:
    out = limit_section(rows, time_limit)
    skipped = sum(r["status"] == "not-run" for r in rows)
    if skipped:
        out += ["", f"Runs not made: {skipped}. A baseline run is not made on the later tasks of a family "
                "(domain, removed action, semantics) after the first task of that family it does not finish "
                "(tasks in order, as in the household series); such a run counts as unsolved at the limit."]
    return out


def summary_markdown(rows: list[dict[str, Any]], time_limit: float, command: str, plots: list[Path],
                     base: Path) -> str:
    """The markdown summary: coverage table, speed-ups, agreement, plots."""
    comps = compare(rows, time_limit=time_limit)
    domains = sorted({r["domain"] for r in rows})
    lines = [
        "# Excuse benchmark",
        "",
        f"Regenerate with: `{command}`",
        "",
        f"{len({r['id'] for r in rows})} tasks over {len(domains)} domains; time limit {time_limit:g} s per task "
        "and run; each run is one `guided-lfd excuse ... --json` process, as a user would start it. *Solved* = "
        "a minimal excuse found, or proved that none exists.",
        "",
        "## Default (landmark) vs baseline (the paper's method)",
        "",
        "Speed-ups are baseline time / landmark time. *search* is the excuse search itself (the engine), on "
        "the tasks both solve; the setup before it is the same code for both strategies and is excluded: "
        "parsing, grounding, invariant synthesis, compiling the relaxed excuse task and the \"already "
        "solvable?\" check (whose reachability memory the landmark search then reuses). *whole run* is the "
        "wall time of the whole process as the shell sees it: start-up, parsing, grounding, search and the "
        "robot's optimal plan. *Non-trivial* tasks are those where the baseline's whole run takes "
        f">= {NONTRIVIAL_S:g} s or does not finish (counted at the limit; an unfinished default run too). "
        "The baseline is generous to the paper's method: each candidate is one in-memory pyperplan call on "
        "the already-grounded task (no re-parsing or re-grounding per candidate). Search phases shorter than "
        "0.1 ms count as 0.1 ms.",
        "",
        "| semantics | tasks | solved: landmark | solved: baseline | both | median speed-up (search) "
        "| geo-mean speed-up (search) | median speed-up (whole run) | non-trivial tasks "
        "| median speed-up (whole run, non-trivial) "
        "| size >= 3 solved: landmark | size >= 3 solved: baseline | size disagreements |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for c in comps:
        lines.append(
            f"| {c.semantics} | {c.tasks} | {c.solved_default} ({100 * c.solved_default / c.tasks:.0f}%) "
            f"| {c.solved_baseline} ({100 * c.solved_baseline / c.tasks:.0f}%) | {c.both} | {c.median_speedup:.0f}x "
            f"| {c.geomean_speedup:.0f}x | {c.median_total_speedup:.1f}x | {c.nontrivial} "
            f"| {c.median_nontrivial_speedup:.1f}x "
            f"| {c.large_default} | {c.large_baseline} | {len(c.size_mismatches)} |"
        )
    lines += _parts_table(rows) + _limit_section(rows, time_limit)
    lines += ["", "## Coverage per domain", "",
              "| domain | tasks | " + " | ".join(f"{st} {se}" for se in ("literal", "consistent")
                                                 for st in ("landmark", "baseline")) + " |",
              "|---|---|" + "---|" * 4]
    for dom in domains:
        ids = {r["id"] for r in rows if r["domain"] == dom}
        cells = []
        for se in ("literal", "consistent"):
            for st in ("landmark", "baseline"):
                n = sum(1 for r in rows if r["domain"] == dom and r["semantics"] == se and r["strategy"] == st
                        and r["status"] in SOLVED)
                cells.append(str(n))
        lines.append(f"| {dom} | {len(ids)} | " + " | ".join(cells) + " |")
    by_size = speedups_by_size(rows)
    lines += ["", "## Median search speed-up by minimal excuse size", "",
              "On the tasks both strategies solve; each cell is the median and, in brackets, the number of tasks.",
              "", "| semantics | " + " | ".join(f"size {b}" if b != "none" else "no excuse" for b in SIZE_BUCKETS)
              + " |", "|---|" + "---|" * len(SIZE_BUCKETS)]
    for se in sorted(by_size):
        cells = [f"{statistics.median(v):.0f}x ({len(v)})" if (v := by_size[se].get(b)) else "-"
                 for b in SIZE_BUCKETS]
        lines.append(f"| {se} | " + " | ".join(cells) + " |")
    sizes: dict[str, int] = {}
    for r in rows:
        if r["strategy"] == "landmark" and r["status"] == "excuse-found":
            key = str(min(int(r["size"]), 6)) if int(r["size"]) < 6 else "6+"
            sizes[f"{r['semantics']} {key}"] = sizes.get(f"{r['semantics']} {key}", 0) + 1
    lines += ["", "## Minimal excuse sizes found (landmark)", "", "| semantics | " +
              " | ".join(["1", "2", "3", "4", "5", "6+"]) + " |", "|---|" + "---|" * 6]
    for se in ("literal", "consistent"):
        lines.append(f"| {se} | " + " | ".join(str(sizes.get(f"{se} {k}", 0))
                                              for k in ["1", "2", "3", "4", "5", "6+"]) + " |")
    mism = [m for c in comps if c.semantics != "both" for m in c.size_mismatches]
    lines += ["", "## Size agreement", "",
              "Every task both strategies solved has the same status and minimal size."
              if not mism else "Disagreements:\n\n" + "\n".join(f"- {m}" for m in mism)]
    errors = [r for r in rows if r["status"] in ("error", "crashed")]
    found = sum(r["status"] == "excuse-found" for r in rows)
    lines += ["", "## Validation", "",
              f"Every run re-checks each excuse it returns with the independent checker "
              f"(`guided_lfd.excuse.check`: the excuse state does not already satisfy the goal, keeps the invariants under the "
              f"consistent semantics, and the robot's plan from it validates); a failed check ends the run "
              f"as an error. Runs that returned an excuse: {found}; runs that ended in an error or crash: {len(errors)}."]
    if errors:
        lines += [""] + [f"- {r['id']} {r['strategy']} {r['semantics']}: {r['status']}"
                         + (f" ({r['excuse']})" if r["excuse"] else "") for r in errors]
    memouts = [r for r in rows if r["status"] == "memout"]
    if memouts:
        lines += ["", f"Runs that exceeded the memory cap (memout, counted as unsolved): {len(memouts)}.", ""]
        lines += [f"- {r['id']} {r['strategy']} {r['semantics']}" for r in memouts]
    lines += ["", "## Plots", ""] + [f"![{p.stem}]({_relative(str(p), base)})" for p in plots]
    return "\n".join(lines) + "\n"
