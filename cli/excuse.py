"""``guided-lfd excuse``: the smallest change to the initial state the robot needs."""

from __future__ import annotations

from typing import Annotated, Any

import typer

from cli.common import (
    JsonOption, MemoryLimitOption, OutputOption, QuietOption, RelaxPriorOption, SkillChangesOption, TimeLimitOption,
    apply_memory_limit, check_files, check_time_limit, command, emit, help_footer, output_format, skill_changes_switch,
    plain_stderr, started_at, ui,
)
from guided_lfd import errors
from guided_lfd.deadline import deadline_after, watchdog
from guided_lfd.excuse.document import candidate_text, cut_short, excuse_summary, held_fixed_text
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.report import ExcuseReport
from guided_lfd.excuse.progress import Progress as SearchProgress
from guided_lfd.excuse.space import Semantics
from guided_lfd.excuse.strategies import DEFAULT_STRATEGY, STRATEGIES
from guided_lfd.excuse.verify import MAX_VERIFIED_SETS
from guided_lfd.io import write_text
from guided_lfd.pddl.fit import check_human_model, check_model_fits
from guided_lfd.pddl.model import Domain
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import problem_to_pddl

def _picture_option(name: str, what: str) -> Any:
    """A ``--svg``/``--dot`` option: the excuse's picture, in one format, into FILE."""
    return typer.Option(name, metavar="FILE", help=f"Also {what} into FILE ('-' = stdout).")


SvgOption = Annotated[str | None, _picture_option("--svg", "draw the initial state and the excuse state side by "
                                                            "side, the changed facts marked, as SVG")]
DotOption = Annotated[str | None, _picture_option("--dot", "write that picture as Graphviz DOT")]


