"""``teach``'s session folder (issue #25): new, empty, or a previous session of the same task, which it replaces
whole; nothing the user had is overwritten, through links too; a refused run creates nothing."""

from __future__ import annotations

import json
import os

from conftest import ROOT
from guided_lfd.errors import EXIT_BAD_OPTION, EXIT_INPUT_FILE, EXIT_OUTPUT

KITCHEN = ROOT / "data" / "domains" / "kitchen-2"
ROBOT, PROBLEM, HUMAN = (str(KITCHEN / f) for f in ("robot.pddl", "problem.pddl", "human.pddl"))


def _teach(runner, app, session, *extra, robot=ROBOT):
    return runner.invoke(app, ["teach", robot, PROBLEM, "--simulate", HUMAN, "-o", str(session), "--quiet", *extra])


def test_a_second_session_replaces_the_first_whole(runner, app, tmp_path):
    session = tmp_path / "session"
    assert _teach(runner, app, session).exit_code == 0
    (session / "round-2").mkdir()  # as a longer earlier session of the task would have left it
    (session / "round-2" / "excuse.json").write_text("{}")
    assert _teach(runner, app, session).exit_code == 0
    rounds = json.loads((session / "session.json").read_text())["rounds"]
    assert sorted(p.name for p in session.iterdir()) == ["robot.pddl", "round-1", "session.json", "session.md"]
    assert len(rounds) == 1


def test_a_folder_with_other_files_or_another_tasks_session_is_refused_untouched(runner, app, tmp_path):
    notes = tmp_path / "notes"
    notes.mkdir()
    (notes / "todo.txt").write_text("mine")
    result = _teach(runner, app, notes)
    assert result.exit_code == EXIT_OUTPUT
    assert "holds todo.txt, which is no file of a teaching session" in result.stderr
    assert sorted(p.name for p in notes.iterdir()) == ["todo.txt"]
    other = tmp_path / "other"
    other.mkdir()
    (other / "session.json").write_text(json.dumps({"format": "guided-lfd/teach", "problem": "elsewhere.pddl"}))
    result = _teach(runner, app, other)
    assert result.exit_code == EXIT_OUTPUT and "holds a session of another task (elsewhere.pddl)" in result.stderr


def test_a_link_where_the_session_writes_is_refused_and_its_target_kept(runner, app, tmp_path):
    """``session/robot.pddl`` linking to the robot's own domain: the session would have written through it
    (exit 0, the input replaced)."""
    robot = tmp_path / "in" / "robot.pddl"
    robot.parent.mkdir()
    robot.write_text((KITCHEN / "robot.pddl").read_text())
    before = robot.read_text()
    session = tmp_path / "session"
    session.mkdir()
    (session / "robot.pddl").symlink_to(robot)
    result = _teach(runner, app, session, robot=str(robot))
    assert result.exit_code == EXIT_OUTPUT and "holds robot.pddl as a link" in result.stderr
    assert robot.read_text() == before


def test_link_loops_are_named_as_an_input_or_the_session(runner, app, tmp_path):
    os.symlink(tmp_path / "b", tmp_path / "a")
    os.symlink(tmp_path / "a", tmp_path / "b")
    result = _teach(runner, app, tmp_path / "a")
    assert result.exit_code == EXIT_OUTPUT and "cannot be the session folder" in result.stderr
    result = _teach(runner, app, tmp_path / "s", robot=str(tmp_path / "a"))
    assert result.exit_code == EXIT_INPUT_FILE and "cannot be read" in result.stderr
    assert not (tmp_path / "s").exists()


def test_a_refused_option_creates_no_session_folder(runner, app, tmp_path):
    session = tmp_path / "session"
    result = _teach(runner, app, session, "--prefer", "demonstration", "--slack", "-1")
    assert result.exit_code == EXIT_BAD_OPTION
    assert not session.exists()


def test_teach_ends_within_its_time_limit_whatever_phase_it_is_in(tmp_path):
    """A 32-item house without `open`: the redundancy check (re-planning each part of the excuse) ran outside
    the deadline, so `--time-limit 5` ended after 13.8 s (46.9 s on a larger house).  Now the whole session,
    reading included, ends within the limit and a second (the run takes about 30 s without a limit)."""
    import subprocess
    import time

    from guided_lfd.benchmark import household
    from guided_lfd.benchmark import cli_command
    from guided_lfd.errors import EXIT_TIME_LIMIT

    house = household.House(8, 32, 4, 1, 4, "no-open")
    (tmp_path / "robot.pddl").write_text(household.domain_pddl("no-open"))
    (tmp_path / "human.pddl").write_text(household.domain_pddl())
    (tmp_path / "problem.pddl").write_text(household.problem_pddl(house))
    start = time.monotonic()
    proc = subprocess.run([*cli_command(), "teach", str(tmp_path / "robot.pddl"), str(tmp_path / "problem.pddl"),
                           "--simulate", str(tmp_path / "human.pddl"), "-o", str(tmp_path / "session"),
                           "--time-limit", "2", "--quiet"], capture_output=True, text=True, timeout=120)
    took = time.monotonic() - start
    assert proc.returncode == EXIT_TIME_LIMIT, proc.stderr
    # Far below the 30 s the session takes without a limit; the margin is for a loaded machine's start-up.
    assert took < 2.0 + 6.0, f"{took:.1f} s for --time-limit 2"


