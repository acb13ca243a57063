"""Guided teaching, the paper's whole loop: excuse -> request -> demonstration -> learn -> merge -> re-plan.

Each round asks for the demonstration the robot needs (its minimal excuse,
in the paper's words: ``Open PinkDrawer``), says why it needs it and what to
leave as it is, takes the demonstration (a hand trace; or, simulated, the
human model's shortest plan to the request rendered as one), segments it,
learns its skills, merges them into the robot's domain and re-plans from
the state the demonstration left.  Rounds go on until the robot can plan
the task, no excuse exists, or the rounds run out.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable, Protocol

from guided_lfd.demonstration.trace import HAND_PREDICATES
from guided_lfd.excuse.change import Change, excuse_state
from guided_lfd.excuse.engine import ExcuseOptions, describe_change, find_excuses
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.io import json_document, write_text
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.pddl.writer import domain_to_pddl
from guided_lfd.validation import PlanStep

__all__ = ["Round", "TeachSession", "SimulatedHuman", "GivenTraces", "teach", "keep_facts"]


class Demonstrator(Protocol):
    """Whoever demonstrates: given the round's folder, the world's state and the request, a hand trace."""

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

    def to_dict(self) -> dict[str, Any]:
        """The round as ``session.json`` has it."""
        return {
            "round": self.index, "excuse": [str(c) for c in self.excuse], "request": [str(c) for c in self.request],
            "request_text": self.request_text, "why": self.why, "keep": [str(a) for a in self.keep],
            "keep_text": self.keep_text, "demonstration_length": self.demonstration_length,
            "new_actions": self.new_actions,
            "learned_actions": self.learned_actions, "request_met": self.request_met,
            "unmet": [str(c) for c in self.unmet], "solvable_after": self.solvable_after, "files": self.files,
            "preference": self.preference, "error": self.error,
        }


@dataclass
class TeachSession:
    """A whole teaching session: its rounds, how it ended, and the robot's plan at the end."""

    robot: str
    problem: str
    status: str  # solved | already-solvable | no-excuse | no-demonstration | max-rounds
    rounds: list[Round]
    plan: list[PlanStep] | None  # the robot's plan from the state the session ended in
    plans_original_task: bool | None  # whether the taught robot plans the task from its original state
    robot_domain: str  # the taught domain's file
    error: Any = field(default=None, repr=False, compare=False)  # the GuidedLfdError that ended it, if any

    @property
    def solved(self) -> bool:
        """Whether the robot can plan the task at the end."""
        return self.status in ("solved", "already-solvable")

    def to_dict(self) -> dict[str, Any]:
        """The body of ``session.json`` (format ``guided-lfd/teach``, version 1)."""
        return {"robot": self.robot, "problem": self.problem, "solved": self.solved, "status": self.status,
                "rounds": [r.to_dict() for r in self.rounds],
                "plan": None if self.plan is None else [str(s) for s in self.plan],
                "plans_original_task": self.plans_original_task, "robot_domain": self.robot_domain}

    def to_json(self) -> str:
        """The ``session.json`` document."""
        return json_document("teach", self.to_dict())

    def to_markdown(self) -> str:
        """``session.md``: the rounds as a person reads them."""
        lines = [f"# Teaching session: {self.problem}", "", f"Robot: `{self.robot}`; status: **{self.status}**.", ""]
        for r in self.rounds:
            lines += [f"## Round {r.index}", "", "Request: " + "; ".join(r.request_text) + ".", ""]
            if r.request != r.excuse:
                lines.append("- the minimal excuse is " + " ".join(str(c) for c in r.excuse)
                             + "; demonstrating the request makes the rest")
            if r.preference:
                lines.append(f"- {r.preference}")
            lines += [f"- why: {w}" for w in r.why]
            if r.keep_text:
                lines.append("- leave as it is: " + "; ".join(r.keep_text))
            lines.append(f"- demonstrated actions: {r.demonstration_length if r.demonstration_length is not None else '-'}"
                         f"; learned: {', '.join(r.learned_actions) or '-'}")
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
    current = set(excuse_state(state, changes))
    made: set[Atom] = set()
    keep: list[Atom] = []
    for step in plan:
        schema = schemas[step.action]
        binding = {v: a for (v, _), a in zip(schema.params, step.args)}
        for lit in schema.precondition:
            atom = lit.atom.substitute(binding)
            if (lit.positive and atom in state and atom not in made and atom not in keep
                    and atom.predicate not in HAND_PREDICATES and atom.predicate != "="):
                keep.append(atom)
        adds = {a.substitute(binding) for a in schema.add}
        dels = {a.substitute(binding) for a in schema.delete}
        made |= adds - current
        current = (current - dels) | adds
    # Facts the human cannot change (graspable) are the world's structure: nothing to ask about.
    static = set(human.predicates) - human.fluent_predicates() if human is not None else set()
    changed = {c.atom for c in changes}
    return [a for a in keep if a not in changed and a.predicate not in static]


