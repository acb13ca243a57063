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
import multiprocessing as mp
import statistics
import time
import traceback
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any, Callable, Iterable

SUITE_FIELDS = ["id", "domain", "task", "removed_action", "domain_file", "problem_file", "fixed_from"]
RESULT_FIELDS = [
    "id", "domain", "task", "removed_action", "semantics", "strategy", "status", "size", "cost",
    "time_s", "search_time_s", "candidates", "planner_calls", "expanded", "excuse",
]
SOLVED = ("excuse-found", "no-excuse")


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


def run_one(task: BenchTask, strategy: str, semantics: str, time_limit: float) -> dict[str, Any]:
    """Run one strategy on one task; returns a result row (never raises)."""
    from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
    from guided_lfd.excuse.space import Semantics

    row: dict[str, Any] = {"id": task.id, "domain": task.domain, "task": task.task,
                           "removed_action": task.removed_action, "semantics": semantics, "strategy": strategy}
    start = time.perf_counter()
    out_of_memory = False
    try:
        robot, problem, complete = task.load()
        report = find_excuses(robot, problem, ExcuseOptions(
            semantics=Semantics(semantics), strategy=strategy, time_limit=time_limit,
            fixed_from=complete, optimal_plans=False))
        stats = report.statistics
        row.update(status=report.status, time_s=round(time.perf_counter() - start, 4),
                   search_time_s=stats.get("search_time_s", ""),
                   candidates=stats.get("candidates", 0), planner_calls=stats.get("planner_calls", 0),
                   expanded=stats.get("nodes_expanded", 0))
        if report.excuse is not None:
            row.update(size=report.excuse.size, cost=report.excuse.cost,
                       excuse=" ".join(str(c) for c in report.excuse.changes))
    except MemoryError:
        # Only a flag here: the traceback still holds the search's frontier,
        # which is freed once the handler is left.
        out_of_memory = True
    except Exception as exc:  # a benchmark row records failures instead of stopping the run
        row.update(status="error", time_s=round(time.perf_counter() - start, 4),
                   excuse=f"{type(exc).__name__}: {exc}"[:300])
        row["trace"] = traceback.format_exc(limit=3)
    if out_of_memory:
        row.update(status="memout", time_s=round(time.perf_counter() - start, 4))
    for key in RESULT_FIELDS:
        row.setdefault(key, "")
    return {k: row[k] for k in RESULT_FIELDS}


def limit_memory(megabytes: int | None) -> None:
    """Cap this process's address space, so that running out raises MemoryError.

    Without a cap, a run whose frontier outgrows the machine (the baseline's
    breadth-first search on sokoban task04 filled a 24 GiB machine) is killed by the
    kernel's OOM killer, and may take the run beside it down too.
    """
    if not megabytes:
        return
    import resource

    # Only the soft limit, and never above a hard limit already in force
    # (``ulimit -v``, a cluster job): raising it would fail every run.
    _, hard = resource.getrlimit(resource.RLIMIT_AS)
    limit = megabytes * 1024 * 1024
    if hard != resource.RLIM_INFINITY:
        limit = min(limit, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))


def _receive(conn) -> dict[str, Any] | None:
    """The row a run sent, or None if its process closed the pipe without one."""
    try:
        return conn.recv()
    except EOFError:
        return None


def _child(conn, task, strategy, semantics, time_limit, memory_limit_mb=None):
    limit_memory(memory_limit_mb)
    conn.send(run_one(task, strategy, semantics, time_limit))
    conn.close()


class RowLog:
    """Appends result rows to a CSV as they arrive, so a long run survives a crash.

    Rows already in the file are skipped when the run is started again (resume).
    """

    def __init__(self, path: Path) -> None:
        self.path = path
        path.parent.mkdir(parents=True, exist_ok=True)
        self.done: set[tuple[str, str, str]] = set()
        if path.exists():
            for row in read_results(path):
                self.done.add((row["id"], row["strategy"], row["semantics"]))
        else:
            with open(path, "w", newline="", encoding="utf-8") as fh:
                csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n").writeheader()

    def append(self, row: dict[str, Any]) -> None:
        with open(self.path, "a", newline="", encoding="utf-8") as fh:
            csv.DictWriter(fh, fieldnames=RESULT_FIELDS, lineterminator="\n", extrasaction="ignore").writerow(row)
            fh.flush()


