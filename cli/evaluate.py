"""``guided-lfd evaluate``: the paper's measures of a guided demonstration."""

from __future__ import annotations

from typing import Annotated

import typer

from cli.common import JsonOption, OutputOption, QuietOption, check_files, output_format, command, help_footer, ui
from guided_lfd import errors
from guided_lfd.demonstration.learn import ground_actions
from guided_lfd.demonstration.segments_document import load_segments
from guided_lfd.errors import EXIT_BAD_OPTION, InputFileError, Location, OptionError
from guided_lfd.evaluate import DEFAULT_EXPLORATION_BOUND, DemonstrationSteps, excuse_defect
from guided_lfd.evaluate import evaluate as run_evaluation
from guided_lfd.excuse.document import read_excuse
from guided_lfd.excuse.engine import find_excuses
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.io import write_text
from guided_lfd.pddl.fit import check_model_fits, refuse_adl
from guided_lfd.pddl.reader import parse_domain, parse_problem_for, parse_task
from guided_lfd.reporting import csv_text


@help_footer(
    example="guided-lfd evaluate data/domains/kitchen-1/robot.pddl \\\n"
            "    data/domains/kitchen-1/problem.pddl \\\n"
            "    --human data/domains/kitchen-1/human.pddl -d p1.segments.json",
    exit_codes=(errors.EXIT_NO_EXCUSE, errors.EXIT_TOO_LARGE, errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX,
                errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED, errors.EXIT_MISMATCH, errors.EXIT_TRACE,
                errors.EXIT_OUTPUT),
    success="measures written",
)
@command
def evaluate(
    robot: Annotated[str, typer.Argument(metavar="ROBOT", help="The robot's prior domain, the one the excuse is for "
                                                                "('-' = stdin).")],
    problem: Annotated[str, typer.Argument(metavar="PROBLEM", help="The robot's task ('-' = stdin).")],
    human: Annotated[str, typer.Option("--human", metavar="DOMAIN",
                                       help="The demonstrator's domain (human skills), for predicted sizes "
                                            "and misdirected guidance.")],
    excuse: Annotated[str | None, typer.Option("--excuse", metavar="JSON",
                                               help="Excuse from 'guided-lfd excuse --json' (default: compute "
                                                    "the minimal excuse).")] = None,
    nonminimal: Annotated[str | None, typer.Option(
        "--nonminimal-excuse", metavar="JSON",
        help="A non-minimal excuse to predict a demonstration size for (default: the last excuse state on "
             "the human's full plan).")] = None,
    demonstration: Annotated[list[str] | None, typer.Option(
        "--demonstration", "-d", metavar="SEGMENTS",
        help="Segments of a demonstration (from 'guided-lfd segment'); repeatable. Gives the fraction of "
             "useful demonstration.")] = None,
    merged: Annotated[str | None, typer.Option("--merged", metavar="DOMAIN",
                                               help="Prior + learned domain (from 'guided-lfd merge'): is the "
                                                    "task solvable after the demonstration?")] = None,
    bound: Annotated[int, typer.Option("--bound", metavar="N", help="Most human states explored for misdirected guidance.")]
    = DEFAULT_EXPLORATION_BOUND,
    csv_out: Annotated[bool, typer.Option("--csv", help="Write CSV rows (measure,value,detail).")] = False,
    output: OutputOption = "-",
    json_out: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Compute the paper's measures of a guided demonstration.

    F1 savings and predicted demonstration sizes, the fraction of useful
    demonstration (-d), misdirected guidance (bounded exploration of the
    human's states) and solvability after the demonstration (--merged), for
    the excuse of --excuse or else the minimal one. A table, --json or --csv.
    """
    if bound < 1:
        raise OptionError(f"--bound {bound}: expected a number of states >= 1")
    chosen = output_format(output, json_out, csv_out, default="table")
    json_out, csv_out = chosen == "json", chosen == "csv"
    demos = demonstration or []
    check_files([robot, problem, human, excuse, nonminimal, merged, *demos], {"--output": output})
    robot_domain, task = parse_task(robot, problem)
    human_domain = parse_domain(human)
    merged_domain = parse_domain(merged) if merged else None
    ui.reading_warnings(robot_domain, human_domain, merged_domain)
    refuse_adl("evaluate", task, robot_domain, human_domain, merged_domain)  # exit 33 before any work
    check_model_fits(robot_domain, human_domain, "--human")  # as excuse and teach: exit 34 naming the predicate
    _fits_task(human_domain, problem, "--human")  # the human's domain must fit the task too
    if excuse is not None:
        changes = read_excuse(excuse, robot_domain, task)
        source = excuse
    else:
        report = find_excuses(robot_domain, task)
        if report.excuse is None:
            why = {ExcuseStatus.ALREADY_SOLVABLE: "the robot can already solve the task, so no excuse is needed",
                   ExcuseStatus.NONE: "no excuse exists (a new skill must be demonstrated)",
                   ExcuseStatus.TIMEOUT: "the excuse search ran out of time"}.get(report.status, report.status.value)
            ui.error(f"{problem}: nothing to evaluate: {why} (see `guided-lfd excuse`; or give --excuse)")
            # The excuse command's code for the outcome; an already solvable task has nothing to evaluate.
            raise typer.Exit(report.status.exit_code or EXIT_BAD_OPTION)
        changes, source = report.excuse.changes, "computed (guided-lfd excuse defaults)"
    other = read_excuse(nonminimal, robot_domain, task) if nonminimal else None
    for path, given in ((excuse, changes), (nonminimal, other)):
        why = excuse_defect(robot_domain, task, given) if path and given is not None else None
        if why:
            raise InputFileError(f"{why} (expected an excuse for {problem})", Location(path))
    documents = []
    for path in demos:
        doc = load_segments(path)
        documents.append(DemonstrationSteps(path, ground_actions(doc, path), doc.get("objects", {})))
    if merged_domain is not None:
        check_model_fits(robot_domain, merged_domain, "--merged")
        _fits_task(merged_domain, problem, "--merged")
    ui.info("[dim]evaluating: planning on the human domain, exploring its states ...[/]")
    result = run_evaluation(robot_domain, task, human_domain, changes, documents, merged_domain, other, bound)
    rows = result.rows()
    if json_out:
        text = result.to_json({"robot": robot, "problem": problem, "human": human, "excuse_source": source,
                               "merged": merged})
    elif csv_out:
        text = csv_text(["measure", "value", "detail"], rows)
    else:
        width = max(len(m) for m, _, _ in rows)
        vwidth = max(len(v) for _, v, _ in rows)
        text = "".join(f"{m:<{width}}  {v:>{vwidth}}  {d}\n" for m, v, d in rows)
    write_text(output, text)


def _fits_task(domain, problem: str, option: str) -> None:
    """The task's problem must read against ``domain`` (given with ``option``): one it cannot is a mismatch of the
    inputs (34, naming the option and what the problem uses), not an error in the problem file."""
    from guided_lfd.errors import MismatchError, PddlSemanticError

    try:
        parse_problem_for(domain, problem)
    except PddlSemanticError as exc:
        raise MismatchError(f"{option}: the task's problem does not fit this domain ({exc.message})",
                            exc.location) from None
