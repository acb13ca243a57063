"""A round that asks for a skill once more: the request a skill excuse turns into, and the teacher's "cannot".

A skill excuse (``-(ontable ?y) in unstack``) says the robot's plan works if a learned precondition is not
needed.  The robot's plan with it dropped tells where: the first step that needs the dropped precondition
false.  The robot makes the steps before it itself (they need nothing dropped), then asks the teacher to show
that step there ("show unstack c b, where (ontable b) is false").  A demonstration is learned together with
the earlier ones, so the skill generalises (the precondition drops) or keeps it; a teacher who answers that
the skill cannot be done there confirms the precondition (its evidence says so, and no skill excuse drops it
again).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, replace

from guided_lfd.excuse.change import Change, SkillChange, describe_change, describe_skill_change
from guided_lfd.pddl.model import ActionSchema, Atom, Domain, Evidence, objects_by_type
from guided_lfd.planning.validation import PlanStep
from guided_lfd.teach.session import Round

__all__ = ["SkillRequest", "skill_request", "skill_round", "confirm", "step_text", "human_refusal", "answer_of"]


@dataclass
class SkillRequest:
    """Show ``step`` (a ground skill) in ``state``, where the ``dropped`` preconditions do not all hold."""

    step: PlanStep
    dropped: list[SkillChange]
    #: The robot's own steps before it, from the state the round began in (the world is in ``state`` after them).
    robot_first: list[PlanStep]
    state: frozenset[Atom]
    #: The step's effect from ``state``, as the changes a demonstration of it makes.
    effects: list[Change]

    def to_dict(self) -> dict:
        """The request as ``session.json`` records it."""
        return {"step": str(self.step), "dropped": [str(c) for c in self.dropped],
                "robot_first": [str(s) for s in self.robot_first]}


def step_text(step: PlanStep) -> str:
    """``(unstack c b)`` as a person reads it: ``unstack c b``."""
    return " ".join((step.action, *step.args))


def _effects(schema: ActionSchema, step: PlanStep) -> tuple[set[Atom], set[Atom]]:
    """The ground step's (adds, deletes)."""
    binding = {v: a for (v, _), a in zip(schema.params, step.args)}
    return {a.substitute(binding) for a in schema.add}, {a.substitute(binding) for a in schema.delete}


def _needed(schema: ActionSchema, step: PlanStep, dropped: list[SkillChange], current: set[Atom],
            objects: dict[str, list[str]]) -> tuple[PlanStep, list[SkillChange]]:
    """The dropped preconditions ``step`` needs false in ``current``, and the step: rebound where a parameter
    only those preconditions name (the other room of a door) can be chosen so that none is needed."""
    def false_ones(binding: dict[str, str]) -> list[SkillChange]:
        return [c for c in dropped if c.action == step.action and not c.literal.substitute(binding).holds(current)]

    binding = {v: a for (v, _), a in zip(schema.params, step.args)}
    needed = false_ones(binding)
    if not needed:
        return step, []
    named_elsewhere = {x for l in schema.precondition if SkillChange(schema.name, l) not in dropped
                       for x in l.atom.args} | {x for a in (*schema.add, *schema.delete) for x in a.args}
    free = [(v, t) for v, t in schema.params if v not in named_elsewhere]
    for choice in itertools.product(*(objects.get(t, []) for _, t in free)):
        rebound = {**binding, **dict(zip((v for v, _ in free), choice))}
        if not false_ones(rebound) and all(l.substitute(rebound).holds(current)
                                           for l in schema.precondition if l.atom.predicate != "="):
            return PlanStep(step.action, tuple(rebound[v] for v, _ in schema.params)), []
    return step, needed


