"""Reading IPC plan files and validating plans step by step.

The validator works on the *lifted* domain and plain atom sets, independently
of the grounder and the searches, so it can check what they produce.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from guided_lfd.errors import InputFileError, Location, PlanFileError
from guided_lfd.pddl.formula import Formula
from guided_lfd.pddl.model import Atom, Domain, Literal, MissingCostError, Problem, action_cost, objects_by_type
from guided_lfd.io import read_text
from guided_lfd.planning.task import GroundAction


@dataclass(frozen=True)
class PlanStep:
    """One ground action of a plan, with where it was written."""

    action: str
    args: tuple[str, ...]
    line: int | None = None
    col: int | None = None

    def __str__(self) -> str:
        return "(" + " ".join((self.action, *self.args)) + ")"


@dataclass
class StepReport:
    """Whether one step was applicable, and which precondition literals (ADL: conjuncts) failed."""

    index: int
    step: PlanStep
    failed: list[Formula] = field(default_factory=list)
    #: The step's cost term when the problem gives it no value (PDDL: then it cannot be applied).
    undefined_cost: Atom | None = None

    @property
    def ok(self) -> bool:
        return not self.failed and self.undefined_cost is None


@dataclass
class ValidationReport:
    """Result of validating a plan from a state."""

    steps: list[StepReport]
    unsatisfied_goal: list[Formula]
    final_state: frozenset[Atom]
    #: What the steps applied cost (see :func:`plan_cost`); None unless the problem was given.
    cost: int | None = None

    @property
    def valid(self) -> bool:
        return all(s.ok for s in self.steps) and not self.unsatisfied_goal

    @property
    def first_failure(self) -> StepReport | None:
        return next((s for s in self.steps if not s.ok), None)


_STEP = re.compile(r"\(([^()]*)\)")


def parse_plan_text(text: str, path: str, domain: Domain, problem: Problem) -> list[PlanStep]:
    """Parse an IPC plan (``(action arg ...)`` per line, ``;`` comments, optional ``N:``)."""
    steps: list[PlanStep] = []
    every = {**domain.constants, **problem.objects}
    by_type = objects_by_type(domain, problem)
    schemas = {a.name: a for a in domain.actions}
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = raw.split(";", 1)[0]
        stripped = line.strip()
        if not stripped:
            continue
        body = re.sub(r"^\s*\d+(\.\d+)?\s*:\s*", "", line)
        offset = len(line) - len(body)
        match = _STEP.search(body)
        if match is None or body[: match.start()].strip() or re.sub(r"\[[^\]]*\]", "", body[match.end():]).strip():
            col = offset + len(body) - len(body.lstrip()) + 1
            raise PlanFileError(f"expected '(action arg ...)', got '{stripped}'", Location(path, lineno, col))
        words = match.group(1).split()
        col = offset + match.start() + 2
        if not words:
            raise PlanFileError("empty action '()', expected '(action arg ...)'", Location(path, lineno, col - 1))
        name, args = words[0].lower(), tuple(w.lower() for w in words[1:])
        schema = schemas.get(name)
        if schema is None:
            raise PlanFileError(
                f"unknown action '{words[0]}' (expected one of: {', '.join(sorted(schemas))})",
                Location(path, lineno, col),
            )
        if len(args) != len(schema.params):
            raise PlanFileError(
                f"action '{name}' takes {len(schema.params)} argument(s), got {len(args)}",
                Location(path, lineno, col),
            )
        pos = col + len(words[0]) + 1
        for arg, (_, typ), word in zip(args, schema.params, words[1:]):
            argcol = body.find(word, pos - offset - 1) + offset + 1
            if arg not in every:
                raise PlanFileError(f"unknown object '{word}' in action '{name}'", Location(path, lineno, argcol))
            if arg not in by_type.get(typ, []):
                raise PlanFileError(
                    f"object '{word}' is a {every[arg]}, but action '{name}' expects a {typ}",
                    Location(path, lineno, argcol),
                )
        steps.append(PlanStep(name, args, lineno, col - 1))
    return steps


def parse_plan(path: str, domain: Domain, problem: Problem) -> list[PlanStep]:
    """Read and parse a plan file (``-`` for stdin). An empty plan is allowed."""
    try:
        text = read_text(path)
    except InputFileError as exc:
        if "empty" in exc.message:
            return []
        raise
    return parse_plan_text(text, path, domain, problem)


def validate_plan(domain: Domain, state: frozenset[Atom] | set[Atom], goal: tuple[Literal, ...], steps: list[PlanStep],
                  problem: Problem | None = None, goal_condition: Formula | None = None) -> ValidationReport:
    """Execute ``steps`` from ``state``; stop at the first inapplicable step.

    With ``problem``, steps are also costed (:func:`guided_lfd.pddl.model.action_cost`): a step
    whose cost has no value there cannot be applied, and the report carries the total cost.
    ADL (:mod:`guided_lfd.pddl.semantics`): preconditions and ``goal_condition`` are evaluated with
    the derived atoms of the state, conditional effects in the state before the step.
    """
    current = set(state)
    schemas = {a.name: a for a in domain.actions}
    adl = _AdlWorld(domain, problem) if domain.is_adl or goal_condition is not None else None
    reports: list[StepReport] = []
    total = 0
    for i, step in enumerate(steps, start=1):
        schema = schemas[step.action]
        binding = {v: a for (v, _), a in zip(schema.params, step.args)}
        if adl is None:
            failed: list[Formula] = [lit for lit in (l.substitute(binding) for l in schema.precondition)
                                     if not lit.holds(current)]
        else:
            world = adl.world(current)
            failed = adl.failed(schema, binding, world)
        report = StepReport(i, step, failed)
        reports.append(report)
        if not failed and problem is not None:
            try:
                total += action_cost(schema, binding, problem)
            except MissingCostError as exc:
                report.undefined_cost = exc.term
        if not report.ok:
            return ValidationReport(reports, [], frozenset(current))
        if adl is None:
            adds = {a.substitute(binding) for a in schema.add}
            dels = {a.substitute(binding) for a in schema.delete}
        else:
            adds, dels = adl.effects(schema, binding, world)
        current = (current - dels) | adds
    if adl is None:
        unsatisfied: list[Formula] = [lit for lit in goal if not lit.holds(current)]
    else:
        unsatisfied = adl.unsatisfied(goal, goal_condition, adl.world(current))
    return ValidationReport(reports, unsatisfied, frozenset(current), None if problem is None else total)


class _AdlWorld:
    """Objects by type and derived atoms, for evaluating ADL formulas on basic states
    (:mod:`guided_lfd.pddl.semantics`, imported only for ADL tasks)."""

    def __init__(self, domain: Domain, problem: Problem | None) -> None:
        from guided_lfd.pddl import semantics

        if problem is None:  # quantifiers range over the problem's objects of each type
            raise ValueError("validating a plan of an ADL domain needs its problem")
        self.domain, self.semantics = domain, semantics
        self.objects = objects_by_type(domain, problem)
        self.layers = semantics.strata(domain)

    def world(self, state: set[Atom]) -> set[Atom]:
        """``state`` with its derived atoms."""
        if not self.layers:
            return state
        return state | self.semantics.derived_atoms(self.domain, state, self.objects, self.layers)

    def failed(self, schema, binding: dict[str, str], world: set[Atom]) -> list[Formula]:
        """The precondition's parts that do not hold in ``world``."""
        return self.semantics.failed_conditions(schema, binding, world, self.objects)

    def effects(self, schema, binding: dict[str, str], world: set[Atom]) -> tuple[set[Atom], set[Atom]]:
        """(adds, deletes) of the step in ``world``."""
        return self.semantics.effect_atoms(schema, binding, world, self.objects)

    def unsatisfied(self, goal: tuple[Literal, ...], goal_condition: Formula | None,
                    world: set[Atom]) -> list[Formula]:
        """The goal's parts that do not hold in ``world``."""
        from guided_lfd.pddl.formula import holds as formula_holds

        parts = list(goal) if goal_condition is None else self.semantics.conjuncts(goal_condition)
        return [part for part in parts if not formula_holds(part, world, self.objects)]


