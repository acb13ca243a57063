"""``guided-lfd excuse``: the smallest change to the initial state the robot needs."""

from __future__ import annotations

from typing import Annotated, Any

import typer

from cli.common import (
    JsonOption, MemoryLimitOption, OutputOption, QuietOption, TimeLimitOption, apply_memory_limit, check_files,
    check_time_limit, command, emit, output_format,
    plain_stderr, started_at, ui,
)
from guided_lfd import errors
from guided_lfd.deadline import deadline_after, watchdog
from guided_lfd.excuse.engine import Excuse, ExcuseOptions, ExcuseReport, describe_change, find_excuses
from guided_lfd.excuse.space import Semantics
from guided_lfd.excuse.strategies import DEFAULT_STRATEGY, STRATEGIES
from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.model import Problem
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import problem_to_pddl

EXIT_BY_STATUS = {
    "excuse-found": errors.EXIT_OK,
    "already-solvable": errors.EXIT_OK,
    "no-excuse": errors.EXIT_NO_EXCUSE,
    "no-excuse-within-size": errors.EXIT_NO_EXCUSE_WITHIN_LIMIT,
    "timeout": errors.EXIT_TIME_LIMIT,
}


@command
def excuse(
    domain: Annotated[str, typer.Argument(help="The robot's domain (its skills).")],
    problem: Annotated[str, typer.Argument(help="The task the robot cannot plan for.")],
    semantics: Annotated[
        Semantics, typer.Option("--semantics", case_sensitive=False,
                                help="literal: the paper's definition over all atoms; "
                                     "consistent: the excuse state must also keep the state invariants.")
    ] = Semantics.CONSISTENT,
    strategy: Annotated[
        str, typer.Option("--strategy", help=f"Search strategy: {', '.join(f'{k} ({v.description})' for k, v in STRATEGIES.items())}.")
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
    max_size: Annotated[int | None, typer.Option("--max-size", help="Give up beyond this many changes (exit 13).")] = None,
    invariants_from: Annotated[
        str | None, typer.Option("--invariants-from", metavar="DOMAIN",
                                 help="Take the consistent semantics' invariants from this domain (e.g. the human's).")
    ] = None,
    fixed_from: Annotated[
        str | None, typer.Option("--fixed-from", metavar="DOMAIN",
                                 help="Also fix every predicate no action of DOMAIN changes "
                                      "(e.g. the human's domain: the world's unchangeable structure).")
    ] = None,
    excuse_problem: Annotated[
        str | None, typer.Option("--excuse-problem", metavar="FILE",
                                 help="Also write the problem with the excuse state as its initial state.")
    ] = None,
    output: OutputOption = "-",
    json_out: JsonOption = False,
    time_limit: TimeLimitOption = None,
    memory_limit: MemoryLimitOption = None,
    quiet: QuietOption = False,
) -> None:
    """Find a minimal excuse: the smallest change to the initial state after which the robot's
    own skills reach the goal. The human then only demonstrates how to reach it."""
    if strategy not in STRATEGIES:
        raise errors.OptionError(f"--strategy {strategy}: unknown strategy (expected one of: {', '.join(STRATEGIES)})")
    if max_size is not None and max_size < 0:
        raise errors.OptionError(f"--max-size {max_size}: expected a number of changes >= 0")
    time_limit = check_time_limit(time_limit)
    apply_memory_limit(memory_limit)
    check_files([domain, problem, invariants_from, fixed_from], {"--output": output, "--excuse-problem": excuse_problem})
    # The time limit bounds the whole run: reading the files counts too.
    started = started_at()
    with watchdog(deadline_after(time_limit, started), "reading the input"):
        dom, prob = parse_task(domain, problem)
        options = ExcuseOptions(
            semantics=semantics, strategy=strategy, fixed=[f.lower() for f in fixed or []], costs=list(cost or []),
            all_minimal=all_minimal, max_size=max_size, time_limit=time_limit,
            invariants_from=parse_domain(invariants_from) if invariants_from else None,
            fixed_from=parse_domain(fixed_from) if fixed_from else None, started=started,
        )
    ui.reading_warnings(dom, options.invariants_from, options.fixed_from)
    report = _run(dom, prob, options)
    spellings = {**prob.spellings, **dom.spellings}  # predicates as the domain writes them
    as_json = output_format(output, json_out) == "json"
    if as_json:
        text = json_document("excuse", _document(report, domain, problem, spellings))
    else:
        text = _text(report, prob, spellings)
    code = EXIT_BY_STATUS[report.status]
    # Every outcome is a document (its status says what happened: a timed-out
    # run says how far it got); a non-zero one also gets its reason on stderr.
    emit(output, text, _summary(report, spellings) if code else None, structured=as_json)
    if excuse_problem and report.excuse is not None:
        header = (f"Excuse state of {problem} for {domain} ({report.semantics.value} semantics):\n"
                  + "\n".join(f"  {c}" for c in report.excuse.changes))
        write_text(excuse_problem, problem_to_pddl(prob, report.excuse.state, header=header))
    stats = report.statistics
    ui.info(f"[dim]{report.strategy} search: {stats.get('candidates', 0)} candidate(s), "
            f"{stats.get('planner_calls', 0)} reachability check(s), {stats['time_s']:.2f} s[/]")
    if code:
        raise typer.Exit(code)


def _run(dom, prob, options: ExcuseOptions) -> ExcuseReport:
    if ui.quiet or plain_stderr():  # no spinner; and rich need not be asked
        return find_excuses(dom, prob, options)
    console = ui.console
    if not console.is_terminal:
        return find_excuses(dom, prob, options)
    # Only a terminal gets the spinner: rich.progress is imported here, not at start-up.
    from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    with Progress(SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn(),
                  console=console, transient=True) as bar:
        job = bar.add_task("grounding", total=None)

        def progress(message: str, candidates: int, bound: float) -> None:
            bar.update(job, description=f"{message}: {candidates} candidates checked")

        return find_excuses(dom, prob, options, progress)


def _summary(report: ExcuseReport, spellings: dict[str, str]) -> str:
    if report.status == "no-excuse":
        fixed = report.statistics.get("fixed_predicates") or []
        while_fixed = f" while {', '.join(fixed)} stay fixed" if fixed else ""
        if report.unachievable_goals:
            goals = ", ".join(str(g) for g in report.unachievable_goals)
            return (f"no excuse exists: no robot skill achieves {goals}{while_fixed}, and no change of the initial "
                    f"state short of satisfying the goal helps; a new skill must be demonstrated")
        return (f"no excuse exists: no change of the initial state lets the robot reach the goal{while_fixed}; "
                "a new skill must be demonstrated")
    if report.status == "no-excuse-within-size":
        return "no excuse within --max-size; a larger change or a new skill is needed"
    if report.status == "timeout":
        return "time limit reached before a minimal excuse was found"
    return ""


def _excuse_dict(e: Excuse, spellings: dict[str, str], costs: dict[str, int] | None = None) -> dict[str, Any]:
    return {
        "size": e.size,
        "cost": e.cost,
        "changes": [
            {"change": str(c), "op": "add" if c.added else "delete", "atom": str(c.atom),
             "text": describe_change(c, spellings)}
            for c in e.changes
        ],
        "state": [str(a) for a in sorted(e.state)],
        "plan": e.plan,
        "plan_length": len(e.plan),
        "plan_optimal": e.plan_optimal,
        "validated": True,
    }


def _document(report: ExcuseReport, domain: str, problem: str, spellings: dict[str, str]) -> dict[str, Any]:
    first = report.excuse
    return {
        "domain": domain,
        "problem": problem,
        "semantics": report.semantics.value,
        "strategy": report.strategy,
        "status": report.status,
        "message": _summary(report, spellings) or None,
        "excuse": _excuse_dict(first, spellings) if first else None,
        "alternatives": [_excuse_dict(e, spellings) for e in report.excuses[1:]],
        "robot_plan": report.robot_plan,
        "unachievable_goals": [str(g) for g in report.unachievable_goals],
        "invariants": sorted({g.invariant for g in report.invariant_groups}),
        "statistics": report.statistics,
    }


def _text(report: ExcuseReport, prob: Problem, spellings: dict[str, str]) -> str:
    name = spellings.get(prob.name, prob.name)
    lines: list[str] = []
    if report.status == "already-solvable":
        plan = report.robot_plan or []
        lines.append(f"{name}: already solvable, no excuse needed (empty excuse).")
        lines.append(f"Robot plan ({len(plan)} steps, validated):")
        lines += [f"  {i}. {step}" for i, step in enumerate(plan, 1)]
        return "\n".join(lines) + "\n"
    if not report.excuses:
        return f"{name}: {_summary(report, spellings)}\n"
    total = len(report.excuses)
    for k, e in enumerate(report.excuses, 1):
        which = f"Minimal excuse {k} of {total}" if total > 1 else "Minimal excuse"
        lines.append(f"{which} for {name} (size {e.size}, cost {e.cost}): demonstrate how to reach")
        width = max(len(describe_change(c, spellings)) for c in e.changes)
        for c in e.changes:
            lines.append(f"  {describe_change(c, spellings):<{width}}   {c}")
        kind = "optimal, validated" if e.plan_optimal else "validated"
        lines.append(f"then the robot's own plan ({len(e.plan)} steps, {kind}):")
        lines += [f"  {i}. {step}" for i, step in enumerate(e.plan, 1)]
        if k < total:
            lines.append("")
    return "\n".join(lines) + "\n"
