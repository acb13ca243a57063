"""`learn-domain` ends within its time and memory limits, as every long command does, and writes nothing then."""

from __future__ import annotations

import subprocess
import time

from conftest import DATA
from guided_lfd.benchmark import cli_command

BLOCKS = DATA / "trajectories" / "blocksworld"
TRAJECTORY, PRIOR = BLOCKS / "0.traj", BLOCKS / "prior.pddl"


def test_the_time_limit_ends_learning_with_exit_20_and_writes_nothing(runner, app, monkeypatch, tmp_path):
    def endless(*args, **kwargs):  # learning that never ends, whatever the machine's speed
        while True:
            time.sleep(0.01)

    monkeypatch.setattr("cli.learn_domain.learn_from_trajectories", endless)
    out = tmp_path / "learned.pddl"
    result = runner.invoke(app, ["learn-domain", str(TRAJECTORY), "--prior", str(PRIOR), "--time-limit", "0.3",
                                 "-o", str(out)])
    assert result.exit_code == 20
    assert result.stderr.strip() == "time limit: learn-domain exceeded the time limit"
    assert not out.exists()


def test_a_time_limit_it_keeps_changes_nothing(runner, app, tmp_path):
    plain, limited = tmp_path / "plain.pddl", tmp_path / "limited.pddl"
    for out, extra in ((plain, []), (limited, ["--time-limit", "600"])):
        result = runner.invoke(app, ["learn-domain", str(TRAJECTORY), "--prior", str(PRIOR), "-o", str(out), *extra])
        assert result.exit_code == 0, result.stderr
    assert plain.read_text() == limited.read_text()


def test_the_time_limit_must_be_positive(runner, app):
    result = runner.invoke(app, ["learn-domain", str(TRAJECTORY), "--prior", str(PRIOR), "--time-limit", "-1"])
    assert result.exit_code == 37 and "--time-limit" in result.stderr


def test_the_memory_limit_ends_learning_with_the_memout_code(tmp_path):
    """A fresh process (the cap is on the process itself): running out is exit 22, one line, no output."""
    out = tmp_path / "learned.pddl"
    proc = subprocess.run([*cli_command(), "learn-domain", str(TRAJECTORY), "--prior", str(PRIOR),
                           "--memory-limit", "1", "-o", str(out)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 22, proc.stderr
    assert proc.stderr.strip() == "out of memory: the run needed more memory than the process may use"
    assert not out.exists()
