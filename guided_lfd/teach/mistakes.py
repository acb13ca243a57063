"""A simulated teacher who makes mistakes: the human model's plan to the request, sometimes done wrong.

Real teachers stop halfway, work on the wrong drawer, do more than asked, or misread the request.  The
simulated human (:class:`~guided_lfd.teach.human.SimulatedHuman`) with ``mistakes`` makes one of them in a
demonstration at the given rates, deterministically for its seed:

* ``wrong-object``: a step done on another object of the same type where that step can be done (the blue
  drawer for the pink one); the rest of the plan goes on where it still can;
* ``partial``: the first half of the plan (at least one step), then it stops;
* ``extra-steps``: the plan, then one or two more actions the human can do from there;
* ``wrong-order``: the plan's steps in another order that the human can still carry out;
* ``misread``: the plan to the nearest other request it can reach: one requested fact taken for another of
  the same predicate, one object different.

A mistake that cannot be made in a demonstration (no other object fits, a one-step plan to halve) is not
made: the demonstration is the plan.  ``SPEC`` is ``KIND=RATE[,KIND=RATE...]`` with each rate a fraction or
a percentage (``partial=0.1``, ``wrong-object=10%``), or ``any=RATE``: a mistake at that rate, its kind drawn
evenly.  The rates are per demonstration and sum to at most 1.
"""

from __future__ import annotations

import random
import re
from dataclasses import dataclass, field, replace

from guided_lfd.excuse.change import Change
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.planning.validation import PlanStep

__all__ = ["MISTAKE_KINDS", "Mistakes", "make_mistake"]

#: The kinds of mistake, in the order a draw checks them.
MISTAKE_KINDS = ("wrong-object", "partial", "extra-steps", "wrong-order", "misread")


@dataclass(frozen=True)
class Mistakes:
    """Per-demonstration rates of each kind of mistake (see the module's doc)."""

    rates: dict[str, float] = field(default_factory=dict)

    @classmethod
    def parse(cls, spec: str) -> "Mistakes":
        """``KIND=RATE,...`` or ``any=RATE`` (an OptionError naming what was expected otherwise)."""
        from guided_lfd.errors import OptionError

        rates: dict[str, float] = {}
        if not str(spec).strip():
            raise OptionError("--mistakes '': expected KIND=RATE[,KIND=RATE...] (nothing given)")
        for part in (p.strip() for p in str(spec).split(",")):
            match = re.fullmatch(r"([a-z-]+)\s*=\s*([0-9.]+(?:e-?[0-9]+)?)(%?)", part)
            if not match:
                raise OptionError(f"--mistakes '{spec}': expected KIND=RATE[,KIND=RATE...] with KIND one of "
                                  f"{', '.join(MISTAKE_KINDS)} or any, and RATE a fraction or a percentage")
            kind, number, percent = match.groups()
            try:
                rate = float(number) / (100 if percent else 1)
            except ValueError:
                raise OptionError(f"--mistakes '{spec}': rate '{number}' is not a number") from None
            if kind not in (*MISTAKE_KINDS, "any"):
                raise OptionError(f"--mistakes '{spec}': unknown kind '{kind}' (expected one of "
                                  f"{', '.join(MISTAKE_KINDS)}, any)")
            if kind == "any":
                for each in MISTAKE_KINDS:
                    rates[each] = rates.get(each, 0.0) + rate / len(MISTAKE_KINDS)
            else:
                rates[kind] = rates.get(kind, 0.0) + rate
        if sum(rates.values()) > 1 + 1e-9:
            raise OptionError(f"--mistakes '{spec}': the rates sum to {sum(rates.values()):g}, expected at most 1 "
                              "(one mistake per demonstration at most)")
        return cls(rates)

    def draw(self, rng: random.Random) -> str | None:
        """The mistake of one demonstration (None: none)."""
        roll = rng.random()
        for kind in MISTAKE_KINDS:
            roll -= self.rates.get(kind, 0.0)
            if roll < 0:
                return kind
        return None

    def __str__(self) -> str:
        return ",".join(f"{k}={self.rates[k]:g}" for k in MISTAKE_KINDS if self.rates.get(k)) or "none"


