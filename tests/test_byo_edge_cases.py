"""Robots in words other than the kitchens': hand facts read off odd domains and arm names, skills named after the
human's actions or refused when they could never run, worlds without objects or with zero-argument facts, bad
vocabularies and demonstrations of another world refused; one test each, their PDDL and traces in
``tests/data/regressions/byo-edge-cases/``."""

from __future__ import annotations

import json
import shutil

import pytest

from conftest import DATA
from guided_lfd.demonstration.vocabulary import HandVocabulary, bind_arms, infer_vocabulary
from guided_lfd.pddl.reader import parse_domain

CASES = DATA / "regressions" / "byo-edge-cases"
BYO = DATA / "byo"


def _teach(runner, app, folder, out, problem="problem.pddl"):
    result = runner.invoke(app, ["teach", str(folder / "robot.pddl"), str(folder / problem), "--simulate",
                                 str(folder / "human.pddl"), "-o", str(out), "--json", "--quiet"])
    return result, (json.loads(result.stdout) if result.stdout.strip() else None)


def test_a_change_about_no_object_is_not_the_doing_of_the_hand_holding_still(runner, app, tmp_path):
    """The left arm holds a cup while the right one switches the light on: only the right arm's skill is learned
    (the hand holding still used to learn "holding any item turns the light on" under the human's name)."""
    result, doc = _teach(runner, app, CASES / "zero-ary-light", tmp_path)
    assert result.exit_code == 0, result.output
    assert doc["rounds"][0]["learned_actions"] == ["switch-light"]
    learned = parse_domain(str(tmp_path / "round-1" / "learned.pddl"))
    assert [a.name for a in learned.actions] == ["switch-light"]
    assert all(t == "arm" for _, t in learned.action("switch-light").params)


def test_a_step_the_robot_makes_only_under_a_stronger_precondition_is_learned(runner, app, tmp_path):
    """The robot opens boxes with an empty hand only; the human opens one holding a cup: that teaches it."""
    result, doc = _teach(runner, app, CASES / "weaker-precondition", tmp_path)
    assert result.exit_code == 0, result.output
    assert doc["status"] == "solved" and doc["plans_original_task"] and doc["rounds"][0]["learned_actions"]


def test_opening_while_holding_something_keeps_it_in_hand(runner, app, tmp_path):
    result, doc = _teach(runner, app, CASES / "open-while-holding", tmp_path)
    assert result.exit_code == 0, result.output
    assert doc["status"] == "solved" and len(doc["rounds"]) == 1
    assert not any(name.startswith("reach") for name in doc["rounds"][0]["learned_actions"])


def test_the_hand_facts_of_a_robot_without_its_putting_skills_are_still_its_own(runner, app, tmp_path):
    """The robot lacks both place actions, so only its taking actions toggle holding/hand-empty; a real trace
    declares no vocabulary: the learner must still speak the robot's hand, not the kitchens'."""
    folder = CASES / "no-put-skill"
    segmented = runner.invoke(app, ["segment", str(folder / "real.csv")])
    assert segmented.exit_code == 0, segmented.output
    learned = runner.invoke(app, ["learn-domain", "-", "--prior", str(folder / "robot.pddl")], input=segmented.stdout)
    assert learned.exit_code == 0, learned.output
    assert "hand-empty" in learned.stdout and "hand_free" not in learned.stdout
    assert "hand facts: held=holding, free=hand-empty" in learned.stderr


@pytest.mark.parametrize("domain, held, free", [
    ("blocks-clear-while-held.pddl", "holding", "handempty"),  # clear/handempty toggle too, but not always together
])
def test_the_hand_facts_are_the_pair_that_always_changes_together(domain, held, free):
    found = infer_vocabulary(parse_domain(str(CASES / domain)))
    assert (found.held, found.free) == (held, free)


def test_a_device_plugged_into_a_socket_is_no_arm_holding_it():
    assert infer_vocabulary(parse_domain(str(CASES / "plugs-no-hand.pddl"))) is None


@pytest.mark.parametrize("arms, hands", [
    (("robot-left", "robot-right"), (("left", "robot-left"), ("right", "robot-right"))),
    (("arm-l", "arm-r"), (("left", "arm-l"), ("right", "arm-r"))),
])
def test_arm_names_tell_the_hands_apart(arms, hands):
    pending = HandVocabulary("grasped", "free", (), "test", by_arm=True, arm_type="arm")
    assert bind_arms(pending, {a: "arm" for a in arms}).hands == hands
    with pytest.raises(ValueError):
        bind_arms(pending, {"arm1": "arm", "arm2": "arm"})
    assert bind_arms(pending, {"arm1": "arm", "arm2": "arm"}, choose=True).hands == (("left", "arm1"),
                                                                                      ("right", "arm2"))


