"""The same command prints the same result, whatever the interpreter's hash seed (string hashing, and so the
order of a set of atoms, changes from one process to the next): a plan among several optimal ones, a rendered
demonstration, a teaching session."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import DATA, ROOT

HOUSE = DATA / "determinism"
SEEDS = ("0", "1", "2")


def _run(args: list[str], seed: str, cwd: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONHASHSEED": seed}
    return subprocess.run([sys.executable, "-c", "from cli.main import run; run()", *args], capture_output=True,
                          text=True, env=env, cwd=cwd, timeout=120)


def test_plan_prints_the_same_plan_under_every_hash_seed(tmp_path):
    outputs = {_run(["plan", str(HOUSE / "human.pddl"), str(HOUSE / "house-r4-i8.pddl"), "--quiet"], seed,
                    ROOT).stdout for seed in SEEDS}
    assert len(outputs) == 1 and next(iter(outputs)).startswith("(")


@pytest.mark.parametrize("robot, problem, human", [
    (HOUSE / "robot-no-open.pddl", HOUSE / "house-r4-i8.pddl", HOUSE / "human.pddl"),
    (DATA / "byo" / "twoarm" / "robot.pddl", DATA / "byo" / "twoarm" / "problem-large.pddl",
     DATA / "byo" / "twoarm" / "human.pddl"),
])
def test_teach_renders_the_same_demonstration_under_every_hash_seed(robot, problem, human, tmp_path):
    sessions = []
    for seed in SEEDS:
        out = tmp_path / seed
        result = _run(["teach", str(robot), str(problem), "--simulate", str(human), "-o", "session", "--quiet"],
                      seed, out if out.mkdir() is None else out)
        assert result.returncode == 0, result.stderr
        files = sorted(p for p in (out / "session").rglob("*") if p.is_file())
        sessions.append({p.relative_to(out).as_posix(): _without_times(p) for p in files})
    assert sessions[0] == sessions[1] == sessions[2]


def _without_times(path: Path):
    """A file's bytes; a JSON document without its measured times (``*time_s``), which differ run to run."""
    import json

    if path.suffix != ".json":
        return path.read_bytes()

    def strip(value):
        if isinstance(value, dict):
            return {k: strip(v) for k, v in value.items() if not k.endswith("time_s")}
        return [strip(v) for v in value] if isinstance(value, list) else value

    return strip(json.loads(path.read_text()))
