"""Guided teaching, the paper's whole loop: excuse -> request -> demonstration -> learn -> merge -> re-plan.

Each round asks for the demonstration the robot needs (its minimal excuse,
in the paper's words: ``Open PinkDrawer``), says why it needs it and what to
leave as it is, takes the demonstration (a hand trace; or, simulated, the
human model's shortest plan to the request rendered as one), segments it,
learns its skills, merges them into the robot's domain and re-plans from
the state the demonstration left.  Rounds go on until the robot can plan
the task, no demonstration is given, or the rounds run out.

The session ends ``solved`` only when the taught robot plans the original
task from its original state: a demonstration that reached the goal while
the skills learned from it do not let the robot plan the task ends
``demonstration-only``.  When no excuse exists because no skill of the robot
makes some goal atom true, the round asks for a demonstration of a new skill
that does (its request is those atoms).
"""

from __future__ import annotations

from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable, Iterator, Protocol

from guided_lfd.deadline import seconds_left
from guided_lfd.demonstration.vocabulary import KITCHEN, HandVocabulary, infer_vocabulary
from guided_lfd.excuse.change import Change, excuse_state
from guided_lfd.excuse.engine import ExcuseOptions, check_option_names, find_excuses
from guided_lfd.excuse.change import describe_change
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.fit import check_model_fits, refuse_adl
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.pddl.writer import domain_to_pddl
from guided_lfd.planning.validation import PlanStep

__all__ = ["Round", "TeachSession", "SimulatedHuman", "GivenTraces", "teach", "keep_facts", "check_human_model"]


class Demonstrator(Protocol):
    """Whoever demonstrates: given the round's folder, the world's state and the request, a hand trace.

    A demonstrator may also have a ``why_none(state, request, problem) -> str`` method: asked after
    ``demonstrate`` gave None, it says why in one line (the session's ``reason``).
    """

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """(trace CSV, state CSV) of the demonstration, or None when there is none to give."""
        ...


@dataclass
class Round:
    """One round of teaching: what was asked, why, what came of it."""

    index: int
    excuse: list[Change]
    request: list[Change]
    request_text: list[str]
    why: list[str]
    keep: list[Atom]
    keep_text: list[str]
    demonstration_length: int | None = None  # demonstrated actions (segments that act)
    new_actions: int | None = None  # of those, the ones no skill of the robot already does (the useful part)
    learned_actions: list[str] = field(default_factory=list)
    request_met: bool | None = None
    unmet: list[Change] = field(default_factory=list)  # the request's changes the demonstration did not make
    solvable_after: bool | None = None
    files: dict[str, str] = field(default_factory=dict)
    preference: str | None = None  # why this excuse among the minimal ones (--prefer demonstration)
    error: str | None = None  # why the demonstration could not be used (it ended the session)
    vocabulary: str | None = None  # the hand facts the demonstration was learned in, and where they came from

    def excuse_text(self) -> str | None:
        """How the request relates to the minimal excuse when it asks for only part of it, else None."""
        if not self.excuse or self.request == self.excuse:
            return None
        return (f"the minimal excuse is {' '.join(str(c) for c in self.excuse)}; the request is the part of it "
                "that suffices")

    def to_dict(self) -> dict[str, Any]:
        """The round as ``session.json`` has it."""
        return {
            "round": self.index, "excuse": [str(c) for c in self.excuse], "request": [str(c) for c in self.request],
            "request_text": self.request_text, "why": self.why, "keep": [str(a) for a in self.keep],
            "keep_text": self.keep_text, "demonstration_length": self.demonstration_length,
            "new_actions": self.new_actions,
            "learned_actions": self.learned_actions, "request_met": self.request_met,
            "unmet": [str(c) for c in self.unmet], "solvable_after": self.solvable_after, "files": self.files,
            "preference": self.preference, "error": self.error, "vocabulary": self.vocabulary,
        }


