"""`plan` and `validate`: optimal plans that validate, and step-by-step diagnosis."""

from __future__ import annotations

import json

import pytest

from conftest import BLOCKS, kitchen
from guided_lfd.planning.grounding import ground
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning import SEARCHES, find_plan
from guided_lfd.planning.validation import PlanStep, validate_plan


@pytest.mark.parametrize("search", sorted(SEARCHES))
def test_every_registered_search_solves_blocks_and_the_plan_validates(search):
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task03.pddl")
    task = ground(domain, problem, fixed=domain.predicates)
    result = find_plan(task, search=search)
    assert result.plan is not None
    steps = [PlanStep(a.schema, a.args) for a in result.plan]
    assert validate_plan(domain, problem.init, problem.goal, steps).valid
    if result.optimal:
        assert len(result.plan) == 6


@pytest.mark.parametrize("by_count_from", [0, 10**9])
def test_atoms_of_the_smallest_predicates_come_first_so_action_masks_stay_narrow(monkeypatch, by_count_from):
    """A bit set is as wide as its highest atom: on a large task (here: any task), (handempty) and (clear ?x)
    before (on ?x ?y) keeps each action's masks as narrow as its widest atom allows; a smaller one keeps the
    order by name."""
    from guided_lfd.planning import task as ground_task

    monkeypatch.setattr(ground_task, "ATOMS_BY_COUNT_FROM", by_count_from)
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task03.pddl")
    task = ground(domain, problem)
    order = list(dict.fromkeys(a.predicate for a in task.atoms))
    if by_count_from:
        assert order == sorted(order)
        return
    counts = {p: sum(1 for a in task.atoms if a.predicate == p) for p in order}
    assert order == sorted(order, key=lambda p: (counts[p], p)) and order[0] == "handempty" and order[-1] == "on"
    pick_up = next(a for a in task.actions if a.schema == "pick-up")
    assert pick_up.pre_pos.bit_length() <= counts["handempty"] + counts["clear"] + counts["holding"] \
        + counts["ontable"]  # (on ?x ?y) is not among its atoms: its masks stay below that relation


@pytest.mark.parametrize("search", sorted(SEARCHES))
def test_every_registered_search_proves_kitchen_unsolvable_for_the_robot(search):
    domain, problem = parse_task(*kitchen(1))
    task = ground(domain, problem, fixed=domain.predicates)
    assert find_plan(task, search=search).plan is None


def test_plan_cli_prints_ipc_plan_and_validate_accepts_it(runner, app, tmp_path):
    result = runner.invoke(app, ["plan", *kitchen(2, "human")])
    assert result.exit_code == 0, result.stderr
    assert result.stdout.splitlines()[-1] == "; cost = 4 (unit cost)"
    plan_file = tmp_path / "plan.txt"
    plan_file.write_text(result.stdout)
    check = runner.invoke(app, ["validate", *kitchen(2, "human"), str(plan_file)])
    assert check.exit_code == 0
    assert check.stdout == "valid: 4 step(s), goal reached, cost 4 (unit cost)\n"


def test_plan_cli_json_and_unsolvable_exit_code(runner, app):
    result = runner.invoke(app, ["plan", *kitchen(1), "--json"])
    assert result.exit_code == 10
    doc = json.loads(result.stdout)
    assert doc["format"] == "guided-lfd/plan" and doc["format_version"] == 1
    assert doc["status"] == "unsolvable" and doc["plan"] is None
    solved = json.loads(runner.invoke(app, ["plan", *kitchen(1, "human"), "--json"]).stdout)
    assert list(doc) == list(solved)  # the documented keys, whatever the status
    assert doc["cost"] is None and doc["optimal"] is None and doc["validated"] is None


def test_validate_names_failing_step_and_precondition(runner, app, tmp_path):
    plan_file = tmp_path / "plan.txt"
    plan_file.write_text("; robot tries without opening\n(take RedPlate Table)\n(put_inside RedPlate PinkDrawer)\n")
    result = runner.invoke(app, ["validate", *kitchen(1, "human"), str(plan_file)])
    assert result.exit_code == 12
    # The text verdict is only the reason: it goes to stderr, once (stdout stays empty).
    assert result.stdout == ""
    assert result.stderr.endswith(
        "plan.txt:3:1: invalid: step 2 (put_inside redplate pinkdrawer) is not applicable: "
        "precondition (open pinkdrawer) does not hold\n"
    )


def test_validate_reports_unreached_goal(runner, app, tmp_path):
    plan_file = tmp_path / "plan.txt"
    plan_file.write_text("(open_drawer PinkDrawer)\n")
    result = runner.invoke(app, ["validate", *kitchen(1, "human"), str(plan_file), "--json"])
    assert result.exit_code == 12
    doc = json.loads(result.stdout)
    assert doc["valid"] is False and doc["unsatisfied_goal"] == ["(inside redplate pinkdrawer)"]


@pytest.mark.parametrize(
    "text,message",
    [
        ("(fly RedPlate)\n", "plan.txt:1:2: plan error: unknown action 'fly'"),
        ("(take RedPlate)\n", "plan.txt:1:2: plan error: action 'take' takes 2 argument(s), got 1"),
        ("(take RedPlate Sofa)\n", "plan.txt:1:16: plan error: unknown object 'Sofa' in action 'take'"),
        ("(take PinkDrawer Table)\n", "plan.txt:1:7: plan error: object 'PinkDrawer' is a drawer, but action 'take' expects a item"),
        ("take RedPlate Table\n", "plan.txt:1:1: plan error: expected '(action arg ...)'"),
    ],
)
def test_bad_plan_files_give_one_line_errors(runner, app, tmp_path, text, message):
    plan_file = tmp_path / "plan.txt"
    plan_file.write_text(text)
    result = runner.invoke(app, ["validate", *kitchen(1, "human"), str(plan_file)])
    assert result.exit_code == 35
    assert result.stderr.strip().endswith(message) or message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert "Traceback" not in result.stderr
