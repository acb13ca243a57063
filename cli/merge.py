"""``guided-lfd merge``: the robot's prior domain + learned domains -> one merged domain."""

from __future__ import annotations

from dataclasses import replace
from typing import Annotated

import typer

from cli.common import JsonOption, OutputOption, QuietOption, check_files, output_format, command, help_footer, ui
from guided_lfd import errors
from guided_lfd.errors import OptionError
from guided_lfd.io import json_document, write_text
from guided_lfd.merge import merge_domains
from guided_lfd.pddl.compile import compile_negative_preconditions
from guided_lfd.pddl.model import pddl_name_defect
from guided_lfd.pddl.reader import parse_domain, parse_problem_for
from guided_lfd.pddl.writer import domain_to_pddl, problem_to_pddl


@help_footer(
    example="guided-lfd merge data/domains/kitchen-1/robot.pddl p1.learned.pddl \\\n    -o merged.pddl",
    exit_codes=(errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_MISMATCH, errors.EXIT_OUTPUT),
    success="merged domain written",
)
@command
def merge(
    prior: Annotated[str, typer.Argument(metavar="PRIOR", help="The robot's prior domain ('-' = stdin).")],
    learned: Annotated[list[str], typer.Argument(metavar="LEARNED",
                                                 help="Learned domains to merge into it ('-' = stdin).")],
    name: Annotated[str | None, typer.Option("--name", metavar="NAME", help="Name of the merged domain (default: the prior's).")] = None,
    positive_for: Annotated[str | None, typer.Option(
        "--positive-for", metavar="PROBLEM",
        help="Compile negative preconditions away (complement predicates not_p) for STRIPS-only tools such as "
             "pyperplan's parser; PROBLEM, with the complements added, goes to --problem-output.")] = None,
    problem_output: Annotated[str | None, typer.Option(
        "--problem-output", metavar="FILE", help="Where --positive-for writes the compiled problem.")] = None,
    output: OutputOption = "-",
    json_out: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Merge learned domains into the robot's prior domain.

    Types, constants, predicates and actions are united: actions equal up to
    parameter renaming are kept once, name clashes are renamed and reported,
    and every action's origin is written as a comment. Writes PDDL (or, with
    --json, a document holding it).
    """
    if (positive_for is None) != (problem_output is None):
        raise OptionError("--positive-for and --problem-output go together")
    if problem_output is not None and problem_output == output:
        raise OptionError("--problem-output must differ from --output")
    why = None if name is None else pddl_name_defect(name.lower())
    if why:
        raise OptionError(f"--name {name!r}: expected {why}")
    check_files([prior, *learned, positive_for], {"--output": output, "--problem-output": problem_output})
    json_out = output_format(output, json_out, default="pddl") == "json"
    domains = [parse_domain(path) for path in (prior, *learned)]
    ui.reading_warnings(*domains)
    result = merge_domains(domains, name.lower() if name else None)
    header = "Merged by guided-lfd merge from: " + ", ".join((prior, *learned))
    if result.notes:
        header += "\n" + "\n".join(result.notes)
    merged = result.domain
    problem_text = None
    if positive_for is not None:
        # Read the problem against the merged domain: it may use what only a learned domain declares.
        problem = replace(parse_problem_for(merged, positive_for), domain_name=merged.name)
        merged, problem = compile_negative_preconditions(merged, problem, result.locate)
        header += "\nNegative preconditions compiled into complement predicates (not_...) for " + positive_for
        problem_text = problem_to_pddl(problem, header=f"{positive_for} with complement atoms for the merged domain")
    text = domain_to_pddl(merged, header=header)
    if json_out:
        text = json_document("merge", {
            "inputs": [prior, *learned], "domain": text,
            "actions": [a.name for a in merged.actions],
            "duplicates": result.duplicates, "renamed": result.renamed, "refined": result.refined,
            "costed": result.costed,
        })
    if problem_text is not None and problem_output is not None:
        write_text(problem_output, problem_text)
    write_text(output, text)
    for note in result.notes:
        ui.info(f"[dim]{note}[/]")
    ui.info(f"[dim]{len(merged.actions)} action(s) after merging {len(domains)} domain(s)[/]")
