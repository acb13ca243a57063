"""Running the study's chain (segment -> learn-domain -> merge -> excuse -> evaluate): computes, writes nothing."""

from __future__ import annotations


from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable

from guided_lfd.demonstration.learn import ground_actions, learn_domain
from guided_lfd.demonstration.segment import segment, segments_document
from guided_lfd.demonstration.trace import load_demonstration
from guided_lfd.evaluate import (
    PredictedSizes, RobotReachability, misdirected_guidance, predicted_sizes, solvability_after, usefulness,
)
from guided_lfd.excuse.engine import find_excuses
from guided_lfd.excuse.change import describe_change
from guided_lfd.merge import merge_domains
from guided_lfd.pddl.model import Domain
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.reporting import relative_path, round_fraction

from guided_lfd.study.paper import DEMONSTRATORS, KITCHEN_NAMES, KITCHENS, PaperData, load_paper_data


#: Bound on the human states explored for misdirected guidance.
STUDY_EXPLORATION_BOUND = 20_000


@dataclass
class DemoResult:
    """One demonstration run through segment -> learn-domain."""

    kitchen: str
    demonstrator: str
    kind: str  # excuse | complete
    duration_s: float
    segments: int
    demonstrated_actions: int
    useful_actions: int
    learned_actions: list[str]
    learned: Domain
    #: The segments document and the trace's file name (the artefacts written from them).
    segments_document: dict[str, Any] = field(default_factory=dict, repr=False)
    trace_name: str = ""


@dataclass
class DemonstratorResult:
    """Everything measured for one kitchen and demonstrator."""

    kitchen: str
    demonstrator: str
    demos: dict[str, DemoResult]
    predicted: dict[str, int | None]
    f1: float | None
    solvable_after_excuse_demo: bool
    plan_after_excuse_demo: list[str] | None
    excuse_on_merged: str
    #: The robot's domain merged with what the excuse demonstration taught.
    merged: Domain | None = field(default=None, repr=False)


@dataclass
class KitchenResult:
    """Per kitchen: the excuse the robot asks for and the measures that do not depend on the demonstrator."""

    kitchen: str
    excuse: list[str]
    excuse_text: list[str]
    human_predicted: dict[str, int | None]
    human_f1: float | None
    nonminimal_excuse: list[str]
    misdirection: dict[str, Any]
    demonstrators: list[DemonstratorResult] = field(default_factory=list)


def run_demo(root: Path, kitchen: str, demonstrator: str, kind: str, robot: Domain) -> DemoResult:
    """Segment and learn one demonstration (its segments document and learned domain are in the result)."""
    trace = root / "data" / "demos" / kitchen / f"{demonstrator}-{kind}.csv"
    state = trace.with_name(trace.stem + ".state.csv")
    demo = load_demonstration(str(trace), str(state))
    segments = [s for s in segment(demo) if s.activity != "Idle"]
    doc = segments_document(demo, segments, relative_path(state, root))
    doc["trace"] = relative_path(trace, root)
    source = f"{kitchen}/{demonstrator}-{kind}"
    steps = ground_actions(doc, source)
    learned = learn_domain([(source, doc)], name=f"learned-{kitchen}-{demonstrator}-{kind}".lower(), context=robot)
    times = demo.frames["time"]
    useful = usefulness(steps, robot, doc.get("objects", {}))
    return DemoResult(kitchen, demonstrator, kind, round(float(times.max() - times.min()), 2), len(segments),
                      len(steps), useful.useful, [a.name for a in learned.actions], learned, doc, trace.name)


def run_kitchen(root: Path, kitchen: str, bound: int = STUDY_EXPLORATION_BOUND,
                progress: Callable[[str], None] | None = None) -> KitchenResult:
    """The chain for one kitchen and all demonstrators (writes nothing)."""
    folder = root / "data" / "domains" / kitchen
    robot, problem = parse_task(str(folder / "robot.pddl"), str(folder / "problem.pddl"))
    # The merged domains name the robot's file: relative to the root, whichever way the root is spelled.
    robot = replace(robot, path=relative_path(robot.path, root))
    human = parse_domain(str(folder / "human.pddl"))
    report = find_excuses(robot, problem)
    if report.excuse is None:
        raise RuntimeError(f"{kitchen}: the robot's task has no excuse ({report.status})")
    excuse = report.excuse.changes
    reach = RobotReachability(robot, problem)
    reference = predicted_sizes(human, problem, excuse, reach)
    misdirection = misdirected_guidance(human, robot, problem, excuse, bound, reach)
    result = KitchenResult(
        kitchen, [str(c) for c in excuse], [describe_change(c, problem.spellings) for c in excuse],
        _predicted(reference), round_fraction(reference.f1), reference.nonminimal_changes,
        misdirection.as_dict(),
    )
    for p in DEMONSTRATORS:
        if progress:
            progress(f"{KITCHEN_NAMES[kitchen]} {p}")
        demos = {kind: run_demo(root, kitchen, p, kind, robot) for kind in ("excuse", "complete")}
        # Solvability after demonstration: the prior + what the excuse demonstration taught.
        merged = merge_domains([robot, demos["excuse"].learned], name=robot.name).domain
        solv = solvability_after(merged, problem, robot)
        on_merged = find_excuses(merged, problem).status
        # Predicted sizes: planning on what this demonstrator showed (both demonstrations) + the prior.
        knowledge = merge_domains([robot, demos["excuse"].learned, demos["complete"].learned], name=robot.name).domain
        sizes = predicted_sizes(knowledge, problem, excuse, reach)
        result.demonstrators.append(DemonstratorResult(
            kitchen, p, demos, _predicted(sizes), round_fraction(sizes.f1), solv.solvable, solv.plan, on_merged, merged))
    return result


def _predicted(sizes: PredictedSizes) -> dict[str, int | None]:
    return {"minimal_excuse": sizes.minimal_excuse, "nonminimal_excuse": sizes.nonminimal_excuse,
            "goal": sizes.goal, "remaining_after_excuse": sizes.remaining_after_excuse}


def run_study(root: Path, progress: Callable[[str], None] | None = None) -> tuple[PaperData, list[KitchenResult]]:
    """The paper's data and the reproduced chain for both kitchens (computes, writes nothing)."""
    return load_paper_data(root / "data" / "study"), [run_kitchen(root, k, progress=progress) for k in KITCHENS]
