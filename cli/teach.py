"""``guided-lfd teach``: the whole guided-teaching loop, round by round, until the robot can plan its task."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Annotated

import typer

from cli.common import (JsonOption, path_name, QuietOption, RelaxPriorOption, SkillChangesOption, TimeLimitOption,
                        check_inputs, check_time_limit, command, help_footer, one_line, skill_changes_switch,
                        started_at, ui)
from guided_lfd.deadline import deadline_after, watchdog
from guided_lfd.pddl.fit import check_model_fits
from guided_lfd import errors


class _Prompted:
    """On a terminal: ask the demonstrator for each round's trace, after showing the request."""

    def demonstrate(self, folder, state, request, problem):
        from guided_lfd.demonstration import default_state_path

        while True:  # a path that is not there is asked again, not the end of the session
            try:
                answer = typer.prompt("Path of the demonstration's trace CSV (empty: stop)", default="",
                                      show_default=False, err=True).strip()
            except typer.Abort as exc:
                if isinstance(exc.__context__, EOFError):
                    return None  # end of input (Ctrl-D, a closed pipe): the demonstrator stopped
                # Ctrl-C (or SIGTERM, raised as Terminated): interrupted, as anywhere else.
                raise (exc.__context__ if isinstance(exc.__context__, KeyboardInterrupt)
                       else KeyboardInterrupt()) from None
            if not answer:
                return None
            try:
                trace, states = Path(answer), Path(default_state_path(answer))
                missing = [str(p) for p in (trace, states) if not p.is_file()]
            except (OSError, ValueError) as exc:  # a name too long for the file system, a NUL in it
                typer.echo(f"not a path: {type(exc).__name__}: {one_line(str(exc))[:200]}", err=True)
                continue
            if not missing:
                return trace, states
            typer.echo(f"not found: {', '.join(missing)} (the trace and its .state.csv beside it)", err=True)

    def answer_skill(self, request) -> str | None:
        """A skill asked for once more: whether the teacher can do it there (no: the answer, yes: None)."""
        try:
            can = typer.confirm(f"Can {' '.join((request.step.action, *request.step.args))} be done here?",
                                default=True, err=True)
        except typer.Abort:
            return None  # no answer: the trace prompt that follows decides
        return None if can else "the teacher answered at the prompt that it cannot be done there"

    def why_none(self, state, request, problem) -> str:
        """The demonstrator stopped: an empty answer at the prompt."""
        return "the demonstrator gave no trace at the prompt (an empty answer stops the session)"


class _Chain:
    """The given traces first, then (on a terminal) prompts; the simulated human instead when one is given."""

    def __init__(self, simulate, traces: list[Path], prompt: bool) -> None:
        self.simulate, self.traces, self.prompt = simulate, traces, prompt
        self.given = len(traces)
        self.answered = False  # the last round asked for a demonstration and got --demo cannot instead

    def demonstrate(self, folder, state, request, problem):
        from guided_lfd.teach import GivenTraces
        from guided_lfd.teach.human import CANNOT

        self.answered = bool(self.traces) and str(self.traces[0]) == CANNOT
        if self.traces:
            return GivenTraces(self.traces).demonstrate(folder, state, request, problem)
        if self.simulate is not None:
            return self.simulate.demonstrate(folder, state, request, problem)
        return _Prompted().demonstrate(folder, state, request, problem) if self.prompt else None

    def answer_skill(self, request) -> str | None:
        """The answer to a skill asked for once more: ``--demo cannot`` next, the simulated human's, the prompt's."""
        from guided_lfd.teach import GivenTraces

        if self.traces:
            return GivenTraces(self.traces).answer_skill(request)
        if self.simulate is not None:
            return self.simulate.answer_skill(request)
        return _Prompted().answer_skill(request) if self.prompt else None

    def why_none(self, state, request, problem) -> str:
        """Why :meth:`demonstrate` gave None: the simulated human's reason, the prompt's, or no demonstrator."""
        if self.answered:
            return ("the round asked for a demonstration and the next --demo was 'cannot', which answers only a "
                    "round that asks for a skill once more")
        if self.simulate is not None:
            return self.simulate.why_none(state, request, problem)
        if self.prompt:
            return _Prompted().why_none(state, request, problem)
        traces = f"all {self.given} --demo trace(s) were used" if self.given else "no --demo trace"
        return f"no demonstration was given ({traces}, no --simulate HUMAN, and no terminal to ask for one)"


