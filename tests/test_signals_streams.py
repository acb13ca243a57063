"""Signals and closed streams (issue #25): a documented exit code and one line, never a traceback.

Each case runs the installed command in a process of its own: what is under test (a signal, a stream closed
before the process starts or by its reader) happens outside Python's test runner.
"""

from __future__ import annotations

import os
import signal
import subprocess
import time

import pytest

from conftest import ROOT
from guided_lfd.benchmark import cli_command
from guided_lfd.errors import EXIT_INPUT_FILE, EXIT_BAD_OPTION, EXIT_OK, EXIT_OUTPUT, EXIT_TERMINATED, Terminated

KITCHEN = ROOT / "data" / "domains" / "kitchen-1"
EXCUSE = [*cli_command(), "excuse", str(KITCHEN / "robot.pddl"), str(KITCHEN / "problem.pddl")]


def _run(args: list[str], close: int | None = None, broken_stdout: bool = False) -> tuple[int, str]:
    """Run ``args`` with file descriptor ``close`` closed from the start, or stdout a pipe no one reads."""
    stdout: int = subprocess.DEVNULL
    if broken_stdout:
        read, stdout = os.pipe()
        os.close(read)
    proc = subprocess.run(args, stdout=stdout, stderr=subprocess.PIPE, text=True, timeout=120,
                          preexec_fn=(lambda: os.close(close)) if close is not None else None)
    if broken_stdout:
        os.close(stdout)
    return proc.returncode, proc.stderr


def _terminated_after(args: list[str], seconds: float) -> tuple[int, str, float]:
    """Start ``args``, send SIGTERM after ``seconds``: (exit code, stderr, seconds from the signal to the end)."""
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(seconds)
    start = time.monotonic()
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    return proc.returncode, err, time.monotonic() - start


def test_a_closed_stdout_is_an_output_error_in_one_line():
    code, err = _run(EXCUSE, close=1)
    assert code == EXIT_OUTPUT, err
    assert err == "-: output error: standard output is closed\n"


def test_a_stdout_its_reader_closed_is_an_output_error_in_one_line():
    for args in (EXCUSE, [*cli_command(), "--help"], [*cli_command(), "excuse", "--help"], [*cli_command(), "--version"]):
        code, err = _run(args, broken_stdout=True)
        assert code == EXIT_OUTPUT, (args, err)
        assert err == "-: output error: standard output closed by the reader (broken pipe)\n", args


def test_a_closed_stderr_changes_no_exit_code():
    assert _run(EXCUSE, close=2)[0] == EXIT_OK
    assert _run([*cli_command(), "excuse", str(KITCHEN / "robot.pddl"), "no-such-problem.pddl"], close=2)[0] \
        == EXIT_INPUT_FILE


def test_sigterm_ends_a_run_as_ctrl_c_does_with_its_own_code_and_nothing_written(tmp_path):
    """The paper's baseline on depot task03 runs for minutes; SIGTERM after 2 s ends it at once: exit 143, one
    line, no output file and no temporary file left."""
    from guided_lfd.benchmark import BenchTask, robot_domain_file

    ipc = ROOT / "data/benchmarks/ipc/depot"
    task = BenchTask("depot-task03-load", "depot", "task03", "load", str(ipc / "domain.pddl"),
                     str(ipc / "task03.pddl"), "")
    robot = robot_domain_file(task, tmp_path)
    out = tmp_path / "out" / "excuse.json"
    out.parent.mkdir()
    code, err, took = _terminated_after([*cli_command(), "excuse", str(robot), task.problem_file, "--strategy",
                                         "baseline", "--time-limit", "100", "--quiet", "--json", "-o", str(out)], 2.0)
    assert code == EXIT_TERMINATED, err
    assert err == "terminated (SIGTERM)\n"
    assert took < 10
    assert list(out.parent.iterdir()) == []


def test_the_teach_prompt_treats_end_of_input_as_stop_and_checks_a_path_like_the_command_line(monkeypatch, capsys):
    """At the prompt, end of input (Ctrl-D, a closed pipe) stops the session as an empty answer does; a line
    too long to be a file name is asked again with a one-line reason (it was ``internal error: OSError``)."""
    import io

    from cli.teach import _Prompted

    monkeypatch.setattr("sys.stdin", io.StringIO(""))
    assert _Prompted().demonstrate(None, None, None, None) is None
    monkeypatch.setattr("sys.stdin", io.StringIO("x" * 5000 + "\n"))
    assert _Prompted().demonstrate(None, None, None, None) is None
    err = capsys.readouterr().err
    assert "not a path: OSError" in err and "File name too long" in err


