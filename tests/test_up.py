"""guided-lfd from unified-planning (the extra ``up``): the engines through UP's factory, the excuse in UP's terms.

Problems come from UP code (the rover world of ``examples/up_excuse.py``:
rooms, doors and a wall switch, no hand) and from the shipped kitchens
through UP's own PDDL reader. The excuse of a UP problem must be the one
guided-lfd finds on the PDDL files, mapped to the problem's fluents and
actions; plans are also checked by UP's own sequential plan validator.
"""

from __future__ import annotations

import runpy
import subprocess
import sys
from fractions import Fraction

import pytest

pytest.importorskip("unified_planning")

from unified_planning.engines import (  # noqa: E402
    FailedValidationReason, PlanGenerationResultStatus as Status, ValidationResultStatus,
)
from unified_planning.environment import Environment  # noqa: E402
from unified_planning.exceptions import UPUsageError  # noqa: E402
from unified_planning.io import PDDLReader  # noqa: E402
from unified_planning.plans import ActionInstance, SequentialPlan  # noqa: E402
from unified_planning.shortcuts import (  # noqa: E402
    GE, DurativeAction, Fluent, MinimizeActionCosts, MinimizeSequentialPlanLength, Not, OneshotPlanner, PlanValidator, RealType,
    get_environment,
)

from conftest import DATA, ROOT, fresh_interpreter, kitchen  # noqa: E402
from guided_lfd import ExcuseOptions, find_excuses, plan, read_task  # noqa: E402
from guided_lfd.errors import OptionError, UnsupportedFeatureError  # noqa: E402
from guided_lfd.up import GuidedLfdPlanner, GuidedLfdValidator, find_up_excuses, register, to_task  # noqa: E402

EXAMPLE = ROOT / "examples" / "up_excuse.py"
rover_world = runpy.run_path(str(EXAMPLE))["rover_world"]
PLANNER, VALIDATOR = "guided-lfd", "guided-lfd-validator"


@pytest.fixture(scope="module", autouse=True)
def engines():
    """guided-lfd's engines in UP's global factory, added as a UP user adds any engine."""
    environment = get_environment()
    environment.credits_stream = None
    factory = environment.factory
    for name, cls in ((PLANNER, "GuidedLfdPlanner"), (VALIDATOR, "GuidedLfdValidator")):
        if name not in factory.engines:
            factory.add_engine(name, "guided_lfd.up", cls)


def solve(problem, **kwargs):
    with OneshotPlanner(name=PLANNER) as planner:
        return planner.solve(problem, **kwargs)


def check(problem, plan_, name: str = VALIDATOR):
    with PlanValidator(name=name) as validator:
        return validator.validate(problem, plan_)


def read_up(domain: str, problem: str):
    return PDDLReader().parse_problem(domain, problem)


def named(plan_: SequentialPlan) -> list[tuple[str, tuple[str, ...]]]:
    return [(a.action.name, tuple(p.object().name for p in a.actual_parameters)) for a in plan_.actions]


