"""The demonstrators: a human simulated by a human model (its shortest plan to the request, rendered as a hand
trace), demonstrations recorded beforehand, and the check that a human model is of the task's world."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from guided_lfd.excuse.change import Change, describe_change
from guided_lfd.io import write_text
from guided_lfd.pddl.fit import check_human_model
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.planning.validation import PlanStep
from guided_lfd.teach.mistakes import Mistakes, make_mistake
from guided_lfd.teach.request import first_unreachable

if TYPE_CHECKING:  # the renderer (numpy) loads only when a demonstration is rendered
    from guided_lfd.demonstration.render import Noise

__all__ = ["MIN_RATE_HZ", "MAX_RATE_HZ", "SimulatedHuman", "GivenTraces", "check_human_model"]


#: What ``--demo`` takes instead of a trace where the teacher answers that a skill cannot be done there.
CANNOT = "cannot"

#: The frame rates a simulated demonstration is rendered at (the VR recorder's are 15-120 Hz).
MIN_RATE_HZ, MAX_RATE_HZ = 1.0, 1000.0


@dataclass
class SimulatedHuman:
    """A demonstrator simulated by a human model: its shortest plan to the request, rendered as a hand trace."""

    human: Domain
    rate_hz: float = 90.0
    seed: int = 0
    robot: Domain | None = None  # whose hand facts the trace declares (else the human model's)
    #: Mistakes the teacher makes, at their rates (:mod:`guided_lfd.teach.mistakes`); None: never.
    mistakes: Mistakes | None = None
    #: The mistake of each demonstration given so far (None: the plan as it is), in order.
    made: list[str | None] = field(default_factory=list)
    #: The rendered traces' sensor noise and tracker events (its seed is ``seed``); None: the default noise.
    noise: "Noise | None" = None

    def __post_init__(self) -> None:
        from guided_lfd.errors import OptionError

        if not isinstance(self.human, Domain):
            raise OptionError(f"SimulatedHuman: human: expected a Domain, got {type(self.human).__name__}")
        rate = self.rate_hz
        if isinstance(rate, bool) or not isinstance(rate, (int, float)) or not MIN_RATE_HZ <= rate <= MAX_RATE_HZ:
            raise OptionError(f"SimulatedHuman: rate_hz {rate!r}: expected a frame rate from {MIN_RATE_HZ:g} to "
                              f"{MAX_RATE_HZ:g} Hz")
        if isinstance(self.seed, bool) or not isinstance(self.seed, int) or self.seed < 0:
            raise OptionError(f"SimulatedHuman: seed {self.seed!r}: expected a whole number >= 0")
        if self.mistakes is not None and not isinstance(self.mistakes, Mistakes):
            raise OptionError(f"SimulatedHuman: mistakes: expected Mistakes (Mistakes.parse(SPEC)) or None, got "
                              f"{type(self.mistakes).__name__}")
        if self.robot is not None and not isinstance(self.robot, Domain):
            raise OptionError(f"SimulatedHuman: robot: expected a Domain or None, got {type(self.robot).__name__}")

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """Render the human's optimal plan from ``state`` to a state where ``request`` holds (None: no plan)."""
        from guided_lfd.demonstration.render import Noise, plan_vocabulary, render, script_for_plan
        from guided_lfd.evaluate import excuse_goal, optimal_plan

        plan = optimal_plan(self.human, replace(problem, init=state), goal=excuse_goal(request))
        if not plan:
            return None
        plan = self._mistaken(plan, state, request, problem)
        _check_drawable([], None, plan, self.human)
        # The trace's state file declares the world's hand facts (none for a world without a hand): the robot's
        # where its grasping actions show them, else the human model's.
        try:
            vocabulary = plan_vocabulary(self.human, {**self.human.constants, **problem.objects}, self.robot)
        except ValueError as exc:
            from guided_lfd.errors import UnsupportedFeatureError

            raise UnsupportedFeatureError(f"--simulate: {exc}", self.human.locate(self.human.name, "domain")) from None
        script = script_for_plan([(s.action, s.args) for s in plan], self.human, set(state), vocabulary=vocabulary)
        scene = _scene(problem, self.human)
        _check_drawable(script, scene, plan, self.human)
        noise = Noise(seed=self.seed) if self.noise is None else replace(self.noise, seed=self.seed)
        rendering = render(script, scene, set(state), self.rate_hz, noise, vocabulary=vocabulary)
        trace, states = folder / "demonstration.csv", folder / "demonstration.state.csv"
        write_text(trace, rendering.trace_csv)
        write_text(states, rendering.state_csv)
        write_text(folder / "demonstration.labels.csv", rendering.labels_csv)
        return trace, states

    def _mistaken(self, plan: list[PlanStep], state: frozenset[Atom], request: list[Change],
                  problem: Problem) -> list[PlanStep]:
        """The plan as this teacher carries it out: with a mistake at its rates (recorded in ``made``)."""
        import random

        kind = None
        if self.mistakes is not None:
            # One stream per task and demonstration: reproducible, and not the same draws in every task.
            rng = random.Random(f"{self.seed}:{problem.name}:{len(self.made)}")
            kind = self.mistakes.draw(rng)
            wrong = make_mistake(kind, plan, self.human, replace(problem, init=state), request, rng) if kind else None
            kind = kind if wrong else None
            plan = wrong or plan
        self.made.append(kind)
        return plan

    def answer_skill(self, request) -> str | None:
        """The human model's answer to "show this skill here" (a :class:`~guided_lfd.teach.skill_request.
        SkillRequest`): why its action of that name cannot be done there, or None (it demonstrates)."""
        from guided_lfd.teach.skill_request import human_refusal

        return human_refusal(self.human, request)

    def why_none(self, state: frozenset[Atom], request: list[Change], problem: Problem) -> str:
        """Why :meth:`demonstrate` gave None: the human model has no plan to the request (the first change it
        cannot make, where one alone is out of its reach)."""
        spellings = {**problem.spellings, **self.human.spellings}
        asked = " and ".join(describe_change(c, spellings) for c in request)
        head = f"the human model ({self.human.path}) has no plan from the current state to {asked}"
        first = first_unreachable(self.human, replace(problem, init=state), request)
        if first is None:
            return f"{head}: it can make each change alone, not all of them together"
        return f"{head}: it cannot reach {describe_change(first, spellings)} ({first})"


