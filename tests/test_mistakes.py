"""The fallible simulated teacher (guided_lfd.teach.mistakes): each kind of mistake, its SPEC, its seed."""

from __future__ import annotations

import random
from dataclasses import replace

import pytest

from guided_lfd.errors import OptionError
from guided_lfd.evaluate import excuse_goal, optimal_plan
from guided_lfd.excuse.change import Change
from guided_lfd.pddl.model import Atom
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning.validation import PlanStep, validate_plan
from guided_lfd.teach.mistakes import MISTAKE_KINDS, Mistakes, make_mistake

BYO = "tests/data/byo/blocksworld"


@pytest.fixture(scope="module")
def blocks():
    """The blocks world's human and its larger task (towers of 2-4 blocks, a loose one)."""
    human, problem = parse_task(f"{BYO}/human.pddl", f"{BYO}/problem-large.pddl")
    return human, problem


def _request(problem, *atoms: str) -> list[Change]:
    return [Change(Atom(a.split()[0], tuple(a.split()[1:])), True) for a in atoms]


def _runs(human, problem, plan: list[PlanStep]) -> bool:
    return validate_plan(human, problem.init, (), plan).valid


def test_a_spec_gives_rates_per_kind_and_any_spreads_evenly():
    assert Mistakes.parse("partial=0.1,wrong-object=10%").rates == {"partial": 0.1, "wrong-object": 0.1}
    assert Mistakes.parse("any=25%").rates == {kind: pytest.approx(0.05) for kind in MISTAKE_KINDS}


@pytest.mark.parametrize("spec, message", [
    ("foo=1", "unknown kind 'foo'"),
    ("partial", "expected KIND=RATE"),
    ("partial=0.7,misread=0.5", "the rates sum to 1.2, expected at most 1"),
])
def test_a_bad_spec_is_refused_naming_what_was_expected(spec, message):
    with pytest.raises(OptionError, match=message):
        Mistakes.parse(spec)


def test_draws_follow_the_rates_for_a_seed():
    rng = random.Random(7)
    draws = [Mistakes.parse("partial=0.5").draw(rng) for _ in range(2000)]
    assert 900 < draws.count("partial") < 1100 and set(draws) == {"partial", None}
    assert Mistakes.parse("partial=0").draw(random.Random(1)) is None


def test_each_mistake_is_a_plan_the_human_can_carry_out_and_not_the_plan(blocks):
    human, problem = blocks
    found = {}
    for seed in range(40):
        for request in (_request(problem, "ontable block-a3", "ontable block-b2"),
                        _request(problem, "holding block-a2")):
            plan = optimal_plan(human, problem, goal=excuse_goal(request))
            for kind in MISTAKE_KINDS:
                wrong = make_mistake(kind, plan, human, problem, request, random.Random(seed))
                if wrong is not None:
                    assert wrong != plan and _runs(human, problem, wrong), (kind, wrong)
                    found.setdefault(kind, wrong)
    assert set(found) == set(MISTAKE_KINDS), found


