"""The paper's measures of guided demonstration (section III-A).

* **Demonstration size savings** ``F1 = |pi'_H| / |pi_H|``: the human plan
  from the excuse state to the goal over the one from I to the goal, both
  found by an optimal planner on the human's domain; with the predicted sizes
  of the demonstrations for the minimal excuse, a non-minimal excuse and the
  full goal (the P columns of the paper's Table II).
* **Fraction of useful demonstration**: the demonstrated actions the robot
  did not already have, over all demonstrated actions.
* **Misdirected guidance**: over the states a demonstrator can reach with the
  human domain (breadth-first, up to a bound) in which the excuse holds, the
  fraction from which the robot still cannot reach the goal, and how they
  differ from the intended excuse state.
* **Plan solvability after demonstration**: whether the merged domain (prior
  + demonstrated actions) solves the original task; the plan is validated.

Every plan behind a number is validated with the lifted validator.
"""

from __future__ import annotations

from collections import Counter, deque
from dataclasses import dataclass, field, replace
from typing import Any

# known_skill and MAX_CULPRIT_SIZE are re-exported: the measures' one implementation is shared with teach's check.
from guided_lfd.demonstration.judgement import (MAX_CULPRIT_SIZE, known_skill, misdirected_culprit,  # noqa: F401
                                                state_after_steps)
from guided_lfd.demonstration.learn import DemonstratedAction
from guided_lfd.excuse.change import Change, excuse_state
from guided_lfd.excuse.prepare import prepare
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.task import GroundTask
from guided_lfd.pddl.model import Atom, Domain, Literal, Problem
from guided_lfd.symbolic.portfolio import validated_plan
from guided_lfd.reporting import round_fraction
from guided_lfd.planning.validation import PlanStep, validate_plan

#: Default bound on the states explored for misdirected guidance.
DEFAULT_EXPLORATION_BOUND = 20_000
#: How many distinct kinds of misdirected state a report lists.
MAX_MISDIRECTION_EXAMPLES = 5


def excuse_goal(changes: list[Change]) -> tuple[Literal, ...]:
    """The excuse as a goal: every change holds (``+p``: p true, ``-p``: p false)."""
    return tuple(Literal(c.atom, c.added) for c in changes)


def holds(goal: tuple[Literal, ...], state: frozenset[Atom] | set[Atom]) -> bool:
    """Whether ``state`` satisfies the conjunction ``goal``."""
    return all(lit.holds(state) for lit in goal)


def excuse_defect(robot: Domain, problem: Problem, excuse: list[Change]) -> str | None:
    """Why ``excuse`` is not an excuse for the robot's task (Definition 2), or None if it is one."""
    if not excuse:
        return "the excuse has no changes"
    state = excuse_state(problem.init, excuse)
    if holds(problem.goal, state):
        return "the changed state already satisfies the goal, so it is not an excuse"
    if not RobotReachability(robot, problem)(state):
        return "the robot cannot reach the goal from the changed state, so it is not an excuse"
    return None


def optimal_plan(domain: Domain, problem: Problem, goal: tuple[Literal, ...] | None = None,
                 init: frozenset[Atom] | None = None, time_limit: float | None = None) -> list[PlanStep] | None:
    """An optimal, validated plan for ``problem`` with another goal or initial state; None if unsolvable."""
    task_problem = replace(problem, goal=problem.goal if goal is None else goal,
                           init=problem.init if init is None else init)
    if holds(task_problem.goal, task_problem.init):
        return []
    return validated_plan(domain, task_problem, "astar-lmcut", time_limit, "a predicted demonstration plan")[1]


# -- F1 and the predicted demonstration sizes ------------------------------------