def _scene(problem: Problem, domain: Domain):
    """A scene for ``problem``'s objects: the study's positions where known, a grid of places otherwise."""
    from guided_lfd.demonstration.render import Scene
    from guided_lfd.demonstration.study_data import SCENE_POSITIONS

    objects = {**domain.constants, **problem.objects}
    positions = {}
    for k, obj in enumerate(sorted(objects)):
        positions[obj] = SCENE_POSITIONS.get(obj, (-0.9 + 0.35 * (k % 6), 0.3 + 0.3 * (k // 6), 0.8))
    return Scene(positions=positions, types=dict(objects), spellings={**domain.spellings, **problem.spellings})


def _check_drawable(script, scene, plan: list[PlanStep], human: Domain) -> None:
    """The renderer draws hand manipulation (take, put, open and close, push an obstacle away): a plan
    with another kind of action (walking through a door, turning a key) is refused in one line, not drawn wrongly."""
    from guided_lfd.demonstration.render import undrawable_actions
    from guided_lfd.errors import UnsupportedFeatureError

    odd = undrawable_actions([(step.action, step.args) for step in plan], human)
    missing = [s.obj for s in script if s.activity not in ("Idle", "Release") and s.obj not in scene.positions]
    if odd:
        raise UnsupportedFeatureError(
            f"--simulate draws every action as the hand working on its objects: the human's plan uses "
            f"{', '.join(sorted(odd))}, which has none (give --demo traces)", human.locate(sorted(odd)[0], ":action"))
    if odd or missing:
        actions = sorted(odd) or sorted({s.action for s in plan})
        raise UnsupportedFeatureError(
            f"--simulate renders hand manipulation (take, put, open or close, push an obstacle): the human's "
            f"plan uses {', '.join(actions)}, which it cannot draw as hand activities (give --demo traces)",
            human.locate(actions[0], ":action"))


@dataclass
class GivenTraces:
    """Demonstrations recorded beforehand (``--demo``), one per round, in order; each with its state file."""

    traces: list[Path]

    def __post_init__(self) -> None:
        from guided_lfd.errors import OptionError

        if not isinstance(self.traces, list) or not all(isinstance(t, (str, Path)) for t in self.traces):
            raise OptionError(f"GivenTraces: traces {self.traces!r}: expected a list of trace paths")
        self.traces[:] = [Path(t) for t in self.traces]  # in place: a caller may hold the list and see it used

    def answer_skill(self, request) -> str | None:
        """``cannot`` in the list, where a skill was asked for once more: the teacher's answer that it cannot be
        done there (consumed); else None (the next trace is its demonstration)."""
        if self.traces and str(self.traces[0]) == CANNOT:
            self.traces.pop(0)
            from guided_lfd.teach.skill_request import step_text

            return f"{step_text(request.step)} cannot be done there (the teacher's answer, --demo {CANNOT})"
        return None

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """The next trace and its state file (``TRACE.state.csv`` beside it), or None when none is left."""
        from guided_lfd.demonstration import default_state_path

        if not self.traces:
            return None
        trace = self.traces.pop(0)
        if str(trace) == CANNOT:
            return None  # an answer where a demonstration was asked for: nothing to learn from
        return trace, Path(default_state_path(str(trace)))