class _World:
    """The human model's ground actions over a task, to try steps and plans."""

    def __init__(self, human: Domain, problem: Problem) -> None:
        from guided_lfd.planning.grounding import ground

        self.task = ground(human, problem)
        self.by_step = {(a.schema, a.args): a for a in self.task.actions}

    def mask(self, state: frozenset[Atom]) -> int:
        return sum(1 << self.task.index[a] for a in state if a in self.task.index)

    def applicable(self, state: int, step: PlanStep) -> int | None:
        """The state after ``step`` (None: it cannot be done there)."""
        act = self.by_step.get((step.action, step.args))
        if act is None or state & act.pre_pos != act.pre_pos or state & act.pre_neg:
            return None
        return (state & ~act.delete) | act.add

    def runs(self, state: int, plan: list[PlanStep]) -> bool:
        for step in plan:
            state = self.applicable(state, step)
            if state is None:
                return False
        return True

    def steps_from(self, state: int) -> list[PlanStep]:
        return [PlanStep(a.schema, a.args) for a in self.task.actions
                if state & a.pre_pos == a.pre_pos and not state & a.pre_neg]


def make_mistake(kind: str, plan: list[PlanStep], human: Domain, problem: Problem, request: list[Change],
                 rng: random.Random) -> list[PlanStep] | None:
    """``plan`` (the human's, from ``problem.init`` to ``request``) with a ``kind`` mistake; None when that
    mistake cannot be made here."""
    world = _World(human, problem)
    start = world.mask(problem.init)
    if kind == "partial":
        return plan[: len(plan) // 2] if len(plan) >= 2 else None
    if kind == "extra-steps":
        return _extra(world, start, plan, rng)
    if kind == "wrong-order":
        return _reordered(world, start, plan, rng)
    if kind == "wrong-object":
        return _wrong_object(world, start, plan, problem, human, rng)
    if kind == "misread":
        return _misread(human, problem, request, rng)
    raise ValueError(f"unknown mistake {kind!r}")


def _extra(world: _World, state: int, plan: list[PlanStep], rng: random.Random) -> list[PlanStep] | None:
    for step in plan:
        state = world.applicable(state, step)
    out = list(plan)
    for _ in range(rng.choice((1, 2))):
        options = world.steps_from(state)
        if not options:
            break
        step = rng.choice(options)
        state = world.applicable(state, step)
        out.append(step)
    return out if len(out) > len(plan) else None


def _reordered(world: _World, state: int, plan: list[PlanStep], rng: random.Random) -> list[PlanStep] | None:
    pairs = [(i, j) for i in range(len(plan)) for j in range(i + 1, len(plan)) if plan[i] != plan[j]]
    rng.shuffle(pairs)
    for i, j in pairs:
        other = list(plan)
        other[i], other[j] = other[j], other[i]
        if world.runs(state, other):
            return other
    for _ in range(200):  # no one swap does: other orders, drawn (two tasks done the other way round)
        other = rng.sample(plan, len(plan))
        if other != plan and world.runs(state, other):
            return other
    return None


def _wrong_object(world: _World, state: int, plan: list[PlanStep], problem: Problem, human: Domain,
                  rng: random.Random) -> list[PlanStep] | None:
    objects = {**human.constants, **problem.objects}
    order = list(range(len(plan)))
    rng.shuffle(order)
    for k in order:
        before = state
        for step in plan[:k]:
            before = world.applicable(before, step)
        step = plan[k]
        swaps = [PlanStep(step.action, step.args[:i] + (other,) + step.args[i + 1:])
                 for i, arg in enumerate(step.args) for other in sorted(objects)
                 if other != arg and objects[other] == objects.get(arg)]
        swaps = [s for s in swaps if world.applicable(before, s) is not None]
        if swaps:
            wrong = rng.choice(swaps)
            out, now = plan[:k] + [wrong], world.applicable(before, wrong)
            for rest in plan[k + 1:]:  # the rest goes on where it still can
                after = world.applicable(now, rest)
                if after is not None:
                    out.append(rest)
                    now = after
            return out
    return None


def _misread(human: Domain, problem: Problem, request: list[Change],
             rng: random.Random) -> list[PlanStep] | None:
    from guided_lfd.evaluate import excuse_goal, optimal_plan

    objects = {**human.constants, **problem.objects}
    order = list(range(len(request)))
    rng.shuffle(order)
    for k in order:
        change = request[k]
        others = [Atom(change.atom.predicate, change.atom.args[:i] + (o,) + change.atom.args[i + 1:])
                  for i, arg in enumerate(change.atom.args) for o in sorted(objects)
                  if o != arg and objects[o] == objects.get(arg)]
        rng.shuffle(others)
        for atom in others[:6]:
            misread = [*request[:k], replace(change, atom=atom), *request[k + 1:]]
            plan = optimal_plan(human, problem, goal=excuse_goal(misread))
            if plan:
                return plan
    return None
