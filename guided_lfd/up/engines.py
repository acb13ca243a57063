"""guided-lfd as unified-planning engines: an optimal ``OneshotPlanner`` and a ``PlanValidator``.

Add them to a UP environment's factory under names of your choice
(``factory.add_engine("guided-lfd", "guided_lfd.up", "GuidedLfdPlanner")``,
or :func:`register` for both) and ask for them by name:
``OneshotPlanner(name="guided-lfd")``, ``PlanValidator(name="guided-lfd-validator")``.
"""

from __future__ import annotations

import warnings
from typing import IO, Any, Callable

from unified_planning.engines import (
    Credits, Engine, FailedValidationReason, LogLevel, LogMessage, PlanGenerationResult,
    PlanGenerationResultStatus, ValidationResult, ValidationResultStatus,
)
from unified_planning.engines.mixins import OneshotPlannerMixin, PlanValidatorMixin
from unified_planning.engines.mixins.oneshot_planner import OptimalityGuarantee
from unified_planning.environment import Environment, get_environment
from unified_planning.exceptions import UPUsageError
from unified_planning.model import AbstractProblem, ProblemKind
from unified_planning.model.metrics import MinimizeActionCosts, MinimizeSequentialPlanLength
from unified_planning.plans import Plan, PlanKind

from guided_lfd.api import PlanReport, plan, validate
from guided_lfd.deadline import MAX_TIME_LIMIT, deadline_after, seconds_left
from guided_lfd.errors import GuidedLfdError, PlanFileError, SearchTimeout, TaskTooLarge
from guided_lfd.up.task import SUPPORTED_KIND, UpTask, to_task
from guided_lfd.planning.validation import ValidationReport

__all__ = ["GuidedLfdPlanner", "GuidedLfdValidator", "register"]

Status = PlanGenerationResultStatus

_CREDITS = Credits(
    name="guided-lfd",
    author="guided-lfd developers",
    contact="guided-lfd developers (see the guided-lfd README)",
    website="see the guided-lfd README",
    license="GPL-3.0-or-later",
    short_description="guided-lfd: optimal A* with LM-cut (plans validated) and a plan validator.",
    long_description="guided-lfd's planner behind `guided-lfd plan`: A* with LM-cut over the reachable, relevant "
                     "actions, cost-optimal under action costs; every plan is validated on the lifted model. "
                     "Its validator executes a sequential plan step by step and names the first failing step.",
)


def _task_or_reason(problem: AbstractProblem) -> UpTask | str:
    """guided-lfd's task of ``problem``, or one line saying why guided-lfd cannot take it (``to_task`` checks
    the problem's kind: UP computes a kind afresh at each call)."""
    try:
        return to_task(problem)  # type: ignore[arg-type]  # an action-based problem is a Problem
    except (GuidedLfdError, TypeError) as exc:
        return str(exc)


class _GuidedLfdEngine(Engine):
    """What both engines share: the name, no options, the supported kind, the credits."""

    _name = "guided-lfd"

    def __init__(self, **options: Any) -> None:
        Engine.__init__(self)
        super(Engine, self).__init__()  # the mixin's (next after Engine in the subclass's MRO)
        if options:
            raise UPUsageError(f"guided-lfd's engines take no options, got {', '.join(sorted(options))}")

    @property
    def name(self) -> str:
        """The engine's name in UP's results."""
        return self._name

    @staticmethod
    def supported_kind() -> ProblemKind:
        """STRIPS with flat or hierarchical typing, negative conditions, equality and action costs."""
        return SUPPORTED_KIND.clone()

    @staticmethod
    def supports(problem_kind: ProblemKind) -> bool:
        """Whether guided-lfd supports every feature of ``problem_kind``."""
        return problem_kind <= SUPPORTED_KIND

    @staticmethod
    def get_credits(**kwargs: Any) -> Credits:
        """guided-lfd's credits, which UP prints when the engine is made."""
        return _CREDITS


class GuidedLfdPlanner(_GuidedLfdEngine, OneshotPlannerMixin):
    """guided-lfd's optimal planner (``guided-lfd plan``) as a UP ``OneshotPlanner``.

    Statuses: ``SOLVED_OPTIMALLY`` (the plan validated, cost-optimal under
    the problem's action costs, else of least length), ``UNSOLVABLE_PROVEN``
    (the exhaustive search found no plan), ``TIMEOUT``, ``MEMOUT`` (out of
    memory, or too large to ground), ``UNSUPPORTED_PROBLEM`` (a kind or a
    construct guided-lfd does not read; the reason is the log message) and
    ``INTERNAL_ERROR``.
    """

    @staticmethod
    def satisfies(optimality_guarantee: OptimalityGuarantee) -> bool:
        """Both guarantees: every plan found is optimal."""
        return True

    def _solve(self, problem: AbstractProblem, heuristic: Callable | None = None, timeout: float | None = None,
               output_stream: IO[str] | None = None) -> PlanGenerationResult:
        """Plan for ``problem`` within ``timeout`` seconds (reading it included)."""
        if heuristic is not None or output_stream is not None:
            warnings.warn("guided-lfd plans with its own heuristic and writes no output: "
                          "the heuristic and output stream given are not used")
        deadline = deadline_after(timeout)
        task = _task_or_reason(problem)
        if isinstance(task, str):
            return self._result(Status.UNSUPPORTED_PROBLEM, task)
        try:
            report = _plan(task, deadline)
        except SearchTimeout as exc:
            return self._result(Status.TIMEOUT, str(exc))
        except (TaskTooLarge, MemoryError) as exc:
            return self._result(Status.MEMOUT, str(exc) or "out of memory")
        except Exception as exc:  # noqa: BLE001  # UP's contract: an engine's failure is a status, not a raise
            return self._result(Status.INTERNAL_ERROR, f"{type(exc).__name__}: {exc}")
        if report.plan is None:
            return self._result(Status.UNSOLVABLE_PROVEN, f"unsolvable: exhaustive {report.search} search found no plan")
        status = Status.SOLVED_OPTIMALLY if report.optimal else Status.SOLVED_SATISFICING
        return PlanGenerationResult(status, task.sequential_plan(report.plan), self.name,
                                    metrics={"cost": str(report.cost), "search": report.search})

    def _result(self, status: PlanGenerationResultStatus, message: str) -> PlanGenerationResult:
        """A result without a plan, ``message`` its log (INFO for an answer, ERROR for a failure)."""
        level = LogLevel.INFO if status == Status.UNSOLVABLE_PROVEN else LogLevel.ERROR
        return PlanGenerationResult(status, None, self.name, log_messages=[LogMessage(level, message)])