def skill_request(robot: Domain, state: frozenset[Atom], plan: list[PlanStep], dropped: list[SkillChange],
                  by_type: dict[str, list[str]] | None = None) -> SkillRequest | None:
    """Where the robot's ``plan`` (from ``state``, with the ``dropped`` preconditions) first needs one dropped:
    the steps before it, which the robot's own domain allows (a step rebound over the task's objects, ``by_type``
    as :func:`~guided_lfd.pddl.model.objects_by_type` gives them, where that makes it so), and that step; None if
    no step needs one."""
    schemas = {a.name: a for a in robot.actions}
    current = set(state)
    done: list[PlanStep] = []
    for step in plan:
        schema = schemas[step.action]
        step, needed = _needed(schema, step, dropped, current, by_type or {})
        adds, dels = _effects(schema, step)
        if needed:
            effects = sorted([Change(a, True) for a in adds if a not in current]
                             + [Change(a, False) for a in dels - adds if a in current], key=lambda c: (c.atom, c.added))
            return SkillRequest(step, needed, done, frozenset(current), effects)
        done.append(step)
        current = (current - dels) | adds
    return None


def request_text(request: SkillRequest, spellings: dict[str, str]) -> list[str]:
    """The request in words: the skill and where, then what showing it makes."""
    where = "; ".join(describe_skill_change(c, spellings) for c in request.dropped)
    made = ", ".join(describe_change(c, spellings) for c in request.effects)
    return [f"Show {step_text(request.step)} here ({where}): {made}"]


def confirm(robot: Domain, changes: list[SkillChange]) -> Domain:
    """``robot`` with the ``changes``' preconditions confirmed by the teacher (never dropped again)."""
    by_action: dict[str, set] = {}
    for change in changes:
        by_action.setdefault(change.action, set()).add(change.literal)
    actions = []
    for action in robot.actions:
        literals = by_action.get(action.name)
        if literals:
            evidence = tuple(Evidence(e.literal, e.shown, e.demonstrations, True) if e.literal in literals else e
                             for e in action.evidence)
            action = replace(action, evidence=evidence)
        actions.append(action)
    return replace(robot, actions=actions)


def human_refusal(human: Domain, request: SkillRequest) -> str | None:
    """How the simulated teacher answers from its human model: why the skill cannot be done there (its action
    of that name needs a precondition that is false), or None when it can be (a demonstration follows)."""
    schema = next((a for a in human.actions if a.name == request.step.action
                   and len(a.params) == len(request.step.args)), None)
    if schema is None:
        return None  # the human model names the skill otherwise: its plan to the request shows what it does
    binding = {v: a for (v, _), a in zip(schema.params, request.step.args)}
    for lit in schema.precondition:
        ground = lit.substitute(binding)
        if lit.atom.predicate != "=" and not ground.holds(request.state):
            return (f"{step_text(request.step)} cannot be done here: it needs "
                    f"{'' if lit.positive else 'not '}{ground.atom}")
    return None


def skill_round(k: int, robot: Domain, state: frozenset[Atom], report) -> Round:
    """Round ``k`` for a skill excuse (``report``'s first excuse, skill changes alone): show the skill where its
    plan first needs a dropped precondition, after the robot's own steps before it."""
    excuse = report.excuse
    ask = skill_request(robot, state, excuse.plan, excuse.skill_changes, objects_by_type(robot, report.problem))
    if ask is None:  # the excuse would not be minimal: the robot could plan without dropping anything
        raise RuntimeError(f"internal check failed: no step of the plan needs {excuse.skill_changes}")
    spellings = report.spellings
    goal = ", ".join(describe_change(Change(lit.atom, lit.positive), spellings) for lit in report.problem.goal)
    why = [f"the robot's {c.action} requires {c.literal}: it held in every demonstration so far and none showed "
           f"{c.action} without it; its plan to {goal} needs {step_text(ask.step)} where it does not hold"
           for c in ask.dropped]
    rnd = Round(k, [], ask.effects, request_text(ask, spellings), why, [], [])
    rnd.skill = ask
    return rnd


def answer_of(demonstrator, request: SkillRequest) -> str | None:
    """The demonstrator's answer to a skill request before any demonstration: why the skill cannot be done there,
    or None (a demonstration follows).  A demonstrator without ``answer_skill`` always demonstrates."""
    answer = getattr(demonstrator, "answer_skill", None)
    return answer(request) if answer is not None else None
