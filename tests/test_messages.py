"""Small things in the messages people read (issue #27): each pinned as it now reads."""

from __future__ import annotations

from conftest import DATA

TASK = [str(DATA / "many-excuses" / "domain.pddl"), str(DATA / "many-excuses" / "problem.pddl")]


def test_a_one_step_plan_is_one_step(runner, app):
    """The text said "(1 steps, ...)" (issue #27)."""
    result = runner.invoke(app, ["excuse", *TASK])
    assert "then the robot's own plan (1 step, optimal, validated):" in result.stdout


def test_no_excuse_with_a_fixed_predicate_says_it_was_held_fixed(runner, app):
    """It read "while open stay fixed" (issue #27)."""
    from conftest import kitchen

    result = runner.invoke(app, ["excuse", *kitchen(1), "--fixed", "open"])
    assert result.exit_code == 11
    assert " with open held fixed" in result.stderr


def test_a_choice_not_offered_is_said_without_the_validators_words(runner, app):
    """It read "Value error, 'strict' is not one of ..." (pydantic's wording; issue #27)."""
    from conftest import kitchen

    result = runner.invoke(app, ["excuse", *kitchen(1), "--semantics", "strict"])
    assert result.exit_code == 37
    assert "Invalid value for '--semantics': 'strict' is not one of 'literal', 'consistent'." in result.stderr
    assert "Value error" not in result.stderr