def _plan(task: UpTask, deadline: float | None) -> PlanReport:
    """guided-lfd's validated optimal plan for ``task`` by ``deadline`` (:class:`SearchTimeout` once it passed)."""
    left = seconds_left(deadline, "reading the problem")
    return plan(task.domain, task.problem, time_limit=None if left is None else min(left, MAX_TIME_LIMIT))


class GuidedLfdValidator(_GuidedLfdEngine, PlanValidatorMixin):
    """guided-lfd's plan validator (``guided-lfd validate``) as a UP ``PlanValidator``.

    ``VALID`` (with the plan's cost as the metric's value when the problem
    has one), ``INVALID`` (reason ``INAPPLICABLE_ACTION`` with the first
    failing step, or ``UNSATISFIED_GOALS``; the log says which precondition
    or goal, as UP expressions), or ``UNKNOWN`` for a problem or plan kind
    guided-lfd does not support.
    """

    _name = "guided-lfd-validator"

    @staticmethod
    def supports_plan(plan_kind: PlanKind) -> bool:
        """Sequential plans only."""
        return plan_kind == PlanKind.SEQUENTIAL_PLAN

    def _validate(self, problem: AbstractProblem, plan: Plan) -> ValidationResult:
        """Execute ``plan`` from the problem's initial state with guided-lfd's validator."""
        if not self.supports_plan(plan.kind):  # before the task is written and read again for nothing
            task: UpTask | str = f"guided-lfd validates sequential plans, not a {plan.kind.name}"
        else:
            task = _task_or_reason(problem)
        if isinstance(task, str):
            return ValidationResult(ValidationResultStatus.UNKNOWN, self.name, [LogMessage(LogLevel.ERROR, task)])
        instances = list(plan.actions)  # type: ignore[attr-defined]  # a SequentialPlan
        try:
            report = validate(task.domain, task.problem, [task.plan_step(a) for a in instances])
        except PlanFileError as exc:  # an action or object the problem lacks, a wrong arity
            index = (exc.location.line or 1) - 1 if exc.location is not None else 0
            return self._invalid(FailedValidationReason.INAPPLICABLE_ACTION, f"step {index + 1}: {exc.message}",
                                 instances[index])
        if report.valid:
            return ValidationResult(ValidationResultStatus.VALID, self.name, [],
                                    _metric_values(problem, report.cost))
        return self._failure(task, report, instances)

    def _failure(self, task: UpTask, report: ValidationReport, instances: list) -> ValidationResult:
        """The INVALID result of ``report``: the first failing step and why, or the goals not reached."""
        failure = report.first_failure
        if failure is None:
            goals = ", ".join(str(task.expression(lit)) for lit in report.unsatisfied_goal)
            return self._invalid(FailedValidationReason.UNSATISFIED_GOALS,
                                 f"all {len(instances)} step(s) apply, but the goal is not reached: {goals} does not hold")
        instance = instances[failure.index - 1]
        if failure.undefined_cost is not None:
            why = f"its cost {failure.undefined_cost} has no value in the initial state"
        else:
            why = f"precondition {', '.join(str(task.expression(lit)) for lit in failure.failed)} does not hold"
        return self._invalid(FailedValidationReason.INAPPLICABLE_ACTION,
                             f"step {failure.index} {instance} is not applicable: {why}", instance)

    def _invalid(self, reason: FailedValidationReason, message: str, instance: Any = None) -> ValidationResult:
        """An INVALID result for ``reason``, ``message`` its log."""
        return ValidationResult(ValidationResultStatus.INVALID, self.name, [LogMessage(LogLevel.INFO, message)],
                                reason=reason, inapplicable_action=instance)


def _metric_values(problem: AbstractProblem, cost: int | None) -> dict | None:
    """The plan's cost as the value of the problem's metric (action costs or plan length), if it has one."""
    metrics = getattr(problem, "quality_metrics", [])
    if len(metrics) != 1 or cost is None or not isinstance(metrics[0], (MinimizeActionCosts,
                                                                         MinimizeSequentialPlanLength)):
        return None
    return {metrics[0]: cost}


def register(environment: Environment | None = None, planner: str = "guided-lfd",
             validator: str = "guided-lfd-validator") -> None:
    """Add both engines to ``environment``'s factory (default: UP's global one) under the names given, once."""
    factory = get_environment(environment).factory
    for name, cls in ((planner, "GuidedLfdPlanner"), (validator, "GuidedLfdValidator")):
        if name not in factory.engines:
            factory.add_engine(name, "guided_lfd.up", cls)
