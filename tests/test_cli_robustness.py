"""Regression tests from an adversarial hunt: every bad input is one line on
stderr with a documented exit code, and outputs are never damaged."""

from __future__ import annotations

import os
import stat

import pytest

from conftest import BLOCKS, kitchen
from guided_lfd.io import write_text

DOMAIN, PROBLEM = kitchen(1)


def one_line(result) -> str:
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert "Traceback" not in result.stderr
    return lines[0]


def test_write_through_symlink_keeps_the_link(tmp_path):
    target = tmp_path / "real.txt"
    target.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_text(link, "new")
    assert link.is_symlink() and target.read_text() == "new"


def test_write_to_device_writes_in_place():
    write_text("/dev/null", "data")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_write_keeps_permissions(tmp_path):
    target = tmp_path / "out.txt"
    target.write_text("old")
    target.chmod(0o644)
    write_text(target, "new")
    assert stat.S_IMODE(target.stat().st_mode) == 0o644


@pytest.mark.parametrize(
    "args,code,message",
    [
        (["--strategy", "zz"], 37, "--strategy zz: unknown strategy"),
        (["--time-limit", "inf"], 37, "--time-limit inf: expected a number of seconds > 0"),
        (["--time-limit", "nan"], 37, "--time-limit nan: expected a number of seconds > 0"),
        (["--time-limit", "-1"], 37, "--time-limit -1: expected a number of seconds > 0"),
        (["--max-size", "-1"], 37, "--max-size -1: expected a number of changes >= 0"),
        (["--max-size", "x"], 2, "usage error"),
        (["--semantics", "zz"], 2, "usage error"),
        (["--cost", "open=\u0661"], 37, "is not a whole number"),
        (["--cost", "((open pinkdrawer))=1"], 37, "expected one atom"),
        (["--fixed", "OPEN", "--fixed", "sofa"], 37, "--fixed 'sofa': unknown predicate"),
    ],
)
def test_bad_option_values(runner, app, args, code, message):
    result = runner.invoke(app, ["excuse", DOMAIN, PROBLEM, *args])
    assert result.exit_code == code
    assert message in one_line(result)


def test_plan_unknown_search_and_huge_time_limit(runner, app):
    assert runner.invoke(app, ["plan", DOMAIN, PROBLEM, "--search", "zz"]).exit_code == 37
    assert runner.invoke(app, ["plan", DOMAIN, PROBLEM, "--time-limit", "1e10"]).exit_code == 37


def test_stdin_twice_is_refused(runner, app):
    result = runner.invoke(app, ["plan", "-", "-"], input="")
    assert result.exit_code == 37
    assert "standard input" in one_line(result)


@pytest.mark.parametrize("args,code", [(["--max-size", "0"], 13), (["--time-limit", "0.000001"], 20)])
def test_unsuccessful_excuse_does_not_replace_output(runner, app, tmp_path, args, code):
    out = tmp_path / "keep.txt"
    out.write_text("precious")
    result = runner.invoke(app, ["excuse", *map(str, (BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")),
                                 "--strategy", "baseline", "-o", str(out), *args])
    assert result.exit_code == code
    assert out.read_text() == "precious"


def test_unwritable_second_output_fails_before_anything_is_written(runner, app, tmp_path):
    out = tmp_path / "keep.txt"
    out.write_text("precious")
    result = runner.invoke(app, ["excuse", DOMAIN, PROBLEM, "-o", str(out), "--excuse-problem", str(tmp_path)])
    assert result.exit_code == 40
    assert out.read_text() == "precious"
    assert "is a directory" in one_line(result)


def test_output_folder_name_is_an_error(runner, app, tmp_path):
    result = runner.invoke(app, ["plan", *kitchen(1, "human"), "-o", str(tmp_path / "nodir") + "/"])
    assert result.exit_code == 40


def test_deep_nesting_is_a_syntax_error(runner, app, tmp_path):
    problem = tmp_path / "deep.pddl"
    problem.write_text("(define (problem p) (:domain kitchen) (:goal " + "(and " * 200 + ")" * 200 + "))")
    result = runner.invoke(app, ["excuse", DOMAIN, str(problem)])
    assert result.exit_code == 31
    assert "nested more than 64 levels" in one_line(result)


def test_empty_goal_is_already_solvable(runner, app, tmp_path):
    problem = tmp_path / "p.pddl"
    problem.write_text(open(PROBLEM).read().replace("(:goal (and (inside RedPlate PinkDrawer)))", "(:goal (and))"))
    result = runner.invoke(app, ["excuse", DOMAIN, str(problem), "--json"])
    assert result.exit_code == 0, result.stderr
    assert '"already-solvable"' in result.stdout


def test_invariants_from_an_unrelated_domain_does_not_crash(runner, app):
    result = runner.invoke(app, ["excuse", DOMAIN, PROBLEM, "--invariants-from", str(BLOCKS / "domain.pddl")])
    assert result.exit_code == 0, result.stderr


def test_action_names_differing_in_case_are_duplicates(runner, app, tmp_path):
    domain = tmp_path / "d.pddl"
    text = open(DOMAIN).read().replace("(:action put_on", "(:action TAKE")
    domain.write_text(text)
    result = runner.invoke(app, ["plan", str(domain), PROBLEM])
    assert result.exit_code == 32
    assert "d.pddl:26:3: semantic error: action 'TAKE' is declared twice" in one_line(result)


def test_action_named_like_a_reversed_action_is_fine(runner, app, tmp_path):
    domain = tmp_path / "d.pddl"
    domain.write_text(open(DOMAIN).read().replace("(:action put_on", "(:action take__reversed"))
    result = runner.invoke(app, ["excuse", str(domain), PROBLEM])
    assert result.exit_code == 0
    assert result.stderr.count("\n") <= 1  # no translator warnings


def test_endless_input_is_refused(runner, app):
    result = runner.invoke(app, ["plan", "/dev/zero", PROBLEM])
    assert result.exit_code == 30
    assert "larger than 64 MiB" in one_line(result)


def test_too_many_atoms_is_refused_quickly(runner, app, tmp_path):
    domain = tmp_path / "big.pddl"
    domain.write_text("(define (domain big) (:requirements :strips :typing) (:types t) "
                      "(:predicates (p ?a ?b ?c ?d ?e ?f - t) (q)) "
                      "(:action a :parameters (?x - t) :precondition (q) :effect (p ?x ?x ?x ?x ?x ?x)))")
    problem = tmp_path / "p.pddl"
    objects = " ".join(f"o{i}" for i in range(12))
    problem.write_text(f"(define (problem p) (:domain big) (:objects {objects} - t) (:init) (:goal (q)))")
    result = runner.invoke(app, ["excuse", str(domain), str(problem)])
    assert result.exit_code == 21
    assert "exceed the limit" in one_line(result)


def test_type_cycle_is_named(runner, app, tmp_path):
    domain = tmp_path / "d.pddl"
    domain.write_text("(define (domain d) (:requirements :strips :typing) (:types t - u u - t) "
                      "(:predicates (p ?x - t)) (:action a :parameters (?x - t) :precondition (p ?x) :effect (not (p ?x))))")
    result = runner.invoke(app, ["plan", str(domain), PROBLEM])
    assert result.exit_code == 32
    assert "type hierarchy has a cycle" in one_line(result)
