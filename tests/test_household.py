"""The household task generator: deterministic, valid PDDL, the intended excuse."""

from __future__ import annotations

import pytest

from guided_lfd.benchmark import household
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.space import Semantics
from guided_lfd.pddl.reader import parse_task


def _write(tmp_path, house: household.House) -> tuple[str, str]:
    dom = tmp_path / "robot.pddl"
    prob = tmp_path / f"{house.name}.pddl"
    dom.write_text(household.domain_pddl(house.variant))
    prob.write_text(household.problem_pddl(house))
    return str(dom), str(prob)


def test_generation_is_deterministic():
    house = household.House(4, 8, 2, 1, 2, "no-push")
    assert household.problem_pddl(house) == household.problem_pddl(house)
    assert household.domain_pddl("no-open") == household.domain_pddl("no-open")


def test_robot_variants_lack_their_skills():
    for variant, missing in household.VARIANTS.items():
        text = household.domain_pddl(variant)
        for name in household.ACTIONS:
            assert (f"(:action {name}\n" in text) == (name not in missing), (variant, name)


@pytest.mark.parametrize("variant,expected", [
    ("no-push", ["+(clear drawer1_1)", "+(clear drawer3_1)"]),
    ("no-open", ["+(open drawer1_1)", "+(open drawer3_1)"]),
    ("no-open-no-push", ["+(clear drawer1_1)", "+(clear drawer3_1)", "+(open drawer1_1)", "+(open drawer3_1)"]),
    ("no-door", ["+(open cupboard1_1)", "+(open cupboard3_1)"]),
])
@pytest.mark.parametrize("semantics", list(Semantics))
def test_small_house_has_the_intended_excuse(tmp_path, variant, expected, semantics):
    house = household.House(4, 8, 2, 1, 2, variant)
    domain, problem = parse_task(*_write(tmp_path, house))
    report = find_excuses(domain, problem, ExcuseOptions(semantics=semantics))
    assert report.status == "excuse-found"
    if semantics is Semantics.CONSISTENT:
        assert sorted(str(c) for c in report.excuse.changes) == expected
        assert report.excuse.plan_optimal and len(report.excuse.plan) == 2 * house.goals
    else:
        # Literal: a goal item may simply appear in its container ('+(inside
        # plate1 drawer1_1)'), so the excuse can be smaller than the intended one.
        assert 1 <= report.excuse.size <= len(expected)


def test_impossible_houses_are_refused():
    with pytest.raises(ValueError, match="goals need at least as many items"):
        household.problem_pddl(household.House(1, 1, 2, 0, 2))
    with pytest.raises(ValueError, match="unknown variant"):
        household.problem_pddl(household.House(1, 2, 2, 0, 1, "no-legs"))
    with pytest.raises(ValueError, match="goal containers"):
        household.problem_pddl(household.House(1, 4, 1, 0, 2, "no-push"))
