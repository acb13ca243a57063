"""guided-lfd teach ends honestly: each way a session ends says why.

* ``solved`` (exit 0) only when the taught robot plans the original task from its original state; a goal
  reached only through the demonstration is ``demonstration-only`` (exit 15), the reason on stderr;
* a task without an excuse names the goal atoms no skill makes true and asks for a new skill that does,
  in a round like any other;
* ``no-demonstration`` says why: the human model's first unreachable change, or no demonstrator at all;
* a human model for another domain is refused before any round (exit 34).
"""

from __future__ import annotations

import json
from pathlib import Path

from conftest import DOMAINS, kitchen
from guided_lfd import errors
from guided_lfd.pddl.model import Atom
from guided_lfd.pddl.reader import parse_domain

TEACH = Path(__file__).parent / "data" / "teach"
HUMAN = {k: str(DOMAINS / f"kitchen-{k}" / "human.pddl") for k in (1, 2)}
NO_PUT = str(TEACH / "no-put-robot.pddl")  # Kitchen I's robot without put_inside: no skill makes (inside ..)


def _goal_reached_by_the_demonstration(rnd, folder, out, robot, task, given, human=None, original=None, history=None,
                                       time_limit=None, checks=True):
    """Stands for ``guided_lfd.teach.learning.learn_round`` after a demonstration of the whole of Kitchen II's task
    (chair pushed to the corner, PinkDrawer opened, RedPlate put inside) from which the robot learned a skill
    it can never use (push_obstacle needing a hand fact of another vocabulary)."""
    learned = parse_domain(str(TEACH / "unusable-skill-robot.pddl"))
    gone = {Atom("on_top", ("redplate", "table")), Atom("blocking", ("chair", "pinkdrawer")),
            Atom("clear", ("corner",))}
    made = {Atom("blocking", ("chair", "corner")), Atom("clear", ("pinkdrawer",)), Atom("open", ("pinkdrawer",)),
            Atom("inside", ("redplate", "pinkdrawer"))}
    rnd.demonstration_length, rnd.new_actions, rnd.learned_actions = 4, 2, ["push_obstacle"]
    rnd.request_met, rnd.unmet = True, []
    return learned, frozenset((task.init - gone) | made)


def test_a_goal_reached_only_through_the_demonstration_is_not_solved(runner, app, tmp_path, monkeypatch):
    from guided_lfd.teach import loop

    monkeypatch.setattr(loop, "learn_round", _goal_reached_by_the_demonstration)
    robot, problem = kitchen(2)
    result = runner.invoke(app, ["teach", robot, problem, "--simulate", HUMAN[2], "-o", str(tmp_path), "--json",
                                 "--quiet"])
    assert result.exit_code == errors.EXIT_DEMONSTRATION_ONLY == 15, result.output
    doc = json.loads(result.stdout)
    assert (doc["status"], doc["solved"], doc["plans_original_task"]) == ("demonstration-only", False, False)
    assert doc["rounds"][0]["solvable_after"] is True  # from the demonstrated state there is nothing left to do
    assert doc == json.loads((tmp_path / "session.json").read_text())
    # One line on stderr: what happened and what the taught robot lacks (the skill it cannot use, and why).
    (line,) = result.stderr.splitlines()
    assert line.startswith("teaching ended: demonstration-only after 1 round(s): the task was reached only through "
                           "the demonstration: the taught robot cannot plan kitchen-2-store-plate from its initial "
                           "state (its learned push_obstacle needs (hand-empty), which nothing makes true from there)")
    assert doc["reason"] in line and "Why: the task was reached only through" in (tmp_path / "session.md").read_text()


def test_without_a_demonstration_no_excuse_names_the_goal_atoms_no_skill_makes_true(runner, app, tmp_path):
    problem = kitchen(1)[1]
    result = runner.invoke(app, ["teach", NO_PUT, problem, "-o", str(tmp_path), "--json"])
    assert result.exit_code == errors.EXIT_NO_EXCUSE == 11, result.output
    doc = json.loads(result.stdout)
    assert (doc["status"], doc["solved"]) == ("no-excuse", False)
    # The request is a round like any other: the goal atom, why, and no excuse behind it.
    (rnd,) = doc["rounds"]
    assert (rnd["excuse"], rnd["request"], rnd["request_text"]) == ([], ["+(inside redplate pinkdrawer)"],
                                                                    ["Inside RedPlate, PinkDrawer"])
    assert rnd["why"] == ["no skill of the robot makes Inside RedPlate, PinkDrawer true"]
    assert "round 1, please demonstrate: Inside RedPlate, PinkDrawer" in result.stderr
    ended = [line for line in result.stderr.splitlines() if line.startswith("teaching ended")]
    assert ended == [f"teaching ended: no-excuse after 1 round(s): {doc['reason']} (see {tmp_path / 'session.md'})"]
    assert doc["reason"] == ("no excuse exists: no skill of the robot makes Inside RedPlate, PinkDrawer true, so a "
                             "new skill that does must be demonstrated; no demonstration was given (no --demo trace, "
                             "no --simulate HUMAN, and no terminal to ask for one)")
    md = (tmp_path / "session.md").read_text()
    assert "no skill of the robot makes Inside RedPlate, PinkDrawer true" in md and "a new skill" in md


