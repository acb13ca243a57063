"""State invariants for the *consistent* excuse semantics.

Lifted mutex invariants are synthesised with Fast Downward's translator
(Helmert 2009, invariant synthesis) from the robot's actions **and the
reverse of each action**.  Without the reverses, an invariant could hold
only because a skill is missing (the robot cannot open a second cupboard, so
"at most one cupboard is open" looks invariant) and would wrongly forbid the
excuse the human should be asked for.

Each lifted invariant is instantiated over all objects into ground groups:

* at most one atom of a group may be true in the excuse state if at most
  one is true in I (a group with two or more true atoms in I constrains
  nothing: the invariant does not describe this initial state);
* exactly one must be true if exactly one is true in I *and* no action can
  change the group's count (every add is paired with a delete of a group atom
  the action requires) — "objects don't vanish or double up".  A group an
  action may empty (``open ?d`` undone by ``close``) only gets "at most one".
"""

from __future__ import annotations

import time
from dataclasses import replace

from guided_lfd.errors import Location, MismatchError, SearchTimeout
from guided_lfd.excuse.space import MutexGroup
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.task import GroundTask, bits
from guided_lfd.pddl.model import TOTAL_COST, Atom, Domain, Literal, Predicate, Problem
from guided_lfd.pddl.translator import find_invariants, quiet, translator_task


#: A 0-ary predicate only used as the goal handed to the translator, which
#: needs a non-empty goal over the synthesised domain's own predicates.
_DUMMY_GOAL = "guided-lfd-invariant-goal"


def with_reversed_actions(domain: Domain) -> Domain:
    """The domain with the reverse of every action added (names kept unique)."""
    taken = {a.name for a in domain.actions}
    reverses = []
    for action in domain.actions:
        rev = action.reversed()
        name, k = rev.name, 1
        while name in taken:
            k += 1
            name = f"{rev.name}{k}"
        taken.add(name)
        reverses.append(replace(rev, name=name))
    return replace(domain, actions=[*domain.actions, *reverses])


def lifted_invariants(domain: Domain, problem: Problem, max_time: float | None = None, reverse: bool = True) -> list:
    """Fast Downward's lifted invariants of ``domain`` (with reversed actions, unless ``reverse`` is False:
    then they hold in every state the actions reach from a state where they hold, no more)."""
    augmented = with_reversed_actions(domain) if reverse else domain
    # The translator refuses an object an action names without declaring it:
    # implicit constants are declared, with the problem's types, for it.
    implicit = {c: problem.objects.get(c, "object") for c in domain.implicit_constants}
    augmented = replace(augmented, predicates={**augmented.predicates, _DUMMY_GOAL: Predicate(_DUMMY_GOAL)},
                        constants={**augmented.constants, **implicit}, implicit_constants=())
    objects = {o: t for o, t in _objects_of_types(domain, problem).items() if o not in augmented.constants}
    prob = replace(problem, domain_name=domain.name, init=frozenset(), objects=objects,
                   goal=(Literal(Atom(_DUMMY_GOAL)),))
    try:
        with quiet():
            found = find_invariants(translator_task(augmented, prob), max(1, int(max_time)) if max_time else 300)
    except (MemoryError, SearchTimeout):
        raise  # a resource or time limit, not a property of the domain
    except (Exception, SystemExit) as exc:  # the translator signals errors with SystemExit too
        detail = " ".join(str(exc).split()) or type(exc).__name__
        raise MismatchError(
            f"cannot synthesise invariants from domain '{domain.name}': {detail[:200]}", Location(domain.path)
        ) from None
    return sorted(found, key=str)


