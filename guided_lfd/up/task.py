"""A unified-planning ``Problem`` as guided-lfd's task, and the names back to UP.

UP's own :class:`~unified_planning.io.PDDLWriter` writes the problem as PDDL
text, which :func:`guided_lfd.read_task` reads as any other; the writer may
rename (PDDL names are lower-case, without spaces, never a keyword), and its
name maps turn every name of guided-lfd's task back into the UP object,
fluent or action it stands for.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Iterable

from unified_planning.exceptions import UPException
from unified_planning.io import PDDLWriter
from unified_planning.model import FNode, Problem as UPProblem, ProblemKind
from unified_planning.model.problem_kind_versioning import LATEST_PROBLEM_KIND_VERSION
from unified_planning.plans import ActionInstance, SequentialPlan

from guided_lfd.errors import OptionError, UnsupportedFeatureError
from guided_lfd.pddl.model import EQUALITY, Atom, Domain, Literal, Problem
from guided_lfd.planning.validation import PlanStep

__all__ = ["SUPPORTED_KIND", "UpTask", "to_task", "unsupported_features"]

#: What guided-lfd reads (see docs/pddl.md), in UP's words. Costs must be whole numbers >= 0, which no
#: ProblemKind feature says: a fractional cost passes :func:`unsupported_features` and is refused when read.
SUPPORTED_KIND = ProblemKind((
    "ACTION_BASED", "FLAT_TYPING", "HIERARCHICAL_TYPING", "NEGATIVE_CONDITIONS", "EQUALITIES",
    "ACTIONS_COST", "PLAN_LENGTH", "STATIC_FLUENTS_IN_ACTIONS_COST", "INT_NUMBERS_IN_ACTIONS_COST",
    # UP's PDDL reader gives every :action-costs number as a real, and costs left out of :init as undefined.
    "REAL_NUMBERS_IN_ACTIONS_COST", "UNDEFINED_INITIAL_NUMERIC",
), version=LATEST_PROBLEM_KIND_VERSION)


def unsupported_features(kind: ProblemKind) -> list[str]:
    """The features of ``kind`` guided-lfd does not support (none: it supports the kind), sorted."""
    if kind <= SUPPORTED_KIND:
        return []
    return sorted(kind.features - SUPPORTED_KIND.features)


@dataclass
class UpTask:
    """guided-lfd's task of a UP problem, with the writer's name maps to go back to UP."""

    up_problem: UPProblem
    domain: Domain
    problem: Problem
    writer: PDDLWriter = field(repr=False)

    def item(self, name: str) -> Any:
        """The UP object, fluent, action or type that guided-lfd's (PDDL) ``name`` stands for."""
        return self.writer.get_item_named(name)

    def pddl_name(self, item: object) -> str:
        """guided-lfd's (PDDL) name of a UP object, fluent, action or type (for ``ExcuseOptions(fixed=...)``)."""
        return self.writer.get_pddl_name(item)

    def expression(self, fact: Atom | Literal) -> FNode:
        """A fact (or a literal: negated, or an equality) as a UP expression over the problem's fluents and objects."""
        manager = self.up_problem.environment.expression_manager
        literal = fact if isinstance(fact, Literal) else Literal(fact)
        args = [manager.ObjectExp(self.item(a)) for a in literal.atom.args]
        if literal.atom.predicate == EQUALITY:
            atom = manager.Equals(*args)
        else:
            atom = manager.FluentExp(self.item(literal.atom.predicate), args)
        return atom if literal.positive else manager.Not(atom)

    def action_instance(self, step: PlanStep) -> ActionInstance:
        """A plan step as a UP ``ActionInstance`` of the problem's action on its objects."""
        return ActionInstance(self.item(step.action), tuple(self.item(a) for a in step.args))

    def sequential_plan(self, steps: Iterable[PlanStep]) -> SequentialPlan:
        """Plan steps as a UP ``SequentialPlan``."""
        return SequentialPlan([self.action_instance(s) for s in steps], self.up_problem.environment)

    def plan_step(self, instance: ActionInstance) -> PlanStep:
        """A UP ``ActionInstance`` as guided-lfd's plan step (a name the writer does not know is kept as UP's,
        so that the validator names it)."""
        args = tuple(self._name_of(p.object()) if p.is_object_exp() else str(p) for p in instance.actual_parameters)
        return PlanStep(self._name_of(instance.action), args)

    def _name_of(self, item: object) -> str:
        """The PDDL name of ``item``, or its own name where the writer never wrote it (another problem's)."""
        try:
            return self.pddl_name(item)
        except UPException:  # not an item of this problem
            return str(getattr(item, "name", item))


def to_task(problem: UPProblem) -> UpTask:
    """guided-lfd's task of a UP ``problem`` (through UP's PDDL writer and guided-lfd's reader).

    A problem of a kind guided-lfd does not support (numeric fluents,
    durative actions, conditional effects, ...) is an
    :class:`~guided_lfd.errors.UnsupportedFeatureError` naming UP's features;
    what the reader refuses in the written PDDL raises the reader's errors.
    """
    from guided_lfd.pddl.reader import parse_task

    if not isinstance(problem, UPProblem):
        raise OptionError(f"problem {type(problem).__name__}: expected a unified-planning Problem")
    missing = unsupported_features(problem.kind)
    if missing:
        raise UnsupportedFeatureError(f"unified-planning problem '{problem.name}': {', '.join(missing)} "
                                      "(guided-lfd plans for STRIPS with typing, negative conditions, equality "
                                      "and action costs)")
    writer = PDDLWriter(problem)
    try:
        domain_text, problem_text = writer.get_domain(), writer.get_problem()
    except UPException as exc:  # e.g. a boolean fluent with no initial value
        raise UnsupportedFeatureError(f"unified-planning problem '{problem.name}' cannot be written as PDDL: {exc}")
    domain, task_problem = parse_task("<domain>", "<problem>", domain_text=domain_text, problem_text=problem_text)
    return UpTask(problem, domain, task_problem, writer)
