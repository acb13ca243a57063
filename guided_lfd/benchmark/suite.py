"""The benchmark suite: IPC (and kitchen) tasks made unsolvable by removing one skill, as a CSV."""

from __future__ import annotations

import csv
import time
from dataclasses import asdict, dataclass, fields, replace
from pathlib import Path
from typing import Callable, Iterable

from guided_lfd.reporting import relative_path

SUITE_FIELDS = ["id", "domain", "task", "removed_action", "domain_file", "problem_file", "fixed_from"]


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
    from guided_lfd.excuse.prepare import prepare

    fixed = ExcuseOptions(fixed_from=complete).fixed_predicates(robot)
    try:
        prepared = prepare(robot, problem, fixed=fixed, deadline=time.monotonic() + time_limit)
        return prepared.oracle.solve(prepared.task.init) is not None
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
            row[key] = relative_path(row[key], root) if row[key] else ""
        writer.writerow(row)
    write_text(path, buf.getvalue())


SUITE_COLUMNS = tuple(f.name for f in fields(BenchTask))


def read_suite(path: Path, root: Path) -> list[BenchTask]:
    """Read a suite CSV; relative paths are taken from ``root``.  A file missing or without the suite's columns,
    or a row with another number of cells, is :class:`~guided_lfd.errors.InputFileError` at its line."""
    from guided_lfd.benchmark.results import checked_records

    out = []
    expected = f"a suite CSV with {', '.join(SUITE_COLUMNS)}"
    for record, _ in checked_records(path, SUITE_COLUMNS, expected, "suite"):
        row = {k: record[k] for k in SUITE_COLUMNS}
        for key in ("domain_file", "problem_file", "fixed_from"):
            if row[key] and not Path(row[key]).is_absolute():
                row[key] = str(root / row[key])
        out.append(BenchTask(**row))
    return out


def check_removed_actions(suite: list[BenchTask], suite_file: Path) -> None:
    """Refuse a suite row whose ``removed_action`` is no action of its domain (its robot would be the whole
    domain, and every run of it a meaningless "already solvable"): :class:`~guided_lfd.errors.InputFileError`
    naming the row's task and the domain file.  Each domain is read once."""
    from guided_lfd.errors import InputFileError, Location
    from guided_lfd.pddl.reader import parse_domain

    actions: dict[str, set[str]] = {}
    for task in suite:
        if not task.removed_action:
            continue
        if task.domain_file not in actions:
            actions[task.domain_file] = {a.name.lower() for a in parse_domain(task.domain_file).actions}
        if task.removed_action.lower() not in actions[task.domain_file]:
            raise InputFileError(f"task {task.id}: removed_action {task.removed_action!r} is no action of "
                                 f"{task.domain_file}", Location(str(suite_file)))


def input_digest(*parts: str | Path | None) -> str:
    """A digest of the tool's version and the *content* of each file (a ``str`` part is taken as text, a
    ``Path`` as the file's bytes, ``None`` as absent): the key of whatever is built or kept from them.

    A key made of paths or names alone serves a stale result after a file is edited; this one changes with
    every byte the result depends on.
    """
    import hashlib

    from guided_lfd import __version__

    digest = hashlib.sha256(f"guided-lfd {__version__}".encode())
    for part in parts:
        if part is None:
            digest.update(b"\0none")
        elif isinstance(part, Path):
            data = part.read_bytes()
            digest.update(b"\0file%d:" % len(data) + data)
        else:
            data = part.encode()
            digest.update(b"\0text%d:" % len(data) + data)
    return digest.hexdigest()


def task_digest(task: BenchTask) -> str:
    """:func:`input_digest` of everything a run of ``task`` reads: domain, problem, complete domain, the
    removed action.  A file that cannot be read gives a digest of its own (the run then fails, and says why)."""
    try:
        return input_digest(Path(task.domain_file), Path(task.problem_file),
                            Path(task.fixed_from) if task.fixed_from else None, task.removed_action)
    except OSError as exc:
        return input_digest(f"unreadable: {exc}")


def robot_domain_file(task: BenchTask, folder: Path) -> Path:
    """The robot's domain file for ``task`` (the domain without ``removed_action``), built once per content.

    The file is named by the digest of the domain's content, the removed action and the tool's version
    (:func:`input_digest`), so an edited domain or a new release builds a new file instead of reusing one
    made from an older text.
    """
    if not task.removed_action:
        return Path(task.domain_file)
    key = input_digest(Path(task.domain_file), task.removed_action)[:16]
    path = folder / f"{task.domain}-without-{task.removed_action}-{key}.pddl"
    if not path.exists():
        from guided_lfd.io import write_text
        from guided_lfd.pddl.reader import parse_domain
        from guided_lfd.pddl.writer import domain_to_pddl

        full = parse_domain(task.domain_file)
        robot = replace(full, actions=[a for a in full.actions if a.name != task.removed_action])
        write_text(path, domain_to_pddl(robot, header=f"{task.domain} without {task.removed_action}"))
    return path