def _why(report, robot: Domain, problem: Problem, excuse: list[Change]) -> list[str]:
    """Why the robot needs the demonstration: each requested change it has no skill for, or that it cannot
    make from here, on the way to the goal it cannot reach."""
    spellings = report.spellings
    goal = ", ".join(describe_change(Change(l.atom, l.positive), spellings) for l in problem.goal)
    out = [f"no skill of the robot makes {g} true" for g in report.unachievable_goals]
    objects = {**robot.constants, **problem.objects}
    subtypes = robot.subtypes()
    for change in excuse:
        can = any(_could_make(act, change, objects, subtypes) for act in robot.actions)
        what = describe_change(change, spellings)
        out.append(f"{what}: no skill of the robot does this, and its plan to {goal} needs it" if not can else
                   f"{what}: the robot cannot do this from here, and its plan to {goal} needs it")
    return out


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


@dataclass
class SimulatedHuman:
    """A demonstrator simulated by a human model: its shortest plan to the request, rendered as a hand trace."""

    human: Domain
    rate_hz: float = 90.0
    seed: int = 0

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """Render the human's optimal plan from ``state`` to a state where ``request`` holds (None: no plan)."""
        from guided_lfd.demonstration.render import Noise, render, script_for_plan
        from guided_lfd.evaluate import excuse_goal, optimal_plan

        plan = optimal_plan(self.human, replace(problem, init=state), goal=excuse_goal(request))
        if not plan:
            return None
        script = script_for_plan([(s.action, s.args) for s in plan], self.human, set(state))
        scene = _scene(problem, self.human)
        _check_drawable(script, scene, plan, self.human)
        rendering = render(script, scene, set(state), self.rate_hz, Noise(seed=self.seed))
        trace, states = folder / "demonstration.csv", folder / "demonstration.state.csv"
        write_text(trace, rendering.trace_csv)
        write_text(states, rendering.state_csv)
        write_text(folder / "demonstration.labels.csv", rendering.labels_csv)
        return trace, states


