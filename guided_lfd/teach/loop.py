"""The teaching loop, round by round: excuse -> request -> demonstration -> learn -> merge -> re-plan (see
:mod:`guided_lfd.teach`)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Callable

from guided_lfd.deadline import seconds_left
from guided_lfd.excuse.document import held_fixed_text
from guided_lfd.excuse.engine import ExcuseOptions, check_option_names, find_excuses
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.io import write_text
from guided_lfd.pddl.fit import check_model_fits, refuse_adl
from guided_lfd.pddl.model import Domain, Problem
from guided_lfd.pddl.writer import domain_to_pddl
from guided_lfd.planning.validation import PlanStep
from guided_lfd.teach.check import asked_again
from guided_lfd.teach.folder import check_session_folder, make_folder, replacing_previous_session
from guided_lfd.teach.human import SimulatedHuman, check_human_model
from guided_lfd.teach.learning import learn_round
from guided_lfd.teach.request import (excuse_request, new_skill_request, no_demonstration, no_excuse_reason,
                                      why_not_original)
from guided_lfd.teach.session import Demonstrator, Round, TeachSession
from guided_lfd.teach.skill_request import answer_of, confirm, skill_round

__all__ = ["teach"]


def teach(robot: Domain, problem: Problem, demonstrator: Demonstrator, out: Path, max_rounds: int = 5,
          options: ExcuseOptions | None = None, human: Domain | None = None, prefer: bool = False,
          redundancy: bool = True, deadline: float | None = None,
          on_request: Callable[[Round], None] | None = None, checks: bool = True) -> TeachSession:
    """Teach the robot its task round by round (see :mod:`guided_lfd.teach`); every round's files go under ``out``.

    With a ``human`` model, excuses change only what the human can change
    (``fixed_from`` the human's domain), the request is the smallest part of
    the excuse whose demonstration suffices (``redundancy``), and with
    ``prefer`` the excuse with the shortest predicted demonstration is asked
    for.  ``deadline`` (a ``time.monotonic()`` value) bounds the whole
    session: past it the session ends as ``timeout``.  ``on_request`` hears
    each round's request before the demonstration is asked for.  A
    demonstration that cannot be read, or starts from another state than the
    task's, ends the session (``error`` in its round; ``status`` names it).
    A human model (``human``, the simulated human's) for another domain is
    refused before any round (:func:`check_human_model`, exit 34).  The
    session is ``solved`` only when the taught robot plans the original task
    from its original state; a goal reached only through the demonstration
    is ``demonstration-only`` (``reason`` says what the robot lacks).
    ``out/robot.pddl`` is the robot's domain after each round;
    ``session.json`` and ``session.md`` are written by the caller.  ``checks`` False keeps the skills of every
    demonstration, whatever its check against the request says (to measure what the checks prevent).
    """
    out = _session_path(out)
    _check_teach_arguments(robot, problem, demonstrator, max_rounds, options, human, prefer, deadline, on_request)
    was_there = out.exists()
    options = options or ExcuseOptions()
    _prepare_session(robot, problem, demonstrator, out, options, human)
    with replacing_previous_session(out, was_there):
        return _rounds(robot, problem, demonstrator, out, max_rounds, options, human, prefer, redundancy, deadline,
                       on_request, checks)


def _check_teach_arguments(robot: object, problem: object, demonstrator: object, max_rounds: object,
                           options: object, human: object, prefer: object, deadline: object,
                           on_request: object = None) -> None:
    """:func:`teach`'s arguments of the wrong kind, as the documented :class:`OptionError`."""
    import math

    from guided_lfd.errors import OptionError

    none = type(None)
    for name, value, kind, expected in (("robot", robot, Domain, "Domain"), ("problem", problem, Problem, "Problem"),
                                        ("human", human, (Domain, none), "a Domain or None"),
                                        ("options", options, (ExcuseOptions, none), "ExcuseOptions or None")):
        if not isinstance(value, kind):
            raise OptionError(f"{name}: expected {expected}, got {type(value).__name__}")
    if not callable(getattr(demonstrator, "demonstrate", None)):
        raise OptionError(f"demonstrator: expected an object with demonstrate() (SimulatedHuman, GivenTraces), got "
                          f"{type(demonstrator).__name__}")
    if isinstance(max_rounds, bool) or not isinstance(max_rounds, int) or max_rounds < 1:
        raise OptionError(f"max_rounds {max_rounds!r}: expected a whole number of rounds >= 1")
    if deadline is not None and (isinstance(deadline, bool) or not isinstance(deadline, (int, float))
                                 or not math.isfinite(deadline)):
        raise OptionError(f"deadline {deadline!r}: expected a time.monotonic() value (or None)")
    if prefer and human is None:
        raise OptionError("prefer: needs the human model it predicts demonstrations with (human=...)")
    if on_request is not None and not callable(on_request):
        raise OptionError(f"on_request: expected a function of one Round (or None), got {type(on_request).__name__}")


def _session_path(out: object) -> Path:
    """``out`` as a path (a library caller may pass a string), refused as OptionError if it is neither."""
    if isinstance(out, (str, Path)) and str(out).strip() and "\x00" not in str(out):
        return Path(out)
    from guided_lfd.errors import OptionError

    raise OptionError(f"out {out!r}: expected the session folder's path")


def _rounds(robot: Domain, problem: Problem, demonstrator: Demonstrator, out: Path, max_rounds: int,
            options: ExcuseOptions, human: Domain | None, prefer: bool, redundancy: bool, deadline: float | None,
            on_request: Callable[[Round], None] | None, checks: bool = True) -> TeachSession:
    """The session's rounds, then its judgement on the original task (see :func:`teach`)."""
    from guided_lfd.errors import GuidedLfdError, SearchTimeout

    if human is not None:
        options = replace(options, fixed_from=human, all_minimal=options.all_minimal or prefer)
    state, current, rounds = problem.init, robot, []
    history: list[tuple[str, dict]] = []  # every round's demonstration: skills are learned from all of them
    confirmed: list = []  # preconditions the teacher said a skill cannot do without (SkillChange)
    status, final_plan, error, reason = "max-rounds", None, None, None
    try:
        for k in range(1, max_rounds + 1):
            folder = make_folder(out / f"round-{k}")
            task = replace(problem, init=state)
            report = find_excuses(current, task, replace(options, time_limit=seconds_left(deadline)))
            write_text(folder / "excuse.json", report.to_json())
            write_text(folder / "excuse.svg", report.to_svg())
            ended = _ended(report, k, task)
            if ended is not None:
                status, final_plan, reason = ended
                break
            rnd = _request(k, current, task, report, human, prefer, redundancy, deadline)
            if rnd.skill is not None:  # the robot first made its own steps before the skill
                state = rnd.skill.state
                task = replace(problem, init=state)
            rnd.files.update(excuse=str(folder / "excuse.json"), picture=str(folder / "excuse.svg"))
            rnd.held = held_fixed_text(report, options.fixed_from)
            if rounds:  # after a partial or unhelpful demonstration: what is still missing, in the domain's words
                rnd.asked_again = asked_again(rounds[-1], rnd.request, report.spellings)
            rounds.append(rnd)
            if on_request:
                on_request(rnd)
            try:
                if _answered(rnd, demonstrator, confirmed):  # the precondition is real: never dropped again
                    current = confirm(current, confirmed)
                    continue
                given = demonstrator.demonstrate(folder, state, rnd.request, task)
                if given is None:
                    status, reason = no_demonstration(demonstrator, state, rnd, task, report)
                    break
                current, state = learn_round(rnd, folder, out, current, task, given, human, robot, history,
                                             seconds_left(deadline), checks)
                current = confirm(current, confirmed)  # learned again from every demonstration: answers stand
            except SearchTimeout:
                raise
            except GuidedLfdError as exc:  # the demonstration's fault: the session so far stays
                rnd.error, error, status = str(exc), exc, "bad-demonstration"
                break
            outcome = _replan(current, replace(problem, init=state), deadline)
            rnd.solvable_after = outcome is not None
            if outcome is not None:
                # Reached from the demonstrated state: whether it counts is judged below, on the original task.
                status, final_plan = "solved", outcome
                break
    except SearchTimeout:
        status = "timeout"
    reason = (_rounds_ran_out(rounds) or reason) if status == "max-rounds" else reason
    write_text(out / "robot.pddl", domain_to_pddl(current, header=f"The robot's domain after teaching {problem.path}"))
    original, status, reason = _judge_original(current, problem, rounds, status, reason, options, deadline)
    return TeachSession(robot.path, problem.path, status, rounds, final_plan, original, str(out / "robot.pddl"),
                        error=error, reason=reason, task=problem.name)


def _answered(rnd: Round, demonstrator: Demonstrator, confirmed: list) -> bool:
    """Whether the teacher answered a skill request that the skill cannot be done there (its preconditions then
    join ``confirmed``); False for any other round, or when a demonstration follows."""
    if rnd.skill is None:
        return False
    rnd.answer = answer_of(demonstrator, rnd.skill)
    if rnd.answer:
        confirmed += rnd.skill.dropped
    return bool(rnd.answer)


def _ended(report, k: int, task: Problem) -> tuple[str, list[PlanStep] | None, str | None] | None:
    """(status, plan, reason) when round ``k``'s excuse report ends the session (nothing to ask), else None."""
    if report.status is ExcuseStatus.ALREADY_SOLVABLE:
        return ("already-solvable" if k == 1 else "solved"), report.robot_plan, None
    if report.excuse is None and (report.status is ExcuseStatus.TIMEOUT or not report.unachievable_goals):
        if report.status is ExcuseStatus.TIMEOUT:
            return "timeout", None, None
        return "no-excuse", None, no_excuse_reason(report, task)
    return None


def _request(k: int, robot: Domain, task: Problem, report, human: Domain | None, prefer: bool, redundancy: bool,
             deadline: float | None) -> Round:
    """Round ``k``'s request: a skill to show again (a skill excuse), the excuse (or its sufficient part), or a
    new skill for goal atoms no skill makes true."""
    if report.excuse is not None and report.excuse.skill_changes and not report.excuse.changes:
        return skill_round(k, robot, task.init, report)
    if report.excuse is None:
        return new_skill_request(k, robot, task, report)
    return excuse_request(k, robot, task, report, human if prefer else None, human if redundancy else None, human,
                          deadline)


def _rounds_ran_out(rounds: list[Round]) -> str | None:
    """Why a session whose rounds ran out ends unsolved: how its last demonstration was judged (None: unchecked)."""
    if not rounds or rounds[-1].check is None:
        return None
    last = rounds[-1]
    return (f"the robot still cannot plan the task after {len(rounds)} round(s); round {last.index}'s "
            f"demonstration was {last.check.outcome}: {last.check.reason}")


def _judge_original(taught: Domain, problem: Problem, rounds: list[Round], status: str, reason: str | None,
                    options: ExcuseOptions, deadline: float | None) -> tuple[bool | None, str, str | None]:
    """(whether the taught robot plans the original task, the session's status, its reason): a session the loop
    ended ``solved`` stays so only if the taught robot plans the task from its original state."""
    from guided_lfd.errors import SearchTimeout

    try:
        # Whether a plan exists, not the best one: greedy search is complete on a finite task, and much faster.
        original = _replan(taught, problem, deadline, search="gbfs-hff") is not None
    except SearchTimeout:
        original = None
    if status == "solved" and not original:
        # The world got to the goal (or near it) through the demonstration; the robot itself still cannot.
        if original is None:
            return None, "timeout", "the time limit was reached before the taught robot's plan for the task"
        learned = [name for r in rounds for name in r.learned_actions]
        return False, "demonstration-only", why_not_original(taught, problem, learned, options, deadline)
    return original, status, reason


def _prepare_session(robot: Domain, problem: Problem, demonstrator, out: Path, options: ExcuseOptions,
                     human: Domain | None) -> None:
    """Every check that refuses a session, before its folder is made (or a previous session's is cleared)."""
    simulated = demonstrator.human if isinstance(demonstrator, SimulatedHuman) else None
    refuse_adl("teach", problem, robot, human, simulated)
    for model, option in ((human, "--human"), (simulated if simulated is not human else None, "--simulate")):
        if model is not None:
            check_model_fits(robot, model, option)  # a clash with the robot first: it says more than a gap
            check_human_model(model, problem)
    check_option_names(robot, options)
    check_session_folder(out, problem)
    make_folder(out)


def _replan(robot: Domain, task: Problem, deadline: float | None = None,
            search: str | None = None) -> list[PlanStep] | None:
    """The robot's validated plan for ``task`` (optimal unless another ``search`` is named), or None when it has
    none (SearchTimeout past ``deadline``)."""
    from guided_lfd.planning import DEFAULT_SEARCH
    from guided_lfd.symbolic.portfolio import validated_plan

    return validated_plan(robot, task, search or DEFAULT_SEARCH, seconds_left(deadline))[1]

