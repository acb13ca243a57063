"""Render the BYO corpus' demonstrations once, as teach --simulate renders them (issue #23).

    python tests/data/byo/render.py        # writes <domain>/demo-round-N.csv and .state.csv

For every domain, ``guided_lfd.teach.teach`` runs on ``robot.pddl`` and
``problem.pddl`` with the human model simulating the demonstrator; each
round's rendered trace and state file are kept beside the domain, so the same
demonstrations can go through ``segment | learn-domain --prior robot.pddl |
merge`` (tests/test_byo.py checks both ways give the same skills).
Deterministic: the renderer's noise is seeded.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2]))


def render_domain(folder: Path, out: Path) -> list[Path]:
    """Teach ``folder``'s robot with its human simulated; copy each round's trace into ``out``; the traces."""
    from guided_lfd.pddl.reader import parse_domain, parse_task
    from guided_lfd.teach import SimulatedHuman, teach

    robot, problem = parse_task(str(folder / "robot.pddl"), str(folder / "problem.pddl"))
    human = parse_domain(str(folder / "human.pddl"))
    written = []
    with tempfile.TemporaryDirectory() as tmp:
        session = teach(robot, problem, SimulatedHuman(human, robot=robot), Path(tmp) / "session", human=human)
        for rnd in session.rounds:
            trace = out / f"demo-round-{rnd.index}.csv"
            shutil.copyfile(rnd.files["trace"], trace)
            shutil.copyfile(rnd.files["state"], out / f"demo-round-{rnd.index}.state.csv")
            written.append(trace)
    return written


def main() -> int:
    """Render every domain's demonstrations beside it."""
    for folder in sorted(p for p in HERE.iterdir() if (p / "robot.pddl").is_file()):
        for trace in render_domain(folder, folder):
            print(trace.relative_to(HERE))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
