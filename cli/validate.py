"""``guided-lfd validate``: check a plan step by step."""

from __future__ import annotations

from typing import Annotated

import typer

from cli.common import JsonOption, OutputOption, QuietOption, check_files, output_format, command, emit, help_footer, ui
from guided_lfd import errors
from guided_lfd.errors import EXIT_PLAN_INVALID
from guided_lfd.io import json_document
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning.validation import cost_kind, parse_plan, validate_plan


@help_footer(
    example="guided-lfd validate data/domains/kitchen-1/human.pddl \\\n"
            "    data/domains/kitchen-1/problem.pddl k1.plan",
    exit_codes=(errors.EXIT_PLAN_INVALID, errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC,
                errors.EXIT_UNSUPPORTED, errors.EXIT_MISMATCH, errors.EXIT_PLAN_FILE, errors.EXIT_OUTPUT),
    success="plan valid: every step applies and the goal is reached",
)
@command
def validate(
    domain: Annotated[str, typer.Argument(metavar="DOMAIN", help="Domain PDDL file ('-' = stdin).")],
    problem: Annotated[str, typer.Argument(metavar="PROBLEM", help="Problem PDDL file ('-' = stdin).")],
    plan_file: Annotated[str, typer.Argument(metavar="PLAN", help="Plan in IPC format ('-' = stdin).")],
    output: OutputOption = "-",
    json_out: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Check a plan step by step from the initial state.

    Executes PLAN from the problem's initial state on the lifted domain; an
    invalid plan is reported with its first failing step and the precondition
    that does not hold, or the goal atoms it leaves unmet (exit 12). A valid
    plan's cost is reported too.
    """
    check_files([domain, problem, plan_file], {"--output": output})
    json_out = output_format(output, json_out) == "json"
    dom, prob = parse_task(domain, problem)
    ui.reading_warnings(dom)
    steps = parse_plan(plan_file, dom, prob)
    report = validate_plan(dom, prob.init, prob.goal, steps, prob, prob.goal_condition)
    failure = report.first_failure
    reason = None if report.valid else _reason(report, steps, plan_file)
    if json_out:
        text = json_document("validation", {
            "domain": domain, "problem": problem, "plan": plan_file, "valid": report.valid,
            "steps": [
                {"step": s.index, "action": str(s.step), "line": s.step.line, "applicable": s.ok,
                 "failed_preconditions": [str(l) for l in s.failed],
                 "undefined_cost": None if s.undefined_cost is None else str(s.undefined_cost)}
                for s in report.steps
            ],
            "goal_reached": failure is None and not report.unsatisfied_goal,
            # null when a step failed: the goal was never evaluated
            "unsatisfied_goal": None if failure is not None else [str(l) for l in report.unsatisfied_goal],
            # the number of steps, or their total-cost under the problem's metric; null when invalid
            "cost": report.cost if report.valid else None,
        })
    elif report.valid:
        text = f"valid: {len(steps)} step(s), goal reached, cost {report.cost} ({cost_kind(prob)})\n"
    else:
        text = f"{reason}\n"
    emit(output, text, reason, structured=json_out)
    if not report.valid:
        raise typer.Exit(EXIT_PLAN_INVALID)


def _reason(report, steps: list, plan_file: str) -> str:
    """Why the plan is invalid, in one line: the failing step and precondition, or the unmet goal."""
    failure = report.first_failure
    if failure is not None:
        where = f"{plan_file}:{failure.step.line}:{failure.step.col}: " if failure.step.line else ""
        if failure.undefined_cost is not None:
            return (f"{where}invalid: step {failure.index} {failure.step} cannot be applied: "
                    f"its cost {failure.undefined_cost} has no value in the problem's :init")
        return (f"{where}invalid: step {failure.index} {failure.step} is not applicable: "
                f"precondition {', '.join(str(l) for l in failure.failed)} does not hold")
    return (f"invalid: all {len(steps)} step(s) apply, but the goal is not reached: "
            f"{', '.join(str(l) for l in report.unsatisfied_goal)} does not hold")
