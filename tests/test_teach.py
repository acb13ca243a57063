"""guided-lfd teach: the whole loop (excuse -> request -> demonstration -> learn -> merge -> re-plan)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import DOMAINS, kitchen
from guided_lfd.excuse.change import Change
from guided_lfd.pddl.model import Atom
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.teach import SimulatedHuman, teach

HUMAN = {k: str(DOMAINS / f"kitchen-{k}" / "human.pddl") for k in (1, 2)}

#: session.json's documented keys and their types (README: JSON formats, guided-lfd/teach).
SESSION_KEYS = {"format": str, "format_version": int, "robot": str, "problem": str, "solved": bool, "status": str,
                "rounds": list, "plan": (list, type(None)), "plans_original_task": (bool, type(None)), "robot_domain": str,
                "reason": (str, type(None)), "task": (str, type(None))}
ROUND_KEYS = {"round": int, "excuse": list, "request": list, "request_text": list, "why": list, "keep": list,
              "keep_text": list, "demonstration_length": (int, type(None)), "new_actions": (int, type(None)), "learned_actions": list,
              "request_met": (bool, type(None)), "unmet": list, "solvable_after": (bool, type(None)), "files": dict,
              "preference": (str, type(None)), "error": (str, type(None)), "vocabulary": (str, type(None)),
              "asked_again": list, "outcome": (str, type(None)), "outcome_reason": (str, type(None)),
              "check": (dict, type(None)), "skill_request": (dict, type(None)), "answer": (str, type(None))}


def _check_schema(doc: dict) -> None:
    assert set(doc) == set(SESSION_KEYS) and (doc["format"], doc["format_version"]) == ("guided-lfd/teach", 3)
    for key, kind in SESSION_KEYS.items():
        assert isinstance(doc[key], kind), key
    for rnd in doc["rounds"]:
        assert set(rnd) == set(ROUND_KEYS)
        for key, kind in ROUND_KEYS.items():
            assert isinstance(rnd[key], kind), key
        assert all(c[0] in "+-" and c[1] == "(" for c in rnd["request"])


@pytest.mark.parametrize("k,asked,learned", [(1, ["+(open pinkdrawer)"], ["open_drawer"]),
                                               (2, ["+(clear pinkdrawer)"], ["move_chair"])])
def test_simulated_teaching_solves_each_kitchen_in_one_round(k, asked, learned, runner, app, tmp_path):
    robot, problem = kitchen(k)
    result = runner.invoke(app, ["teach", robot, problem, "--simulate", HUMAN[k], "-o", str(tmp_path), "--json",
                                 "--quiet"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc == json.loads((tmp_path / "session.json").read_text())
    _check_schema(doc)
    assert doc["solved"] and doc["plans_original_task"] and len(doc["rounds"]) == 1
    assert doc["rounds"][0]["request"] == asked and doc["rounds"][0]["learned_actions"] == learned
    assert doc["rounds"][0]["request_met"] is True and doc["rounds"][0]["demonstration_length"] == 1
    # Every round's files are there, and the taught domain plans the task.
    for name in ("excuse.json", "excuse.svg", "demonstration.csv", "demonstration.state.csv", "segments.json",
                 "learned.pddl", "robot.pddl"):
        assert (tmp_path / "round-1" / name).stat().st_size > 0, name
    taught, task = parse_task(str(tmp_path / "robot.pddl"), problem)
    assert {a.name for a in taught.actions} >= set(learned)
    assert (tmp_path / "session.md").read_text().startswith(f"# Teaching session: {problem}")


def test_the_request_says_why_and_what_to_leave_as_it_is(tmp_path):
    robot, problem = parse_task(*kitchen(1))
    human = parse_domain(HUMAN[1])
    session = teach(robot, problem, SimulatedHuman(human), tmp_path, human=human)
    rnd = session.rounds[0]
    assert rnd.request_text == ["Open PinkDrawer"]
    assert rnd.why == ["Open PinkDrawer: no skill of the robot does this, and its plan to Inside RedPlate, "
                       "PinkDrawer needs it"]
    # The robot's plan takes the plate from the table: moving it would misdirect the demonstration.
    assert Atom("on_top", ("redplate", "table")) in rnd.keep and "keep On_top RedPlate, Table" in rnd.keep_text
    assert all(a.predicate != "graspable" for a in rnd.keep)  # nothing can change it: nothing to ask


def test_only_the_part_of_the_excuse_that_suffices_is_requested(runner, app, tmp_path):
    """The paper's redundancy example (III-B-1): a robot that can neither open drawers nor move the chair.

    The minimal excuse is to clear and open PinkDrawer; asking only "Open PinkDrawer" suffices, as the
    human must clear it first.
    """
    robot, problem = str(DOMAINS / "kitchen-2" / "robot-no-open.pddl"), kitchen(2)[1]
    result = runner.invoke(app, ["teach", robot, problem, "--simulate", HUMAN[2], "-o", str(tmp_path), "--json",
                                 "--quiet"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    (rnd,) = doc["rounds"]
    assert rnd["excuse"] == ["+(clear pinkdrawer)", "+(open pinkdrawer)"]
    assert (rnd["request"], rnd["request_text"]) == (["+(open pinkdrawer)"], ["Open PinkDrawer"])
    assert rnd["request_met"] and set(rnd["learned_actions"]) == {"move_chair", "open_drawer"}
    assert doc["solved"] and doc["plans_original_task"]  # the learned robot plans the original task
    # The why explains the request, and says how the rest of the excuse gets made without being asked for.
    assert rnd["why"] == [
        "Open PinkDrawer: no skill of the robot does this, and its plan to Inside RedPlate, PinkDrawer needs it",
        "Clear PinkDrawer: also in the minimal excuse, not asked for: demonstrating Open PinkDrawer makes it on the "
        "way"]
    reconcile = ("the minimal excuse is +(clear pinkdrawer) +(open pinkdrawer); the request is the part of it that "
                 "suffices")
    assert f"- {reconcile}\n" in (tmp_path / "session.md").read_text()
    # The text the demonstrator reads (stderr without --quiet) says the same, in the same order.
    text = runner.invoke(app, ["teach", robot, problem, "--simulate", HUMAN[2], "-o", str(tmp_path / "text")])
    assert text.exit_code == 0, text.output
    assert text.stderr.startswith("round 1, please demonstrate: Open PinkDrawer\n"
                                  f"  {reconcile}\n" + "".join(f"  why: {w}\n" for w in rnd["why"]))
    # Without the redundancy step, the whole excuse is asked for.
    plain = runner.invoke(app, ["teach", robot, problem, "--simulate", HUMAN[2], "-o", str(tmp_path / "plain"),
                                "--json", "--quiet", "--no-redundancy"])
    assert json.loads(plain.stdout)["rounds"][0]["request"] == ["+(clear pinkdrawer)", "+(open pinkdrawer)"]


def test_a_demonstration_that_misses_the_request_gives_a_second_round(runner, app, tmp_path):
    robot, problem = kitchen(2)
    # A demonstration of something else: opening BlueDrawer (a skill the robot has) when
    # clearing PinkDrawer (moving the chair, which it cannot do) was asked for.
    wrong = tmp_path / "wrong"
    wrong.mkdir()
    task = parse_task(robot, problem)[1]
    trace, _ = SimulatedHuman(parse_domain(HUMAN[2])).demonstrate(
        wrong, task.init, [Change(Atom("open", ("bluedrawer",)), True)], task)
    session = tmp_path / "session"
    result = runner.invoke(app, ["teach", robot, problem, "--demo", str(trace), "--simulate", HUMAN[2],
                                 "-o", str(session), "--json", "--quiet"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    first, second = doc["rounds"]
    assert (first["request"], first["request_met"], first["unmet"], first["solvable_after"]) == (
        ["+(clear pinkdrawer)"], False, ["+(clear pinkdrawer)"], False)
    assert first["learned_actions"] == []  # opening a drawer: the robot knew it already
    # Round two asks again, from the state the first demonstration left (BlueDrawer open).
    second_task = json.loads((session / "round-2" / "excuse.json").read_text())
    assert "(open bluedrawer)" in second_task["excuse"]["state"]
    assert (second["request"], second["request_met"], doc["status"]) == (["+(clear pinkdrawer)"], True, "solved")
    assert "the demonstration did not make: +(clear pinkdrawer)" in (session / "session.md").read_text()


def test_no_demonstration_ends_the_session_with_its_exit_code(runner, app, tmp_path):
    robot, problem = kitchen(2)
    result = runner.invoke(app, ["teach", robot, problem, "-o", str(tmp_path), "--json"])
    assert result.exit_code == 14
    doc = json.loads(result.stdout)
    _check_schema(doc)
    assert doc["status"] == "no-demonstration" and not doc["solved"] and doc["rounds"][0]["request_met"] is None
    assert "teaching ended: no-demonstration after 1 round(s)" in result.stderr


def test_an_already_solvable_task_needs_no_round(runner, app, tmp_path):
    _, problem = kitchen(1)
    result = runner.invoke(app, ["teach", HUMAN[1], problem, "-o", str(tmp_path), "--json", "--quiet"])
    assert result.exit_code == 0
    doc = json.loads(result.stdout)
    assert (doc["status"], doc["rounds"], doc["solved"]) == ("already-solvable", [], True) and doc["plan"]


def test_max_rounds_must_be_positive(runner, app, tmp_path):
    robot, problem = kitchen(1)
    result = runner.invoke(app, ["teach", robot, problem, "-o", str(tmp_path), "--max-rounds", "0"])
    assert result.exit_code == 37 and "--max-rounds 0" in result.stderr


ROOMS = Path(__file__).parent / "data" / "teach"


def test_the_preferred_excuse_has_the_shortest_predicted_demonstration(runner, app):
    """Case 1 (III-B-2): two minimal excuses, a door whose key is here (2 actions) and one whose key is in the
    hall (4); the search's own order puts the far one first, the preference picks the near one and says why."""
    robot, problem, human = (str(ROOMS / f"rooms-{n}.pddl") for n in ("robot", "problem", "human"))
    base = ["excuse", robot, problem, "--fixed-from", human, "--json", "--quiet"]
    plain = json.loads(runner.invoke(app, base).stdout)
    assert plain["excuse"]["changes"][0]["change"] == "+(unlocked adoor)" and plain["preference"] is None
    preferred = runner.invoke(app, [*base, "--prefer", "demonstration", "--human", human])
    assert preferred.exit_code == 0, preferred.output
    doc = json.loads(preferred.stdout)
    assert doc["excuse"]["changes"][0]["change"] == "+(unlocked bdoor)" and doc["alternatives"] == []
    assert doc["preference"] == ("preferred +(unlocked bdoor): its demonstration takes 2 action(s), "
                                 "against 4 for +(unlocked adoor)")
    text = runner.invoke(app, [*base[:-2], "--quiet", "--prefer", "demonstration", "--human", human]).stdout
    assert text.startswith("two-doors: preferred +(unlocked bdoor)")
    assert runner.invoke(app, [*base, "--prefer", "demonstration"]).exit_code == 37  # needs --human


