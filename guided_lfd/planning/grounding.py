"""Grounding a lifted task into a propositional one over bit-set states.

States are Python ``int`` bit sets over an atom index: subset tests and
updates are single big-integer operations, which keeps the pure-Python
searches of guided-lfd fast.  Unlike a planner's grounder, this one can keep
*every* type-correct atom and action (``prune_static=False``): an excuse may
change any atom of the initial state, static ones included, so nothing may be
pruned by reachability from the original initial state.
"""

from __future__ import annotations

import functools
import time
from dataclasses import dataclass
from itertools import product
from typing import Iterable, Sequence

from guided_lfd.deadline import linger
from guided_lfd.errors import Location, SearchTimeout, TaskTooLarge
from guided_lfd.pddl.model import (EQUALITY, ActionSchema, Atom, Domain, Literal, MissingCostError, Problem,
                                   action_cost, objects_by_type)

#: Grounding limits: beyond them the task is refused (exit 21) instead of
#: exhausting memory.  Both are far above what the searches can handle.
MAX_GROUND_ATOMS = 1_000_000
MAX_GROUND_ACTIONS = 1_000_000
#: Tasks of at least this many typed ground atoms index their atoms by predicate size (see ground_atoms).
ATOMS_BY_COUNT_FROM = 50_000


@dataclass(frozen=True)
class GroundAction:
    """A ground action with bit-set preconditions and effects."""

    name: str
    schema: str
    args: tuple[str, ...]
    pre_pos: int
    pre_neg: int
    add: int
    delete: int
    #: What the action costs (:func:`guided_lfd.pddl.model.action_cost`): 1 without action costs.
    cost: int = 1
    #: ADL: conditional effects, each applied when its condition holds in the state before the action.
    effects: tuple["GroundEffect", ...] = ()

    # Index lists of the masks, for code that walks an action's atoms (the
    # relaxed tasks, relevance, LM-cut): filled in by the grounder, computed
    # on first use otherwise.  Walking a wide bit mask costs far more.
    @functools.cached_property
    def pre_pos_ids(self) -> tuple[int, ...]:
        """Indices of the positive preconditions."""
        return tuple(bits(self.pre_pos))

    @functools.cached_property
    def pre_neg_ids(self) -> tuple[int, ...]:
        """Indices of the negative preconditions."""
        return tuple(bits(self.pre_neg))

    @functools.cached_property
    def add_ids(self) -> tuple[int, ...]:
        """Indices of the add effects."""
        return tuple(bits(self.add))

    @functools.cached_property
    def delete_ids(self) -> tuple[int, ...]:
        """Indices of the delete effects."""
        return tuple(bits(self.delete))

    def applicable(self, state: int) -> bool:
        """Whether the action's preconditions hold in ``state``."""
        return (state & self.pre_pos) == self.pre_pos and not (state & self.pre_neg)

    def apply(self, state: int) -> int:
        """The successor state (adds win over deletes, as in PDDL); derived atoms are the task's to close."""
        if not self.effects:
            return (state & ~self.delete) | self.add
        add, delete = self.add, self.delete
        for eff in self.effects:
            if state & eff.pos == eff.pos and not state & eff.neg:
                add |= eff.add
                delete |= eff.delete
        return (state & ~delete) | add


@dataclass(frozen=True)
class GroundEffect:
    """A conditional effect: ``add`` and ``delete`` when ``pos`` holds and nothing of ``neg``."""

    pos: int
    neg: int
    add: int
    delete: int


@dataclass(frozen=True)
class GroundAxiom:
    """A derived atom ``head`` holds when ``pos`` does and nothing of ``neg`` (negation as failure)."""

    head: int
    pos: int
    neg: int


class AxiomClosure:
    """The derived atoms of a state: axiom layers evaluated in order, each to its least fixpoint.

    A layer's negative conditions are on atoms of earlier layers (or basic
    ones), so they are settled when it runs, as in Fast Downward's search.
    """

    def __init__(self, layers: list[list[GroundAxiom]], derived: int) -> None:
        self.layers = layers
        self.derived = derived
        #: Per layer: axioms waiting on each atom (positive body), and how many body atoms each needs.
        self._watch: list[dict[int, list[int]]] = []
        for layer in layers:
            watch: dict[int, list[int]] = {}
            for k, ax in enumerate(layer):
                for i in bits(ax.pos):
                    watch.setdefault(i, []).append(k)
            self._watch.append(watch)

    def close(self, state: int) -> int:
        """``state`` with its derived atoms (whatever derived atoms it had are recomputed)."""
        state &= ~self.derived
        for layer, watch in zip(self.layers, self._watch):
            missing = [(ax.pos & ~state).bit_count() for ax in layer]
            ready = [k for k, ax in enumerate(layer) if not missing[k] and not state & ax.neg]
            while ready:
                ax = layer[ready.pop()]
                if state >> ax.head & 1:
                    continue
                state |= 1 << ax.head
                for k in watch.get(ax.head, ()):
                    missing[k] -= 1
                    if not missing[k] and not state & layer[k].neg:
                        ready.append(k)
        return state