def _check_session(session: Path, inputs: list[str | None]) -> None:
    """Refuse, before any work, a session folder that is a file, or that holds one of the run's inputs
    (a session writes robot.pddl, session.json, session.md and round-N/ there)."""
    from guided_lfd.errors import Location, OutputError

    check_inputs(*[p for p in inputs if p is not None])
    resolved = []
    for path in inputs:
        if path is not None and path != "-":
            try:
                resolved.append((path, Path(path).resolve()))
            except (OSError, RuntimeError) as exc:  # a link loop
                raise errors.InputFileError(f"cannot be read ({getattr(exc, 'strerror', None) or exc})",
                                            Location(path)) from None
    try:
        if session.exists() and not session.is_dir():
            raise OutputError("is a file, expected a folder for the session (-o SESSION_DIR)", Location(str(session)))
        root = session.resolve()
    except (OSError, RuntimeError) as exc:  # a link loop
        raise OutputError(f"cannot be the session folder ({getattr(exc, 'strerror', None) or exc})",
                          Location(str(session))) from None
    for path, where in resolved:
        if where.is_relative_to(root):
            raise errors.OptionError(f"-o {session}: holds {path}, an input of this run, which the session's files "
                                     "may replace; expected another folder")


@help_footer(
    example="guided-lfd teach data/domains/kitchen-2/robot.pddl \\\n"
            "    data/domains/kitchen-2/problem.pddl \\\n"
            "    --simulate data/domains/kitchen-2/human.pddl -o session",
    exit_codes=(errors.EXIT_NO_EXCUSE, errors.EXIT_NOT_TAUGHT, errors.EXIT_DEMONSTRATION_ONLY, errors.EXIT_TIME_LIMIT,
                errors.EXIT_INPUT_FILE, errors.EXIT_PDDL_SYNTAX, errors.EXIT_PDDL_SEMANTIC, errors.EXIT_UNSUPPORTED,
                errors.EXIT_MISMATCH, errors.EXIT_TRACE, errors.EXIT_BAD_OPTION, errors.EXIT_OUTPUT),
    success="the taught robot plans its task from the start (or already could)",
)
@command
def teach(
    robot: Annotated[str, typer.Argument(metavar="ROBOT", help="The robot's domain (its skills).")],
    problem: Annotated[list[str], typer.Argument(metavar="PROBLEM",
                                                 help="The task to teach; several (or a folder of problem files, "
                                                      "in name order): taught in sequence, each from the skills the "
                                                      "earlier ones left.")],
    session: Annotated[Path, typer.Option("-o", "--output", parser=path_name, metavar="SESSION_DIR",
                                          help="Folder for every round's files, robot.pddl, session.json and "
                                               "session.md.")] = Path("session"),
    demo: Annotated[list[Path] | None, typer.Option("--demo", parser=path_name, metavar="TRACE",
                                                    help="A demonstration's trace CSV (its state file beside it, "
                                                         "TRACE.state.csv); repeatable, one per round, in order; "
                                                         "'cannot' answers a round that asks for a skill once "
                                                         "more that it cannot be done there.")] = None,
    simulate: Annotated[str | None, typer.Option("--simulate", metavar="HUMAN",
                                                 help="Simulate the demonstrator with this human domain: its "
                                                      "shortest plan to each request, rendered as a hand trace.")] = None,
    human_model: Annotated[str | None, typer.Option("--human", metavar="DOMAIN",
                                                    help="The human model (default: the --simulate domain): "
                                                         "excuses only change what the human can, and the request "
                                                         "is the smallest part of the excuse that suffices.")] = None,
    prefer: Annotated[str | None, typer.Option("--prefer", metavar="CRITERION",
                                               help="'demonstration': ask for the minimal excuse with the "
                                                    "shortest predicted demonstration (needs a human model).")] = None,
    slack: Annotated[int | None, typer.Option("--slack", metavar="K",
                                              help="With --prefer: also consider excuses up to K costlier than the "
                                                   "minimum.")] = None,
    redundancy: Annotated[bool, typer.Option("--redundancy/--no-redundancy",
                                             help="Ask only for the part of the excuse that suffices "
                                                  "(with a human model).")] = True,
    mistakes: Annotated[str | None, typer.Option("--mistakes", metavar="SPEC",
                                                 help="With --simulate: the simulated teacher makes mistakes at "
                                                      "these rates per demonstration: KIND=RATE[,...] with KIND "
                                                      "wrong-object, partial, extra-steps, wrong-order, misread, or "
                                                      "any=RATE (e.g. any=25%).")] = None,
    trace_noise: Annotated[str | None, typer.Option("--trace-noise", metavar="SPEC",
                                                    help="With --simulate: a real tracker's noise in the rendered "
                                                         "traces: KEY=VALUE[,...] with loss, regrasp, grip (s), "
                                                         "drops, duplicates, bursts, flicker (rates), jitter (s); "
                                                         "e.g. loss=2,regrasp=0.25,drops=0.05.")] = None,
    seed: Annotated[int, typer.Option("--seed", metavar="N", help="With --simulate: the seed of its mistakes and "
                                                                  "the rendered trace's noise.")] = 0,
    skill_changes: SkillChangesOption = "on",
    relax_prior: RelaxPriorOption = False,
    max_rounds: Annotated[int, typer.Option("--max-rounds", metavar="N", help="Stop after N rounds.")] = 5,
    json_out: JsonOption = False,
    time_limit: TimeLimitOption = None,
    quiet: QuietOption = False,
) -> None:
    """Teach the robot its task, one demonstration per round.

    Each round asks for the minimal excuse (in the paper's words: Open
    PinkDrawer), says why the robot needs it and what to leave as it is, takes
    the next --demo trace (or a simulated one with --simulate, or asks for a
    path on a terminal), segments it, learns and merges its skills and
    re-plans.  SESSION_DIR/session.json (format guided-lfd/teach) records
    every round.
    """
    from guided_lfd.excuse.engine import ExcuseOptions
    from guided_lfd.io import write_text
    from guided_lfd.pddl.reader import parse_domain, parse_task
    from guided_lfd.teach import SimulatedHuman, check_human_model, teach as run_teach
    from guided_lfd.teach.mistakes import Mistakes

    if max_rounds < 1:
        raise errors.OptionError(f"--max-rounds {max_rounds}: expected a number of rounds >= 1")
    if prefer not in (None, "demonstration"):
        raise errors.OptionError(f"--prefer {prefer}: expected 'demonstration'")
    time_limit = check_time_limit(time_limit)
    switch = skill_changes_switch(skill_changes, relax_prior)
    given = [name for name, value in (("--mistakes", mistakes), ("--trace-noise", trace_noise), ("--seed", seed))
             if value is not None and value != 0]
    if given and not simulate:
        raise errors.OptionError(f"{given[0]}: needs the simulated teacher (--simulate HUMAN)")
    if seed < 0:
        raise errors.OptionError(f"--seed {seed}: expected a whole number >= 0")
    if mistakes is not None:
        Mistakes.parse(mistakes)  # refused before anything is read
    noise = _trace_noise(trace_noise, seed)
    from guided_lfd.demonstration import default_state_path

    problems = _problem_files(problem)
    _check_session(session, [robot, *problems, simulate, human_model, *(str(d) for d in demo or []),
                             *(default_state_path(str(d)) for d in demo or [])])
    deadline = deadline_after(time_limit, started_at())  # the whole run: reading, every round, re-planning
    with watchdog(deadline, "reading the input"):
        robot_domain, task = parse_task(robot, problems[0])
        tasks = [task, *(parse_task(robot, p)[1] for p in problems[1:])]
        human = SimulatedHuman(parse_domain(simulate), robot=robot_domain, seed=seed, noise=noise,
                               mistakes=None if mistakes is None else Mistakes.parse(mistakes)) if simulate else None
        model = parse_domain(human_model) if human_model else human.human if human else None
    ui.reading_warnings(robot_domain)
    if slack and not prefer:
        raise errors.OptionError(f"--slack {slack}: needs --prefer demonstration")
    if prefer and model is None:
        raise errors.OptionError("--prefer demonstration: needs a human model (--human DOMAIN or --simulate HUMAN)")
    for human_domain, option in ((model, "--human" if human_model else "--simulate"),
                                 (human.human if human else None, "--simulate")):
        if human_domain is not None:  # a model of another world: exit 34 before any round
            check_model_fits(robot_domain, human_domain, option)  # a clash with the robot says more than a gap
            for each in tasks:
                check_human_model(human_domain, each)
    prompt = sys.stdin is not None and sys.stdin.isatty() and not json_out and human is None
    demonstrator = _Chain(human, list(demo or []), prompt=prompt)

    excuse_options = ExcuseOptions(slack=slack or 0, skill_changes=switch, relax_prior=relax_prior)
    options = dict(max_rounds=max_rounds, options=excuse_options, human=model,
                   prefer=prefer is not None, redundancy=redundancy, deadline=deadline, on_request=_shower(prompt))
    if len(tasks) > 1:
        _teach_sequence(robot_domain, tasks, demonstrator, session, options, json_out)
        return
    with watchdog(deadline, "teaching"):  # the rounds check it themselves; this ends what does not
        session_obj = run_teach(robot_domain, task, demonstrator, session, **options)
    write_text(session / "session.json", session_obj.to_json())
    write_text(session / "session.md", session_obj.to_markdown())
    if json_out:
        write_text("-", session_obj.to_json())
    _report(session_obj, session)


