"""Ask guided-lfd, from unified-planning, what a robot needs demonstrated (no ROS install needed).

A rover drives between rooms through doors. A door opens with the switch
beside it, but this rover cannot press switches: it has no skill for it. The
problem is built in unified-planning (UP) code, as a UP program or a UP4ROS2
node holds it; guided-lfd's planner proves the rover cannot reach the lab, and
its excuse says what a human must demonstrate: open the lab's door. The same
task as PDDL text, as PlanSys2's domain and problem experts give it, gets the
same excuse from guided-lfd's plain reader.

    python examples/up_excuse.py        # needs the extra: pip install 'guided-lfd[up]'
"""

from __future__ import annotations

from unified_planning.io import PDDLWriter
from unified_planning.shortcuts import (
    BoolType, Equals, Fluent, InstantaneousAction, Not, Object, OneshotPlanner, PlanValidator, Problem, UserType,
    get_environment,
)

from guided_lfd import ExcuseOptions, find_excuses, read_task
from guided_lfd.up import find_up_excuses, register


def rover_world(can_press: bool) -> Problem:
    """Base -(Door B, open)- Hall -(Door A, closed; its switch in the hall)- Lab; the goal: the rover in the lab."""
    room, door, switch = UserType("Room"), UserType("Door"), UserType("Switch")
    rover_at = Fluent("roverAt", BoolType(), r=room)
    connects = Fluent("connects", BoolType(), d=door, a=room, b=room)
    door_open = Fluent("door_open", BoolType(), d=door)
    switch_in = Fluent("switch_in", BoolType(), s=switch, r=room)
    controls = Fluent("controls", BoolType(), s=switch, d=door)

    drive = InstantaneousAction("drive", d=door, a=room, b=room)
    d, a, b = drive.parameters
    for condition in (rover_at(a), connects(d, a, b), door_open(d), Not(Equals(a, b))):
        drive.add_precondition(condition)
    drive.add_effect(rover_at(b), True)
    drive.add_effect(rover_at(a), False)
    press = InstantaneousAction("press", s=switch, r=room, d=door)
    s, r, d = press.parameters
    for condition in (rover_at(r), switch_in(s, r), controls(s, d), Not(door_open(d))):
        press.add_precondition(condition)
    press.add_effect(door_open(d), True)

    problem = Problem("rover-lab" if can_press else "rover-lab-no-switches")
    for fluent in (rover_at, connects, door_open, switch_in, controls):
        problem.add_fluent(fluent, default_initial_value=False)
    problem.add_action(drive)
    if can_press:
        problem.add_action(press)
    base, hall, lab = Object("Base", room), Object("Hall", room), Object("Lab", room)
    door_a, door_b, wall_switch = Object("Door A", door), Object("Door B", door), Object("Wall Switch", switch)
    problem.add_objects([base, hall, lab, door_a, door_b, wall_switch])
    for fact in (rover_at(base), door_open(door_b), switch_in(wall_switch, hall), controls(wall_switch, door_a)):
        problem.set_initial_value(fact, True)
    for x, y, via in ((base, hall, door_b), (hall, base, door_b), (hall, lab, door_a), (lab, hall, door_a)):
        problem.set_initial_value(connects(via, x, y), True)
    problem.add_goal(rover_at(lab))
    return problem


def main() -> None:
    """Plan, find the excuse, and check its plan, all from UP; then the same from PDDL text."""
    get_environment().credits_stream = None  # UP prints each engine's credits otherwise
    register()  # "guided-lfd" (OneshotPlanner) and "guided-lfd-validator" (PlanValidator)
    robot = rover_world(can_press=False)
    with OneshotPlanner(name="guided-lfd") as planner:
        print("robot:", planner.solve(robot).status.name)
        result = planner.solve(rover_world(can_press=True))
        print("with press:", result.status.name, [str(a) for a in result.plan.actions])

    # Which doors connect which rooms is no one's to change: no excuse may change it.
    report = find_up_excuses(robot, fixed=[robot.fluent("connects")])
    excuse = report.excuse
    print("excuse:", report.status, "add", [str(f) for f in excuse.added], "remove", [str(f) for f in excuse.removed])
    print("robot's plan from there:", [str(a) for a in excuse.plan.actions])
    with PlanValidator(name="guided-lfd-validator") as validator:
        print("from the excuse state:", validator.validate(excuse.excuse_problem(), excuse.plan).status.name)

    # PlanSys2's experts give the domain and the problem as PDDL text; so does UP's writer here.
    writer = PDDLWriter(robot)
    domain_text, problem_text = writer.get_domain(), writer.get_problem()
    pddl_report = find_excuses(*read_task(domain_text, problem_text), ExcuseOptions(fixed=["connects"]))
    print("from PDDL text:", pddl_report.status, [str(c) for c in pddl_report.excuse.changes])


if __name__ == "__main__":
    main()