@pytest.mark.parametrize("signal_raised", [KeyboardInterrupt, Terminated])
def test_ctrl_c_or_sigterm_at_the_teach_prompt_stays_what_it_is(monkeypatch, signal_raised):
    """click turns whatever interrupts its prompt into Abort: Ctrl-C must stay an interruption (130), and
    SIGTERM, raised as Terminated, termination (143; it became 130, found by review)."""
    import io

    from cli.teach import _Prompted

    class Stopped(io.StringIO):
        def readline(self, *args: object) -> str:
            raise signal_raised

    monkeypatch.setattr("sys.stdin", Stopped())
    with pytest.raises(signal_raised):
        _Prompted().demonstrate(None, None, None, None)


def test_sigterm_stops_a_benchmark_run_at_once_and_records_no_interrupted_run(tmp_path):
    """``bench run`` waited for every queued run after SIGTERM (20 s for three depot runs) and recorded the
    interrupted one as ``crashed``, which a resumed run kept.  Now it ends at once with 143, terminating its
    runs; the partial results hold only finished runs."""
    code, err, took = _terminated_after([*cli_command(), "bench", "run", "--root", str(ROOT), "--only",
                                         "depot-task05", "--strategies", "baseline", "--stop-after-unfinished", "",
                                         "--time-limit", "30", "--results", str(tmp_path / "results")], 3.0)
    assert code == EXIT_TERMINATED, err
    assert took < 5
    partial = tmp_path / "results" / "results.partial.csv"
    rows = partial.read_text().splitlines()[1:] if partial.exists() else []
    assert not [r for r in rows if "crashed" in r or "interrupted" in r], rows


@pytest.mark.parametrize("delay", [0.2, 0.5])
@pytest.mark.parametrize("signum, code, line", [(signal.SIGTERM, EXIT_TERMINATED, "terminated (SIGTERM)"),
                                                (signal.SIGINT, 130, "interrupted")])
def test_a_signal_early_in_a_run_is_its_code_and_one_line(delay, signum, code, line):
    """While typer still parsed the options, SIGTERM was 130 without a word and Ctrl-C in ``import typer`` a
    traceback (the adversarial round's start-up cases)."""
    ipc = ROOT / "data" / "benchmarks" / "ipc" / "depot"
    proc = subprocess.Popen([*cli_command(), "plan", str(ipc / "domain.pddl"), str(ipc / "task05.pddl")],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(delay)
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=60)
    assert (proc.returncode, err) == (code, line + "\n")


@pytest.mark.parametrize("args", [["--help"], ["excuse", "-h"], ["--version"]])
def test_help_and_the_version_with_stdout_closed_are_an_output_error(args):
    """#25 second round: help and the version with stdout closed from the start (`>&-`) exited 0."""
    code, err = _run([*cli_command(), *args], close=1)
    assert code == EXIT_OUTPUT, err
    assert err == "-: output error: standard output is closed\n"


def test_a_reader_that_leaves_part_way_is_an_output_error_not_a_cut_success(tmp_path):
    """#25 second round: `excuse --all | head -c10` exited 0 with 65,536 of 204,273 bytes written (Python's
    buffered stdout took the pipe's short write as done).  Here ~240 kB of text, far beyond a pipe's buffer."""
    task = ROOT / "tests" / "data" / "many-excuses-slack"
    parts = " ".join(f"p{i}" for i in range(60))
    problem = tmp_path / "p.pddl"
    problem.write_text(f"(define (problem g) (:domain gate2) (:objects k1 k2 k3 - key {parts} - part) (:init) "
                       "(:goal (open)))")
    command = " ".join([*cli_command(), "excuse", str(task / "domain.pddl"), str(problem), "--all", "--slack", "1",
                        "-q"])
    proc = subprocess.run(["bash", "-c", f"{command} | head -c10 >/dev/null; exit ${{PIPESTATUS[0]}}"],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == EXIT_OUTPUT, proc.stderr
    assert proc.stderr == "-: output error: standard output closed by the reader (broken pipe)\n"


@pytest.mark.parametrize("command", ["plan", "excuse"])
def test_an_output_naming_the_file_on_standard_input_is_refused_and_kept(tmp_path, command):
    """``plan - p.pddl -o robot.pddl < robot.pddl``: the output is the input, reached through fd 0 (#25)."""
    robot = tmp_path / "robot.pddl"
    robot.write_text((KITCHEN / "robot.pddl").read_text())
    before = robot.read_bytes()
    with open(robot, "rb") as stdin:
        proc = subprocess.run([*cli_command(), command, "-", str(KITCHEN / "problem.pddl"), "-o", str(robot)],
                              stdin=stdin, capture_output=True, text=True, timeout=120)
    assert proc.returncode == EXIT_BAD_OPTION, proc.stderr
    assert proc.stderr.endswith("is the file on standard input ('-'); expected another file\n")
    assert robot.read_bytes() == before