@dataclass
class PredictedSizes:
    """Predicted demonstration sizes (plan lengths on the human domain); None = unreachable."""

    minimal_excuse: int | None
    nonminimal_excuse: int | None
    goal: int | None
    remaining_after_excuse: int | None
    nonminimal_changes: list[str] = field(default_factory=list)
    plans: dict[str, list[str] | None] = field(default_factory=dict)

    @property
    def f1(self) -> float | None:
        """|pi'_H| / |pi_H|: the share of the full demonstration the excuse saves."""
        if self.remaining_after_excuse is None or not self.goal:
            return None
        return self.remaining_after_excuse / self.goal


def latest_excuse_on_plan(robot_can_reach: "RobotReachability", human: Domain, problem: Problem,
                          plan: list[PlanStep]) -> list[Change] | None:
    """A non-minimal excuse: the last state on the human's full plan from which the robot can finish.

    Demonstrating up to it is asking for all of the demonstration but the
    robot's last steps; it is an excuse (it does not satisfy the goal and the
    robot reaches the goal from it) but usually far from minimal.
    """
    states = [problem.init]
    for k in range(1, len(plan) + 1):
        states.append(validate_plan(human, problem.init, (), plan[:k]).final_state)
    for state in reversed(states[1:-1]):
        if not holds(problem.goal, state) and robot_can_reach(state):
            return sorted([Change(a, True) for a in state - problem.init]
                          + [Change(a, False) for a in problem.init - state], key=str)
    return None


def predicted_sizes(human: Domain, problem: Problem, excuse: list[Change],
                    robot_can_reach: "RobotReachability | None" = None,
                    nonminimal: list[Change] | None = None) -> PredictedSizes:
    """The P columns: plans on ``human`` to the minimal excuse, a non-minimal excuse and the goal."""
    to_goal = optimal_plan(human, problem)
    to_excuse = optimal_plan(human, problem, goal=excuse_goal(excuse))
    remaining = optimal_plan(human, problem, init=excuse_state(problem.init, excuse))
    if nonminimal is None and to_goal is not None and robot_can_reach is not None:
        nonminimal = latest_excuse_on_plan(robot_can_reach, human, problem, to_goal)
    to_nonminimal = optimal_plan(human, problem, goal=excuse_goal(nonminimal)) if nonminimal else None

    def size(plan: list[PlanStep] | None) -> int | None:
        return None if plan is None else len(plan)

    def text(plan: list[PlanStep] | None) -> list[str] | None:
        return None if plan is None else [str(s) for s in plan]

    return PredictedSizes(
        minimal_excuse=size(to_excuse), nonminimal_excuse=size(to_nonminimal), goal=size(to_goal),
        remaining_after_excuse=size(remaining), nonminimal_changes=[str(c) for c in nonminimal or []],
        plans={"minimal_excuse": text(to_excuse), "nonminimal_excuse": text(to_nonminimal),
               "goal": text(to_goal), "remaining_after_excuse": text(remaining)},
    )


# -- robot reachability from arbitrary states --------------------------------------

class RobotReachability:
    """Whether the robot reaches its goal from a given state (memoised across states)."""

    def __init__(self, robot: Domain, problem: Problem) -> None:
        prepared = prepare(robot, problem)  # no pruning: any atom may change
        self.task: GroundTask = prepared.task
        self.oracle = prepared.oracle

    def __call__(self, state: frozenset[Atom] | set[Atom]) -> bool:
        bits = 0
        index = self.task.index
        for atom in state:
            i = index.get(atom)
            if i is not None:  # atoms the robot's domain does not know cannot matter to it
                bits |= 1 << i
        return self.oracle.solve(bits) is not None


# -- misdirected guidance ----------------------------------------------------------

@dataclass
class Misdirection:
    """States a demonstrator may leave behind when negating the excuse."""

    bound: int
    explored: int
    complete: bool  # the whole reachable space fit in the bound
    excuse_states: int
    misdirected: int
    examples: list[dict[str, Any]] = field(default_factory=list)

    @property
    def fraction(self) -> float | None:
        """Misdirected over excuse states (None when no excuse state was reached)."""
        return self.misdirected / self.excuse_states if self.excuse_states else None

    def as_dict(self) -> dict[str, Any]:
        """The JSON form used by reports."""
        return {"fraction": round_fraction(self.fraction), "excuse_states": self.excuse_states,
                "misdirected_states": self.misdirected, "explored_states": self.explored, "bound": self.bound,
                "exhaustive": self.complete, "causes": self.examples}