@dataclass
class GroundTask:
    """A propositional STRIPS task with negative preconditions and goals."""

    domain: Domain
    problem: Problem
    atoms: list[Atom]
    index: dict[Atom, int]
    init: int
    goal_pos: int
    goal_neg: int
    actions: list[GroundAction]
    #: ADL: how derived atoms follow from a state (None: the task has none) and their mask.
    axioms: AxiomClosure | None = None

    @property
    def derived(self) -> int:
        """The derived atoms' mask (0 without axioms)."""
        return self.axioms.derived if self.axioms is not None else 0

    @functools.cached_property
    def is_adl(self) -> bool:
        """Whether states need more than STRIPS successors (conditional effects or axioms); worked out once
        (planner calls ask it every time)."""
        return self.axioms is not None or any(a.effects for a in self.actions)

    def close(self, state: int) -> int:
        """``state`` with its derived atoms."""
        return state if self.axioms is None else self.axioms.close(state)

    def successor(self, action: GroundAction, state: int) -> int:
        """The state after ``action`` (conditional effects and derived atoms included)."""
        return self.close(action.apply(state))

    def satisfies_goal(self, state: int) -> bool:
        """Whether ``state`` models the goal."""
        return (state & self.goal_pos) == self.goal_pos and not (state & self.goal_neg)


def bits(mask: int) -> Iterable[int]:
    """Indices of the set bits of ``mask``, ascending."""
    if mask.bit_count() <= 16:
        while mask:
            low = mask & -mask
            yield low.bit_length() - 1
            mask ^= low
        return
    # Many bits: clearing them one by one costs a pass over the whole
    # integer each (quadratic on wide masks); scan its binary digits once.
    digits = bin(mask)[:1:-1]  # least significant first, without '0b'
    i = digits.find("1")
    while i >= 0:
        yield i
        i = digits.find("1", i + 1)


def mask_of(indices: Iterable[int]) -> int:
    """The bit mask of a collection of atom indices (one big-integer build)."""
    indices = list(indices)
    if not indices:
        return 0
    top = max(indices)
    raw = bytearray(top // 8 + 1)
    for i in indices:
        raw[i >> 3] |= 1 << (i & 7)
    return int.from_bytes(raw, "little")


def ground_atoms(domain: Domain, problem: Problem, skip: set[str] | None = None) -> list[Atom]:
    """Every type-correct ground atom of the domain's predicates (except ``skip``): by predicate, by name or,
    from :data:`ATOMS_BY_COUNT_FROM` atoms on, those with the fewest atoms first (then by name), each
    predicate's atoms in argument order."""
    by_type = objects_by_type(domain, problem)
    out: list[Atom] = []
    counts: dict[str, int] = {}
    for pred in domain.predicates.values():
        if skip and pred.name in skip:
            continue
        count = 1
        for _, t in pred.params:
            count *= len(by_type.get(t, []))
        counts[pred.name] = count
    total = sum(counts.values())
    if total > MAX_GROUND_ATOMS:
        raise TaskTooLarge(
            f"{total} ground atoms exceed the limit of {MAX_GROUND_ATOMS} (fewer objects or --fixed predicates help)",
            Location(problem.path),
        )
    # On a large task, predicates with the fewest atoms first: a bit set is as wide as its highest atom, and
    # most actions touch one atom of a wide relation beside atoms of small ones ((hand_free), (clear ?f)),
    # so their masks stay as narrow as that one atom allows (a house of 256 items: half the grounding's
    # memory).  Smaller tasks keep the order by name: the landmark search breaks ties between equal
    # landmarks and children by atom order, and on some tasks the by-count order breaks them far worse
    # (transport task07 without pick-up: 10 nodes by name, a 60 s timeout after 11,000 by count).
    by_count = total >= ATOMS_BY_COUNT_FROM
    for pred in sorted(domain.predicates.values(),
                       key=lambda p: (counts.get(p.name, 0) if by_count else 0, p.name)):
        if skip and pred.name in skip:
            continue
        domains = [by_type.get(t, []) for _, t in pred.params]
        for args in product(*domains):
            out.append(Atom(pred.name, tuple(args)))
    return out


def static_predicates(domain: Domain) -> set[str]:
    """Predicates no action changes."""
    return set(domain.predicates) - domain.fluent_predicates()


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
                if not _holds(lit, binding, init):
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


def _holds(lit: Literal, binding: dict[str, str], init: frozenset[Atom]) -> bool:
    atom = lit.atom.substitute(binding)
    if atom.predicate == EQUALITY:
        value = atom.args[0] == atom.args[1]
    else:
        value = atom in init
    return value == lit.positive
