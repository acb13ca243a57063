"""A second model of the world must speak the robot's language (issue #25): ``--human``, ``--invariants-from``,
``--fixed-from`` and ``teach --simulate`` with a predicate of the robot's name but another arity or an argument
of an unrelated type are exit 34 naming the predicate, before any work (it was exit 0, silently)."""

from __future__ import annotations

import json

import pytest

from conftest import DATA, ROOT
from guided_lfd.errors import EXIT_MISMATCH, MismatchError
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.pddl.fit import check_model_fits
from guided_lfd.pddl.reader import parse_domain, parse_task

KITCHEN = ROOT / "data" / "domains" / "kitchen-1"
ROBOT, PROBLEM = str(KITCHEN / "robot.pddl"), str(KITCHEN / "problem.pddl")
ARITY, TYPE = str(DATA / "fit" / "human-arity.pddl"), str(DATA / "fit" / "human-type.pddl")


@pytest.mark.parametrize("options", [["--invariants-from", ARITY], ["--fixed-from", ARITY],
                                     ["--human", ARITY, "--prefer", "demonstration"]])
def test_a_model_with_another_arity_is_refused_naming_the_predicate(runner, app, options):
    result = runner.invoke(app, ["excuse", ROBOT, PROBLEM, *options])
    assert result.exit_code == EXIT_MISMATCH, result.output
    assert result.stderr.strip() == (
        f"{ARITY}:13:17: mismatch: {options[0]}: predicate open takes 2 argument(s) here and 1 in the robot's "
        f"domain {ROBOT}; expected the same arity")
    assert result.stdout == ""


def test_a_model_with_an_unrelated_argument_type_is_refused(runner, app):
    result = runner.invoke(app, ["excuse", ROBOT, PROBLEM, "--fixed-from", TYPE])
    assert result.exit_code == EXIT_MISMATCH
    assert "--fixed-from: argument 1 of predicate open is of type item here and of type drawer" in result.stderr


def test_teach_refuses_a_simulated_human_of_another_arity_before_making_its_folder(runner, app, tmp_path):
    session = tmp_path / "session"
    result = runner.invoke(app, ["teach", ROBOT, PROBLEM, "--simulate", ARITY, "-o", str(session)])
    assert result.exit_code == EXIT_MISMATCH
    assert "predicate open takes 2 argument(s)" in result.stderr
    assert not session.exists()


def test_the_library_refuses_it_too():
    domain, problem = parse_task(ROBOT, PROBLEM)
    with pytest.raises(MismatchError, match="--invariants-from: predicate open takes 2"):
        find_excuses(domain, problem, ExcuseOptions(invariants_from=parse_domain(ARITY)))


def test_the_humans_own_model_fits_and_types_of_its_own_naming_are_allowed():
    """Kitchen I's human model fits its robot; a type only one domain declares is not a clash."""
    robot = parse_domain(ROBOT)
    check_model_fits(robot, parse_domain(str(KITCHEN / "human.pddl")), "--human")
    for domain in sorted((ROOT / "data" / "domains").glob("*/human.pddl")):
        check_model_fits(parse_domain(str(domain.parent / "robot.pddl")), parse_domain(str(domain)), "--human")


@pytest.mark.parametrize("model, said", [
    (ARITY, "--human: predicate open takes 2 argument(s) here and 1 in the robot's domain"),
    (TYPE, "--human: argument 1 of predicate open is of type item here and of type drawer"),
])
def test_evaluate_refuses_a_human_model_that_does_not_fit(runner, app, model, said):
    """#25 second round: evaluate --human took such models (exit 0, meaningless measures)."""
    result = runner.invoke(app, ["evaluate", ROBOT, PROBLEM, "--human", model])
    assert result.exit_code == EXIT_MISMATCH, result.output
    assert said in result.stderr and result.stdout == ""


WIDGET = str(DATA / "fit" / "human-widget.pddl")


@pytest.mark.parametrize("command", [
    ["excuse", ROBOT, PROBLEM, "--human", WIDGET],
    ["excuse", ROBOT, PROBLEM, "--invariants-from", WIDGET],
    ["excuse", ROBOT, PROBLEM, "--fixed-from", WIDGET],
    ["teach", ROBOT, PROBLEM, "--simulate", WIDGET, "-o", "SESSION"],
    ["evaluate", ROBOT, PROBLEM, "--human", str(KITCHEN / "human.pddl"), "--merged", WIDGET],
    ["learn-domain", "SEGMENTS", "--prior", ROBOT, "--human", WIDGET],
])
def test_a_type_neither_domain_relates_is_a_clash_in_every_command(runner, app, tmp_path, command):
    """Third round: an argument type the robot does not declare (widget beside drawer) was taken as related, so
    the model was accepted (exit 0), and teach named a missing predicate instead, evaluate --merged a problem
    error (32), learn-domain nothing."""
    segments = tmp_path / "p1.segments.json"
    trace = ROOT / "data" / "demos" / "kitchen-1" / "P1-excuse.csv"
    assert runner.invoke(app, ["segment", str(trace), "-o", str(segments)]).exit_code == 0
    args = [{"SESSION": str(tmp_path / "session"), "SEGMENTS": str(segments)}.get(a, a) for a in command]
    result = runner.invoke(app, args)
    assert result.exit_code == EXIT_MISMATCH, result.output
    assert "argument 1 of predicate open is of type widget here and of type drawer" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "session").exists()


def test_an_either_type_is_related_through_its_members(runner, app):
    """Review of this change: (at ?v - (either truck plane) ...) beside the robot's (at ?v - truck ...) was refused
    (34) once undeclared types stopped counting as related."""
    folder = DATA / "fit"
    result = runner.invoke(app, ["excuse", str(folder / "either-robot.pddl"), str(folder / "either-problem.pddl"),
                                 "--human", str(folder / "either-human.pddl"), "--json"])
    assert result.exit_code == 0, result.stderr
    assert [c["change"] for c in json.loads(result.stdout)["excuse"]["changes"]] == ["-(at t a)", "+(at t b)"]


def test_an_adl_model_sharing_none_of_the_robots_predicates_gives_the_invariants_it_has(runner, app):
    """Its conservation check grounds it on the robot's task: the translator refused the robot's atoms and
    objects it does not know (exit 1, 'Undefined predicate ... Got: blocking'); now they are left out."""
    model = str(DATA / "fit" / "adl-unrelated.pddl")
    result = runner.invoke(app, ["excuse", ROBOT, PROBLEM, "--semantics", "consistent", "--invariants-from", model,
                                 "--json"])
    assert result.exit_code == 0, result.output
    assert [c["change"] for c in json.loads(result.stdout)["excuse"]["changes"]] == ["+(open pinkdrawer)"]