@dataclass
class TeachSession:
    """A whole teaching session: its rounds, how it ended, and the robot's plan at the end."""

    robot: str
    problem: str
    #: solved | already-solvable | demonstration-only | no-excuse | no-demonstration | bad-demonstration
    #: | max-rounds | timeout
    status: str
    rounds: list[Round]
    plan: list[PlanStep] | None  # the robot's plan from the state the session ended in
    plans_original_task: bool | None  # whether the taught robot plans the task from its original state
    robot_domain: str  # the taught domain's file
    error: Any = field(default=None, repr=False, compare=False)  # the GuidedLfdError that ended it, if any
    reason: str | None = None  # why it ended unsolved, in one line (None when solved)
    task: str | None = None  # the problem's PDDL name: a later session in the folder must be of the same task

    @property
    def solved(self) -> bool:
        """Whether the robot can plan the task at the end."""
        return self.status in ("solved", "already-solvable")

    def to_dict(self) -> dict[str, Any]:
        """The body of ``session.json`` (format ``guided-lfd/teach``, version 1)."""
        return {"robot": self.robot, "problem": self.problem, "solved": self.solved, "status": self.status,
                "rounds": [r.to_dict() for r in self.rounds],
                "plan": None if self.plan is None else [str(s) for s in self.plan],
                "plans_original_task": self.plans_original_task, "robot_domain": self.robot_domain,
                "reason": self.reason, "task": self.task}

    def to_json(self) -> str:
        """The ``session.json`` document."""
        return json_document("teach", self.to_dict())

    def to_markdown(self) -> str:
        """``session.md``: the rounds as a person reads them."""
        lines = [f"# Teaching session: {self.problem}", "", f"Robot: `{self.robot}`; status: **{self.status}**.", ""]
        if self.reason:
            lines += [f"Why: {self.reason}.", ""]
        for r in self.rounds:
            lines += [f"## Round {r.index}", "", "Request: " + "; ".join(r.request_text) + ".", ""]
            if not r.excuse:
                lines.append("- no excuse exists: a new skill that makes this true must be demonstrated")
            elif r.excuse_text():
                lines.append(f"- {r.excuse_text()}")
            if r.preference:
                lines.append(f"- {r.preference}")
            lines += [f"- why: {w}" for w in r.why]
            if r.keep_text:
                lines.append("- leave as it is: " + "; ".join(r.keep_text))
            lines.append(f"- demonstrated actions: {r.demonstration_length if r.demonstration_length is not None else '-'}"
                         f"; learned: {', '.join(r.learned_actions) or '-'}")
            if r.vocabulary:
                lines.append(f"- hand facts: {r.vocabulary}")
            if r.error:
                lines.append(f"- the demonstration could not be used: {r.error}")
            if r.request_met is False:
                lines.append("- the demonstration did not make: " + ", ".join(str(c) for c in r.unmet))
            lines.append("")
        if self.plan is not None:
            lines += ["## The robot's plan", ""] + [f"{i}. `{s}`" for i, s in enumerate(self.plan, 1)] + [""]
        return "\n".join(lines)


def keep_facts(robot: Domain, problem: Problem, state: frozenset[Atom], changes: list[Change],
               plan: list[PlanStep], human: Domain | None = None) -> list[Atom]:
    """The facts true now that the robot's plan from the excuse state relies on, no step of it making them true.

    Asking the demonstrator to leave them as they are prevents misdirected
    guidance (a chair put back in front of the drawer the robot needs).  With
    a ``human`` model, facts no human action changes are left out (nobody can
    disturb them); without one, every such fact is listed.
    """
    schemas = {a.name: a for a in robot.actions}
    hand = robot_vocabulary(robot, human).predicates  # the hand's own state is the demonstrator's business
    current = set(excuse_state(state, changes))
    made: set[Atom] = set()
    keep: list[Atom] = []
    for step in plan:
        schema = schemas[step.action]
        binding = {v: a for (v, _), a in zip(schema.params, step.args)}
        for lit in schema.precondition:
            atom = lit.atom.substitute(binding)
            if (lit.positive and atom in state and atom not in made and atom not in keep
                    and atom.predicate not in hand and atom.predicate != "="):
                keep.append(atom)
        adds = {a.substitute(binding) for a in schema.add}
        dels = {a.substitute(binding) for a in schema.delete}
        made |= adds - current
        current = (current - dels) | adds
    # Facts the human cannot change (graspable) are the world's structure: nothing to ask about.
    static = set(human.predicates) - human.fluent_predicates() if human is not None else set()
    changed = {c.atom for c in changes}
    return [a for a in keep if a not in changed and a.predicate not in static]


def robot_vocabulary(robot: Domain, human: Domain | None = None) -> HandVocabulary:
    """The robot's hand facts as its grasping actions (or, lacking them, the human model's) show them; the
    kitchens' when neither shows any and the robot declares ``in_hand``, none otherwise."""
    from guided_lfd.demonstration.vocabulary import NO_HAND

    try:
        found = infer_vocabulary(robot, human)
    except ValueError:
        found = None
    if found is not None:
        return found
    return KITCHEN if "in_hand" in robot.predicates else NO_HAND


def _why(report, robot: Domain, problem: Problem, excuse: list[Change]) -> list[str]:
    """Why the robot needs the demonstration: each requested change it has no skill for, or that it cannot
    make from here, on the way to the goal it cannot reach."""
    spellings, goal = report.spellings, _goal_text(report, problem)
    out = [f"no skill of the robot makes {describe_change(Change(g.atom, g.positive), spellings)} true"
           for g in report.unachievable_goals]
    objects = {**robot.constants, **problem.objects}
    subtypes = robot.subtypes()
    for change in excuse:
        can = any(_could_make(act, change, objects, subtypes) for act in robot.actions)
        what = describe_change(change, spellings)
        out.append(f"{what}: no skill of the robot does this, and its plan to {goal} needs it" if not can else
                   f"{what}: the robot cannot do this from here, and its plan to {goal} needs it")
    return out