def _trace_noise(spec: str | None, seed: int):
    """``--trace-noise SPEC`` as the renderer's Noise (None: the default noise)."""
    if spec is None:
        return None
    from guided_lfd.demonstration.render import Noise

    try:
        return Noise.parse(spec, seed)
    except ValueError as exc:
        raise errors.OptionError(f"--trace-noise: {exc}") from None


def _shower(prompt: bool):
    """What shows each round's request as the demonstrator reads it: on a terminal always, else a diagnostic."""
    def show(rnd) -> None:
        lines = [f"round {rnd.index}, please demonstrate: {'; '.join(rnd.request_text)}",
                 *(f"  asked again: {line}" for line in rnd.asked_again),
                 *([f"  {rnd.excuse_text()}"] if rnd.excuse_text() else []), *(f"  why: {w}" for w in rnd.why)]
        if rnd.keep_text:
            lines.append("  leave as it is: " + "; ".join(rnd.keep_text))
        if rnd.held:
            lines.append(f"  {rnd.held}")
        for line in lines:
            typer.echo(line, err=True) if prompt else ui.info_plain(line)

    return show


def _problem_files(arguments: list[str]) -> list[str]:
    """The tasks named: each file as given, each folder's problem files (``(define (problem``) in name order."""
    import re

    from guided_lfd.errors import InputFileError, Location

    out: list[str] = []
    for argument in arguments:
        folder = Path(argument)
        if argument == "-" or not folder.is_dir():
            out.append(argument)
            continue
        found = [str(p) for p in sorted(folder.glob("*.pddl"))
                 if re.search(r"\(\s*define\s*\(\s*problem\b", _without_comments(p), re.IGNORECASE)]
        if not found:
            raise InputFileError("holds no problem file (expected *.pddl files that define a problem)",
                                 Location(argument))
        out += found
    if out.count("-") > 1:
        raise errors.OptionError("- (stdin) names a task twice: expected it at most once")
    return out


