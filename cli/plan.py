"""``guided-lfd plan``: an optimal plan, or a proof that there is none."""

from __future__ import annotations

from typing import Annotated

import typer

from cli.common import (
    JsonOption, MemoryLimitOption, OutputOption, QuietOption, TimeLimitOption, apply_memory_limit, check_files,
    check_time_limit, command, emit, output_format,
    started_at, ui,
)
from guided_lfd.deadline import deadline_after, remaining, watchdog
from guided_lfd.errors import EXIT_UNSOLVABLE, OptionError
from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning import DEFAULT_SEARCH, SEARCHES, plan_task
from guided_lfd.validate import PlanStep, format_plan, validate_plan


@command
def plan(
    domain: Annotated[str, typer.Argument(help="Domain PDDL file ('-' = stdin).")],
    problem: Annotated[str, typer.Argument(help="Problem PDDL file ('-' = stdin).")],
    search: Annotated[
        str, typer.Option("--search", help=f"Search: {', '.join(SEARCHES)} (astar-lmcut is guided-lfd's own; the rest are pyperplan's).")
    ] = DEFAULT_SEARCH,
    output: OutputOption = "-",
    json_out: JsonOption = False,
    time_limit: TimeLimitOption = None,
    memory_limit: MemoryLimitOption = None,
    quiet: QuietOption = False,
) -> None:
    """Plan optimally (A* with LM-cut); print the plan in IPC format (exit 10 if unsolvable)."""
    if search not in SEARCHES:
        raise OptionError(f"--search {search}: unknown search (expected one of: {', '.join(SEARCHES)})")
    time_limit = check_time_limit(time_limit)
    apply_memory_limit(memory_limit)
    check_files([domain, problem], {"--output": output})
    json_out = output_format(output, json_out) == "json"
    # The time limit bounds the whole run (reading and grounding too).
    deadline = deadline_after(time_limit, started_at())
    with watchdog(deadline, "plan"):
        dom, prob = parse_task(domain, problem)
        ui.reading_warnings(dom)
        task, result = plan_task(dom, prob, search, remaining(deadline))
    if result.plan is None:
        reason = f"unsolvable: exhaustive {search} search found no plan ({result.time_s:.2f} s)"
        if json_out:
            emit(output, json_document("plan", {
                "domain": domain, "problem": problem, "status": "unsolvable", "plan": None,
                "cost": None, "optimal": None, "validated": None,
                "search": search, "time_s": round(result.time_s, 4),
            }), reason)
        else:
            ui.error(reason)  # a text result has no plan to write
        raise typer.Exit(EXIT_UNSOLVABLE)
    steps = [PlanStep(a.schema, a.args) for a in result.plan]
    report = validate_plan(dom, prob.init, prob.goal, steps)
    if not report.valid:  # the planner and the validator disagree: a bug
        raise RuntimeError("planner returned a plan that does not validate")
    names = [a.name for a in result.plan]
    if json_out:
        text = json_document("plan", {
            "domain": domain, "problem": problem, "status": "solved", "plan": names,
            "cost": len(names), "optimal": result.optimal, "validated": True,
            "search": search, "time_s": round(result.time_s, 4),
        })
    else:
        text = format_plan(names)
    write_text(output, text)
    ui.info(f"plan of length {len(names)} found by {search} in {result.time_s:.2f} s"
            + (" (optimal)" if result.optimal else "") + ", validated")
