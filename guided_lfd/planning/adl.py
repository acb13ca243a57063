"""ADL tasks: Fast Downward's normal form, grounded on bit sets, and an optimal A* over them.

:func:`ground_adl` writes the model's domain and problem as PDDL, lets Fast
Downward's translator normalise them (quantifiers and disjunctions compiled
into axioms and split actions, complicated goals into a derived atom) and
ground them by its relaxed reachability analysis, and turns the result into
a :class:`~guided_lfd.planning.task.GroundTask` whose actions carry conditional
effects and whose states are closed under the axioms.

:func:`astar` is guided-lfd's A* for such tasks, with LM-cut on a relaxation
that stays admissible: effect conditions dropped (every conditional add
counts as possible), negative conditions on derived atoms ignored, axioms as
actions of cost 0.
"""

from __future__ import annotations

import time
from typing import Any

from guided_lfd.deadline import linger
from guided_lfd.errors import Location, SearchTimeout, TaskTooLarge
from guided_lfd.pddl.model import Atom, Domain, Problem
from guided_lfd.pddl.translator import quiet, translator_options, translator_task
from guided_lfd.planning.relaxation import RelaxedTask
from guided_lfd.planning.task import (MAX_GROUND_ACTIONS, UNREACHABLE_GOAL, AxiomClosure, GroundAction, GroundAxiom,
                                      GroundEffect, GroundTask, ground_atoms, mask_of)


def _changeable(task: Any, domain: Domain, problem: Problem, predicates: set[str]) -> None:
    """Make ``predicates`` fluent for the translator and every atom of theirs possible.

    An excuse may change any atom of these predicates in the initial state,
    so none may be compiled away as static and grounding must not prune by
    reachability from the one initial state: each gets an action that adds it
    and can never run (its precondition is an atom nothing adds), and the
    exploration starts from every type-correct atom of theirs.
    """
    from fast_downward.translate import pddl

    never = pddl.Atom(NEVER, [])
    for name in sorted(predicates):
        args = [f"?a{k}" for k in range(domain.predicates[name].arity)]
        effect = pddl.Effect([], pddl.Truth(), pddl.Atom(name, args))
        task.actions.append(pddl.Action(f"{NEVER}-{name}", [pddl.TypedObject(a, "object") for a in args], len(args),
                                        never, [effect], None))
    skip = set(domain.predicates) - predicates
    known = set(task.init)
    task.init += [atom for atom in (pddl.Atom(a.predicate, list(a.args)) for a in ground_atoms(domain, problem, skip))
                  if atom not in known]


#: The atom no action adds, and the prefix of the translator-only actions that make predicates fluent.
NEVER = "guided-lfd-never"


def _explore(domain: Domain, problem: Problem, changeable: set[str] = frozenset()) -> tuple:  # type: ignore[assignment]
    """Normalise and ground with the translator: (reachable, atoms, actions, goal, axioms, layers)."""
    from fast_downward.translate import axiom_rules, instantiate, normalize

    with quiet():
        task = translator_task(domain, problem)
        if changeable:
            _changeable(task, domain, problem, changeable)
        normalize.normalize(task)
        reachable, atoms, actions, goal, axioms, _ = instantiate.explore(task)
        layers: dict = {}
        if reachable and goal is not None:
            axioms, layers = axiom_rules.handle_axioms(actions, axioms, goal, translator_options().layer_strategy)
    return reachable, atoms, actions, goal, axioms, layers


def ground_adl(domain: Domain, problem: Problem, deadline: float | None = None,
               changeable: set[str] = frozenset()) -> GroundTask:  # type: ignore[assignment]
    """Ground an ADL task in Fast Downward's normal form (static atoms compiled away, as its translator does).

    ``changeable``: predicates whose every atom an excuse may change (kept, and
    grounded over all type-correct atoms, see :func:`_changeable`); planning
    gives none and gets the translator's reachability grounding.  An
    unreachable goal gives a task whose goal is one atom no action adds (every
    search proves it unsolvable at once).
    """
    reachable, fd_atoms, fd_actions, fd_goal, fd_axioms, layer_of = _explore(domain, problem, changeable)
    if changeable:
        reachable = True  # the exploration started from every atom, not from the initial state
    if deadline is not None and time.monotonic() > deadline:
        raise SearchTimeout("grounding exceeded the time limit")
    if len(fd_actions) > MAX_GROUND_ACTIONS:
        raise TaskTooLarge(f"more than {MAX_GROUND_ACTIONS} ground actions", Location(problem.path))
    heads = sorted({_atom(ax.effect) for ax in fd_axioms})
    derived_names = domain.derived_predicates()
    # Atoms of derived predicates no axiom needed by the task derives are never true: not kept as basic atoms.
    atoms = sorted({_atom(a) for a in fd_atoms if a.predicate not in derived_names} - set(heads)) + heads
    index = {a: i for i, a in enumerate(atoms)}
    derived = mask_of(index[a] for a in heads)
    actions: list[GroundAction] = []
    linger(actions)
    for op in fd_actions:
        act = _action(op, index)
        if act is not None:
            actions.append(act)
    closure = _closure(fd_axioms, layer_of, index, derived) if heads else None
    init = mask_of(index[a] for a in problem.init if a in index)
    goal_pos, goal_neg = _masks(fd_goal, index) if reachable and fd_goal is not None else (None, 0)
    if goal_pos is None:  # the translator proved the goal unreachable
        index[UNREACHABLE_GOAL] = len(atoms)
        atoms.append(UNREACHABLE_GOAL)
        goal_pos, goal_neg = 1 << index[UNREACHABLE_GOAL], 0
    task = GroundTask(domain, problem, atoms, index, init, goal_pos, goal_neg, actions, closure)
    task.init = task.close(init)
    return task