def misdirected_guidance(human: Domain, robot: Domain, problem: Problem, excuse: list[Change],
                         bound: int = DEFAULT_EXPLORATION_BOUND,
                         robot_can_reach: RobotReachability | None = None) -> Misdirection:
    """Explore the human's reachable states breadth-first (at most ``bound``) and test each excuse state."""
    task = ground(human, problem)
    goal = excuse_goal(excuse)
    intended = excuse_state(problem.init, excuse)
    reach = robot_can_reach or RobotReachability(robot, problem)
    seen = {task.init}
    queue = deque([task.init])
    explored = 0
    excuse_states = misdirected = 0
    kinds: Counter[tuple[str, ...]] = Counter()
    first_seen: dict[tuple[str, ...], int] = {}
    example: dict[tuple[str, ...], list[str]] = {}
    while queue and explored < bound:
        state_bits = queue.popleft()
        explored += 1
        state = frozenset(task.atoms[i] for i in range(len(task.atoms)) if (state_bits >> i) & 1)
        if holds(goal, state):
            # A state where the goal holds too counts (the robot needs no plan).
            excuse_states += 1
            culprit = misdirected_culprit(state, goal, problem.goal, intended, reach)
            if culprit is not None:
                misdirected += 1
                cause = tuple(str(c) for c in culprit)
                kinds[cause] += 1
                if cause not in first_seen:
                    first_seen[cause] = explored
                    example[cause] = sorted([f"+{a}" for a in state - intended] + [f"-{a}" for a in intended - state])
        for act in task.actions:
            if act.applicable(state_bits):
                nxt = act.apply(state_bits)
                if nxt not in seen:
                    seen.add(nxt)
                    queue.append(nxt)
    examples = [{"cause": list(cause), "states": n, "example_difference": example[cause]}
                for cause, n in sorted(kinds.items(), key=lambda kv: (-kv[1], first_seen[kv[0]]))]
    return Misdirection(bound, explored, not queue, excuse_states, misdirected,
                        examples[:MAX_MISDIRECTION_EXAMPLES])


# -- fraction of useful demonstration ----------------------------------------------

@dataclass
class Usefulness:
    """Which demonstrated actions taught the robot something new."""

    steps: list[dict[str, Any]]

    @property
    def demonstrated(self) -> int:
        """Number of demonstrated actions (the paper's observed size O)."""
        return len(self.steps)

    @property
    def useful(self) -> int:
        """Demonstrated actions the robot did not already have."""
        return sum(1 for s in self.steps if s["known_as"] is None)

    @property
    def fraction(self) -> float | None:
        """Useful over demonstrated (None for an empty demonstration)."""
        return self.useful / self.demonstrated if self.steps else None


def usefulness(steps: list[DemonstratedAction], robot: Domain, types: dict[str, str]) -> Usefulness:
    """The fraction of useful demonstration over the demonstrated ``steps``."""
    return Usefulness([{"step": s.source, "action": s.name, "objects": list(s.objects),
                        "known_as": known_skill(s, robot, types)} for s in steps])


# -- solvability after demonstration -----------------------------------------------

@dataclass
class Solvability:
    """Whether the merged domain solves the original task."""

    solvable: bool
    plan: list[str] | None
    demonstrated_actions_used: list[str]


def solvability_after(merged: Domain, problem: Problem, prior: Domain | None = None,
                      time_limit: float | None = None) -> Solvability:
    """Plan the original task on ``merged`` (validated); which plan steps were not in ``prior``."""
    plan = optimal_plan(merged, problem, time_limit=time_limit)
    if plan is None:
        return Solvability(False, None, [])
    known = _prior_names(prior)
    return Solvability(True, [str(s) for s in plan], [str(s) for s in plan if s.action not in known])


