"""Grounding a lifted task into a propositional one over bit-set states (:mod:`guided_lfd.planning.task`).

Unlike a planner's grounder, this one can keep
*every* type-correct atom and action (``prune_static=False``): an excuse may
change any atom of the initial state, static ones included, so nothing may be
pruned by reachability from the original initial state.
"""

from __future__ import annotations

import time
from itertools import product
from typing import Iterable, Sequence

from guided_lfd.deadline import linger
from guided_lfd.errors import Location, SearchTimeout, TaskTooLarge
from guided_lfd.pddl.model import (EQUALITY, ActionSchema, Atom, Domain, MissingCostError, Problem,
                                   action_cost, objects_by_type)
from guided_lfd.planning.task import (MAX_GROUND_ACTIONS, GroundAction, GroundTask, ground_atoms,
                                      static_predicates)

def ground(
    domain: Domain,
    problem: Problem,
    fixed: Iterable[str] = (),
    actions: Sequence[ActionSchema] | None = None,
    deadline: float | None = None,
) -> GroundTask:
    """Ground ``problem`` over all type-correct atoms.

    Predicates in ``fixed`` that are also static keep their initial value in
    every state the task will be asked about, so actions whose static
    preconditions on them are false are pruned (as a planner's grounder does).
    ``actions`` overrides the domain's action list (e.g. with a skill removed).
    ADL tasks go to Fast Downward's normal form (:func:`guided_lfd.planning.adl.ground_adl`); with every
    predicate fixed (planning), grounded by its reachability analysis from the initial state.
    """
    if domain.is_adl or problem.goal_condition is not None:
        return _ground_adl(domain, problem, fixed, actions, deadline)
    static = static_predicates(domain) & set(fixed)
    # Atoms of fixed static predicates keep their initial value in every state
    # considered: only the true ones need an index (a planner's grounding).
    atoms = ground_atoms(domain, problem, skip=static)
    atoms += sorted(a for a in problem.init if a.predicate in static)
    known = set(atoms)
    for atom in sorted(problem.init):
        if atom not in known:
            # Type-incorrect init atoms are kept, so that nothing the user wrote is dropped.
            atoms.append(atom)
    index = {a: i for i, a in enumerate(atoms)}
    schemas = domain.actions if actions is None else actions
    by_type = objects_by_type(domain, problem)
    ground_actions: list[GroundAction] = []
    linger(ground_actions)  # see guided_lfd.deadline.linger
    key_index = {(a.predicate, *a.args): i for a, i in index.items()}
    for schema in schemas:
        for k, act in enumerate(_ground_schema(schema, by_type, index, problem.init, static, key_index, problem)):
            ground_actions.append(act)
            if not k & 1023:
                if len(ground_actions) > MAX_GROUND_ACTIONS:
                    raise TaskTooLarge(
                        f"more than {MAX_GROUND_ACTIONS} ground actions (fewer objects or --fixed predicates help)",
                        Location(problem.path),
                    )
                if deadline is not None and time.monotonic() > deadline:
                    raise SearchTimeout("grounding exceeded the time limit")
    init = 0
    for atom in problem.init:
        init |= 1 << index[atom]
    goal_pos = goal_neg = 0
    for lit in problem.goal:
        if lit.atom not in index:
            index[lit.atom] = len(atoms)
            atoms.append(lit.atom)
        if lit.positive:
            goal_pos |= 1 << index[lit.atom]
        else:
            goal_neg |= 1 << index[lit.atom]
    return GroundTask(domain, problem, atoms, index, init, goal_pos, goal_neg, ground_actions)


def _ground_adl(domain: Domain, problem: Problem, fixed: Iterable[str], actions: Sequence[ActionSchema] | None,
                deadline: float | None) -> GroundTask:
    from dataclasses import replace

    from guided_lfd.planning.adl import ground_adl

    if actions is not None:
        domain = replace(domain, actions=list(actions))
    basic = set(domain.predicates) - domain.derived_predicates()
    if basic <= set(fixed):  # planning: nothing changes the initial state
        return ground_adl(domain, problem, deadline)
    # An excuse may change every atom but those of fixed static predicates (as for STRIPS tasks).
    return ground_adl(domain, problem, deadline, basic - (static_predicates(domain) & set(fixed)))


def _key_function(atom: Atom, params: list[str]):
    """A function from a binding's values (in parameter order) to ``atom``'s index key.

    Keys are plain tuples ``(predicate, arg, ...)``: hashing a tuple is far
    cheaper than hashing an :class:`Atom`, and grounding looks up every
    literal of every ground action.
    """
    position = {v: k for k, v in enumerate(params)}
    pred = atom.predicate
    spec = [(True, position[a]) if a in position else (False, a) for a in atom.args]
    if all(is_var for is_var, _ in spec):
        where = [k for _, k in spec]
        if not where:
            return lambda values: (pred,)
        if len(where) == 1:
            j = where[0]
            return lambda values: (pred, values[j])
        if len(where) == 2:
            j, k = where
            return lambda values: (pred, values[j], values[k])
        return lambda values: (pred, *(values[k] for k in where))
    return lambda values: (pred, *(values[x] if is_var else x for is_var, x in spec))


