"""Render the demonstrations that go wrong (issue #52) once, as teach --simulate renders them.

    python tests/data/teach/checks/render.py     # writes <name>.csv and <name>.state.csv here

Each is the fetch human's (tests/data/byo/fetch/human.pddl) shortest plan from problem.pddl's initial state to
another goal than the request (Cabinet-open upper-cabinet) asks for; inconsistent.csv is close-lower's trace with
its state file changed by hand below (the red cup leaves the cabinet as the door closes);
kitchen-blue-drawer.csv is Kitchen I's human opening BlueDrawer where Open PinkDrawer is asked for.  Deterministic: the
renderer's noise is seeded.
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[3]))

#: name -> the goal the demonstrator reaches instead of the request.
DEMONSTRATIONS = {
    "wrong-object": ["+(cabinet-open side-cabinet)"],  # the side cabinet, not the upper one
    "close-lower": ["-(cabinet-open lower-cabinet)"],  # nothing asked for: the lower cabinet closed
    "kept-fact-changed": ["+(cabinet-open upper-cabinet)", "+(in blue-cup lower-cabinet)"],  # the cup moved too
    # The cup shut away in the side cabinet: the request holds, the robot cannot reach the cup (misdirected).
    "cup-shut-away": ["+(cabinet-open upper-cabinet)", "+(in blue-cup side-cabinet)", "-(cabinet-open side-cabinet)"],
    "open-upper": ["+(cabinet-open upper-cabinet)"],  # the request (part of problem-close-lower's)
}


def main() -> None:
    import shutil

    from guided_lfd.excuse.change import Change
    from guided_lfd.pddl.model import Atom
    from guided_lfd.pddl.reader import parse_domain, parse_task
    from guided_lfd.teach import SimulatedHuman

    fetch = HERE.parents[1] / "byo" / "fetch"
    robot, problem = parse_task(str(fetch / "robot.pddl"), str(HERE / "problem.pddl"))
    human = SimulatedHuman(parse_domain(str(fetch / "human.pddl")), robot=robot)
    for name, goal in DEMONSTRATIONS.items():
        request = [Change(Atom(g[2:-1].split()[0], tuple(g[2:-1].split()[1:])), g[0] == "+") for g in goal]
        with tempfile.TemporaryDirectory() as tmp:
            trace, states = human.demonstrate(Path(tmp), problem.init, request, problem)
            shutil.copyfile(trace, HERE / f"{name}.csv")
            shutil.copyfile(states, HERE / f"{name}.state.csv")
    # Kitchen I (the paper's): BlueDrawer opened where PinkDrawer was asked for.
    kitchen = HERE.parents[3] / "data" / "domains" / "kitchen-1"
    robot, problem = parse_task(str(kitchen / "robot.pddl"), str(kitchen / "problem.pddl"))
    human = SimulatedHuman(parse_domain(str(kitchen / "human.pddl")), robot=robot)
    with tempfile.TemporaryDirectory() as tmp:
        trace, states = human.demonstrate(Path(tmp), problem.init, [Change(Atom("open", ("bluedrawer",)), True)],
                                          problem)
        shutil.copyfile(trace, HERE / "kitchen-blue-drawer.csv")
        shutil.copyfile(states, HERE / "kitchen-blue-drawer.state.csv")
    # The lower cabinet's door closes and the red cup is on the counter at that moment: a close-cabinet that
    # also moves a cup, which neither the robot's close-cabinet nor the human's does.
    shutil.copyfile(HERE / "close-lower.csv", HERE / "inconsistent.csv")
    lines = (HERE / "close-lower.state.csv").read_text().splitlines()
    when = next(line.split(",")[0] for line in lines if line.startswith(tuple("123456789")) and "cabinet-open" in line)
    lines += [f'{when},"in(red-cup,lower-cabinet)",false', f"{when},on-counter(red-cup),true"]
    (HERE / "inconsistent.state.csv").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