def mutex_groups(source: Domain, task: GroundTask, deadline: float | None = None,
                 refuted: list[str] | None = None) -> list[MutexGroup]:
    """Ground mutex groups of ``task`` from invariants of ``source`` (usually its own domain).

    An invariant the task's goal breaks (two of a group's atoms wanted true, or every atom of an exactly-one
    group wanted false) is no law of the world: it holds only because the robot lacks a skill (without
    pick-up, a paper is never carried again once one is delivered, so "at most one of carrying and satisfied"
    holds for the robot, though the task wants two houses satisfied).  It is left out, and its description
    appended to ``refuted``.
    """
    remaining = None if deadline is None else max(1.0, deadline - time.monotonic())
    invariants = lifted_invariants(source, task.problem, remaining)
    groups: list[MutexGroup] = []
    if source is task.domain:
        check_task = task
    else:
        # Conservation is judged with the actions the invariants come from.
        check_task = ground(source, _problem_for(source, task.problem))
    atoms_of = atoms_by_predicate(task)
    for inv in invariants:
        by_key = invariant_instances(inv, task, atoms_of)
        conserved = _conserved(check_task, task, [m for m in by_key.values()])
        # Only where the initial state keeps the group (where it does not, the group is not used anyway).
        if any(_goal_breaks(task, mask, conserved and (task.init & mask).bit_count() == 1)
               for mask in by_key.values() if (task.init & mask).bit_count() <= 1):
            if refuted is not None:
                refuted.append(describe_invariant(inv))
            continue
        for key in sorted(by_key):
            mask = by_key[key]
            count = (task.init & mask).bit_count()
            if count > 1:
                continue
            exactly = count == 1 and conserved
            if mask.bit_count() < 2 and not exactly:
                continue  # "at most one of one atom" says nothing
            groups.append(MutexGroup(mask, exactly, describe_invariant(inv)))
    # The same ground group can come from several invariants: keep the strongest.
    unique: dict[int, MutexGroup] = {}
    for g in groups:
        if g.mask not in unique or (g.exactly_one and not unique[g.mask].exactly_one):
            unique[g.mask] = g
    return [unique[m] for m in sorted(unique)]


def atoms_by_predicate(task: GroundTask) -> dict[str, list[int]]:
    """The task's atom indices by predicate: each invariant part only looks at its own predicate's atoms."""
    atoms_of: dict[str, list[int]] = {}
    for i, atom in enumerate(task.atoms):
        atoms_of.setdefault(atom.predicate, []).append(i)
    return atoms_of


def invariant_instances(inv, task: GroundTask, atoms_of: dict[str, list[int]]) -> dict[tuple, int]:
    """A lifted invariant's ground groups in ``task``, by the objects its parameters are bound to, as atom masks
    (``atoms_of``: the task's atom indices by predicate)."""
    by_key: dict[tuple, int] = {}
    for part in inv.parts:
        for i in atoms_of.get(part.predicate, ()):
            atom = task.atoms[i]
            if len(atom.args) != len(part.args):
                continue
            key = tuple(
                atom.args[pos]
                for arg_index in range(part.arity())
                for pos, arg in enumerate(part.args)
                if arg == arg_index
            )
            by_key[key] = by_key.get(key, 0) | (1 << i)
    return by_key


def placement_groups(task: GroundTask, placing: dict[str, str], groups: list[MutexGroup],
                     refuted: list[str] | None = None) -> tuple[list[MutexGroup], list[str]]:
    """``groups`` with "at most one" added for each object a ``placing`` predicate puts in one place
    (:func:`guided_lfd.excuse.structure.placing_predicates`), and the predicates that added some; a predicate
    the goal wants true of one object twice is no such law (it goes to ``refuted``)."""
    masks: dict[str, dict[tuple[str, ...], int]] = {}
    for i, atom in enumerate(task.atoms):
        if atom.predicate in placing and atom.args:
            by_object = masks.setdefault(atom.predicate, {})
            key = atom.args[:-1]  # the thing placed (none for a one-argument marker: where the robot is)
            by_object[key] = by_object.get(key, 0) | (1 << i)
    have = {g.mask for g in groups}
    added: list[MutexGroup] = []
    kept: list[str] = []
    for name, by_object in sorted(masks.items()):
        law = f"{{({name} ?v0 *)}} (one place)" if len(next(iter(by_object))) else f"{{({name} *)}} (one place)"
        if any(_goal_breaks(task, mask, False) for mask in by_object.values()):
            if refuted is not None:
                refuted.append(law)
            continue
        new = [MutexGroup(mask, False, law) for _, mask in sorted(by_object.items())
               if mask.bit_count() > 1 and mask not in have and (task.init & mask).bit_count() <= 1]
        added += new
        kept += [name] if new else []
    return sorted([*groups, *added], key=lambda g: g.mask), kept


