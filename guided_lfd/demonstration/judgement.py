"""A demonstration judged against what was asked for: the one implementation behind ``evaluate``'s measures
(useful fraction, misdirected guidance) and ``teach``'s check of each demonstration (issue #52).

* :func:`known_skill`: the action of a domain making exactly a demonstrated step's changes (a step the robot
  already has is no useful demonstration);
* :func:`misdirected_culprit`: whether a state where the excuse holds leaves the robot unable to reach its goal
  (misdirected guidance), and the fewest differences from the intended excuse state that are to blame;
* :func:`contradiction`: an action of a domain that a demonstrated step contradicts (it makes part of the
  step's changes on the step's objects, and the step makes others beside them);
* :func:`differences`: what a demonstration changed, as changes.
"""

from __future__ import annotations

import itertools
from typing import Callable, Iterable

from guided_lfd.demonstration.learn import DemonstratedAction
from guided_lfd.excuse.change import Change, excuse_state
from guided_lfd.pddl.model import Atom, Domain, Literal

__all__ = ["MAX_CULPRIT_SIZE", "known_skill", "misdirected_culprit", "contradiction", "differences",
           "state_after_steps"]

#: Largest set of differences tried when explaining a misdirected state.
MAX_CULPRIT_SIZE = 3


def differences(before: Iterable[Atom], after: Iterable[Atom]) -> list[Change]:
    """The changes that turn ``before`` into ``after`` (``+p`` made true, ``-p`` made false), sorted."""
    before, after = set(before), set(after)
    return sorted([Change(a, True) for a in after - before] + [Change(a, False) for a in before - after], key=str)


def state_after_steps(state: Iterable[Atom], steps: Iterable[DemonstratedAction]) -> frozenset[Atom]:
    """The state the demonstrated ``steps`` leave, applied in order from ``state`` (what each deleted, then added)."""
    out = set(state)
    for step in steps:
        out = (out - set(step.delete)) | set(step.add)
    return frozenset(out)


def _ground_effects(step: DemonstratedAction, domain: Domain, types: dict[str, str], same_size: bool = False):
    """Every action of ``domain`` bound to the step's objects (parameters in its effects only, types
    respected): (``(name args)``, adds, deletes); ``same_size``: only actions with as many add and delete
    effects as the step."""
    subtypes = domain.subtypes()
    objects = sorted({o for a in (*step.add, *step.delete) for o in a.args})
    for schema in domain.actions:
        if same_size and (len(schema.add) != len(step.add) or len(schema.delete) != len(step.delete)):
            continue
        in_effects = [v for v, _ in schema.params if any(v in a.args for a in (*schema.add, *schema.delete))]
        ptype = dict(schema.params)
        for combo in itertools.product(objects, repeat=len(in_effects)):
            if any(types.get(o, "object") not in subtypes.get(ptype[v], {ptype[v]}) for v, o in zip(in_effects, combo)):
                continue
            binding = dict(zip(in_effects, combo))
            name = "(" + " ".join([schema.name, *(binding.get(v, v) for v, _ in schema.params)]) + ")"
            yield name, {a.substitute(binding) for a in schema.add}, {a.substitute(binding) for a in schema.delete}


def known_skill(step: DemonstratedAction, robot: Domain, types: dict[str, str]) -> str | None:
    """The robot action making exactly the step's changes (M(a) in A_R), as ``(name args)``, or None.

    A demonstrated step is a skill the robot already has when one of its
    actions, bound to the step's objects, adds and deletes exactly what the
    step added and deleted.  Preconditions are not compared: a learned action
    carries extra nodes-of-interest preconditions and is still the same skill.
    """
    add, delete = set(step.add), set(step.delete)
    for name, adds, dels in _ground_effects(step, robot, types, same_size=True):
        if adds == add and dels == delete:
            return name
    return None


def contradiction(step: DemonstratedAction, domain: Domain, types: dict[str, str], strict: bool = True,
                  ignore: frozenset[str] | set[str] = frozenset()) -> tuple[str, list[Change]] | None:
    """An action of ``domain`` the step contradicts, as (``(name args)``, the changes that action makes), or None.

    The step contradicts an action when the action, bound to the step's objects, makes some of the step's
    changes and no action makes exactly them (:func:`known_skill`): learned, the step would be a second skill
    for the same act with other effects.  ``strict`` (a model of every skill, the human's): any overlap
    counts; otherwise (the robot's own skills) only an action whose changes are all among the step's (the step
    did what the robot's skill does, and more at once).  Among several, the one sharing most changes and making
    fewest others.  Atoms of the predicates in ``ignore`` (the hand's, which a model may name otherwise) are left
    out on both sides."""
    def seen(atoms):
        return {a for a in atoms if a.predicate not in ignore}

    add, delete = seen(step.add), seen(step.delete)
    best, best_key = None, None
    for name, adds, dels in _ground_effects(step, domain, types):
        adds, dels = seen(adds), seen(dels)
        if adds == add and dels == delete:
            return None
        shared = len(adds & add) + len(dels & delete)
        other = len(adds - add) + len(dels - delete)
        if not shared or (not strict and other):
            continue
        key = (-shared, other, name)
        if best_key is None or key < best_key:
            best, best_key = (name, sorted([Change(a, True) for a in adds] + [Change(a, False) for a in dels],
                                           key=str)), key
    return best


def misdirected_culprit(state: frozenset[Atom], excuse: tuple[Literal, ...], goal: tuple[Literal, ...],
                        intended: frozenset[Atom], reach: Callable[[frozenset[Atom]], bool]) -> list[Change] | None:
    """Whether ``state`` is misdirected guidance: the ``excuse`` holds in it, the ``goal`` does not, and the robot
    (``reach``: whether it reaches the goal from a state) cannot reach it; then the fewest differences from the
    ``intended`` excuse state that, undone, let the robot succeed (e.g. ``+(blocking chair table)``: the chair
    now blocks the plate), tried by size up to :data:`MAX_CULPRIT_SIZE`, beyond it the whole difference.
    None when the state is not misdirected."""
    if not all(lit.holds(state) for lit in excuse) or all(lit.holds(state) for lit in goal) or reach(state):
        return None
    diff = differences(intended, state)
    for size in range(1, min(len(diff), MAX_CULPRIT_SIZE) + 1):
        for subset in itertools.combinations(diff, size):
            if reach(excuse_state(state, [Change(c.atom, not c.added) for c in subset])):
                return list(subset)
    return diff