def _atom(fd_atom: Any) -> Atom:
    return Atom(fd_atom.predicate, tuple(fd_atom.args))


def _masks(literals: list[Any], index: dict[Atom, int]) -> tuple[int | None, int]:
    """(positive, negative) masks of a condition; None when a positive part can never hold."""
    pos = neg = 0
    for lit in literals:
        i = index.get(_atom(lit))
        if i is None:
            if not lit.negated:
                return None, 0
            continue
        if lit.negated:
            neg |= 1 << i
        else:
            pos |= 1 << i
    return pos, neg


def _action(op: Any, index: dict[Atom, int]) -> GroundAction | None:
    """A translator action as a ground action (None: a precondition can never hold)."""
    pre_pos, pre_neg = _masks(op.precondition, index)
    if pre_pos is None or pre_pos & pre_neg:
        return None
    add = delete = 0
    conditional: dict[tuple[int, int], list[int]] = {}
    for effects, is_add in ((op.add_effects, True), (op.del_effects, False)):
        for condition, fd_atom in effects:
            i = index.get(_atom(fd_atom))
            pos, neg = _masks(condition, index)
            if i is None or pos is None:
                continue
            if not pos and not neg:
                if is_add:
                    add |= 1 << i
                else:
                    delete |= 1 << i
                continue
            masks = conditional.setdefault((pos, neg), [0, 0])
            masks[0 if is_add else 1] |= 1 << i
    effects_of = tuple(GroundEffect(pos, neg, a, d) for (pos, neg), (a, d) in conditional.items())
    words = op.name.strip("()").split()
    return GroundAction(op.name, words[0], tuple(words[1:]), pre_pos, pre_neg, add, delete, op.cost, effects_of)


def _closure(fd_axioms: list[Any], layer_of: dict, index: dict[Atom, int], derived: int) -> AxiomClosure:
    layers: dict[int, list[GroundAxiom]] = {}
    for ax in fd_axioms:
        pos, neg = _masks(ax.condition, index)
        if pos is None:
            continue
        layers.setdefault(layer_of.get(ax.effect, 0), []).append(GroundAxiom(index[_atom(ax.effect)], pos, neg))
    return AxiomClosure([layers[k] for k in sorted(layers)], derived)


def relaxed_view(task: GroundTask) -> tuple[list[GroundAction], int, int, list[int]]:
    """Actions, positive and negative goal of an admissible delete relaxation of an ADL task, and each action's
    sure adds (see :class:`~guided_lfd.planning.relaxation.RelaxedTask`).

    Each action adds and deletes what any of its effects may (conditions
    dropped: only more is reachable); only its plain adds win over its
    deletes; axioms are actions of cost 0; negative conditions on derived
    atoms are dropped (no action deletes a derived atom).
    """
    derived = task.derived
    out: list[GroundAction] = []
    sure: list[int] = []
    for act in task.actions:
        add, delete = act.add, act.delete
        for eff in act.effects:
            add |= eff.add
            delete |= eff.delete
        out.append(GroundAction(act.name, act.schema, act.args, act.pre_pos, act.pre_neg & ~derived, add, delete,
                                act.cost))
        sure.append(act.add)
    if task.axioms is not None:
        for layer in task.axioms.layers:
            for ax in layer:
                out.append(GroundAction("axiom", "axiom", (), ax.pos, 0, 1 << ax.head, 0, 0))
                sure.append(1 << ax.head)
    return out, task.goal_pos, task.goal_neg & ~derived, sure


def astar(task: GroundTask, init: int | None = None, deadline: float | None = None) -> list[GroundAction] | None:
    """An optimal plan of an ADL task from ``init`` (default: its initial state), or None: proved unsolvable.

    guided-lfd's A* (:func:`guided_lfd.planning.search.astar`) with the task's successors and LM-cut on
    :func:`relaxed_view`.  Raises :class:`SearchTimeout` past ``deadline`` (a ``time.monotonic()`` value).
    """
    from guided_lfd.planning.search import astar as search

    relaxed_actions, goal_pos, goal_neg, sure = relaxed_view(task)
    relaxed = RelaxedTask(relaxed_actions, goal_pos, goal_neg, sure_adds=sure)
    start = task.close(task.init if init is None else init)
    return search(task.actions, start, task.goal_pos, task.goal_neg, relaxed, deadline, successor=task.successor)
