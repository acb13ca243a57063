"""The paper's measures (guided_lfd.evaluate) and the evaluate subcommand."""

from __future__ import annotations

import csv
import io
import json

import pytest

from conftest import DOMAINS
from guided_lfd.demonstration.learn import DemonstratedAction
from guided_lfd.evaluate import (
    RobotReachability, excuse_goal, holds, known_skill, misdirected_guidance, predicted_sizes, solvability_after,
)
from guided_lfd.excuse.change import Change
from guided_lfd.merge import merge_domains
from guided_lfd.pddl.model import Atom, Literal
from guided_lfd.pddl.reader import parse_domain, parse_task


def kitchen(k: int):
    robot, problem = parse_task(str(DOMAINS / f"kitchen-{k}" / "robot.pddl"),
                                str(DOMAINS / f"kitchen-{k}" / "problem.pddl"))
    return robot, problem, parse_domain(str(DOMAINS / f"kitchen-{k}" / "human.pddl"))


OPEN = [Change(Atom("open", ("pinkdrawer",)), True)]
CLEAR = [Change(Atom("clear", ("pinkdrawer",)), True)]


def test_excuse_goal_and_holds():
    goal = excuse_goal([Change(Atom("open", ("d",)), True), Change(Atom("clear", ("d",)), False)])
    assert goal == (Literal(Atom("open", ("d",))), Literal(Atom("clear", ("d",)), False))
    assert holds(goal, {Atom("open", ("d",))})
    assert not holds(goal, {Atom("open", ("d",)), Atom("clear", ("d",))})


@pytest.mark.parametrize("k,excuse,expected", [
    (1, OPEN, (1, 2, 3, 2, 2 / 3)),
    (2, CLEAR, (1, 3, 4, 3, 3 / 4)),
])
def test_predicted_sizes_and_f1_on_the_human_domain(k, excuse, expected):
    robot, problem, human = kitchen(k)
    sizes = predicted_sizes(human, problem, excuse, RobotReachability(robot, problem))
    got = (sizes.minimal_excuse, sizes.nonminimal_excuse, sizes.goal, sizes.remaining_after_excuse, sizes.f1)
    assert got == pytest.approx(expected)
    assert sizes.plans["minimal_excuse"][0].startswith(("(open_drawer", "(move_chair"))
    assert "+(open pinkdrawer)" in sizes.nonminimal_changes


def test_misdirected_guidance_finds_the_chair_blocking_the_plate():
    robot, problem, human = kitchen(2)
    m = misdirected_guidance(human, robot, problem, CLEAR)
    assert m.complete and m.explored == 100
    assert (m.misdirected, m.excuse_states) == (24, 80)  # goal states count as excuse states
    assert m.fraction == 0.3
    blocking_plate = [c for c in m.examples if c["cause"] == ["-(clear table)"]]
    assert blocking_plate and "+(blocking chair table)" in blocking_plate[0]["example_difference"]


def test_misdirection_exploration_honours_its_bound():
    robot, problem, human = kitchen(2)
    m = misdirected_guidance(human, robot, problem, CLEAR, bound=10)
    assert m.explored == 10 and not m.complete


def test_known_skill_matches_effects_not_preconditions():
    robot, _, _ = kitchen(1)
    types = {"redplate": "item", "table": "surface", "pinkdrawer": "drawer"}
    take = DemonstratedAction(
        "take_item", ("redplate", "table"),
        frozenset({Literal(Atom("on_top", ("redplate", "table"))), Literal(Atom("hand_free")),
                   Literal(Atom("clear", ("table",)))}),
        frozenset({Atom("in_hand", ("redplate",))}),
        frozenset({Atom("on_top", ("redplate", "table")), Atom("hand_free")}), "demo")
    opening = DemonstratedAction("open_drawer", ("pinkdrawer",), frozenset(), frozenset({Atom("open", ("pinkdrawer",))}),
                                 frozenset(), "demo")
    assert known_skill(take, robot, types) == "(take redplate table)"
    assert known_skill(opening, robot, types) is None


