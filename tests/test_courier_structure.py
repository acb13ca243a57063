"""A courier robot in its own vocabulary (doors as the STRIPS pair door-open / door-closed, the robot lacks
open-door): what the excuse holds fixed is said on stderr, and a human model of another world is refused."""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from conftest import DATA
from guided_lfd.excuse.structure import structural_predicates
from guided_lfd.pddl.reader import parse_task

COURIER = DATA / "courier"
ROBOT, HUMAN, PROBLEM = COURIER / "robot.pddl", COURIER / "human.pddl", COURIER / "problem.pddl"
SOKOBAN = DATA.parent.parent / "data" / "benchmarks" / "ipc" / "sokoban"


def excuse(runner, app, *args):
    return runner.invoke(app, ["excuse", str(ROBOT), str(PROBLEM), *map(str, args)])


def changes(result) -> list[str]:
    return [c["change"] for c in json.loads(result.stdout)["excuse"]["changes"]]


def test_a_human_model_of_another_world_is_refused_naming_what_it_lacks(runner, app):
    result = excuse(runner, app, "--human", DATA.parent.parent / "data" / "domains" / "kitchen-1" / "human.pddl")
    assert result.exit_code == 34
    assert "human.pddl: mismatch: the human model (domain 'kitchen') is for another domain than the task's " \
           "('courier'): it has no predicate at-obj, which the task uses in (at-obj mail corridor)" in result.stderr
    assert result.stdout == ""


def test_a_door_the_robot_cannot_open_is_state_so_the_default_excuse_opens_it_and_nothing_else(runner, app):
    """door-open / door-closed classify the doors as two kinds, but with them freed the relaxed robot reaches
    the goal and without them not: a skill that changes them is missing, so they are state."""
    result = excuse(runner, app, "--json")
    assert result.exit_code == 0
    assert changes(result) == ["+(door-open office-door)"]


def test_the_excuse_says_in_one_line_what_it_held_fixed_and_the_switch_that_frees_it(runner, app):
    result = excuse(runner, app, "--json")
    assert result.exit_code == 0
    held = [line for line in result.stderr.splitlines() if line.startswith("held fixed")]
    assert held == ["held fixed as the world's structure: connects (a fixed graph over room objects); "
                    "--change-structure lets the excuse change them"]


@pytest.mark.parametrize("removed", ["move", "push-to-nongoal", "push-to-goal"])
def test_a_pair_that_classifies_places_stays_a_kind(removed):
    """Sokoban's is-goal / is-nongoal classify the squares (places things are pushed to): the pair stays held
    whichever skill is missing, though freed it would let push-to-goal end anywhere."""
    domain, problem = parse_task(SOKOBAN / "domain.pddl", SOKOBAN / "task01.pddl")
    robot = replace(domain, actions=[a for a in domain.actions if a.name != removed])
    held = structural_predicates(robot, problem)
    assert held["is-goal"] == "a kind: classifies location objects with is-nongoal"
    assert held["is-nongoal"] == "a kind: classifies location objects with is-goal"


def test_with_the_human_model_what_it_cannot_change_is_said_held(runner, app):
    result = excuse(runner, app, "--human", HUMAN, "--json")
    assert result.exit_code == 0
    assert changes(result) == ["+(door-open office-door)"]
    assert "held fixed: connects (no action of the model courier changes it); without --fixed-from or --human " \
           "the excuse may change it" in result.stderr.splitlines()


def test_the_human_models_invariants_open_the_door_and_no_longer_close_it(runner, app):
    result = excuse(runner, app, "--human", HUMAN, "--invariants-from", HUMAN, "--json")
    assert result.exit_code == 0
    assert changes(result) == ["-(door-closed office-door)", "+(door-open office-door)"]


def test_quiet_holds_its_tongue(runner, app):
    result = excuse(runner, app, "--quiet", "--json")
    assert result.exit_code == 0 and "held fixed" not in result.stderr


PAIRS = DATA / "pairs"


@pytest.mark.parametrize(("world", "expected"), [
    ("light", ["+(on desk-lamp)"]),  # no skill changes on / off: the rule above frees the pair
    ("gripper", ["-(gripper-closed hand)", "+(gripper-open hand)"]),  # grasp closes it: the robot's invariants
    ("container", ["-(empty green-can)", "+(full green-can)"]),  # watering empties a can: likewise
])
def test_a_complementary_pair_gets_the_excuse_a_person_would_name(runner, app, world, expected):
    robot, problem = PAIRS / world / "robot.pddl", PAIRS / world / "problem.pddl"
    result = runner.invoke(app, ["excuse", str(robot), str(problem), "--json"])
    assert result.exit_code == 0, result.stderr
    assert changes(result) == expected


def test_the_lamps_human_model_keeps_on_and_off_apart(runner, app):
    light = PAIRS / "light"
    result = runner.invoke(app, ["excuse", str(light / "robot.pddl"), str(light / "problem.pddl"), "--human",
                                 str(light / "human.pddl"), "--invariants-from", str(light / "human.pddl"), "--json"])
    assert result.exit_code == 0
    assert changes(result) == ["-(off desk-lamp)", "+(on desk-lamp)"]


def test_teach_says_what_each_rounds_excuse_held_fixed_and_teaches_the_door(runner, app, tmp_path):
    result = runner.invoke(app, ["teach", str(ROBOT), str(PROBLEM), "--simulate", str(HUMAN), "-o",
                                 str(tmp_path / "session")])
    assert result.exit_code == 0, result.stderr
    lines = result.stderr.splitlines()
    assert lines[0] == "round 1, please demonstrate: Door-open office-door"
    assert ("  held fixed: connects (no action of the model courier changes it); without --fixed-from or --human "
            "the excuse may change it") in lines
    assert json.loads((tmp_path / "session" / "session.json").read_text())["status"] == "solved"
