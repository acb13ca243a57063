"""`guided-lfd excuse` through the CLI: output formats, exit codes, errors."""

from __future__ import annotations

import json

import pytest

from conftest import BLOCKS, DATA, kitchen
from guided_lfd.pddl.reader import parse_task


def run(runner, app, *args):
    return runner.invoke(app, ["excuse", *map(str, args)])


def test_kitchen_1_json_acceptance(runner, app):
    result = run(runner, app, *kitchen(1), "--json")
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["format"] == "guided-lfd/excuse" and doc["format_version"] == 1
    assert doc["status"] == "excuse-found"
    changes = [c["change"] for c in doc["excuse"]["changes"]]
    assert "+(open pinkdrawer)" in changes
    assert not any("redplate" in c for c in changes)
    assert doc["excuse"]["changes"][0]["text"] == "Open PinkDrawer"
    assert doc["excuse"]["validated"] is True
    assert {"time_s", "candidates", "planner_calls"} <= set(doc["statistics"])


def test_kitchen_2_json_acceptance(runner, app):
    result = run(runner, app, *kitchen(2), "--json")
    assert result.exit_code == 0
    doc = json.loads(result.stdout)
    assert "+(clear pinkdrawer)" in [c["change"] for c in doc["excuse"]["changes"]]


def test_text_output_speaks_the_papers_words(runner, app):
    result = run(runner, app, *kitchen(1))
    assert result.exit_code == 0
    assert "Open PinkDrawer   +(open pinkdrawer)" in result.stdout
    assert "1. (take redplate table)" in result.stdout


def test_all_lists_alternatives_in_json(runner, app):
    result = run(runner, app, BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl", "--semantics", "literal", "--all", "--json")
    doc = json.loads(result.stdout)
    assert doc["excuse"]["size"] == 2 and len(doc["alternatives"]) == 5


def test_output_file_is_json_and_excuse_problem_plans(runner, app, tmp_path):
    out = tmp_path / "excuse.json"
    state = tmp_path / "excuse-problem.pddl"
    result = run(runner, app, *kitchen(1), "-o", out, "--excuse-problem", state, "--quiet")
    assert result.exit_code == 0 and result.stdout == "" and result.stderr == ""
    assert json.loads(out.read_text())["status"] == "excuse-found"
    plan = runner.invoke(app, ["plan", kitchen(1)[0], str(state)])
    assert plan.exit_code == 0
    assert parse_task(kitchen(1)[0], state)[1].init >= {a for a in parse_task(*kitchen(1))[1].init}


def test_already_solvable_exits_zero_with_plan(runner, app):
    result = run(runner, app, *kitchen(1, "human"), "--json")
    assert result.exit_code == 0
    doc = json.loads(result.stdout)
    assert doc["status"] == "already-solvable" and doc["excuse"] is None and len(doc["robot_plan"]) == 3


def test_no_excuse_exit_code_and_message(runner, app, tmp_path):
    domain = tmp_path / "robot.pddl"
    text = open(kitchen(1)[0]).read()
    start = text.index("  ;; Put the held item inside")
    domain.write_text(text[:start] + ")\n")
    result = run(runner, app, domain, kitchen(1)[1])
    assert result.exit_code == 11
    assert "no robot skill achieves (inside redplate pinkdrawer)" in result.stderr
    assert "a new skill must be demonstrated" in result.stderr


def test_max_size_exit_code(runner, app):
    result = run(runner, app, BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl", "--max-size", "1")
    assert result.exit_code == 13


@pytest.mark.parametrize(
    "args,code,message",
    [
        (["--cost", "sofa=3"], 37, "option error: --cost 'sofa=3': unknown predicate 'sofa'"),
        (["--cost", "open=cheap"], 37, "option error: --cost 'open=cheap': cost 'cheap' is not a whole number"),
        (["--cost", "(open sofa)=2"], 37, "is not a ground atom of this task"),
        (["--fixed", "sofa"], 37, "option error: --fixed 'sofa': unknown predicate"),
    ],
)
def test_bad_options_are_one_line_errors(runner, app, args, code, message):
    result = run(runner, app, *kitchen(1), *args)
    assert result.exit_code == code
    assert message in result.stderr and len(result.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize(
    "name,code",
    [("unknown-object.pddl", 32), ("unknown-predicate.pddl", 32), ("syntax-goal.pddl", 31),
     ("wrong-domain.pddl", 34), ("empty.pddl", 30), ("missing.pddl", 30)],
)
def test_bad_problem_through_cli_never_tracebacks(runner, app, name, code):
    result = run(runner, app, BLOCKS / "domain.pddl", DATA / "bad" / name)
    assert result.exit_code == code
    assert result.stdout == ""
    line = result.stderr.strip()
    assert "\n" not in line and "Traceback" not in line and name in line


def test_bad_domain_requirement_through_cli(runner, app):
    result = run(runner, app, DATA / "bad" / "requirement.pddl", BLOCKS / "task03.pddl")
    assert result.exit_code == 33
    assert "requirement.pddl:6:34: unsupported: unsupported requirement :durative-actions" in result.stderr


def test_output_is_not_clobbered_on_error(runner, app, tmp_path):
    out = tmp_path / "keep.json"
    out.write_text("precious")
    result = run(runner, app, BLOCKS / "domain.pddl", DATA / "bad" / "empty.pddl", "-o", out)
    assert result.exit_code == 30
    assert out.read_text() == "precious"


def test_stdin_problem(runner, app):
    with open(kitchen(1)[1]) as fh:
        result = runner.invoke(app, ["excuse", kitchen(1)[0], "-", "--json"], input=fh.read())
    assert result.exit_code == 0
    assert json.loads(result.stdout)["excuse"]["size"] == 1


def test_time_limit_is_honoured(runner, app):
    result = run(runner, app, BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl", "--strategy", "baseline",
                 "--time-limit", "0.001")
    assert result.exit_code == 20
    assert "time limit reached" in result.stderr


def test_fixed_from_fixes_what_no_action_of_that_domain_changes(runner, app):
    # graspable is static in the human's domain: the excuse may not touch it.
    result = run(runner, app, *kitchen(1), "--fixed-from", kitchen(1, "human")[0], "--semantics", "literal", "--all", "--json")
    doc = json.loads(result.stdout)
    assert result.exit_code == 0
    every = [doc["excuse"], *doc["alternatives"]]
    assert all("graspable" not in c["atom"] for e in every for c in e["changes"])
    every_change = json.loads(run(runner, app, *kitchen(1), "--change-structure", "--json").stdout)
    assert doc["statistics"]["changeable_atoms"] < every_change["statistics"]["changeable_atoms"]


def test_a_goal_that_can_never_hold_is_said_in_the_domains_terms_not_an_internal_atom(runner, app):
    """(not (= a a)): the translator proves the goal unreachable; the reason names no internal atom."""
    fuzz = DATA / "adl" / "fuzz"
    result = run(runner, app, fuzz / "goal-equality.pddl", fuzz / "goal-equality-self.pddl")
    assert result.exit_code == 11
    assert "guided-lfd-unreachable-goal" not in result.stderr
    assert ("no excuse exists: the goal can never hold, in any state (Fast Downward's translator proves it: an "
            "equality or another condition no state satisfies); no demonstration helps") in result.stderr