def run_suite(
    suite: list[BenchTask],
    strategies: list[str],
    semantics: list[str],
    time_limit: float,
    jobs: int = 2,
    executor: str = "local",
    scheduler: str | None = None,
    on_row: Callable[[dict[str, Any]], None] | None = None,
    skip: set[tuple[str, str, str]] | None = None,
    memory_limit_mb: int | None = None,
) -> list[dict[str, Any]]:
    """Run every (task, strategy, semantics) not in ``skip``; ``executor`` is ``local`` or ``dask``.

    Locally, each run's address space is capped at ``memory_limit_mb`` (a run
    that needs more ends as ``memout``); Dask workers keep their own limits.
    """
    # Import the engine before forking: every run uses the code as it was at start.
    import guided_lfd.excuse.engine  # noqa: F401
    import guided_lfd.excuse.invariants  # noqa: F401
    import guided_lfd.excuse.strategies  # noqa: F401
    import guided_lfd.planning  # noqa: F401  (pyperplan, for the baseline's planner calls)
    from guided_lfd.excuse.lmcut import load_numpy

    load_numpy()  # imported on demand by LM-cut: keep its import out of the timed runs, as before

    work = [(t, st, se) for t in suite for se in semantics for st in strategies
            if (t.id, st, se) not in (skip or set())]
    if executor == "dask":
        return _run_dask(work, time_limit, scheduler, on_row)
    rows: list[dict[str, Any]] = []
    ctx = mp.get_context("fork")
    running: list[tuple[Any, Any, float, tuple]] = []
    pending = list(work)
    hard = time_limit + 60.0  # grounding and checks on top of the search limit
    while pending or running:
        while pending and len(running) < jobs:
            item = pending.pop(0)
            parent, child = ctx.Pipe(duplex=False)
            proc = ctx.Process(target=_child, args=(child, item[0], item[1], item[2], time_limit, memory_limit_mb),
                               daemon=True)
            proc.start()
            child.close()
            running.append((proc, parent, time.monotonic(), item))
        for entry in list(running):
            proc, parent, started, (t, st, se) = entry
            if parent.poll(0.05):
                row = _receive(parent)
                proc.join()
            elif not proc.is_alive() or time.monotonic() - started > hard:
                # The row may have arrived just before the process ended.
                row = _receive(parent) if parent.poll() else None
                proc.kill()
                proc.join()
            else:
                continue
            if row is None:
                row = {k: "" for k in RESULT_FIELDS}
                over = time.monotonic() - started > hard
                row.update(id=t.id, domain=t.domain, task=t.task, removed_action=t.removed_action, semantics=se,
                           strategy=st, status="timeout" if over else "crashed",
                           time_s=round(time.monotonic() - started, 4),
                           excuse="" if over else f"process ended with exit code {proc.exitcode}")
            running.remove(entry)
            rows.append(row)
            if on_row:
                on_row(row)
    return sorted(rows, key=lambda r: (r["id"], r["semantics"], r["strategy"]))


def _run_dask(work, time_limit, scheduler, on_row):
    try:
        from dask.distributed import Client, as_completed
    except ImportError:
        raise ImportError("the dask executor needs the 'dist' extra: pip install 'guided-lfd[dist]'") from None
    client = Client(scheduler) if scheduler else Client(processes=True)
    try:
        futures = [client.submit(run_one, t, st, se, time_limit, pure=False) for t, st, se in work]
        rows = []
        for fut in as_completed(futures):
            row = fut.result()
            rows.append(row)
            if on_row:
                on_row(row)
    finally:
        client.close()
    return sorted(rows, key=lambda r: (r["id"], r["semantics"], r["strategy"]))


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


#: Search phases shorter than this (seconds) count as this long in speed-ups.
SEARCH_TIME_FLOOR = 1e-4


def compare(rows: list[dict[str, Any]], default: str = "landmark", baseline: str = "baseline") -> list[Comparison]:
    """Coverage, speed-up and size agreement per semantics, and over both (a task in each semantics)."""
    semantics = sorted({r["semantics"] for r in rows})
    out = [_compare([r for r in rows if r["semantics"] == sem], sem, default, baseline) for sem in semantics]
    if len(semantics) > 1:
        out.append(_compare(rows, "both", default, baseline))
    return out