def _ground_schema(
    schema: ActionSchema,
    by_type: dict[str, list[str]],
    index: dict[Atom, int],
    init: frozenset[Atom],
    static: set[str],
    key_index: dict[tuple[str, ...], int] | None = None,
    problem: Problem | None = None,
) -> Iterable[GroundAction]:
    params = [v for v, _ in schema.params]
    # Costs: FD's semantics (see action_cost); a constant cost is worked out once.
    costed = problem is not None and problem.metric
    fixed_cost = 1 if not costed else (schema.cost or 0) if not isinstance(schema.cost, Atom) else None
    if key_index is None:
        key_index = {(a.predicate, *a.args): i for a, i in index.items()}
    pre = [(_key_function(lit.atom, params), lit.positive) for lit in schema.precondition
           if lit.atom.predicate != EQUALITY and lit.atom.predicate not in static]
    adds = [_key_function(a, params) for a in schema.add]
    dels = [_key_function(a, params) for a in schema.delete]
    lookup = key_index.get
    for b in _bindings(schema, by_type, init, static):
        values = tuple(b[v] for v in params)
        pos_ids: list[int] = []
        neg_ids: list[int] = []
        ok = True
        for key, positive in pre:
            idx = lookup(key(values))
            if idx is None:
                # A precondition on an atom of the wrong type can never hold.
                ok = ok and not positive
                continue
            (pos_ids if positive else neg_ids).append(idx)
        if not ok:
            continue
        pre_pos = pre_neg = add = delete = 0
        for idx in pos_ids:
            pre_pos |= 1 << idx
        for idx in neg_ids:
            pre_neg |= 1 << idx
        if pre_pos & pre_neg:
            continue
        add_ids = [i for i in (lookup(k(values)) for k in adds) if i is not None]
        del_ids = [i for i in (lookup(k(values)) for k in dels) if i is not None]
        for idx in add_ids:
            add |= 1 << idx
        for idx in del_ids:
            delete |= 1 << idx
        cost = fixed_cost
        if cost is None:
            try:
                cost = action_cost(schema, b, problem)  # type: ignore[arg-type]
            except MissingCostError:
                # PDDL: an effect on an undefined value makes the action inapplicable
                # (Fast Downward only ever instantiates the ones that have values).
                continue
        name = "(" + " ".join((schema.name, *values)) + ")"
        act = GroundAction(name, schema.name, values, pre_pos, pre_neg, add, delete, cost)
        # The index lists, sorted and without repeats, as bits() would give them.
        act.__dict__.update(pre_pos_ids=tuple(sorted(set(pos_ids))), pre_neg_ids=tuple(sorted(set(neg_ids))),
                            add_ids=tuple(sorted(set(add_ids))), delete_ids=tuple(sorted(set(del_ids))))
        yield act


def _bindings(
    schema: ActionSchema, by_type: dict[str, list[str]], init: frozenset[Atom], static: set[str]
) -> Iterable[dict[str, str]]:
    """Parameter bindings that satisfy the static and equality preconditions.

    A join: positive static preconditions are matched against the initial
    atoms of their predicate (smallest relation first), the remaining
    parameters range over their type, and negative static and equality
    literals are checked as soon as their variables are bound.
    """
    params = [v for v, _ in schema.params]
    type_sets = {v: set(by_type.get(t, [])) for v, t in schema.params}
    relations: dict[str, list[tuple[str, ...]]] = {}
    # In sorted order: a set's order follows the string hash, which changes from one process to the next,
    # and the ground actions' order decides the planner's ties (the same command must print the same plan).
    for atom in sorted(init):
        if atom.predicate in static:
            relations.setdefault(atom.predicate, []).append(atom.args)
    joins = sorted(
        (lit for lit in schema.precondition if lit.positive and lit.atom.predicate in static),
        key=lambda lit: len(relations.get(lit.atom.predicate, ())),
    )
    checks = [
        lit for lit in schema.precondition
        if lit.atom.predicate == EQUALITY or (not lit.positive and lit.atom.predicate in static)
    ]

    def consistent(binding: dict[str, str]) -> bool:
        for lit in checks:
            if all(not a.startswith("?") or a in binding for a in lit.atom.args):
                if not lit.substitute(binding).holds(init):
                    return False
        return True

    def join(k: int, binding: dict[str, str]):
        if k == len(joins):
            free = [v for v in params if v not in binding]
            for values in product(*(sorted(type_sets[v]) for v in free)):
                full = {**binding, **dict(zip(free, values))}
                if consistent(full):
                    yield full
            return
        lit = joins[k]
        for args in relations.get(lit.atom.predicate, ()):
            new = dict(binding)
            for term, value in zip(lit.atom.args, args):
                if term.startswith("?"):
                    if new.get(term, value) != value or value not in type_sets.get(term, ()):
                        break
                    new[term] = value
                elif term != value:
                    break
            else:
                if consistent(new):
                    yield from join(k + 1, new)

    if not consistent({}):
        return
    seen: set[tuple[str, ...]] = set()
    for binding in join(0, {}):
        key = tuple(binding[v] for v in params)
        if key not in seen:
            seen.add(key)
            yield binding