def _without_comments(path: Path) -> str:
    from guided_lfd.pddl.reader import without_comments

    try:
        return without_comments(path.read_text(errors="replace"))
    except OSError:
        return ""


def _teach_sequence(robot, tasks, demonstrator, session: Path, options: dict, json_out: bool) -> None:
    """Several tasks: taught in sequence (guided_lfd.teach.library), each reported, the library's document."""
    from guided_lfd.io import write_text
    from guided_lfd.teach.library import teach_tasks

    with watchdog(options["deadline"], "teaching"):
        library = teach_tasks(robot, tasks, demonstrator, session, **options)
    if json_out:
        write_text("-", library.to_json())
    code = 0
    for k, (session_obj, folder) in enumerate(zip(library.sessions, library.folders), 1):
        ui.info_plain(f"task {k} ({session_obj.problem}):")
        try:
            _report(session_obj, Path(folder))
        except typer.Exit as ended:
            code = code or ended.exit_code
    ui.info(f"the library after {len(tasks)} task(s) is {session / 'robot.pddl'} (see {session / 'library.md'})")
    if code:
        raise typer.Exit(code)


def _report(session_obj, session: Path) -> None:
    """Each round on stderr, then the session's end: its exit code and, when not taught, why."""
    for r in session_obj.rounds:
        if r.answer:  # a skill asked for once more, answered instead of shown
            ui.info_plain(f"round {r.index}: the teacher answered: {r.answer}; the precondition is confirmed")
        if r.demonstration_length is None:
            continue
        ui.info(f"round {r.index}: {'; '.join(r.request_text)}; demonstrated {r.demonstration_length} action(s), "
                f"learned {', '.join(r.learned_actions) or 'nothing new'}"
                + ("" if r.request_met is not False else f"; not done: {', '.join(str(c) for c in r.unmet)}"))
        if r.check is not None:  # the demonstration against its request: its outcome and why
            ui.info_plain(f"round {r.index}: {r.check.outcome}: {r.check.reason}")
        if r.vocabulary:  # which hand facts were chosen, and from where, so a wrong binding shows
            ui.info(f"[dim]round {r.index}: hand facts: {r.vocabulary}[/]")
    if session_obj.error is not None:  # the demonstration's own error, its own exit code
        ui.error(f"{session_obj.error} (teaching ended; see {session / 'session.md'})")
        raise typer.Exit(session_obj.error.exit_code)
    codes = {"solved": 0, "already-solvable": 0, "no-excuse": errors.EXIT_NO_EXCUSE,
             "demonstration-only": errors.EXIT_DEMONSTRATION_ONLY, "timeout": errors.EXIT_TIME_LIMIT}
    code = codes.get(session_obj.status, errors.EXIT_NOT_TAUGHT)
    if code:
        why = f": {session_obj.reason}" if session_obj.reason else ""
        ui.error(f"teaching ended: {session_obj.status} after {len(session_obj.rounds)} round(s){why} "
                 f"(see {session / 'session.md'})")
        raise typer.Exit(code)
    ui.info(f"taught in {len(session_obj.rounds)} round(s); the robot's domain is {session / 'robot.pddl'}")