def test_an_interrupted_session_puts_the_previous_one_back(tmp_path):
    """Ctrl-C (or SIGTERM) during a second session of the task: the first session's files are as they were
    (it was deleted before the first round: only the interrupted round's excuse.json stayed)."""
    import pytest

    from guided_lfd.pddl.reader import parse_domain, parse_task
    from guided_lfd.teach import SimulatedHuman, teach

    robot, problem = parse_task(ROBOT, PROBLEM)
    human = SimulatedHuman(parse_domain(HUMAN), robot=robot)
    session = tmp_path / "session"
    teach(robot, problem, human, session)
    (session / "session.json").write_text('{"problem": "problem.pddl"}')  # as the command line writes it
    before = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}

    def interrupt(rnd) -> None:
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        teach(robot, problem, human, session, on_request=interrupt)
    after = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}
    assert after == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["session"]  # nothing set aside is left behind


def test_the_state_file_beside_a_demonstration_is_an_input_too(runner, app, tmp_path):
    """A ``--demo`` trace whose state file links into the session folder: the session would replace it (it was
    deleted; the trace itself was refused already)."""
    session = tmp_path / "session"
    assert _teach(runner, app, session).exit_code == 0
    demo = ROOT / "data" / "demos" / "kitchen-2" / "P1-excuse"
    (tmp_path / "t.csv").write_text(demo.with_suffix(".csv").read_text())
    kept = session / "robot.pddl"
    (tmp_path / "t.state.csv").symlink_to(kept)
    result = runner.invoke(app, ["teach", ROBOT, PROBLEM, "--demo", str(tmp_path / "t.csv"), "-o", str(session),
                                 "--quiet"])
    assert result.exit_code == EXIT_BAD_OPTION and "an input of this run" in result.stderr
    assert kept.exists()


def test_an_interrupted_first_session_leaves_no_folder(tmp_path):
    """It left an empty round-1/ in a folder the run had made (the adversarial round)."""
    import pytest

    from guided_lfd.pddl.reader import parse_domain, parse_task
    from guided_lfd.teach import SimulatedHuman, teach

    robot, problem = parse_task(ROBOT, PROBLEM)
    human = SimulatedHuman(parse_domain(HUMAN), robot=robot)

    def interrupt(rnd) -> None:
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        teach(robot, problem, human, tmp_path / "session", on_request=interrupt)
    assert list(tmp_path.iterdir()) == []


def test_a_previous_session_that_cannot_be_set_aside_is_the_output_error_with_nothing_moved(runner, app, tmp_path,
                                                                                          monkeypatch):
    """The OS refuses to move the second entry of the previous session (a read-only folder, a busy file): exit 40
    in one line, and the entry already moved is back (it was an internal error with the session half moved)."""
    from pathlib import Path

    session = tmp_path / "session"
    assert _teach(runner, app, session).exit_code == 0
    before = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}
    real_rename, calls = Path.rename, []

    def refuse_second(self, target):
        calls.append(self)
        if len(calls) == 2:
            raise PermissionError(13, "Permission denied")
        return real_rename(self, target)

    monkeypatch.setattr(Path, "rename", refuse_second)
    result = _teach(runner, app, session)
    monkeypatch.undo()
    assert result.exit_code == EXIT_OUTPUT, result.stderr
    assert result.stderr.strip().endswith("cannot set the previous session aside (Permission denied); nothing was "
                                          "changed")
    after = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}
    assert after == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["session"]


def test_a_session_that_fails_puts_the_previous_one_back(tmp_path):
    """Not only an interruption: a round that ends in an error the caller sees keeps the previous session too."""
    import pytest

    from guided_lfd.pddl.reader import parse_domain, parse_task
    from guided_lfd.teach import SimulatedHuman, teach

    robot, problem = parse_task(ROBOT, PROBLEM)
    human = SimulatedHuman(parse_domain(HUMAN), robot=robot)
    session = tmp_path / "session"
    teach(robot, problem, human, session)
    before = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}

    def fail(rnd) -> None:
        raise OSError(28, "No space left on device")

    with pytest.raises(OSError):
        teach(robot, problem, human, session, on_request=fail)
    after = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}
    assert after == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["session"]


def test_a_session_of_another_task_with_the_same_file_name_is_refused_untouched(runner, app, tmp_path):
    """Both kitchens' problems are problem.pddl: the second session replaced the first (third adversarial round).
    The session now records the task's PDDL name, and the problem file is compared by content."""
    session = tmp_path / "session"
    assert _teach(runner, app, session).exit_code == 0
    before = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}
    other = ROOT / "data" / "domains" / "kitchen-1"
    result = runner.invoke(app, ["teach", str(other / "robot.pddl"), str(other / "problem.pddl"), "--simulate",
                                 str(other / "human.pddl"), "-o", str(session), "--quiet"])
    assert result.exit_code == EXIT_OUTPUT
    assert "holds a session of another task (kitchen-2-store-plate)" in result.stderr
    after = {p.relative_to(session): p.read_bytes() for p in session.rglob("*") if p.is_file()}
    assert after == before