def test_the_example_runs_and_prints_the_excuse():
    done = subprocess.run([sys.executable, str(EXAMPLE)], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [
        "robot: UNSOLVABLE_PROVEN",
        "with press: SOLVED_OPTIMALLY ['drive(Door B, Base, Hall)', 'press(Wall Switch, Hall, Door A)', "
        "'drive(Door A, Hall, Lab)']",
        "excuse: excuse-found add ['door_open(Door A)'] remove []",
        "robot's plan from there: ['drive(Door B, Base, Hall)', 'drive(Door A, Hall, Lab)']",
        "from the excuse state: VALID",
        "from PDDL text: excuse-found ['+(door_open door_a)']",
    ]


def test_the_planner_proves_unsolvable_and_plans_optimally_on_a_problem_built_in_up():
    robot, human = rover_world(can_press=False), rover_world(can_press=True)
    assert GuidedLfdPlanner.supports(robot.kind) and GuidedLfdPlanner.supports(human.kind)
    assert solve(robot).status == Status.UNSOLVABLE_PROVEN
    result = solve(human)
    assert result.status == Status.SOLVED_OPTIMALLY and result.engine_name == PLANNER
    assert named(result.plan) == [("drive", ("Door B", "Base", "Hall")), ("press", ("Wall Switch", "Hall", "Door A")),
                                  ("drive", ("Door A", "Hall", "Lab"))]
    assert result.plan.actions[0].action == human.action("drive")  # the problem's own action and objects
    assert result.plan.actions[0].actual_parameters[0].object() == human.object("Door B")
    assert check(human, result.plan).status == ValidationResultStatus.VALID
    assert check(human, result.plan, "sequential_plan_validator").status == ValidationResultStatus.VALID


@pytest.mark.parametrize("who, status", [("robot", Status.UNSOLVABLE_PROVEN), ("human", Status.SOLVED_OPTIMALLY)])
def test_the_planner_on_a_shipped_kitchen_read_by_ups_pddl_reader(who, status):
    files = kitchen(1, who)
    result = solve(read_up(*files))
    assert result.status == status
    if status == Status.SOLVED_OPTIMALLY:
        report = plan(*read_task(*files))
        assert named(result.plan) == [(s.action, s.args) for s in report.plan]
        assert result.metrics["cost"] == str(report.cost) == "3"


@pytest.mark.filterwarnings("ignore:We cannot establish whether sequential_plan_validator")  # undefined costs
def test_action_costs_give_the_cheapest_plan_and_the_validator_its_cost():
    problem = read_up(str(DATA / "costs" / "domain.pddl"), str(DATA / "costs" / "problem.pddl"))
    result = solve(problem)
    assert result.status == Status.SOLVED_OPTIMALLY
    assert named(result.plan) == [("drive", ("home", "mid1")), ("drive", ("mid1", "mid2")), ("drive", ("mid2", "shop"))]
    ours, ups = check(problem, result.plan), check(problem, result.plan, "sequential_plan_validator")
    assert ours.status == ups.status == ValidationResultStatus.VALID
    assert list(ours.metric_evaluations.values()) == [15] == list(ups.metric_evaluations.values())
    problem.clear_quality_metrics()
    problem.add_quality_metric(MinimizeSequentialPlanLength())
    assert list(check(problem, result.plan).metric_evaluations.values()) == [3]
    assert named(solve(problem).plan) == [("drive", ("home", "shop"))]


def test_the_validator_rejects_an_invalid_plan_naming_the_step_or_the_goal():
    human = rover_world(can_press=True)
    drive, press = human.action("drive"), human.action("press")
    base, hall, lab, door_a, door_b = (human.object(n) for n in ("Base", "Hall", "Lab", "Door A", "Door B"))
    skipped_press = SequentialPlan([ActionInstance(drive, (door_b, base, hall)), ActionInstance(drive, (door_a, hall, lab))])
    result = check(human, skipped_press)
    assert result.status == ValidationResultStatus.INVALID
    assert result.reason == FailedValidationReason.INAPPLICABLE_ACTION
    assert result.inapplicable_action is skipped_press.actions[1]
    assert result.log_messages[0].message == ("step 2 drive(Door A, Hall, Lab) is not applicable: "
                                              "precondition door_open(Door A) does not hold")
    assert check(human, skipped_press, "sequential_plan_validator").status == ValidationResultStatus.INVALID
    stops_early = SequentialPlan([ActionInstance(drive, (door_b, base, hall)),
                                  ActionInstance(press, (human.object("Wall Switch"), hall, door_a))])
    result = check(human, stops_early)
    assert (result.status, result.reason) == (ValidationResultStatus.INVALID, FailedValidationReason.UNSATISFIED_GOALS)
    assert "roverAt(Lab) does not hold" in result.log_messages[0].message


def test_a_step_of_another_problems_action_is_invalid():
    kitchen_problem = read_up(*kitchen(1, "human"))
    foreign = solve(kitchen_problem).plan
    result = check(rover_world(can_press=True), foreign)
    assert result.status == ValidationResultStatus.INVALID and result.inapplicable_action is foreign.actions[0]
    assert result.reason == FailedValidationReason.INAPPLICABLE_ACTION
    assert "unknown action 'open_drawer'" in result.log_messages[0].message


def numeric_world():
    """The rover world with a battery that each drive drains: a numeric fluent."""
    problem = rover_world(can_press=True)
    battery = Fluent("battery", RealType())
    problem.add_fluent(battery, default_initial_value=10)
    problem.action("drive").add_precondition(GE(battery, 1))
    problem.action("drive").add_decrease_effect(battery, 1)
    return problem


def durative_world():
    """The rover world with a drive that takes time: a durative action."""
    problem = rover_world(can_press=True)
    wait = DurativeAction("wait")
    wait.set_fixed_duration(5)
    problem.add_action(wait)
    return problem


@pytest.mark.parametrize("make, feature", [(numeric_world, "NUMERIC"), (durative_world, "CONTINUOUS_TIME")])
def test_unsupported_kinds_are_refused_by_supports_and_the_engines(make, feature):
    problem = make()
    assert not GuidedLfdPlanner.supports(problem.kind) and not GuidedLfdValidator.supports(problem.kind)
    with pytest.warns(UserWarning, match="cannot establish"):  # UP's own kind check, which the name overrides
        result = solve(problem)
    assert result.status == Status.UNSUPPORTED_PROBLEM and result.plan is None
    assert feature in result.log_messages[0].message
    plan_ = solve(rover_world(can_press=True)).plan
    with pytest.warns(UserWarning, match="cannot establish"):
        assert check(problem, plan_).status == ValidationResultStatus.UNKNOWN
    with pytest.raises(UnsupportedFeatureError, match=feature) as info:
        find_up_excuses(problem)
    assert info.value.exit_code == 33


def test_a_fractional_cost_passes_the_kind_check_and_is_refused_when_read():
    problem = rover_world(can_press=True)
    problem.add_quality_metric(MinimizeActionCosts({problem.action("drive"): Fraction(5, 2),
                                                    problem.action("press"): 1}))
    assert GuidedLfdPlanner.supports(problem.kind)
    result = solve(problem)
    assert result.status == Status.UNSUPPORTED_PROBLEM and "2.5" in result.log_messages[0].message


def test_a_past_deadline_is_a_timeout():
    assert solve(rover_world(can_press=True), timeout=1e-9).status == Status.TIMEOUT
    # The excuse's time limit counts from the call: reading the problem already uses it up.
    report = find_up_excuses(rover_world(can_press=False), ExcuseOptions(time_limit=1e-9))
    assert report.status == "timeout" and report.excuses == []


def test_a_task_too_large_to_ground_is_a_memout_and_a_failure_an_internal_error(monkeypatch):
    monkeypatch.setattr("guided_lfd.planning.grounding.MAX_GROUND_ACTIONS", 0)
    result = solve(rover_world(can_press=True))
    assert result.status == Status.MEMOUT and "ground actions" in result.log_messages[0].message
    monkeypatch.undo()

    def broken(*args, **kwargs):
        raise RuntimeError("planner and validator disagree on the plan's cost")

    monkeypatch.setattr("guided_lfd.up.engines.plan", broken)
    result = solve(rover_world(can_press=True))
    assert result.status == Status.INTERNAL_ERROR and "disagree" in result.log_messages[0].message


def test_engines_take_no_options_and_register_adds_each_once():
    with pytest.raises(UPUsageError, match="search"):
        OneshotPlanner(name=PLANNER, params={"search": "bfs"})
    register()
    register()
    factory = get_environment().factory
    assert factory.engines.count(PLANNER) == 1 and factory.engines.count(VALIDATOR) == 1
    other = Environment()
    register(other, planner="mine")
    assert "mine" in other.factory.engines and "mine" not in factory.engines


@pytest.mark.parametrize("n", [1, 2])
def test_the_excuse_of_a_up_problem_is_the_excuse_of_the_pddl_files(n):
    files = kitchen(n)
    problem = read_up(*files)
    expected = find_excuses(*read_task(*files))
    report = find_up_excuses(problem)
    assert report.status == expected.status == "excuse-found"
    excuse, want = report.excuse, expected.excuse
    as_up = {c: problem.fluent(c.atom.predicate)(*(problem.object(a) for a in c.atom.args)) for c in want.changes}
    assert excuse.added == [as_up[c] for c in want.changes if c.added]
    assert excuse.removed == [as_up[c] for c in want.changes if not c.added]
    assert excuse.size == want.size and excuse.cost == want.cost and excuse.plan_cost == want.plan_cost
    assert named(excuse.plan) == [(s.action, s.args) for s in want.plan]
    excused = excuse.excuse_problem()
    assert check(excused, excuse.plan, "sequential_plan_validator").status == ValidationResultStatus.VALID
    assert check(problem, excuse.plan).status == ValidationResultStatus.INVALID  # not from the initial state


def test_the_excuse_maps_renamed_names_back_to_the_up_objects():
    robot = rover_world(can_press=False)
    report = find_up_excuses(robot, fixed=[robot.fluent("connects")])
    assert report.excuse.added == [robot.fluent("door_open")(robot.object("Door A"))]
    assert report.task.pddl_name(robot.object("Door A")) == "door_a" and report.task.item("door_a") is robot.object("Door A")
    assert "(door_open door_a)" in report.to_json()  # guided-lfd's document, in the PDDL names
    # Without it, which doors connect which rooms is the world's structure, held fixed by default (#28) ...
    assert find_up_excuses(robot).excuse.added == [robot.fluent("door_open")(robot.object("Door A"))]
    # ... and with the structure changeable, a new connection is an excuse as small (one of the minimal ones).
    free = find_up_excuses(robot, ExcuseOptions(change_structure=True, all_minimal=True))
    connection = robot.fluent("connects")(*(robot.object(n) for n in ("Door B", "Base", "Lab")))
    assert [connection] in [e.added for e in free.excuses] and {e.size for e in free.report.excuses} == {1}


def test_an_excuse_that_removes_a_fact():
    robot = rover_world(can_press=False)
    locked = Fluent("locked", d=robot.user_type("Door"))
    robot.add_fluent(locked, default_initial_value=False)
    robot.action("drive").add_precondition(Not(locked(robot.action("drive").parameter("d"))))
    door_a = robot.object("Door A")
    robot.set_initial_value(robot.fluent("door_open")(door_a), True)
    robot.set_initial_value(locked(door_a), True)
    report = find_up_excuses(robot, fixed=[robot.fluent("connects")])
    assert (report.excuse.added, report.excuse.removed) == ([], [locked(door_a)])
    assert [str(c) for c in report.report.excuse.changes] == ["-(locked door_a)"]


def test_a_solvable_problem_needs_no_excuse_and_gets_the_robots_plan():
    report = find_up_excuses(rover_world(can_press=True))
    assert report.status == "already-solvable" and report.excuse is None
    assert [a.action.name for a in report.robot_plan.actions] == ["drive", "press", "drive"]


def test_fixed_must_be_fluents_of_the_problem():
    other = rover_world(can_press=True)
    other_fluent = Fluent("elsewhere")
    with pytest.raises(OptionError, match="elsewhere"):
        find_up_excuses(other, fixed=[other_fluent])
    with pytest.raises(OptionError):
        find_up_excuses(other, ExcuseOptions(semantics="no such"))


@pytest.mark.parametrize("problem", [None, "kitchen.pddl", 3])
def test_something_other_than_a_up_problem_is_the_librarys_option_error(problem):
    """It was Python's TypeError, which the library documents only for an unknown keyword argument."""
    with pytest.raises(OptionError, match=f"problem {type(problem).__name__}: expected a unified-planning Problem"):
        find_up_excuses(problem)
    with pytest.raises(OptionError):
        to_task(problem)


def test_read_task_takes_a_up_problem_alone():
    files = kitchen(1)
    domain, problem = read_task(read_up(*files))
    want_domain, want_problem = read_task(*files)
    assert domain.actions == want_domain.actions and domain.predicates == want_domain.predicates
    assert (problem.objects, problem.init, problem.goal) == (want_problem.objects, want_problem.init, want_problem.goal)
    assert to_task(read_up(*files)).problem.init == want_problem.init
    with pytest.raises(OptionError, match="alone"):
        read_task(read_up(*files), files[1])
    with pytest.raises(OptionError, match="bytes"):
        read_task(b"(define (domain d))", files[1])  # type: ignore[arg-type]
    with pytest.raises(OptionError, match="needs its problem"):
        read_task(files[0])


def test_guided_lfd_runs_without_unified_planning_and_names_the_extra():
    out = fresh_interpreter(
        "import sys; sys.modules['unified_planning'] = None\n"
        "import guided_lfd\n"
        f"guided_lfd.find_excuses(*guided_lfd.read_task({kitchen(1)[0]!r}, {kitchen(1)[1]!r}))\n"
        "try:\n    import guided_lfd.up\nexcept ModuleNotFoundError as exc:\n    print(exc)\n")
    assert out.strip() == "guided_lfd.up needs unified-planning: pip install 'guided-lfd[up]'"