@help_footer(
    example="guided-lfd excuse data/domains/kitchen-1/robot.pddl \\\n    data/domains/kitchen-1/problem.pddl",
    exit_codes=(errors.EXIT_NO_EXCUSE, errors.EXIT_NO_EXCUSE_WITHIN_LIMIT, errors.EXIT_TIME_LIMIT,
                errors.EXIT_TOO_LARGE, errors.EXIT_MEMORY, errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX,
                errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED, errors.EXIT_MISMATCH, errors.EXIT_OUTPUT),
    success="excuse found, or none needed (the task is already solvable)",
)
@command
def excuse(
    domain: Annotated[str, typer.Argument(metavar="DOMAIN", help="The robot's domain: its skills ('-' = stdin).")],
    problem: Annotated[str, typer.Argument(metavar="PROBLEM",
                                           help="The task the robot cannot plan for ('-' = stdin).")],
    semantics: Annotated[
        Semantics, typer.Option("--semantics", case_sensitive=False, metavar="[literal|consistent]",
                                help="literal: the paper's definition over all atoms; "
                                     "consistent: the excuse state must also keep the state invariants.")
    ] = Semantics.CONSISTENT,
    strategy: Annotated[
        str, typer.Option("--strategy", metavar="NAME", help=f"Search strategy: {', '.join(f'{k} ({v.description})' for k, v in STRATEGIES.items())}.")
    ] = DEFAULT_STRATEGY,
    fixed: Annotated[
        list[str] | None, typer.Option("--fixed", metavar="PRED", help="Predicate the excuse may not change (repeatable).")
    ] = None,
    cost: Annotated[
        list[str] | None, typer.Option("--cost", metavar="SPEC",
                                       help="Change cost: 'PRED=N' or '(atom args)=N' (repeatable; default 1). "
                                            "Total cost is minimised, ties broken by size.")
    ] = None,
    all_minimal: Annotated[bool, typer.Option("--all", help="List every minimal excuse, not just the first.")] = False,
    max_size: Annotated[int | None, typer.Option("--max-size", metavar="N", help="Give up beyond N changes (exit 13).")] = None,
    invariants_from: Annotated[
        str | None, typer.Option("--invariants-from", metavar="DOMAIN",
                                 help="Take the consistent semantics' invariants from this domain (e.g. the human's).")
    ] = None,
    fixed_from: Annotated[
        str | None, typer.Option("--fixed-from", metavar="DOMAIN",
                                 help="Also fix every predicate no action of DOMAIN changes "
                                      "(e.g. the human's domain: the world's unchangeable structure).")
    ] = None,
    prefer: Annotated[
        str | None, typer.Option("--prefer", metavar="CRITERION",
                                 help="'demonstration': of the minimal excuses, the one whose predicted "
                                      "demonstration (the --human model's shortest plan to it) is shortest.")
    ] = None,
    human: Annotated[
        str | None, typer.Option("--human", metavar="DOMAIN",
                                 help="The human model: the excuse changes only what its actions change (as with "
                                      "--fixed-from, which wins if given), and --prefer predicts with it.")
    ] = None,
    slack: Annotated[
        int | None, typer.Option("--slack", metavar="K", help="With --all or --prefer: also the excuses up to K "
                                                              "costlier than the minimum (none a superset of another).")
    ] = None,
    excuse_problem: Annotated[
        str | None, typer.Option("--excuse-problem", metavar="FILE",
                                 help="Also write the problem with the excuse state as its initial state to FILE "
                                      "('-' = stdout).")
    ] = None,
    change_structure: Annotated[
        bool, typer.Option("--change-structure",
                           help="Let the excuse change the world's structure: the kinds of things and fixed graphs "
                                "(adjacency, floors) that no action changes, held fixed by default unless --fixed-from "
                                "or --human says what can change.")
    ] = False,
    one_place: Annotated[
        bool, typer.Option("--one-place/--many-places",
                           help="Under --semantics consistent, keep each thing a static relation puts in one place "
                                "((at bot hall), no robot action moving it) in at most one place (default), or let "
                                "the excuse put it in several.")
    ] = True,
    skill_changes: SkillChangesOption = "on",
    relax_prior: RelaxPriorOption = False,
    verify: Annotated[
        bool, typer.Option("--verify", help="Re-verify the minimum: enumerate every cheaper change set and refuse "
                                            "each with the checker's own invariants and another planner (up to "
                                            f"{MAX_VERIFIED_SETS} sets; statistics.minimality says how it went).")
    ] = False,
    svg: SvgOption = None,
    dot: DotOption = None,
    output: OutputOption = "-",
    json_out: JsonOption = False,
    time_limit: TimeLimitOption = None,
    memory_limit: MemoryLimitOption = None,
    quiet: QuietOption = False,
) -> None:
    """Find a minimal excuse: what the human must demonstrate.

    The excuse is the smallest change to the initial state after which the
    robot's own skills reach the goal: the human then demonstrates only how to
    reach it. The robot's plan from the excuse state is printed, validated.
    """
    _check_choices(prefer, human, slack, all_minimal, strategy, max_size, skill_changes, relax_prior)
    time_limit = check_time_limit(time_limit)
    apply_memory_limit(memory_limit)
    check_files([domain, problem, invariants_from, fixed_from, human],
                {"--output": output, "--excuse-problem": excuse_problem, "--svg": svg, "--dot": dot})
    # The time limit bounds the whole run: reading the files counts too.
    started = started_at()
    with watchdog(deadline_after(time_limit, started), "reading the input"):
        dom, prob = parse_task(domain, problem)
        options = ExcuseOptions(
            semantics=semantics, strategy=strategy, fixed=[f.lower() for f in fixed or []], costs=list(cost or []),
            all_minimal=all_minimal or prefer is not None, max_size=max_size, time_limit=time_limit, slack=slack or 0,
            invariants_from=parse_domain(invariants_from) if invariants_from else None,
            fixed_from=parse_domain(fixed_from) if fixed_from else None, started=started,
            verify=verify, change_structure=change_structure, one_place=one_place,
            skill_changes=skill_changes_switch(skill_changes, relax_prior), relax_prior=relax_prior,
        )
        human_domain = parse_domain(human) if human else None
        if human_domain is not None:
            check_model_fits(dom, human_domain, "--human")
            check_human_model(human_domain, prob)
            if options.fixed_from is None:  # what the human can change decides what the excuse may change
                options.fixed_from = human_domain
    ui.reading_warnings(dom, options.invariants_from, options.fixed_from)
    report = _run(dom, prob, options)
    if prefer and human_domain is not None and report.excuses:
        _prefer(report, human_domain, dom, prob, all_minimal, deadline_after(time_limit, started))
    spellings = report.spellings  # predicates as the domain writes them
    as_json = output_format(output, json_out) == "json"
    text = report.to_json() if as_json else report.to_text()
    code = report.status.exit_code
    # Every outcome is a document (its status says what happened: a timed-out
    # run says how far it got); a non-zero one also gets its reason on stderr.
    # A timed-out run's best excuse is more than the reason: text on stdout
    # gets it (the reason goes to stderr only).
    best = "" if as_json or output != "-" else candidate_text(report, prob, spellings)
    emit(output, best or text, excuse_summary(report, spellings) if code else None, structured=as_json or bool(best))
    if as_json:  # the text says it itself
        for note in cut_short(report):
            ui.info_plain(f"warning: {note}")
    if excuse_problem and report.excuse is not None:
        dropped = [str(c) for c in report.excuse.skill_changes]
        header = (f"Excuse state of {problem} for {domain} ({report.semantics.value} semantics):\n"
                  + "\n".join(f"  {c}" for c in [*report.excuse.changes, *dropped]))
        write_text(excuse_problem, problem_to_pddl(prob, report.excuse.state, header=header))
        if dropped:  # the problem alone is not what the robot plans: its skills need the preconditions dropped
            ui.info_plain(f"warning: {excuse_problem} is the excuse state; the robot plans from it only with "
                          f"{', '.join(dropped)} (the skill changes)")
    if svg:  # every outcome has a picture: without an excuse, the initial state and why
        write_text(svg, report.to_svg())
    if dot:
        write_text(dot, report.to_dot())
    _diagnostics(report, options.fixed_from)
    if code:
        raise typer.Exit(code)