def _goal_breaks(task: GroundTask, mask: int, exactly_one: bool) -> bool:
    """Whether no state satisfying ``task``'s goal keeps the group ``mask`` (at most one, or exactly one, true)."""
    return (task.goal_pos & mask).bit_count() > 1 or (exactly_one and not mask & ~task.goal_neg)


def describe_invariant(inv) -> str:
    """Readable form of a lifted invariant: ``{(holding *), (handempty)}``."""
    parts = []
    for part in sorted(inv.parts):
        args = ["*" if a == -1 else f"?v{a}" for a in part.args]
        parts.append("(" + " ".join([part.predicate, *args]) + ")")
    return "{" + ", ".join(parts) + "}"


def _problem_for(source: Domain, problem: Problem) -> Problem:
    """``problem`` in the terms of ``source``, another model of the world (``--invariants-from``): the objects of
    the types it declares (its own constants aside) and the initial atoms, goal literals and cost values of its
    predicates and functions on them.  The rest means nothing to its actions, and the translator refuses it in
    an ADL model's task."""
    objects = _objects_of_types(source, problem)
    terms = {**objects, **source.constants}

    def fits(atom: Atom, names: dict) -> bool:
        return atom.predicate in names and all(a in terms for a in atom.args)

    return replace(problem, domain_name=source.name, objects=objects,
                   init=frozenset(a for a in problem.init if fits(a, source.predicates)),
                   goal=tuple(lit for lit in problem.goal if fits(lit.atom, source.predicates)), goal_condition=None,
                   function_values={a: v for a, v in problem.function_values.items() if fits(a, source.functions)},
                   metric=problem.metric and TOTAL_COST in source.functions)


def _objects_of_types(domain: Domain, problem: Problem) -> dict[str, str]:
    """The problem's objects whose types ``domain`` declares, but for its constants: the invariants are lifted,
    objects only matter for their types."""
    types = set(domain.types) | {"object"}
    return {o: t for o, t in problem.objects.items() if t in types and o not in domain.constants}


def _conserved(check_task: GroundTask, task: GroundTask, masks: list[int]) -> bool:
    """Whether every action keeps the number of true atoms in each group constant."""
    if check_task is not task:
        # Map the groups into the other task's atom index by atom identity.
        remap = []
        for mask in masks:
            m = 0
            for i in bits(mask):
                j = check_task.index.get(task.atoms[i])
                if j is not None:
                    m |= 1 << j
            remap.append(m)
        masks = remap
    # Each action is checked against the groups its effects touch only
    # (linear in the ground task, not actions x groups).
    groups_of: dict[int, list[int]] = {}
    for k, mask in enumerate(masks):
        for i in bits(mask):
            groups_of.setdefault(i, []).append(k)
    for act in check_task.actions:
        touched: set[int] = set()
        for i in (*act.add_ids, *act.delete_ids):
            touched.update(groups_of.get(i, ()))
        for eff in act.effects:  # ADL: whether a conditional effect runs depends on the state
            if any(i in groups_of for i in bits(eff.add | eff.delete)):
                return False
        for k in touched:
            mask = masks[k]
            added = act.add & mask & ~act.pre_pos
            removed = act.delete & mask & ~act.add
            if not added and not removed:
                continue
            if removed & ~act.pre_pos or added.bit_count() != removed.bit_count():
                return False
    return True