def _prior_names(prior: Domain | None) -> set[str]:
    return set() if prior is None else {a.name for a in prior.actions}



# -- the whole report ----------------------------------------------------------------

@dataclass
class DemonstrationSteps:
    """A demonstration as evaluate sees it: where it came from, its demonstrated actions, its objects' types.

    (The recorded demonstration itself, frames and states, is :class:`guided_lfd.demonstration.trace.Demonstration`.)
    """

    source: str
    steps: list[DemonstratedAction]
    types: dict[str, str]


@dataclass
class Evaluation:
    """The paper's measures for one task, excuse and (optionally) demonstrations and merged domain."""

    excuse: list[Change]
    sizes: PredictedSizes
    misdirection: Misdirection
    #: Each demonstration with how much of it was new to the robot.
    demonstrations: list[tuple[DemonstrationSteps, Usefulness]] = field(default_factory=list)
    #: Whether the merged domain solves the task (None without a merged domain).
    solvability: Solvability | None = None
    #: Per demonstration, the state it left judged as teach judges it: the misdirected guidance's culprit there
    #: (None when the robot reaches its goal from it, or the excuse does not hold there), and whether it holds.
    left: list[tuple[bool, list[Change] | None]] = field(default_factory=list)

    def to_dict(self) -> dict[str, Any]:
        """The measures as the ``guided-lfd/evaluation`` document has them (after its input keys)."""
        sizes = self.sizes
        return {
            "excuse": [str(c) for c in self.excuse],
            "demonstration_size": {
                "f1": round_fraction(sizes.f1),
                "predicted": {
                    "minimal_excuse": sizes.minimal_excuse,
                    "nonminimal_excuse": sizes.nonminimal_excuse,
                    "goal": sizes.goal,
                    "remaining_after_excuse": sizes.remaining_after_excuse,
                },
                "nonminimal_excuse": sizes.nonminimal_changes,
                "plans": sizes.plans,
            },
            "misdirected_guidance": self.misdirection.as_dict(),
            "demonstrations": [
                {"source": demo.source, "demonstrated_actions": useful.demonstrated, "useful_actions": useful.useful,
                 "useful_fraction": round_fraction(useful.fraction), "steps": useful.steps,
                 **({} if k >= len(self.left) else {
                     "excuse_reached": self.left[k][0],
                     "misdirected": None if self.left[k][1] is None else [str(c) for c in self.left[k][1]]})}
                for k, (demo, useful) in enumerate(self.demonstrations)
            ],
            "solvability_after_demonstration": None if self.solvability is None else {
                "solvable": self.solvability.solvable, "plan": self.solvability.plan,
                "demonstrated_actions_used": self.solvability.demonstrated_actions_used,
            },
        }

    def to_json(self, inputs: dict[str, Any] | None = None) -> str:
        """The ``guided-lfd/evaluation`` document: ``inputs`` (paths, the excuse's source) first, then the measures."""
        from guided_lfd.io import json_document

        return json_document("evaluation", {**(inputs or {}), **self.to_dict()})

    def rows(self) -> list[tuple[str, str, str]]:
        """The measures as (measure, value, detail) rows, for the table and the CSV."""
        return report_rows(self.to_dict())


def evaluate(robot: Domain, problem: Problem, human: Domain, excuse: list[Change],
             demonstrations: list[DemonstrationSteps] = (),  # type: ignore[assignment]
             merged: Domain | None = None, nonminimal: list[Change] | None = None,
             bound: int = DEFAULT_EXPLORATION_BOUND) -> Evaluation:
    """All the paper's measures for the task (see the module docstring)."""
    from guided_lfd.pddl.fit import refuse_adl

    refuse_adl("evaluate", problem, robot, human, merged)
    reach = RobotReachability(robot, problem)
    sizes = predicted_sizes(human, problem, excuse, reach, nonminimal)
    misdirection = misdirected_guidance(human, robot, problem, excuse, bound, reach)
    useful = [(demo, usefulness(demo.steps, robot, demo.types)) for demo in demonstrations]
    left = [demonstration_left(demo, problem, excuse, reach) for demo in demonstrations]
    solvability = solvability_after(merged, problem, robot) if merged is not None else None
    return Evaluation(list(excuse), sizes, misdirection, useful, solvability, left)