def test_partial_stops_halfway_and_extra_steps_go_on(blocks):
    human, problem = blocks
    request = _request(problem, "holding block-a2")
    plan = optimal_plan(human, problem, goal=excuse_goal(request))
    assert make_mistake("partial", plan, human, problem, request, random.Random(0)) == plan[: len(plan) // 2]
    extra = make_mistake("extra-steps", plan, human, problem, request, random.Random(0))
    assert extra[: len(plan)] == plan and 1 <= len(extra) - len(plan) <= 2


def test_a_one_step_plan_cannot_be_halved(blocks):
    human, problem = blocks
    one = [PlanStep("unstack", ("block-a3", "block-a2"))]
    assert make_mistake("partial", one, human, replace(problem), [], random.Random(0)) is None


def test_the_teachers_mistakes_are_the_same_for_the_same_seed(runner, app, tmp_path):
    def run(folder):
        result = runner.invoke(app, ["teach", f"{BYO}/robot.pddl", f"{BYO}/problem-large.pddl", "--simulate",
                                     f"{BYO}/human.pddl", "-o", str(tmp_path / folder), "--mistakes", "any=100%",
                                     "--seed", "3", "--json", "-q"])
        return result.stdout

    assert run("a").replace(str(tmp_path / "a"), "") == run("b").replace(str(tmp_path / "b"), "")


def test_mistakes_without_the_simulated_teacher_are_refused(runner, app, tmp_path):
    result = runner.invoke(app, ["teach", f"{BYO}/robot.pddl", f"{BYO}/problem.pddl", "--mistakes", "any=10%",
                                 "-o", str(tmp_path / "s")])
    assert result.exit_code == 37 and "--mistakes: needs the simulated teacher (--simulate HUMAN)" in result.stderr


def test_a_skill_shown_between_pieces_of_furniture_keeps_the_robots_types(runner, app, tmp_path):
    """Kitchen II, seed 0 at 50 %: the teacher pushes the chair three times (drawer, corner, table); the learned
    move_chair's rooms are furniture, as the robot declares them, so its domain reads back (it was 'object')."""
    result = runner.invoke(app, ["teach", "data/domains/kitchen-2/robot.pddl", "data/domains/kitchen-2/problem.pddl",
                                 "--simulate", "data/domains/kitchen-2/human.pddl", "-o", str(tmp_path / "s"),
                                 "--mistakes", "any=50%", "--seed", "0", "-q"])
    assert result.exit_code == 0, result.output
    from guided_lfd.pddl.reader import parse_domain

    move = parse_domain(tmp_path / "s" / "robot.pddl").action("move_chair")
    assert dict(move.params) == {"?c": "obstacle", "?from": "furniture", "?to": "furniture"}


NOISY = "loss=2,regrasp=0.28,grip=0.14,drops=0.1,duplicates=0.02,bursts=0.01,jitter=0.002"


def test_a_change_after_the_traces_last_frame_still_happened(runner, app, tmp_path):
    """tools, seed 19, 50 % mistakes, a noisy tracker: round 1 stops holding the wrong wrench, its last frames
    lost before the state file records the wrench leaving the bench; round 2 must start with the wrench off the
    bench (it started on it and in the hand, and learned a put_wrench that needs it on the bench)."""
    tools = "tests/data/byo/tools"
    result = runner.invoke(app, ["teach", f"{tools}/robot.pddl", f"{tools}/problem.pddl", "--simulate",
                                 f"{tools}/human.pddl", "-o", str(tmp_path / "s"), "--mistakes", "any=50%",
                                 "--trace-noise", NOISY, "--seed", "19", "-q"])
    assert result.exit_code == 0, result.output
    from guided_lfd.pddl.reader import parse_domain

    learned = {a.name for a in parse_domain(tmp_path / "s" / "robot.pddl").actions}
    assert learned == {a.name for a in parse_domain(f"{tools}/human.pddl").actions}


def test_trace_noise_is_refused_in_one_line_when_its_spec_is_wrong(runner, app, tmp_path):
    result = runner.invoke(app, ["teach", f"{BYO}/robot.pddl", f"{BYO}/problem.pddl", "--simulate",
                                 f"{BYO}/human.pddl", "--trace-noise", "loss=2,foo=1", "-o", str(tmp_path / "s")])
    assert result.exit_code == 37
    assert "--trace-noise: 'foo=1': expected KEY=VALUE with KEY one of loss, regrasp, grip" in result.stderr


def test_the_tracker_events_draw_from_their_own_stream_so_a_clean_trace_is_unchanged():
    from guided_lfd.demonstration.render import Noise

    assert not Noise().tracker and Noise.parse("loss=2", seed=3).tracker
    assert Noise.parse("drops=0.1,jitter=0.002", seed=4) == Noise(seed=4, drop_rate=0.1, jitter_s=0.002)


@pytest.mark.parametrize("option, spec, message", [
    ("--mistakes", "", "--mistakes '': expected KIND=RATE[,KIND=RATE...] (nothing given)"),
    ("--trace-noise", "", "--trace-noise: expected KEY=VALUE[,...]: nothing given"),
    ("--trace-noise", "loss=-1", "--trace-noise: 'loss=-1': expected a number >= 0 for loss"),
])
def test_an_empty_or_negative_noise_or_mistake_spec_is_refused(runner, app, tmp_path, option, spec, message):
    result = runner.invoke(app, ["teach", f"{BYO}/robot.pddl", f"{BYO}/problem.pddl", "--simulate",
                                 f"{BYO}/human.pddl", option, spec, "-o", str(tmp_path / "s")])
    assert result.exit_code == 37 and message in result.stderr, result.output


def test_a_tiny_rate_in_scientific_notation_is_a_rate():
    assert Mistakes.parse("partial=1e-3").rates == {"partial": 0.001}