def test_solvability_after_demonstration_names_the_demonstrated_actions():
    robot, problem, human = kitchen(1)
    merged = merge_domains([robot, human]).domain
    result = solvability_after(merged, problem, robot)
    assert result.solvable and result.demonstrated_actions_used == ["(open_drawer pinkdrawer)"]
    assert not solvability_after(robot, problem, robot).solvable


def _args(k: int) -> list[str]:
    base = DOMAINS / f"kitchen-{k}"
    return [str(base / "robot.pddl"), str(base / "problem.pddl"), "--human", str(base / "human.pddl")]


def test_cli_evaluate_text_json_and_csv(runner, app, tmp_path):
    text = runner.invoke(app, ["evaluate", *_args(2), "-q"])
    assert text.exit_code == 0, text.stderr
    assert "f1_savings" in text.stdout and "misdirected_guidance" in text.stdout
    # F1 says what it means: the share saved (higher saves more), with the plan lengths behind it.
    (f1_line,) = [line for line in text.stdout.splitlines() if line.startswith("f1_savings")]
    assert f1_line.split(None, 2)[1:] == ["0.750", "higher = more saved: the share of the whole-task demonstration "
                                          "the human need not give, |pi'_H| / |pi_H| = 3 / 4 (human plan from the "
                                          "excuse state over the full one)"]
    doc = json.loads(runner.invoke(app, ["evaluate", *_args(2), "--json", "-q"]).stdout)
    assert doc["format"] == "guided-lfd/evaluation" and doc["format_version"] == 1
    assert doc["excuse"] == ["+(clear pinkdrawer)"]
    assert doc["demonstration_size"]["f1"] == 0.75
    rows = list(csv.reader(io.StringIO(runner.invoke(app, ["evaluate", *_args(2), "--csv", "-q"]).stdout)))
    assert rows[0] == ["measure", "value", "detail"]
    assert ["f1_savings", "0.750"] == rows[2][:2]