def test_a_human_who_walks_and_unlocks_doors_is_simulated_and_taught_without_hand_facts(runner, app, tmp_path):
    """Walking and turning a key are drawn as the hand working on the action's objects (issue #23): the rooms
    world has no hand facts, so the learned skills have none, and the taught robot plans the task itself."""
    robot, problem, human = (str(ROOMS / f"rooms-{n}.pddl") for n in ("robot", "problem", "human"))
    result = runner.invoke(app, ["teach", robot, problem, "--simulate", human, "-o", str(tmp_path), "--json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["status"] == "solved" and doc["plans_original_task"]
    (rnd,) = doc["rounds"]
    assert set(rnd["learned_actions"]) == {"pick", "unlock"} and rnd["vocabulary"].startswith("none")
    assert "round 1: hand facts: none" in result.stderr
    learned = (tmp_path / "round-1" / "learned.pddl").read_text()
    assert "hand_free" not in learned and "in_hand" not in learned


def test_slack_widens_the_excuses_and_the_preference_may_pick_a_costlier_one(runner, app):
    """The direct door's key is two rooms away (1 change, 4 actions); the detour's two doors share a key at
    hand (2 changes, 3 actions): within a slack of 1 the preference asks for the detour."""
    robot, problem, human = (str(ROOMS / f"corridor-{n}.pddl") for n in ("robot", "problem", "human"))
    base = ["excuse", robot, problem, "--fixed-from", human, "--json", "--quiet"]
    listed = json.loads(runner.invoke(app, [*base, "--all", "--slack", "1"]).stdout)
    assert [c["change"] for c in listed["excuse"]["changes"]] == ["+(unlocked direct)"]
    assert [[c["change"] for c in e["changes"]] for e in listed["alternatives"]] == [
        ["+(unlocked first)", "+(unlocked second)"]]  # no superset of the minimal one
    assert json.loads(runner.invoke(app, [*base, "--all"]).stdout)["alternatives"] == []
    preferred = json.loads(runner.invoke(app, [*base, "--prefer", "demonstration", "--human", human,
                                               "--slack", "1"]).stdout)
    assert [c["change"] for c in preferred["excuse"]["changes"]] == ["+(unlocked first)", "+(unlocked second)"]
    assert preferred["preference"] == ("preferred +(unlocked first) +(unlocked second): its demonstration takes "
                                       "3 action(s), against 4 for +(unlocked direct)")
    assert runner.invoke(app, [*base, "--slack", "1"]).exit_code == 37  # needs --all or --prefer
    assert runner.invoke(app, [*base, "--all", "--slack", "1", "--strategy", "baseline"]).exit_code == 37


def test_a_session_folder_holding_an_input_or_that_is_a_file_is_refused_before_any_work(runner, app, tmp_path):
    import shutil

    for name in ("robot.pddl", "problem.pddl", "human.pddl"):
        shutil.copy(DOMAINS / "kitchen-2" / name, tmp_path / name)
    before = (tmp_path / "robot.pddl").read_bytes()
    inside = runner.invoke(app, ["teach", str(tmp_path / "robot.pddl"), str(tmp_path / "problem.pddl"),
                                 "--simulate", str(tmp_path / "human.pddl"), "-o", str(tmp_path)])
    assert inside.exit_code == 37 and "an input of this run" in inside.stderr
    assert (tmp_path / "robot.pddl").read_bytes() == before  # nothing the user had is replaced
    (tmp_path / "afile").write_text("x")
    robot, problem = kitchen(2)
    for target in (tmp_path / "afile", tmp_path / "afile" / "sub"):
        result = runner.invoke(app, ["teach", robot, problem, "--simulate", HUMAN[2], "-o", str(target)])
        assert result.exit_code == 40 and "internal error" not in result.stderr, result.stderr


def test_a_trace_of_another_world_is_refused_and_the_session_so_far_is_written(runner, app, tmp_path):
    robot, problem = kitchen(2)
    other = DOMAINS.parent / "demos" / "kitchen-1" / "P1-excuse.csv"  # Kitchen I: no chair in front of the drawer
    result = runner.invoke(app, ["teach", robot, problem, "--demo", str(other), "-o", str(tmp_path), "--json"])
    assert result.exit_code == 34 and "the demonstration starts from another state" in result.stderr
    doc = json.loads((tmp_path / "session.json").read_text())
    _check_schema(doc)
    assert doc["status"] == "bad-demonstration" and "starts from another state" in doc["rounds"][0]["error"]
    missing = runner.invoke(app, ["teach", robot, problem, "--demo", str(tmp_path / "nope.csv"), "-o",
                                  str(tmp_path / "s2")])
    assert missing.exit_code == 30 and "nope.csv" in missing.stderr  # refused before any work


def test_the_time_limit_bounds_the_whole_session(runner, app, tmp_path):
    import time

    robot, problem = kitchen(2)
    start = time.monotonic()
    result = runner.invoke(app, ["teach", robot, problem, "--simulate", HUMAN[2], "-o", str(tmp_path),
                                 "--time-limit", "0.001", "--json"])
    assert result.exit_code == 20 and json.loads(result.stdout)["status"] == "timeout"
    assert time.monotonic() - start < 5


def test_the_human_model_decides_what_the_excuse_may_change_without_prefer(runner, app):
    """#28: excuse --human alone holds fixed what no action of the human changes (as teach does), not the
    world's structure the robot's domain suggests; it was refused without --prefer (37)."""
    robot, problem = kitchen(2)
    result = runner.invoke(app, ["excuse", robot, problem, "--human", HUMAN[2], "--json"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert [c["atom"] for c in doc["excuse"]["changes"]] == ["(clear pinkdrawer)"]
    assert doc["statistics"]["fixed_predicates"] == ["graspable"] and "structure_held" not in doc["statistics"]



def test_why_respects_types_a_cupboard_door_skill_does_not_open_a_drawer(tmp_path):
    """The household robot without the drawer skill opens cupboard doors: 'open' alone is not a skill for it."""
    from guided_lfd.benchmark import household

    house = household.House(2, 4, 2, 1, 1, "no-open")
    (tmp_path / "robot.pddl").write_text(household.domain_pddl("no-open"))
    (tmp_path / "problem.pddl").write_text(household.problem_pddl(house))
    (tmp_path / "human.pddl").write_text(household.domain_pddl())
    robot, problem = parse_task(str(tmp_path / "robot.pddl"), str(tmp_path / "problem.pddl"))
    human = parse_domain(str(tmp_path / "human.pddl"))
    session = teach(robot, problem, SimulatedHuman(human), tmp_path / "s", human=human)
    (rnd,) = session.rounds
    assert rnd.why[0].endswith("no skill of the robot does this, and its plan to Inside plate1, drawer1_1 needs it")
    assert session.status == "solved"


def test_the_rest_of_the_excuse_the_robot_makes_itself_is_said_so(tmp_path):
    """Two closed goal drawers, a robot that cannot open drawers: one drawer opened is asked for; the why says
    the robot opens the other itself with the skill it learns (no demonstration makes it on the way)."""
    data = Path(__file__).parent / "data" / "determinism"
    robot, problem = parse_task(str(data / "robot-no-open.pddl"), str(data / "house-r4-i8.pddl"))
    human = parse_domain(str(data / "human.pddl"))

    class Nobody:
        def demonstrate(self, *args):
            return None

    session = teach(robot, problem, Nobody(), tmp_path, human=human)
    (rnd,) = session.rounds
    assert [str(c) for c in rnd.excuse] == ["+(open drawer1_1)", "+(open drawer3_1)"]
    assert rnd.request_text == ["Open drawer1_1"]
    assert rnd.why[1:] == ["Open drawer3_1: also in the minimal excuse, not asked for: the robot then makes it "
                           "itself, with the skills it learns from the demonstration"]
    assert rnd.excuse_text() == ("the minimal excuse is +(open drawer1_1) +(open drawer3_1); the request is the "
                                 "part of it that suffices")


def test_predicting_demonstrations_for_prefer_stays_within_the_time_limit(runner, app, monkeypatch):
    """--time-limit bounds the whole run, --prefer's predictions too: past it, the excuse found is printed
    unranked and stderr says why (a prediction made slow on purpose stands for a large human model)."""
    import time

    from guided_lfd import preference

    def slow(*args, **kwargs):
        time.sleep(30)
        raise AssertionError("the watchdog should have stopped this")

    monkeypatch.setattr(preference, "prefer_demonstration", slow)
    robot, problem, human = (str(ROOMS / f"rooms-{n}.pddl") for n in ("robot", "problem", "human"))
    start = time.monotonic()
    result = runner.invoke(app, ["excuse", robot, problem, "--fixed-from", human, "--json", "--prefer",
                                 "demonstration", "--human", human, "--time-limit", "2"])
    assert time.monotonic() - start < 2 + 1.0
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["status"] == "excuse-found" and doc["preference"] is None and doc["alternatives"] == []
    assert "the time limit was reached before the demonstrations were predicted" in result.stderr
