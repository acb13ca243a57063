"""``guided-lfd plan``: an optimal plan, or a proof that there is none."""

from __future__ import annotations

from typing import Annotated

import typer

from cli.common import (
    JsonOption, MemoryLimitOption, OutputOption, QuietOption, TimeLimitOption, apply_memory_limit, check_files,
    check_time_limit, command, emit, help_footer, output_format,
    started_at, ui,
)
from guided_lfd.deadline import deadline_after, seconds_left, watchdog
from guided_lfd import errors
from guided_lfd.errors import EXIT_UNSOLVABLE, OptionError
from guided_lfd.api import plan as plan_and_validate
from guided_lfd.io import write_text
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning import DEFAULT_SEARCH, SEARCHES
from guided_lfd.planning.validation import cost_kind, format_plan


@help_footer(
    example="guided-lfd plan data/domains/kitchen-1/human.pddl \\\n    data/domains/kitchen-1/problem.pddl -o k1.plan",
    exit_codes=(errors.EXIT_UNSOLVABLE, errors.EXIT_TIME_LIMIT, errors.EXIT_TOO_LARGE, errors.EXIT_MEMORY,
                errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_MISMATCH, errors.EXIT_OUTPUT),
    success="plan found (and validated)",
)
@command
def plan(
    domain: Annotated[str, typer.Argument(metavar="DOMAIN", help="Domain PDDL file ('-' = stdin).")],
    problem: Annotated[str, typer.Argument(metavar="PROBLEM", help="Problem PDDL file ('-' = stdin).")],
    search: Annotated[
        str, typer.Option("--search", metavar="NAME", help=f"Search: {', '.join(SEARCHES)} (astar-lmcut is guided-lfd's own; the rest are pyperplan's).")
    ] = DEFAULT_SEARCH,
    output: OutputOption = "-",
    json_out: JsonOption = False,
    time_limit: TimeLimitOption = None,
    memory_limit: MemoryLimitOption = None,
    quiet: QuietOption = False,
) -> None:
    """Plan optimally (A* with LM-cut), or prove unsolvability.

    The plan is printed in IPC format (one action a line, then its cost as a
    comment) once it has been validated against the lifted domain. When an
    exhaustive search finds no plan, the task is unsolvable (exit 10).
    """
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
        report = plan_and_validate(dom, prob, search, seconds_left(deadline, "plan"))
    if not report.solved:
        if report.answered_by == "symbolic":
            reason = f"unsolvable: proved by symbolic search beside {search} ({report.time_s:.2f} s)"
        else:
            reason = f"unsolvable: exhaustive {search} search found no plan ({report.time_s:.2f} s)"
        if json_out:
            emit(output, report.to_json(), reason)
        else:
            ui.error(reason)  # a text result has no plan to write
        raise typer.Exit(EXIT_UNSOLVABLE)
    names = [str(step) for step in report.plan or []]
    text = report.to_json() if json_out else format_plan(names, report.cost, cost_kind(prob))
    write_text(output, text)
    costs = f", cost {report.cost}" if prob.metric else ""
    ui.info(f"plan of length {len(names)}{costs} found by {search} in {report.time_s:.2f} s"
            + (" (optimal)" if report.optimal else "") + ", validated")