def test_no_excuse_asks_for_the_new_skill_and_a_demonstration_of_it_teaches_the_robot(runner, app, tmp_path):
    problem = kitchen(1)[1]
    result = runner.invoke(app, ["teach", NO_PUT, problem, "--simulate", HUMAN[1], "-o", str(tmp_path), "--json",
                                 "--quiet"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert (doc["status"], doc["solved"], doc["plans_original_task"], doc["reason"]) == ("solved", True, True, None)
    (rnd,) = doc["rounds"]
    assert (rnd["excuse"], rnd["request"], rnd["request_met"]) == ([], ["+(inside redplate pinkdrawer)"], True)
    assert rnd["learned_actions"]  # the new skill (and opening the drawer on the way)
    for name in ("excuse.json", "demonstration.csv", "segments.json", "learned.pddl", "robot.pddl"):
        assert (tmp_path / "round-1" / name).is_file(), name
    assert result.stderr == ""
    plan = runner.invoke(app, ["plan", str(tmp_path / "robot.pddl"), problem, "--quiet"])
    assert plan.exit_code == 0, plan.output  # the taught robot plans the original task


def test_no_demonstration_names_the_change_the_human_model_cannot_reach(runner, app, tmp_path):
    """Kitchen II's request is Clear PinkDrawer; this human moves only a light chair, and the chair is not."""
    robot, problem = kitchen(2)
    human = str(TEACH / "heavy-chair-human.pddl")
    result = runner.invoke(app, ["teach", robot, problem, "--simulate", human, "-o", str(tmp_path), "--json"])
    assert result.exit_code == errors.EXIT_NOT_TAUGHT == 14, result.output
    doc = json.loads(result.stdout)
    assert doc["status"] == "no-demonstration" and doc["rounds"][0]["request"] == ["+(clear pinkdrawer)"]
    assert doc["reason"] == (f"the human model ({human}) has no plan from the current state to Clear PinkDrawer: "
                             "it cannot reach Clear PinkDrawer (+(clear pinkdrawer))")
    assert f"teaching ended: no-demonstration after 1 round(s): {doc['reason']}" in result.stderr
    assert f"Why: {doc['reason']}." in (tmp_path / "session.md").read_text()
    # Asked for two changes, it names the first one out of its reach (opening needs the drawer clear, too).
    both = runner.invoke(app, ["teach", str(DOMAINS / "kitchen-2" / "robot-no-open.pddl"), problem, "--simulate",
                               human, "-o", str(tmp_path / "both"), "--no-redundancy", "--json", "--quiet"])
    assert both.exit_code == 14
    assert json.loads(both.stdout)["reason"].endswith(
        "to Clear PinkDrawer and Open PinkDrawer: it cannot reach Clear PinkDrawer (+(clear pinkdrawer))")


def test_without_any_demonstrator_the_session_says_none_was_given(runner, app, tmp_path):
    robot, problem = kitchen(2)
    result = runner.invoke(app, ["teach", robot, problem, "-o", str(tmp_path), "--quiet"])
    assert result.exit_code == 14
    assert result.stderr.strip() == ("teaching ended: no-demonstration after 1 round(s): no demonstration was given "
                                     "(no --demo trace, no --simulate HUMAN, and no terminal to ask for one) "
                                     f"(see {tmp_path / 'session.md'})")


def test_a_human_model_for_another_domain_is_refused_before_any_round(runner, app, tmp_path):
    robot, problem = kitchen(2)
    rooms = str(TEACH / "rooms-human.pddl")  # walking between rooms with keys: nothing of a kitchen
    for option in ("--simulate", "--human"):
        session = tmp_path / option.strip("-")
        result = runner.invoke(app, ["teach", robot, problem, option, rooms, "-o", str(session)])
        assert result.exit_code == errors.EXIT_MISMATCH == 34, result.output
        assert result.stderr.strip() == (
            f"{rooms}: mismatch: the human model (domain 'rooms') is for another domain than the task's ('kitchen'): "
            "it has no predicate blocking, which the task uses in (blocking chair pinkdrawer) (expected a model of "
            "the task's world)")
        assert result.stdout == "" and not (session / "round-1").exists()
