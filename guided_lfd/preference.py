"""Which excuse to ask for, given a model of the human (paper, III-B): the preferred excuse and its redundancy.

* Case 1 of the preferred excuse (III-B-2): among the minimal excuses, the
  one whose predicted demonstration (the human's shortest plan from the
  current state to the excuse state) is shortest, then the one that teaches
  the most (the largest fraction of its actions new to the robot).
* Redundancy (III-B-1): the smallest part of the excuse whose shortest
  human demonstration, once learned, already lets the robot plan its task:
  in Kitchen II, for a robot that can neither open drawers nor move the
  chair, asking only ``Open PinkDrawer`` suffices, as the human must clear
  the drawer to open it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from itertools import combinations

from guided_lfd.excuse.change import Change
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.planning.validation import PlanStep, validate_plan

__all__ = ["PredictedDemonstration", "apply_preference", "predict_demonstration", "prefer_demonstration",
           "minimal_request", "sufficient_part"]


@dataclass
class PredictedDemonstration:
    """What the human model would demonstrate for ``changes``: its shortest plan and how much of it is new."""

    changes: list[Change]
    plan: list[PlanStep] | None  # None: the human model cannot reach it
    new_fraction: float  # of the plan's actions, the fraction of skills the robot does not have

    @property
    def length(self) -> int | None:
        """The predicted demonstration's length in actions."""
        return None if self.plan is None else len(self.plan)


def _left(deadline: float | None) -> float | None:
    """Seconds left before ``deadline`` (None: no limit); :class:`SearchTimeout` once it has passed."""
    from guided_lfd.deadline import seconds_left

    return seconds_left(deadline, "preferring and reducing excuses")


def predict_demonstration(human: Domain, robot: Domain, task: Problem, changes: list[Change],
                          deadline: float | None = None) -> PredictedDemonstration:
    """The human model's shortest plan from ``task``'s state to a state where ``changes`` hold (within
    ``deadline``, a ``time.monotonic()`` value: :class:`~guided_lfd.errors.SearchTimeout` past it)."""
    from guided_lfd.evaluate import excuse_goal, optimal_plan

    plan = optimal_plan(human, task, goal=excuse_goal(changes), time_limit=_left(deadline))
    known = {a.name for a in robot.actions}
    new = sum(step.action not in known for step in plan) / len(plan) if plan else 0.0
    return PredictedDemonstration(list(changes), plan, new)


def prefer_demonstration(excuses: list[list[Change]], human: Domain, robot: Domain,
                         task: Problem, deadline: float | None = None) -> tuple[int, str]:
    """The index of the preferred excuse among ``excuses`` (all minimal) and why, in one line.

    Shortest predicted demonstration first, then the most new skills, then the
    search's own order; an excuse the human model cannot demonstrate comes last.
    """
    predictions = [predict_demonstration(human, robot, task, changes, deadline) for changes in excuses]
    order = sorted(range(len(excuses)), key=lambda k: (predictions[k].length is None,
                                                       predictions[k].length or 0, -predictions[k].new_fraction, k))
    best = order[0]
    words = lambda p: " ".join(str(c) for c in p.changes)  # noqa: E731
    chosen = predictions[best]
    if chosen.length is None:
        return best, "the human model can demonstrate none of the minimal excuses; the first is kept"
    others = [f"{predictions[k].length} for {words(predictions[k])}" if predictions[k].length is not None
              else f"none possible for {words(predictions[k])}" for k in order[1:]]
    why = f"preferred {words(chosen)}: its demonstration takes {chosen.length} action(s)"
    return best, why + (f", against {'; '.join(others)}" if others else "")


def sufficient_part(human: Domain, robot: Domain, task: Problem, excuse: list[Change],
                    deadline: float | None = None) -> tuple[list[Change], frozenset[Atom] | None]:
    """The smallest part of ``excuse`` whose human demonstration, learned, lets the robot plan ``task``, and
    the state that predicted demonstration leaves (which of the rest it makes on the way).

    Parts are tried smallest first (in the excuse's order); the learned
    skills are predicted as the human model's actions the demonstration uses.
    The whole excuse, with no state, is the answer when no smaller part does.
    """
    from guided_lfd.merge import merge_domains
    from guided_lfd.symbolic.portfolio import validated_plan

    for size in range(1, len(excuse)):
        for part in combinations(excuse, size):
            predicted = predict_demonstration(human, robot, task, list(part), deadline)
            if not predicted.plan:
                continue
            after = validate_plan(human, task.init, (), predicted.plan).final_state
            used = {step.action for step in predicted.plan}
            skills = replace(human, actions=[a for a in human.actions if a.name in used])
            taught = merge_domains([robot, skills], name=robot.name).domain
            if validated_plan(taught, replace(task, init=after), time_limit_s=_left(deadline))[1] is not None:
                return list(part), after
    return list(excuse), None


def minimal_request(human: Domain, robot: Domain, task: Problem, excuse: list[Change],
                    deadline: float | None = None) -> list[Change]:
    """The smallest part of ``excuse`` whose human demonstration, learned, lets the robot plan ``task`` (see
    :func:`sufficient_part`)."""
    return sufficient_part(human, robot, task, excuse, deadline)[0]


def apply_preference(report, human: Domain, robot: Domain, task: Problem, keep_all: bool = False,
                     deadline: float | None = None) -> None:
    """Put the preferred of ``report``'s minimal excuses first (and only it, unless ``keep_all``), saying why."""
    if len(report.excuses) < 2:
        return
    index, why = prefer_demonstration([e.changes for e in report.excuses], human, robot, task, deadline)
    preferred = report.excuses[index]
    rest = [e for k, e in enumerate(report.excuses) if k != index]
    report.excuses = [preferred, *rest] if keep_all else [preferred]
    report.preference = why