def cost_kind(problem: Problem) -> str:
    """How a plan's cost is counted, in the words of the IPC plan format."""
    return "general cost" if problem.metric else "unit cost"


def validated(domain: Domain, problem: Problem, steps: list[PlanStep], what: str = "a plan",
              state: frozenset[Atom] | set[Atom] | None = None,
              goal: tuple[Literal, ...] | None = None) -> ValidationReport:
    """The report of ``steps`` from ``state`` (default: the problem's initial state) to ``goal`` (the problem's);
    a :class:`RuntimeError` if they do not validate: a plan guided-lfd made that fails is a bug, never hidden."""
    report = validate_plan(domain, problem.init if state is None else state, problem.goal if goal is None else goal,
                           steps, problem, problem.goal_condition if goal is None else None)
    if not report.valid:
        raise RuntimeError(f"internal check failed: {what} does not validate")
    return report


def format_plan(steps: list[str], cost: int | None = None, kind: str = "unit cost") -> str:
    """A plan in the IPC format: one action per line and a cost comment (``kind``: see :func:`cost_kind`)."""
    body = "".join(f"{s}\n" for s in steps)
    return body + f"; cost = {len(steps) if cost is None else cost} ({kind})\n"


def plan_steps(plan: list[GroundAction]) -> list[PlanStep]:
    """A plan of ground actions as the steps a validator and a document read (schema and arguments)."""
    return [PlanStep(a.schema, a.args) for a in plan]