def _why_rest(excuse: list[Change], request: list[Change], after: frozenset[Atom] | None, spellings) -> list[str]:
    """Why the excuse's changes left out of the request are not asked for: the predicted demonstration of the
    request makes them on the way (``after`` is the state it leaves), or the robot then makes them itself."""
    asked = " and ".join(describe_change(c, spellings) for c in request)
    out = []
    for change in (c for c in excuse if c not in request):
        made = after is not None and (change.atom in after) == change.added
        how = (f"demonstrating {asked} makes it on the way" if made else
               "the robot then makes it itself, with the skills it learns from the demonstration")
        out.append(f"{describe_change(change, spellings)}: also in the minimal excuse, not asked for: {how}")
    return out


def check_human_model(human: Domain, problem: Problem) -> None:
    """Refuse (exit 34) a human model written for another domain: one lacking a predicate or an object type
    the task uses (its plans could not say anything about this world), before any round."""
    from guided_lfd.errors import Location, MismatchError

    def refuse(what: str) -> None:
        raise MismatchError(f"the human model (domain '{human.name}') is for another domain than the task's "
                            f"('{problem.domain_name}'): {what} (expected a model of the task's world)",
                            Location(human.path))

    used = {a for a in problem.init} | {lit.atom for lit in problem.goal}
    for atom in sorted(used):
        if atom.predicate == "=":
            continue
        declared = human.predicates.get(atom.predicate)
        if declared is None:
            refuse(f"it has no predicate {atom.predicate}, which the task uses in {atom}")
        elif declared.arity != len(atom.args):
            refuse(f"its predicate {atom.predicate} takes {declared.arity} argument(s), the task's {atom} "
                   f"{len(atom.args)}")
    types = set(human.types) | {"object"}
    for obj, kind in sorted(problem.objects.items()):
        if kind not in types:
            refuse(f"it has no type {kind}, the type of the task's object {obj}")


def _relaxed_reach(task) -> tuple[int, int]:
    """(atoms some state reachable from ``task``'s initial state may hold, atoms some action there may delete),
    ignoring deletes and negative preconditions: an atom outside the first is never true (a proof)."""
    reached, deletable, pending = task.init, 0, list(task.actions)
    while True:
        ready = [act for act in pending if not act.pre_pos & ~reached]
        if not ready:
            return reached, deletable
        for act in ready:
            reached |= act.add
            deletable |= act.delete
        pending = [act for act in pending if act.pre_pos & ~reached]


def _first_unreachable(domain: Domain, task: Problem, changes: list[Change]) -> Change | None:
    """The first of ``changes`` that no plan of ``domain`` makes from ``task``'s state on its own (a relaxed
    check first, then each change's own optimal plan), or None when each one alone can be made."""
    from guided_lfd.evaluate import excuse_goal, optimal_plan
    from guided_lfd.planning.grounding import ground

    ground_task = ground(domain, task)
    reached, deletable = _relaxed_reach(ground_task)
    for change in changes:
        i = ground_task.index.get(change.atom)
        if i is None:
            if change.added:  # an atom no action of the domain can even name
                return change
            continue
        if not (reached if change.added else deletable | ~ground_task.init) >> i & 1:
            return change
    if len(changes) > 1:
        for change in changes:
            if optimal_plan(domain, task, goal=excuse_goal([change])) is None:
                return change
    return None


# -- demonstrators -----------------------------------------------------------------------