def _check_choices(prefer: str | None, human: str | None, slack: int | None, all_minimal: bool, strategy: str,
                   max_size: int | None, skill_changes: str, relax_prior: bool) -> None:
    """Options that contradict each other or take no such value, refused before anything is read."""
    if prefer not in (None, "demonstration"):
        raise errors.OptionError(f"--prefer {prefer}: expected 'demonstration'")
    if prefer and not human:
        raise errors.OptionError("--prefer demonstration: needs the human model (--human DOMAIN)")
    if slack and not (all_minimal or prefer):
        raise errors.OptionError(f"--slack {slack}: needs --all or --prefer (it widens the excuses listed)")
    if strategy not in STRATEGIES:
        raise errors.OptionError(f"--strategy {strategy}: unknown strategy (expected one of: {', '.join(STRATEGIES)})")
    if max_size is not None and max_size < 0:
        raise errors.OptionError(f"--max-size {max_size}: expected a number of changes >= 0")
    skill_changes_switch(skill_changes, relax_prior)

def _diagnostics(report: ExcuseReport, model: Domain | None) -> None:
    """On stderr: what the excuse held fixed and why, and the search's effort."""
    stats = report.statistics
    held = held_fixed_text(report, model)
    if held:
        ui.info_plain(held)
    ui.info(f"[dim]{report.strategy} search: {stats.candidates or 0} candidate(s), "
            f"{stats.planner_calls or 0} reachability check(s), {stats.time_s or 0:.2f} s[/]")


def _prefer(report: ExcuseReport, human, dom, prob, keep_all: bool, deadline: float | None) -> None:
    """Rank the minimal excuses by predicted demonstration (--prefer), within the run's time limit: past it,
    the excuses found are printed unranked (the first one alone without --all) and stderr says so."""
    from guided_lfd.errors import SearchTimeout
    from guided_lfd.preference import apply_preference

    try:
        with watchdog(deadline, "predicting the demonstrations"):
            apply_preference(report, human, dom, prob, keep_all=keep_all, deadline=deadline)
    except SearchTimeout:
        report.preference = None
        if not keep_all:
            report.excuses = report.excuses[:1]
        ui.info_plain("--prefer demonstration: the time limit was reached before the demonstrations were "
                      "predicted; the minimal excuses are not ranked")


def _run(dom, prob, options: ExcuseOptions) -> ExcuseReport:
    if ui.quiet or plain_stderr():  # no status line; and rich need not be asked
        return find_excuses(dom, prob, options)
    console = ui.console
    if not console.is_terminal:
        return find_excuses(dom, prob, options)
    # Only a terminal gets the status line: rich.progress is imported here, not at start-up.
    from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    with Progress(SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn(),
                  console=console, transient=True) as bar:
        job = bar.add_task("grounding", total=None)
        return find_excuses(dom, prob, options, lambda p: bar.update(job, description=progress_line(p)))


def progress_line(progress: SearchProgress) -> str:
    """The status line for one progress report: the phase, then what the search has proven and done."""
    if progress.lower_bound is None:
        return progress.phase
    line = (f"{progress.phase}: lower bound {progress.lower_bound}, {progress.nodes:,} nodes, "
            f"{progress.oracle_calls:,} reachability checks")
    if progress.best_cost is not None:
        line += f", best excuse so far costs {progress.best_cost}"
    return line