def test_a_world_whose_only_initial_facts_are_the_hands_starts_at_the_vocabulary_rows(runner, app, tmp_path):
    result, doc = _teach(runner, app, CASES / "zero-ary-light", tmp_path, "problem-empty-env.pddl")
    assert result.exit_code == 0, result.output


def test_an_action_without_objects_is_refused_in_one_line_not_a_crash(runner, app, tmp_path):
    result, _ = _teach(runner, app, CASES / "zero-param", tmp_path)
    assert result.exit_code == 33 and "which has none (give --demo traces)" in result.stderr


def test_a_zero_argument_open_fact_is_drawn_like_any_change(runner, app, tmp_path):
    result, doc = _teach(runner, app, CASES / "open0", tmp_path)
    assert result.exit_code == 0, result.output


def test_a_skill_is_named_after_the_human_action_whose_precondition_it_shares(runner, app, tmp_path):
    """Kicking a door open and unlocking it have the same effect; the demonstration had no key."""
    result, doc = _teach(runner, app, CASES / "same-effects", tmp_path)
    assert result.exit_code == 0, result.output
    assert doc["rounds"][0]["learned_actions"] == ["kick-door"]


def _segments(runner, app, tmp_path, name="twoarm"):
    segmented = runner.invoke(app, ["segment", str(BYO / name / "demo-round-1.csv")])
    assert segmented.exit_code == 0
    return json.loads(segmented.stdout)


@pytest.mark.parametrize("vocabulary, message", [
    ({"held": "grasped", "free": "free", "hands": ["left-arm"]}, r"vocabulary.hands: expected"),
    ({"held": "grasped", "free": "free", "hands": {"left": ["x"]}}, r"vocabulary.hands: expected"),
    ({"held": "free", "free": "free", "hands": {"left": "left-arm"}}, r"held and free are both free"),
    ({"held": "grabbed", "free": "free", "hands": {"left": "left-arm", "right": "right-arm"}},
     r"declares the hand facts held=grabbed.*expected the robot's own"),
    ({"held": "grasped", "free": "free", "hands": {"left": "tool-box", "right": "right-arm"}},
     r"declares tool-box \(box\) an arm.*of type arm"),
])
def test_a_segments_document_with_a_bad_vocabulary_is_refused_at_its_json_path(vocabulary, message, runner, app,
                                                                                tmp_path):
    doc = _segments(runner, app, tmp_path)
    doc["vocabulary"] = vocabulary
    (tmp_path / "bad.json").write_text(json.dumps(doc))
    result = runner.invoke(app, ["learn-domain", str(tmp_path / "bad.json"), "--prior",
                                 str(BYO / "twoarm" / "robot.pddl")])
    assert result.exit_code == 36, result.output
    assert "internal error" not in result.stderr
    assert pytest.importorskip("re").search(message, result.stderr), result.stderr


def test_a_demonstration_of_another_world_is_refused_before_anything_is_learned(runner, app, tmp_path):
    """teach --demo with the fetch demonstration on the blocksworld task: 34 naming the objects, not a type error
    of a skill learned from it."""
    demo = tmp_path / "demo.csv"
    shutil.copyfile(BYO / "fetch" / "demo-round-1.csv", demo)
    shutil.copyfile(BYO / "fetch" / "demo-round-1.state.csv", tmp_path / "demo.state.csv")
    result = runner.invoke(app, ["teach", str(BYO / "blocksworld" / "robot.pddl"),
                                 str(BYO / "blocksworld" / "problem.pddl"), "--demo", str(demo), "-o",
                                 str(tmp_path / "session")])
    assert result.exit_code == 34 and "has object(s) the task does not" in result.stderr


def test_a_skill_that_could_never_run_beside_the_robots_is_refused_not_learned(runner, app, tmp_path):
    """Through the command line: a trace without vocabulary rows, a robot whose hand facts cannot be read off it;
    the skills learned in the kitchens' hand facts need (hand_free), which the robot never makes true: exit 34
    naming the skill and the predicate, nothing written."""
    trace = tmp_path / "demo.csv"
    shutil.copyfile(BYO / "blocksworld" / "demo-round-1.csv", trace)
    rows = (BYO / "blocksworld" / "demo-round-1.state.csv").read_text().splitlines(keepends=True)
    (tmp_path / "demo.state.csv").write_text("".join(r for r in rows if "vocabulary(" not in r))
    segmented = runner.invoke(app, ["segment", str(trace)])
    assert segmented.exit_code == 0, segmented.output
    out = tmp_path / "learned.pddl"
    result = runner.invoke(app, ["learn-domain", "-", "--prior", str(CASES / "painter-robot.pddl"), "-o", str(out)],
                           input=segmented.stdout)
    assert result.exit_code == 34, result.output
    assert "learned skill take_block needs (hand_free ...), a predicate" in result.stderr
    assert "never makes true" in result.stderr and not out.exists()