def _scene(problem: Problem, domain: Domain):
    """A scene for ``problem``'s objects: the study's positions where known, a grid of places otherwise."""
    from guided_lfd.demonstration.render import Scene
    from guided_lfd.demonstration.study_data import SCENE_POSITIONS

    objects = {**domain.constants, **problem.objects}
    positions = {}
    for k, obj in enumerate(sorted(objects)):
        positions[obj] = SCENE_POSITIONS.get(obj, (-0.9 + 0.35 * (k % 6), 0.3 + 0.3 * (k // 6), 0.8))
    return Scene(positions=positions, types=dict(objects), spellings={**domain.spellings, **problem.spellings})


#: The frame rates a simulated demonstration is rendered at (the VR recorder's are 15-120 Hz).
MIN_RATE_HZ, MAX_RATE_HZ = 1.0, 1000.0


@dataclass
class SimulatedHuman:
    """A demonstrator simulated by a human model: its shortest plan to the request, rendered as a hand trace."""

    human: Domain
    rate_hz: float = 90.0
    seed: int = 0
    robot: Domain | None = None  # whose hand facts the trace declares (else the human model's)

    def __post_init__(self) -> None:
        from guided_lfd.errors import OptionError

        if not isinstance(self.human, Domain):
            raise OptionError(f"SimulatedHuman: human: expected a Domain, got {type(self.human).__name__}")
        rate = self.rate_hz
        if isinstance(rate, bool) or not isinstance(rate, (int, float)) or not MIN_RATE_HZ <= rate <= MAX_RATE_HZ:
            raise OptionError(f"SimulatedHuman: rate_hz {rate!r}: expected a frame rate from {MIN_RATE_HZ:g} to "
                              f"{MAX_RATE_HZ:g} Hz")
        if isinstance(self.seed, bool) or not isinstance(self.seed, int):
            raise OptionError(f"SimulatedHuman: seed {self.seed!r}: expected a whole number")
        if self.robot is not None and not isinstance(self.robot, Domain):
            raise OptionError(f"SimulatedHuman: robot: expected a Domain or None, got {type(self.robot).__name__}")

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """Render the human's optimal plan from ``state`` to a state where ``request`` holds (None: no plan)."""
        from guided_lfd.demonstration.render import Noise, plan_vocabulary, render, script_for_plan
        from guided_lfd.evaluate import excuse_goal, optimal_plan

        plan = optimal_plan(self.human, replace(problem, init=state), goal=excuse_goal(request))
        if not plan:
            return None
        _check_drawable([], None, plan, self.human)
        # The trace's state file declares the world's hand facts (none for a world without a hand): the robot's
        # where its grasping actions show them, else the human model's.
        try:
            vocabulary = plan_vocabulary(self.human, {**self.human.constants, **problem.objects}, self.robot)
        except ValueError as exc:
            from guided_lfd.errors import UnsupportedFeatureError

            raise UnsupportedFeatureError(f"--simulate: {exc}", self.human.locate(self.human.name, "domain")) from None
        script = script_for_plan([(s.action, s.args) for s in plan], self.human, set(state), vocabulary=vocabulary)
        scene = _scene(problem, self.human)
        _check_drawable(script, scene, plan, self.human)
        rendering = render(script, scene, set(state), self.rate_hz, Noise(seed=self.seed), vocabulary=vocabulary)
        trace, states = folder / "demonstration.csv", folder / "demonstration.state.csv"
        write_text(trace, rendering.trace_csv)
        write_text(states, rendering.state_csv)
        write_text(folder / "demonstration.labels.csv", rendering.labels_csv)
        return trace, states

    def why_none(self, state: frozenset[Atom], request: list[Change], problem: Problem) -> str:
        """Why :meth:`demonstrate` gave None: the human model has no plan to the request (the first change it
        cannot make, where one alone is out of its reach)."""
        spellings = {**problem.spellings, **self.human.spellings}
        asked = " and ".join(describe_change(c, spellings) for c in request)
        head = f"the human model ({self.human.path}) has no plan from the current state to {asked}"
        first = _first_unreachable(self.human, replace(problem, init=state), request)
        if first is None:
            return f"{head}: it can make each change alone, not all of them together"
        return f"{head}: it cannot reach {describe_change(first, spellings)} ({first})"


def _check_drawable(script, scene, plan: list[PlanStep], human: Domain) -> None:
    """The renderer draws hand manipulation (take, put, open and close, push an obstacle away): a plan
    with another kind of action (walking through a door, turning a key) is refused in one line, not drawn wrongly."""
    from guided_lfd.demonstration.render import undrawable_actions
    from guided_lfd.errors import UnsupportedFeatureError

    odd = undrawable_actions([(step.action, step.args) for step in plan], human)
    missing = [s.obj for s in script if s.activity not in ("Idle", "Release") and s.obj not in scene.positions]
    if odd:
        raise UnsupportedFeatureError(
            f"--simulate draws every action as the hand working on its objects: the human's plan uses "
            f"{', '.join(sorted(odd))}, which has none (give --demo traces)", human.locate(sorted(odd)[0], ":action"))
    if odd or missing:
        actions = sorted(odd) or sorted({s.action for s in plan})
        raise UnsupportedFeatureError(
            f"--simulate renders hand manipulation (take, put, open or close, push an obstacle): the human's "
            f"plan uses {', '.join(actions)}, which it cannot draw as hand activities (give --demo traces)",
            human.locate(actions[0], ":action"))


@dataclass
class GivenTraces:
    """Demonstrations recorded beforehand (``--demo``), one per round, in order; each with its state file."""

    traces: list[Path]

    def __post_init__(self) -> None:
        from guided_lfd.errors import OptionError

        if not isinstance(self.traces, list) or not all(isinstance(t, (str, Path)) for t in self.traces):
            raise OptionError(f"GivenTraces: traces {self.traces!r}: expected a list of trace paths")
        self.traces[:] = [Path(t) for t in self.traces]  # in place: a caller may hold the list and see it used

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """The next trace and its state file (``TRACE.state.csv`` beside it), or None when none is left."""
        from guided_lfd.demonstration import default_state_path

        if not self.traces:
            return None
        trace = self.traces.pop(0)
        return trace, Path(default_state_path(str(trace)))


# -- the loop ----------------------------------------------------------------------------

def teach(robot: Domain, problem: Problem, demonstrator: Demonstrator, out: Path, max_rounds: int = 5,
          options: ExcuseOptions | None = None, human: Domain | None = None, prefer: bool = False,
          redundancy: bool = True, deadline: float | None = None,
          on_request: Callable[[Round], None] | None = None) -> TeachSession:
    """Teach the robot its task round by round (see the module docstring); every round's files go under ``out``.

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
    ``session.json`` and ``session.md`` are written by the caller.
    """
    out = _session_path(out)
    _check_teach_arguments(robot, problem, demonstrator, max_rounds, options, human, prefer, deadline, on_request)
    was_there = out.exists()
    options = options or ExcuseOptions()
    _prepare_session(robot, problem, demonstrator, out, options, human)
    with replacing_previous_session(out, was_there):
        return _rounds(robot, problem, demonstrator, out, max_rounds, options, human, prefer, redundancy, deadline,
                       on_request)


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
            on_request: Callable[[Round], None] | None) -> TeachSession:
    """The session's rounds, then its judgement on the original task (see :func:`teach`)."""
    from guided_lfd.errors import GuidedLfdError, SearchTimeout

    if human is not None:
        options = replace(options, fixed_from=human, all_minimal=options.all_minimal or prefer)
    state, current, rounds = problem.init, robot, []
    history: list[tuple[str, dict]] = []  # every round's demonstration: skills are learned from all of them
    status, final_plan, error, reason = "max-rounds", None, None, None
    try:
        for k in range(1, max_rounds + 1):
            folder = _make_folder(out / f"round-{k}")
            task = replace(problem, init=state)
            report = find_excuses(current, task, replace(options, time_limit=seconds_left(deadline)))
            write_text(folder / "excuse.json", report.to_json())
            write_text(folder / "excuse.svg", report.to_svg())
            if report.status is ExcuseStatus.ALREADY_SOLVABLE:
                status, final_plan = ("already-solvable" if k == 1 else "solved"), report.robot_plan
                break
            if report.excuse is None and (report.status is ExcuseStatus.TIMEOUT or not report.unachievable_goals):
                status = "no-excuse" if report.status is not ExcuseStatus.TIMEOUT else "timeout"
                if status == "no-excuse":
                    reason = _no_excuse_reason(report, task)
                break
            rnd = (_new_skill_request(k, current, task, report) if report.excuse is None else
                   _request(k, current, task, report, human if prefer else None, human if redundancy else None, human,
                            deadline))
            rnd.files.update(excuse=str(folder / "excuse.json"), picture=str(folder / "excuse.svg"))
            rounds.append(rnd)
            if on_request:
                on_request(rnd)
            try:
                given = demonstrator.demonstrate(folder, state, rnd.request, task)
                if given is None:
                    status, reason = _no_demonstration(demonstrator, state, rnd, task, report)
                    break
                current, state = _learn_round(rnd, folder, out, current, task, given, human, robot, history)
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
    write_text(out / "robot.pddl", domain_to_pddl(current, header=f"The robot's domain after teaching {problem.path}"))
    original, status, reason = _judge_original(current, problem, rounds, status, reason, options, deadline)
    session = TeachSession(robot.path, problem.path, status, rounds, final_plan, original, str(out / "robot.pddl"),
                           reason=reason, task=problem.name)
    session.error = error
    return session


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
        return False, "demonstration-only", _why_not_original(taught, problem, learned, options, deadline)
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
    _make_folder(out)


#: What a session writes into its folder (besides ``round-N/``).
SESSION_FILES = ("robot.pddl", "session.json", "session.md")


def check_session_folder(out: Path, problem: Problem) -> None:
    """Refuse (exit 40), before any work, a session folder that is neither new, nor empty, nor a previous session
    of the same task (which :func:`replacing_previous_session` then replaces whole).

    Nothing the user had is overwritten: a folder holding other files, or a link where the session writes (a
    ``robot.pddl`` linking to the robot's own domain), is refused."""
    from guided_lfd.errors import Location, OutputError

    def refuse(why: str) -> None:
        raise OutputError(f"{why}; expected a new or empty folder, or a previous session of this task",
                          Location(str(out)))

    try:
        if not out.exists():
            return
        if not out.is_dir():
            raise OutputError("is a file, expected a folder for the session", Location(str(out)))
        entries = sorted(out.iterdir())
    except (OSError, RuntimeError) as exc:  # a link loop, a folder the OS refuses
        raise OutputError(f"cannot use it as the session folder ({getattr(exc, 'strerror', None) or exc})",
                          Location(str(out))) from None
    for entry in entries:
        ours = entry.name in SESSION_FILES or (entry.name.startswith("round-") and entry.name[6:].isdigit())
        if not ours:
            refuse(f"holds {entry.name}, which is no file of a teaching session")
        if entry.is_symlink():
            refuse(f"holds {entry.name} as a link (the session would write through it)")
    if entries:
        _check_same_task(out, problem, refuse)


def _check_same_task(out: Path, problem: Problem, refuse) -> None:
    """A previous session in ``out`` must be of ``problem``: the same PDDL problem name (its session.json's
    ``task``) and problem file name (the recorded path may be relative to another working folder).  A session
    without a session.json was interrupted before its end."""
    import json

    record = out / "session.json"
    if not record.exists():
        return  # a session that ended before writing it (interrupted): its rounds are replaced
    try:
        doc = json.loads(record.read_text(encoding="utf-8"))
        earlier, task = Path(doc["problem"]), doc.get("task")
    except (OSError, ValueError, KeyError, TypeError):
        refuse("holds a session.json that is not a teaching session's")
        return
    if task is not None and problem.name and task != problem.name:
        refuse(f"holds a session of another task ({task})")
    if problem.path and earlier.name != Path(problem.path).name:
        refuse(f"holds a session of another task ({earlier})")


@contextmanager
def replacing_previous_session(out: Path, was_there: bool = True) -> Iterator[None]:
    """Set aside what a previous session of the task left in ``out`` (checked by :func:`check_session_folder`)
    while the new one runs: it is deleted when the new one ends, and put back as it was if the new one fails
    or is interrupted (an error, Ctrl-C, SIGTERM), so such a run loses nothing and leaves nothing (``was_there``:
    whether ``out`` existed before the run; if not, it is removed again).  A previous session the OS will not
    let us move is the output error (exit 40), with nothing moved."""
    import shutil

    aside = _set_aside(out)
    try:
        yield
    except BaseException:
        _put_back(out, aside, was_there)
        raise
    if aside is not None:
        shutil.rmtree(aside, ignore_errors=True)


def _set_aside(out: Path) -> Path | None:
    """Move the previous session's entries in ``out`` into a new hidden folder beside it (None: nothing there)."""
    import tempfile

    from guided_lfd.errors import Location, OutputError

    moved: list[Path] = []
    aside: Path | None = None
    try:
        previous = sorted(out.iterdir()) if out.is_dir() else []
        if not previous:
            return None
        aside = Path(tempfile.mkdtemp(prefix=f".{out.name}.previous-", dir=out.parent))
        for entry in previous:
            entry.rename(aside / entry.name)
            moved.append(entry)
    except BaseException as exc:  # an OS refusal, or Ctrl-C/SIGTERM part-way: move back what was moved
        for entry in moved:
            (aside / entry.name).rename(entry)
        if aside is not None:
            aside.rmdir()
        if not isinstance(exc, OSError):
            raise
        raise OutputError(f"cannot set the previous session aside ({exc.strerror or exc}); nothing was changed",
                          Location(str(out))) from None
    return aside


def _put_back(out: Path, aside: Path | None, was_there: bool) -> None:
    """Undo a failed run: remove what it made in ``out``, return the previous session from ``aside``."""
    import shutil

    for entry in out.iterdir() if out.is_dir() else []:
        shutil.rmtree(entry) if entry.is_dir() and not entry.is_symlink() else entry.unlink()
    if aside is not None:
        for entry in aside.iterdir():
            entry.rename(out / entry.name)
        aside.rmdir()
    elif not was_there and out.is_dir():
        out.rmdir()


def _make_folder(folder: Path) -> Path:
    """``folder``, created if need be; one the OS refuses is the output error (exit 40)."""
    from guided_lfd.errors import Location, OutputError

    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot make the session folder ({exc.strerror or exc})", Location(str(folder))) from None
    return folder


def _request(k: int, robot: Domain, task: Problem, report, prefer_by: Domain | None,
             reduce_by: Domain | None, human: Domain | None = None, deadline: float | None = None) -> Round:
    """The round's request: the (preferred) minimal excuse or its smallest sufficient part, why the robot
    needs it, what to leave as it is."""
    from guided_lfd.preference import prefer_demonstration, sufficient_part
    from guided_lfd.pddl.model import pretty_atom

    spellings = report.spellings
    chosen, preference = report.excuse, None
    if prefer_by is not None and len(report.excuses) > 1:
        index, preference = prefer_demonstration([e.changes for e in report.excuses], prefer_by, robot, task,
                                                 deadline)
        chosen = report.excuses[index]
    excuse = chosen.changes
    request, after = (sufficient_part(reduce_by, robot, task, excuse, deadline) if reduce_by is not None
                      else (list(excuse), None))
    # The why explains what is asked for; the rest of the excuse says how it gets made without being asked.
    why = _why(report, robot, task, request) + _why_rest(excuse, request, after, spellings)
    keep = keep_facts(robot, task, task.init, excuse, chosen.plan, human)
    return Round(k, excuse, request, [describe_change(c, spellings) for c in request], why, keep,
                 [f"keep {pretty_atom(a, spellings)}" for a in keep], preference=preference)


def _goal_text(report, task: Problem) -> str:
    """The task's goal in the paper's words (``Inside RedPlate, PinkDrawer``)."""
    return ", ".join(describe_change(Change(lit.atom, lit.positive), report.spellings) for lit in task.goal)


def _unachievable_text(report) -> str:
    """The goal atoms no skill of the robot makes true, in the paper's words."""
    return ", ".join(describe_change(Change(lit.atom, lit.positive), report.spellings)
                     for lit in report.unachievable_goals)


def _no_excuse_reason(report, task: Problem) -> str:
    """Why no excuse exists, in one line: the goal atoms no skill makes true, or no change that helps."""
    if report.unachievable_goals:
        return (f"no excuse exists: no skill of the robot makes {_unachievable_text(report)} true, so a new "
                "skill that does must be demonstrated")
    return f"no excuse exists: no change of the world's state lets the robot's skills reach {_goal_text(report, task)}"


def _new_skill_request(k: int, robot: Domain, task: Problem, report) -> Round:
    """A round for a task without an excuse: no skill of the robot makes some goal atoms true, so the request is
    those atoms (a demonstration of a new skill that makes them), and the why says so."""
    request = [Change(lit.atom, lit.positive) for lit in report.unachievable_goals]
    return Round(k, [], request, [describe_change(c, report.spellings) for c in request],
                 _why(report, robot, task, []), [], [])


def _no_demonstration(demonstrator: Demonstrator, state: frozenset[Atom], rnd: Round, task: Problem,
                      report) -> tuple[str, str]:
    """(status, reason) of a session whose demonstrator gave no demonstration: ``no-excuse`` when the round
    asked for a new skill (no excuse exists), ``no-demonstration`` otherwise; the reason says why none came."""
    why_none = getattr(demonstrator, "why_none", None)
    why = why_none(state, rnd.request, task) if why_none is not None else "the demonstrator gave no demonstration"
    if not rnd.excuse:
        return "no-excuse", f"{_no_excuse_reason(report, task)}; {why}"
    return "no-demonstration", why


def _why_not_original(taught: Domain, problem: Problem, learned: list[str], options: ExcuseOptions,
                      deadline: float | None) -> str:
    """Why a session that reached the goal only through the demonstration is not solved, in one line: what the
    taught robot lacks to plan the task from its initial state (a learned skill that can never apply, else its
    excuse there, else the goal atoms no skill of it makes true)."""
    from guided_lfd.errors import GuidedLfdError

    head = (f"the task was reached only through the demonstration: the taught robot cannot plan {problem.name} "
            "from its initial state")
    try:
        lacks = _what_it_lacks(taught, problem, learned, options, deadline)
    except GuidedLfdError:  # the time limit, or a task too large: the reason without its detail
        lacks = None
    return f"{head} ({lacks})" if lacks else head


def _what_it_lacks(taught: Domain, problem: Problem, learned: list[str], options: ExcuseOptions,
                   deadline: float | None) -> str | None:
    """See :func:`_why_not_original`: the detail, or None when nothing more can be said."""
    from guided_lfd.planning.grounding import ground
    from guided_lfd.planning.task import bits

    ground_task = ground(taught, problem, deadline=deadline)
    reached, _ = _relaxed_reach(ground_task)
    true_somewhere = {ground_task.atoms[i].predicate for i in bits(reached)}
    for schema in taught.actions:
        if schema.name not in learned:
            continue
        for lit in schema.precondition:
            if lit.positive and lit.atom.predicate != "=" and lit.atom.predicate not in true_somewhere:
                return f"its learned {schema.name} needs {lit.atom}, which nothing makes true from there"
    report = find_excuses(taught, problem, replace(options, time_limit=seconds_left(deadline)))
    if report.excuse is not None:
        return "it still needs: " + "; ".join(describe_change(c, report.spellings) for c in report.excuse.changes)
    if report.unachievable_goals:
        return f"no skill of it makes {_unachievable_text(report)} true"
    return None


def _could_make(act, change: Change, objects: dict[str, str], subtypes: dict[str, set[str]]) -> bool:
    """Whether ``act`` has an effect that makes ``change`` (its predicate, with arguments its parameters' types
    admit): a drawer's ``open`` is not made by opening cupboard doors."""
    params = dict(act.params)
    for atom in act.add if change.added else act.delete:
        if atom.predicate != change.atom.predicate or len(atom.args) != len(change.atom.args):
            continue
        if all((objects.get(value) in subtypes.get(params[term], {params[term]})) if term in params
               else term == value for term, value in zip(atom.args, change.atom.args)):
            return True
    return False


def _learn_round(rnd: Round, folder: Path, out: Path, robot: Domain, task: Problem,
                 given: tuple[Path, Path], human: Domain | None = None, original: Domain | None = None,
                 history: list[tuple[str, dict]] | None = None) -> tuple[Domain, frozenset[Atom]]:
    """Segment the demonstration, learn its skills (in the robot's hand facts, named after the ``human``
    model's actions), merge them into the robot; (new domain, state it left).  A skill that could never run
    beside the robot's is a MismatchError.

    With the ``original`` robot and the ``history`` of earlier rounds' demonstrations, the skills are learned
    from all of them and merged into the original: a skill shown again from another situation (unstacking off
    a block, not the table) is generalised, not learned twice."""
    from guided_lfd.demonstration.learn import (check_usable, document_vocabulary, ground_actions, learn_domain,
                                                robot_declarations)
    from guided_lfd.demonstration.segment import segment, segments_document
    from guided_lfd.demonstration.trace import load_demonstration
    from guided_lfd.merge import merge_domains

    trace, states = given
    demo = load_demonstration(str(trace), str(states))
    acting = [s for s in segment(demo) if s.activity != "Idle"]
    doc = segments_document(demo, acting, str(states))
    doc["trace"] = str(trace)
    write_text(folder / "segments.json", json_document("segments", doc))
    rnd.files.update(trace=str(trace), state=str(states), segments=str(folder / "segments.json"))
    from guided_lfd.evaluate import usefulness

    _check_start(demo, task, trace)  # a demonstration of another world is refused before anything is learned
    base = original if original is not None else robot
    vocabulary = document_vocabulary(doc, base, human, source=str(trace))
    rnd.vocabulary = f"{vocabulary.describe()} (from {vocabulary.origin})"
    demonstrated = ground_actions(doc, str(trace), vocabulary=vocabulary)
    rnd.demonstration_length = len(demonstrated)
    rnd.new_actions = usefulness(demonstrated, robot, doc.get("objects", {})).useful
    documents = [*(history or []), (str(trace), doc)]
    learned = learn_domain(documents, name=f"learned-round-{rnd.index}", context=base, human=human, skip_known=True)
    # The robot's declaration of a predicate stands: merging a learned one would widen its argument types.
    learned = replace(learned, predicates=robot_declarations(learned.predicates, base))
    write_text(folder / "learned.pddl", domain_to_pddl(learned, header=f"Learned from {trace}"))
    merged = merge_domains([base, learned], name=robot.name).domain
    # New skills, and skills this demonstration generalised (the same name, another body).
    known = {a.name: (a.params, a.precondition, a.add, a.delete) for a in robot.actions}
    rnd.learned_actions = [a.name for a in merged.actions
                           if known.get(a.name) != (a.params, a.precondition, a.add, a.delete)]
    check_usable(merged, base, {a.name for a in merged.actions} - {a.name for a in base.actions}, str(trace))
    write_text(folder / "robot.pddl", domain_to_pddl(merged, header=f"The robot's domain after round {rnd.index}"))
    write_text(out / "robot.pddl", domain_to_pddl(merged, header=f"The robot's domain after round {rnd.index}"))
    rnd.files.update(learned=str(folder / "learned.pddl"), robot=str(folder / "robot.pddl"))
    state = _state_after(demo, task, merged, vocabulary)
    rnd.unmet = [c for c in rnd.request if (c.atom in state) != c.added]
    rnd.request_met = not rnd.unmet
    if history is not None:
        history.append((str(trace), doc))
    return merged, state


def _traced_predicates(demo) -> set[str]:
    """The predicates the demonstration's state file records (its fluents' vocabulary)."""
    return {a.predicate for a in demo.initial} | {a.predicate for _, a, _ in demo.events}


def _check_start(demo, task: Problem, trace: Path) -> None:
    """The demonstration starts where the task is now: its objects are the task's, its first state is the
    task's current one on the fluents the trace records (a trace of another world is refused, exit 34)."""
    from guided_lfd.errors import Location, MismatchError

    unknown = sorted(set(demo.objects) - set(task.objects))
    if unknown:
        raise MismatchError(f"the demonstration has object(s) the task does not: {', '.join(unknown)} "
                            "(expected a demonstration of this task)", Location(str(trace)))
    traced = _traced_predicates(demo)
    here = {a for a in task.init if a.predicate in traced}
    differ = sorted(here ^ set(demo.initial))
    if differ:
        which = differ[0]
        side = "true now but not at the demonstration's start" if which in here else "true at its start, not now"
        raise MismatchError(f"the demonstration starts from another state: {which} is {side} "
                            f"({len(differ)} fact(s) differ; expected a demonstration from the task's current "
                            "state)", Location(str(trace)))


def _state_after(demo, task: Problem, robot: Domain, vocabulary: HandVocabulary = KITCHEN) -> frozenset[Atom]:
    """The world as the demonstration left it: the trace's fluents at its end, the hand facts (in the robot's
    ``vocabulary``) as the trace's last frames say, the rest as it was."""
    end = float(demo.frames["time"].max())
    observed = demo.state_at(end)
    traced = _traced_predicates(demo)
    state = {a for a in task.init if a.predicate not in traced and a.predicate not in vocabulary.predicates}
    state |= set(observed)
    last = demo.frames.groupby("hand")["in_hand"].last()
    held = {str(hand): str(v).strip().lower() for hand, v in last.items() if str(v).strip() and str(v) != "nan"}
    if vocabulary.by_arm:
        for hand in ("left", "right"):
            state |= vocabulary.fluents(hand, held.get(hand, ""))
    else:  # one hand in the robot's words: it holds what either trace hand holds, free when neither holds
        for obj in held.values():
            state |= vocabulary.fluents("right", obj)
        if not held:
            state |= vocabulary.fluents("right", "")
    return frozenset(a for a in state if a.predicate in robot.predicates or a.predicate not in vocabulary.predicates)


def _replan(robot: Domain, task: Problem, deadline: float | None = None,
            search: str | None = None) -> list[PlanStep] | None:
    """The robot's validated plan for ``task`` (optimal unless another ``search`` is named), or None when it has
    none (SearchTimeout past ``deadline``)."""
    from guided_lfd.planning import DEFAULT_SEARCH
    from guided_lfd.symbolic.portfolio import validated_plan

    return validated_plan(robot, task, search or DEFAULT_SEARCH, seconds_left(deadline))[1]