def demonstration_left(demo: DemonstrationSteps, problem: Problem, excuse: list[Change],
                       reach: RobotReachability) -> tuple[bool, list[Change] | None]:
    """(whether the excuse holds in the state ``demo`` leaves from the task's initial state, the misdirected
    guidance's culprit there or None): what ``teach`` checks on each demonstration (the same
    :func:`~guided_lfd.demonstration.judgement.misdirected_culprit`)."""
    end = state_after_steps(problem.init, demo.steps)
    goal = excuse_goal(excuse)
    return holds(goal, end), misdirected_culprit(end, goal, problem.goal, excuse_state(problem.init, excuse), reach)


def report_rows(report: dict[str, Any]) -> list[tuple[str, str, str]]:
    """The report as (measure, value, detail) rows, for the table and the CSV."""
    size = report["demonstration_size"]
    pred = size["predicted"]
    mis = report["misdirected_guidance"]
    rows = [
        ("excuse", " ".join(report["excuse"]), f"{len(report['excuse'])} change(s)"),
        # The paper's F1 (III-A-1): the part of the whole-task demonstration the human no longer gives.
        ("f1_savings", _fmt(size["f1"]), "higher = more saved: the share of the whole-task demonstration the "
         f"human need not give, |pi'_H| / |pi_H| = {_fmt(pred['remaining_after_excuse'])} / {_fmt(pred['goal'])} "
         "(human plan from the excuse state over the full one)"),
        ("predicted_size_minimal_excuse", _fmt(pred["minimal_excuse"]), "human plan to the minimal excuse"),
        ("predicted_size_nonminimal_excuse", _fmt(pred["nonminimal_excuse"]),
         "human plan to " + (" ".join(size["nonminimal_excuse"]) or "-")),
        ("predicted_size_goal", _fmt(pred["goal"]), "human plan to the goal"),
        ("predicted_size_remaining", _fmt(pred["remaining_after_excuse"]), "human plan from the excuse state"),
        ("misdirected_guidance", _fmt(mis["fraction"]),
         f"{mis['misdirected_states']} of {mis['excuse_states']} excuse states; "
         f"{mis['explored_states']} states explored (bound {mis['bound']}"
         + (", exhaustive)" if mis["exhaustive"] else ", not exhaustive)")),
    ]
    for cause in mis["causes"]:
        rows.append(("misdirection_cause", str(cause["states"]),
                     " ".join(cause["cause"]) + "  (e.g. " + " ".join(cause["example_difference"]) + ")"))
    for demo in report["demonstrations"]:
        rows.append(("useful_fraction", _fmt(demo["useful_fraction"]),
                     f"{demo['useful_actions']} of {demo['demonstrated_actions']} demonstrated actions new "
                     f"({demo['source']})"))
        if demo.get("excuse_reached"):
            rows.append(("demonstration_misdirected", "yes" if demo["misdirected"] else "no",
                         (" ".join(demo["misdirected"]) + ": the robot cannot reach its goal from the state it left"
                          if demo["misdirected"] else "the robot reaches its goal from the state it left")
                         + f" ({demo['source']})"))
    solv = report["solvability_after_demonstration"]
    if solv is not None:
        rows.append(("solvable_after_demonstration", "yes" if solv["solvable"] else "no",
                     " ".join(solv["plan"]) if solv["plan"] else "no plan on the merged domain"))
    return rows


def _fmt(value: Any) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.3f}"
    return str(value)