def test_cli_evaluate_reads_an_excuse_file_and_a_merged_domain(runner, app, tmp_path):
    base = DOMAINS / "kitchen-1"
    excuse = tmp_path / "excuse.json"
    made = runner.invoke(app, ["excuse", str(base / "robot.pddl"), str(base / "problem.pddl"), "--json", "-q",
                               "-o", str(excuse)])
    assert made.exit_code == 0
    merged = tmp_path / "merged.pddl"
    assert runner.invoke(app, ["merge", str(base / "robot.pddl"), str(base / "human.pddl"), "-q",
                               "-o", str(merged)]).exit_code == 0
    result = runner.invoke(app, ["evaluate", *_args(1), "--excuse", str(excuse), "--merged", str(merged),
                                 "--json", "-q"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["excuse_source"] == str(excuse)
    assert doc["solvability_after_demonstration"]["solvable"] is True


@pytest.mark.parametrize("extra,code,message", [
    (["--bound", "0"], 37, "--bound 0: expected a number of states >= 1"),
    (["--csv", "--json"], 37, "--csv and --json: choose one output format"),
])
def test_cli_evaluate_bad_options(runner, app, extra, code, message):
    result = runner.invoke(app, ["evaluate", *_args(1), *extra])
    assert result.exit_code == code
    assert message in result.stderr and result.stderr.count("\n") == 1


def test_cli_evaluate_bad_excuse_file(runner, app, tmp_path):
    bad = tmp_path / "excuse.json"
    bad.write_text('{"format": "guided-lfd/excuse", "excuse": {"changes": [{"op": "add", "atom": "(open nodrawer)"}]}}')
    result = runner.invoke(app, ["evaluate", *_args(1), "--excuse", str(bad)])
    assert result.exit_code == 30
    assert f"{bad}:1:79: input error: excuse change (open nodrawer): unknown object nodrawer" in result.stderr
    bad.write_text("{not json")
    result = runner.invoke(app, ["evaluate", *_args(1), "--excuse", str(bad)])
    assert result.exit_code == 30 and f"{bad}:1:2: input error: not JSON" in result.stderr


@pytest.mark.parametrize("changes,message", [
    ('[{"op": "add", "atom": "(open)"}]', "open takes 1 argument(s), got 0"),
    ('[{"op": "add", "atom": "(open redplate)"}]', "redplate is a item, open expects a drawer"),
    ('[]', "the excuse has no changes"),
    ('[{"op": "add", "atom": "(inside redplate pinkdrawer)"}]', "already satisfies the goal"),
    ('[{"op": "add", "atom": "(open bluedrawer)"}]', "the robot cannot reach the goal from the changed state"),
])
def test_cli_evaluate_checks_the_excuse(runner, app, tmp_path, changes, message):
    bad = tmp_path / "excuse.json"
    bad.write_text('{"format": "guided-lfd/excuse", "excuse": {"changes": ' + changes + '}}')
    result = runner.invoke(app, ["evaluate", *_args(1), "--excuse", str(bad)])
    assert result.exit_code == 30, result.stderr
    assert message in result.stderr and result.stderr.startswith(str(bad)) and result.stderr.count("\n") == 1


def test_cli_evaluate_refuses_a_human_domain_that_does_not_fit(runner, app):
    from conftest import DATA

    args = _args(1)
    args[3] = str(DATA / "merge" / "bad-arity.pddl")
    result = runner.invoke(app, ["evaluate", *args])
    assert result.exit_code in (32, 34) and "Traceback" not in result.stderr
    assert result.stderr.count("\n") == 1


def test_cli_evaluate_with_a_demonstration_and_a_nonminimal_excuse(runner, app, tmp_path):
    base = DOMAINS / "kitchen-2"
    segments = tmp_path / "s.json"
    demo = DOMAINS.parent / "demos" / "kitchen-2" / "P1-excuse.csv"
    assert runner.invoke(app, ["segment", str(demo), "-q", "-o", str(segments)]).exit_code == 0
    other = tmp_path / "other.json"
    other.write_text('{"format": "guided-lfd/excuse", "excuse": {"changes": ['
                     '{"op": "add", "atom": "(clear pinkdrawer)"}, {"op": "add", "atom": "(open pinkdrawer)"}]}}')
    result = runner.invoke(app, ["evaluate", str(base / "robot.pddl"), str(base / "problem.pddl"), "--human",
                                 str(base / "human.pddl"), "-d", str(segments), "--nonminimal-excuse", str(other),
                                 "--json", "-q"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["demonstration_size"]["predicted"]["nonminimal_excuse"] == 2
    [d] = doc["demonstrations"]
    assert (d["demonstrated_actions"], d["useful_actions"]) == (2, 1)  # the robot can already open drawers


def test_cli_evaluate_on_a_solvable_task_says_there_is_nothing_to_evaluate(runner, app):
    base = DOMAINS / "kitchen-1"
    result = runner.invoke(app, ["evaluate", str(base / "human.pddl"), str(base / "problem.pddl"),
                                 "--human", str(base / "human.pddl")])
    assert result.exit_code == 37
    assert "nothing to evaluate: the robot can already solve the task" in result.stderr
    assert result.stderr.count("\n") == 1


def test_evaluate_returns_an_evaluation_with_its_document_and_rows():
    from guided_lfd.evaluate import Evaluation, evaluate
    from guided_lfd.excuse.engine import find_excuses

    robot, problem, human = kitchen(2)
    result = evaluate(robot, problem, human, find_excuses(robot, problem).excuse.changes, bound=500)
    assert isinstance(result, Evaluation)
    doc = json.loads(result.to_json({"robot": "r.pddl"}))
    assert list(doc)[:3] == ["format", "format_version", "robot"] and doc["excuse"] == ["+(clear pinkdrawer)"]
    assert result.rows()[0] == ("excuse", "+(clear pinkdrawer)", "1 change(s)")
