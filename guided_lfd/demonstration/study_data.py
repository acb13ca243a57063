"""Rendering the study's demonstrations (Kitchen I/II x demonstrators P1-P5).

The paper's VR recordings are not public.  These stand-ins are *rendered*:
for each kitchen and demonstrator, the human's plan to the minimal excuse
(excuse demonstration) or to the goal (complete demonstration) is found with
the planner on ``human.pddl``, padded with redundant skills (closing and
re-opening a drawer, pushing the chair away and back, opening another
drawer) until it has the number of demonstrated actions the paper observed
(Table II, O columns), and rendered over the demonstration time the paper
measured (Table I).  P3's complete demonstrations used both hands at once,
which the paper's LfD tool could not process; they are rendered that way: the
left hand fetches the plate while the right hand prepares the drawer.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

from guided_lfd.demonstration.render import Noise, Scene, Step, render, schedule, script_for_plan
from guided_lfd.pddl.model import Atom, Literal
from guided_lfd.pddl.reader import parse_task
from guided_lfd.symbolic.portfolio import plan_task
from guided_lfd.planning.validation import PlanStep, validate_plan

DEMONSTRATORS = ("P1", "P2", "P3", "P4", "P5")
#: Table I: demonstration time in seconds (excuse, complete) per kitchen.
TABLE_I = {
    "kitchen-1": {"excuse": (3.71, 8.77, 4.38, 8.19, 4.4), "complete": (9.64, 30.65, 10.87, 15.57, 13.94)},
    "kitchen-2": {"excuse": (5.09, 12.25, 6.81, 4.48, 5.87), "complete": (15.0, 36.3, 16.29, 16.03, 9.54)},
}
#: Table II, O columns: observed demonstration size (None: not processable).
TABLE_II_OBSERVED = {
    "kitchen-1": {"excuse": (3, 7, 4, 3, 3), "complete": (9, 25, None, 12, 7)},
    "kitchen-2": {"excuse": (2, 4, 2, 2, 2), "complete": (9, 19, None, 10, 7)},
}
#: The minimal excuse of each kitchen (what the excuse demonstration reaches).
EXCUSE = {"kitchen-1": [Atom("open", ("pinkdrawer",))], "kitchen-2": [Atom("clear", ("pinkdrawer",))]}
#: Where the demonstrators leave things: the chair pushed away from PinkDrawer
#: goes into the corner, not in front of BlueDrawer (which the planner, caring
#: only for the goal, might choose, blocking the drawer the padding opens).
TIDY = {"kitchen-1": [], "kitchen-2": [Atom("blocking", ("chair", "corner"))]}
#: Redundant skills a demonstrator may add: (pair that undoes itself, single).
PADDING = {
    "kitchen-1": ([("close_drawer", ("pinkdrawer",)), ("open_drawer", ("pinkdrawer",))],
                  [("open_drawer", ("bluedrawer",))]),
    "kitchen-2": ([("move_chair", ("chair", "corner", "counter")), ("move_chair", ("chair", "counter", "corner"))],
                  [("open_drawer", ("bluedrawer",))]),
}
SCENE_POSITIONS = {
    "redplate": (0.5, 0.2, 0.8), "table": (0.5, 0.2, 0.75), "counter": (0.9, 0.2, 0.9),
    "pinkdrawer": (-0.1, 0.45, 0.6), "bluedrawer": (-0.4, 0.45, 0.6), "corner": (-1.0, -0.5, 0.5),
    "chair": (-0.1, 0.1, 0.5),
}


@dataclass
class RenderedDemo:
    """One rendered demonstration and what it was made from."""

    kitchen: str
    demonstrator: str
    kind: str  # excuse | complete
    plan: list[tuple[str, tuple[str, ...]]]
    files: dict[str, str]


def _plan_to(domain, problem, goal: list[Atom]) -> list[tuple[str, tuple[str, ...]]]:
    _, result = plan_task(domain, replace(problem, goal=tuple(Literal(a) for a in goal)))
    if result.plan is None:
        raise RuntimeError(f"the human cannot reach {goal}")
    return [(a.schema, a.args) for a in result.plan]


def padded_plan(kitchen: str, base: list[tuple[str, tuple[str, ...]]], size: int) -> list[tuple[str, tuple[str, ...]]]:
    """``base`` with redundant skills appended until it has ``size`` actions."""
    pair, single = PADDING[kitchen]
    extra = size - len(base)
    if extra < 0:
        raise ValueError(f"{size} actions are fewer than the {len(base)} the task needs")
    plan = list(base) + pair * (extra // 2)
    if extra % 2:
        plan += single
    return plan


def check_executable(plan: list[tuple[str, tuple[str, ...]]], domain, state: set[Atom]) -> None:
    """Raise ValueError unless every action of ``plan`` is applicable in turn from ``state``.

    The renderer writes whatever a script says; an inapplicable padding skill
    would show the chair teleporting and teach the learner wrong actions.
    """
    report = validate_plan(domain, frozenset(state), (), [PlanStep(name, args) for name, args in plan])
    failure = report.first_failure
    if failure is not None:
        raise ValueError(f"step {failure.index} {failure.step} is not applicable: "
                         f"{' '.join(str(l) for l in failure.failed)} does not hold")


def render_study(domains_root: Path, out_root: Path, rate_hz: float = 90.0) -> list[RenderedDemo]:
    """Render every demonstration of the study into ``out_root/<kitchen>/``."""
    out: list[RenderedDemo] = []
    for kitchen in ("kitchen-1", "kitchen-2"):
        human, problem = parse_task(domains_root / kitchen / "human.pddl", domains_root / kitchen / "problem.pddl")
        scene = Scene(positions=SCENE_POSITIONS, types=dict(problem.objects), spellings=problem.spellings)
        base = {"excuse": _plan_to(human, problem, EXCUSE[kitchen] + TIDY[kitchen]),
                "complete": _plan_to(human, problem, [l.atom for l in problem.goal] + TIDY[kitchen])}
        for kind in ("excuse", "complete"):
            for k, who in enumerate(DEMONSTRATORS):
                size = TABLE_II_OBSERVED[kitchen][kind][k]
                parallel = size is None
                plan = padded_plan(kitchen, base[kind], len(base[kind]) if parallel else size)
                check_executable(plan, human, set(problem.init))
                steps = script_for_plan(plan, human, set(problem.init))
                if parallel:
                    steps = _parallel(steps)
                steps = _scaled(steps, TABLE_I[kitchen][kind][k])
                seed = 1000 * (kitchen == "kitchen-2") + 100 * (kind == "complete") + k
                rendering = render(steps, scene, set(problem.init), rate_hz, Noise(seed=seed))
                folder = out_root / kitchen
                folder.mkdir(parents=True, exist_ok=True)
                stem = f"{who}-{kind}"
                files = {"trace": str(folder / f"{stem}.csv"), "state": str(folder / f"{stem}.state.csv"),
                         "labels": str(folder / f"{stem}.labels.csv")}
                Path(files["trace"]).write_text(rendering.trace_csv)
                Path(files["state"]).write_text(rendering.state_csv)
                Path(files["labels"]).write_text(rendering.labels_csv)
                out.append(RenderedDemo(kitchen, who, kind, plan, files))
    return out


def _scaled(steps: list[Step], seconds: float) -> list[Step]:
    """Stretch or shrink step durations so the demonstration lasts ``seconds``.

    The length is the schedule's (steps of the two hands may overlap), not
    the sum of the durations.
    """
    total = max(end for _, end in schedule(steps))
    factor = seconds / total
    return [replace(s, duration=max(0.12, s.duration * factor)) for s in steps]


def _parallel(steps: list[Step]) -> list[Step]:
    """Both hands at once: the left hand fetches the first item taken.

    The Reach and Take of the first item move to the left hand and run in
    parallel with the right hand's earlier steps (after the opening pause);
    the left hand then puts the item (Put and Release) once the right hand
    is done, since the Put may need what the right hand prepared (an open
    drawer).  Everything else stays with the right hand.
    """
    take = next(i for i, s in enumerate(steps) if s.activity == "Take")
    reach, put, release = take - 1, take + 1, take + 2
    if steps[reach].activity != "Reach" or steps[put].activity not in ("Put", "Stack") \
            or steps[release].activity != "Release":
        raise ValueError("expected Reach, Take, Put, Release of the first item taken")
    left = [replace(s, hand="left") for s in steps[reach:release + 1]]
    first, earlier = steps[:1], [replace(s, parallel=True) for s in steps[1:reach]]
    return first + [replace(s, parallel=True) for s in left[:2]] + earlier + left[2:] + steps[release + 1:]
