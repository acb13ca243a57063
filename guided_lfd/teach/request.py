"""What a round asks for, and why, in words: the (preferred) minimal excuse or its sufficient part, why the robot
needs it, what to leave as it is; and why a session ends without the robot's plan (what a domain cannot reach)."""

from __future__ import annotations

from dataclasses import replace

from guided_lfd.deadline import seconds_left
from guided_lfd.demonstration.vocabulary import KITCHEN, HandVocabulary, infer_vocabulary
from guided_lfd.excuse.change import Change, describe_change, excuse_state
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.planning.validation import PlanStep
from guided_lfd.planning.search import relaxed_reach
from guided_lfd.teach.session import Demonstrator, Round

__all__ = ["keep_facts", "robot_vocabulary", "excuse_request", "new_skill_request", "no_excuse_reason",
           "no_demonstration", "why_not_original", "first_unreachable"]


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


def excuse_request(k: int, robot: Domain, task: Problem, report, prefer_by: Domain | None,
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


def _goal_text(report, task: Problem) -> str:
    """The task's goal in the paper's words (``Inside RedPlate, PinkDrawer``)."""
    return ", ".join(describe_change(Change(lit.atom, lit.positive), report.spellings) for lit in task.goal)


def _unachievable_text(report) -> str:
    """The goal atoms no skill of the robot makes true, in the paper's words."""
    return ", ".join(describe_change(Change(lit.atom, lit.positive), report.spellings)
                     for lit in report.unachievable_goals)


def new_skill_request(k: int, robot: Domain, task: Problem, report) -> Round:
    """A round for a task without an excuse: no skill of the robot makes some goal atoms true, so the request is
    those atoms (a demonstration of a new skill that makes them), and the why says so."""
    request = [Change(lit.atom, lit.positive) for lit in report.unachievable_goals]
    return Round(k, [], request, [describe_change(c, report.spellings) for c in request],
                 _why(report, robot, task, []), [], [])


def no_excuse_reason(report, task: Problem) -> str:
    """Why no excuse exists, in one line: the goal atoms no skill makes true, or no change that helps."""
    if report.unachievable_goals:
        return (f"no excuse exists: no skill of the robot makes {_unachievable_text(report)} true, so a new "
                "skill that does must be demonstrated")
    return f"no excuse exists: no change of the world's state lets the robot's skills reach {_goal_text(report, task)}"


def no_demonstration(demonstrator: Demonstrator, state: frozenset[Atom], rnd: Round, task: Problem,
                      report) -> tuple[str, str]:
    """(status, reason) of a session whose demonstrator gave no demonstration: ``no-excuse`` when the round
    asked for a new skill (no excuse exists), ``no-demonstration`` otherwise; the reason says why none came."""
    why_none = getattr(demonstrator, "why_none", None)
    why = why_none(state, rnd.request, task) if why_none is not None else "the demonstrator gave no demonstration"
    if not rnd.excuse and rnd.skill is None:
        return "no-excuse", f"{no_excuse_reason(report, task)}; {why}"
    return "no-demonstration", why


def why_not_original(taught: Domain, problem: Problem, learned: list[str], options: ExcuseOptions,
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
    """See :func:`why_not_original`: the detail, or None when nothing more can be said."""
    from guided_lfd.planning.grounding import ground
    from guided_lfd.planning.task import bits

    ground_task = ground(taught, problem, deadline=deadline)
    reached, _ = relaxed_reach(ground_task.actions, ground_task.init)
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


def first_unreachable(domain: Domain, task: Problem, changes: list[Change]) -> Change | None:
    """The first of ``changes`` that no plan of ``domain`` makes from ``task``'s state on its own (a relaxed
    check first, then each change's own optimal plan), or None when each one alone can be made."""
    from guided_lfd.evaluate import excuse_goal, optimal_plan
    from guided_lfd.planning.grounding import ground

    ground_task = ground(domain, task)
    reached, deletable = relaxed_reach(ground_task.actions, ground_task.init)
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