def search_speedup(default_row: dict[str, Any], baseline_row: dict[str, Any]) -> float | None:
    """Baseline search time / default search time (None when a run has no search time)."""
    d, b = default_row.get("search_time_s"), baseline_row.get("search_time_s")
    if d in ("", None) or b in ("", None):
        return None
    # Search times are recorded to the microsecond; below SEARCH_TIME_FLOOR
    # scheduling noise dominates, so shorter phases count as the floor.
    return max(float(b), SEARCH_TIME_FLOOR) / max(float(d), SEARCH_TIME_FLOOR)


def _compare(rows: list[dict[str, Any]], label: str, default: str, baseline: str) -> Comparison:
    """Coverage, speed-up and size agreement over ``rows`` (``label``: a semantics, or "both")."""
    by_task: dict[str, dict[str, dict]] = {}
    for r in rows:
        key = r["id"] if label != "both" else f"{r['id']} ({r['semantics']})"
        by_task.setdefault(key, {})[r["strategy"]] = r
    solved_d = solved_b = large_d = large_b = 0
    ratios: list[float] = []
    total_ratios: list[float] = []
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
        if ok_d and ok_b:
            if (d["status"], str(d["size"])) != (b["status"], str(b["size"])):
                mismatches.append(f"{tid}: {default} {d['status']} {d['size']} vs {baseline} {b['status']} {b['size']}")
            total_ratios.append(float(b["time_s"]) / max(float(d["time_s"]), 1e-4))
            ratio = search_speedup(d, b)
            if ratio is not None:
                ratios.append(ratio)
    return Comparison(
        label, len(by_task), solved_d, solved_b, len(ratios),
        statistics.median(ratios) if ratios else math.nan,
        math.exp(statistics.fmean(math.log(r) for r in ratios)) if ratios else math.nan,
        statistics.median(total_ratios) if total_ratios else math.nan,
        mismatches, large_d, large_b,
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
        times = sorted(float(r["time_s"]) for r in rows
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
            pts = [(int(r["size"]), float(r["time_s"])) for r in rows
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


def summary_markdown(rows: list[dict[str, Any]], time_limit: float, command: str, plots: list[Path],
                     base: Path) -> str:
    """The markdown summary: coverage table, speed-ups, agreement, plots."""
    comps = compare(rows)
    domains = sorted({r["domain"] for r in rows})
    lines = [
        "# Excuse benchmark",
        "",
        f"Regenerate with: `{command}`",
        "",
        f"{len({r['id'] for r in rows})} tasks over {len(domains)} domains; time limit {time_limit:g} s per task "
        "and run; one process per run. *Solved* = a minimal excuse found, or proved that none exists.",
        "",
        "## Default (landmark) vs baseline (the paper's method)",
        "",
        "Speed-ups are baseline time / landmark time on the tasks both solve: *search* is the excuse search "
        "itself (the engine). The setup before it is the same code for both strategies and is excluded: "
        "parsing, grounding, invariant synthesis, compiling the relaxed excuse task and the \"already "
        "solvable?\" check (whose reachability memory the landmark search then reuses). *total* is the wall "
        "time of the whole run, setup included. The baseline is generous to the paper's method: each "
        "candidate is one in-memory pyperplan call on the already-grounded task (no re-parsing or "
        "re-grounding per candidate). Search phases shorter than 0.1 ms count as 0.1 ms.",
        "",
        "| semantics | tasks | solved: landmark | solved: baseline | both | median speed-up (search) "
        "| geo-mean speed-up (search) | median speed-up (total) "
        "| size >= 3 solved: landmark | size >= 3 solved: baseline | size disagreements |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for c in comps:
        lines.append(
            f"| {c.semantics} | {c.tasks} | {c.solved_default} ({100 * c.solved_default / c.tasks:.0f}%) "
            f"| {c.solved_baseline} ({100 * c.solved_baseline / c.tasks:.0f}%) | {c.both} | {c.median_speedup:.0f}x "
            f"| {c.geomean_speedup:.0f}x | {c.median_total_speedup:.1f}x "
            f"| {c.large_default} | {c.large_baseline} | {len(c.size_mismatches)} |"
        )
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