def _check_drawable(script, scene, plan: list[PlanStep], human: Domain) -> None:
    """The renderer draws hand manipulation (take, put, open and close, push an obstacle away): a plan
    with another kind of action (walking through a door, turning a key) is refused in one line, not drawn wrongly."""
    from guided_lfd.demonstration.render import undrawable_actions
    from guided_lfd.errors import UnsupportedFeatureError

    odd = undrawable_actions([(step.action, step.args) for step in plan], human)
    missing = [s.obj for s in script if s.activity not in ("Idle", "Release") and s.obj not in scene.positions]
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

    def demonstrate(self, folder: Path, state: frozenset[Atom], request: list[Change],
                    problem: Problem) -> tuple[Path, Path] | None:
        """The next trace and its state file (``TRACE.state.csv`` beside it), or None when none is left."""
        from guided_lfd.demonstration.trace import default_state_path

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
    ``out/robot.pddl`` is the robot's domain after each round;
    ``session.json`` and ``session.md`` are written by the caller.
    """
    from guided_lfd.errors import GuidedLfdError, SearchTimeout

    _make_folder(out)
    options = options or ExcuseOptions()
    if human is not None:
        options = replace(options, fixed_from=human, all_minimal=options.all_minimal or prefer)
    state, current, rounds = problem.init, robot, []
    status, final_plan, error = "max-rounds", None, None
    try:
        for k in range(1, max_rounds + 1):
            folder = _make_folder(out / f"round-{k}")
            task = replace(problem, init=state)
            report = find_excuses(current, task, replace(options, time_limit=_left(deadline)))
            write_text(folder / "excuse.json", report.to_json())
            if report.status is ExcuseStatus.ALREADY_SOLVABLE:
                status, final_plan = ("already-solvable" if k == 1 else "solved"), report.robot_plan
                break
            if report.excuse is None:
                status = "no-excuse" if report.status is not ExcuseStatus.TIMEOUT else "timeout"
                break
            rnd = _request(k, current, task, report, human if prefer else None, human if redundancy else None,
                           human)
            rnd.files["excuse"] = str(folder / "excuse.json")
            rounds.append(rnd)
            if on_request:
                on_request(rnd)
            try:
                given = demonstrator.demonstrate(folder, state, rnd.request, task)
                if given is None:
                    status = "no-demonstration"
                    break
                current, state = _learn_round(rnd, folder, out, current, task, given)
            except SearchTimeout:
                raise
            except GuidedLfdError as exc:  # the demonstration's fault: the session so far stays
                rnd.error, error, status = str(exc), exc, "bad-demonstration"
                break
            outcome = _replan(current, replace(problem, init=state), deadline)
            rnd.solvable_after = outcome is not None
            if outcome is not None:
                status, final_plan = "solved", outcome
                break
    except SearchTimeout:
        status = "timeout"
    write_text(out / "robot.pddl", domain_to_pddl(current, header=f"The robot's domain after teaching {problem.path}"))
    try:
        original = _replan(current, problem, deadline) is not None
    except SearchTimeout:
        original = None
    session = TeachSession(robot.path, problem.path, status, rounds, final_plan, original, str(out / "robot.pddl"))
    session.error = error
    return session


def _left(deadline: float | None) -> float | None:
    """Seconds left before ``deadline`` (at least a little: the search then ends as a timeout)."""
    from guided_lfd.deadline import remaining

    left = remaining(deadline)
    return None if left is None else max(0.001, left)


def _make_folder(folder: Path) -> Path:
    """``folder``, created if need be; one the OS refuses is the output error (exit 40)."""
    from guided_lfd.errors import Location, OutputError

    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot make the session folder ({exc.strerror or exc})", Location(str(folder))) from None
    return folder


def _request(k: int, robot: Domain, task: Problem, report, prefer_by: Domain | None,
             reduce_by: Domain | None, human: Domain | None = None) -> Round:
    """The round's request: the (preferred) minimal excuse or its smallest sufficient part, why the robot
    needs it, what to leave as it is."""
    from guided_lfd.excuse.preference import minimal_request, prefer_demonstration
    from guided_lfd.pddl.model import pretty_atom

    spellings = report.spellings
    chosen, preference = report.excuse, None
    if prefer_by is not None and len(report.excuses) > 1:
        index, preference = prefer_demonstration([e.changes for e in report.excuses], prefer_by, robot, task)
        chosen = report.excuses[index]
    excuse = chosen.changes
    request = minimal_request(reduce_by, robot, task, excuse) if reduce_by is not None else list(excuse)
    keep = keep_facts(robot, task, task.init, excuse, chosen.plan, human)
    return Round(k, excuse, request, [describe_change(c, spellings) for c in request],
                 _why(report, robot, task, excuse), keep, [f"keep {pretty_atom(a, spellings)}" for a in keep],
                 preference=preference)


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
                 given: tuple[Path, Path]) -> tuple[Domain, frozenset[Atom]]:
    """Segment the demonstration, learn its skills, merge them into the robot; (new domain, state it left)."""
    from guided_lfd.demonstration.learn import ground_actions, learn_domain
    from guided_lfd.demonstration.segment import segment, segments_document
    from guided_lfd.demonstration.trace import load_demonstration
    from guided_lfd.merge import merge_domains

    trace, states = given
    demo = load_demonstration(str(trace), str(states))
    acting = [s for s in segment(demo) if s.activity != "Idle"]
    doc = segments_document(demo, acting, str(states))
    doc["trace"] = str(trace)
    write_text(folder / "segments.json", json_document("segments", doc))
    from guided_lfd.evaluate import usefulness

    demonstrated = ground_actions(doc, str(trace))
    rnd.demonstration_length = len(demonstrated)
    rnd.new_actions = usefulness(demonstrated, robot, doc.get("objects", {})).useful
    learned = learn_domain([(str(trace), doc)], name=f"learned-round-{rnd.index}", context=robot)
    write_text(folder / "learned.pddl", domain_to_pddl(learned, header=f"Learned from {trace}"))
    merged = merge_domains([robot, learned], name=robot.name).domain
    known = {a.name for a in robot.actions}
    rnd.learned_actions = [a.name for a in merged.actions if a.name not in known]
    write_text(folder / "robot.pddl", domain_to_pddl(merged, header=f"The robot's domain after round {rnd.index}"))
    write_text(out / "robot.pddl", domain_to_pddl(merged, header=f"The robot's domain after round {rnd.index}"))
    rnd.files.update(trace=str(trace), state=str(states), segments=str(folder / "segments.json"),
                     learned=str(folder / "learned.pddl"), robot=str(folder / "robot.pddl"))
    _check_start(demo, task, trace)
    state = _state_after(demo, task, merged)
    rnd.unmet = [c for c in rnd.request if (c.atom in state) != c.added]
    rnd.request_met = not rnd.unmet
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


def _state_after(demo, task: Problem, robot: Domain) -> frozenset[Atom]:
    """The world as the demonstration left it: the trace's fluents at its end, the rest as it was."""
    end = float(demo.frames["time"].max())
    observed = demo.state_at(end)
    traced = _traced_predicates(demo)
    state = {a for a in task.init if a.predicate not in traced and a.predicate not in HAND_PREDICATES}
    state |= set(observed)
    held = {str(v).strip().lower() for v in demo.frames.groupby("hand")["in_hand"].last() if str(v).strip()
            and str(v) != "nan"}
    if "in_hand" in robot.predicates:
        state |= {Atom("in_hand", (obj,)) for obj in held}
    if "hand_free" in robot.predicates and not held:
        state.add(Atom("hand_free"))
    return frozenset(state)


def _replan(robot: Domain, task: Problem, deadline: float | None = None) -> list[PlanStep] | None:
    """The robot's validated optimal plan for ``task``, or None when it has none (SearchTimeout past ``deadline``)."""
    from guided_lfd.api import plan

    return plan(robot, task, time_limit=_left(deadline)).plan
