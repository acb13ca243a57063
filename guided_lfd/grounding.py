"""Grounding a lifted task into a propositional one over bit-set states.

States are Python ``int`` bit sets over an atom index: subset tests and
updates are single big-integer operations, which keeps the pure-Python
searches of guided-lfd fast.  Unlike a planner's grounder, this one can keep
*every* type-correct atom and action (``prune_static=False``): an excuse may
change any atom of the initial state, static ones included, so nothing may be
pruned by reachability from the original initial state.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import product
from typing import Iterable, Sequence

from guided_lfd.pddl.model import EQUALITY, ActionSchema, Atom, Domain, Literal, Problem, objects_by_type


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

    def applicable(self, state: int) -> bool:
        """Whether the action's preconditions hold in ``state``."""
        return (state & self.pre_pos) == self.pre_pos and not (state & self.pre_neg)

    def apply(self, state: int) -> int:
        """The successor state (adds win over deletes, as in PDDL)."""
        return (state & ~self.delete) | self.add


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
    fixed_static: frozenset[str] = field(default_factory=frozenset)

    def satisfies_goal(self, state: int) -> bool:
        """Whether ``state`` models the goal."""
        return (state & self.goal_pos) == self.goal_pos and not (state & self.goal_neg)

    def atoms_of(self, mask: int) -> list[Atom]:
        """The atoms in a bit set, sorted."""
        return sorted(self.atoms[i] for i in bits(mask))

    def mask_of(self, atoms: Iterable[Atom]) -> int:
        """The bit set of ``atoms`` (all must be in the index)."""
        mask = 0
        for atom in atoms:
            mask |= 1 << self.index[atom]
        return mask

    def with_init(self, init: int) -> "GroundTask":
        """The same task from another initial state."""
        return GroundTask(
            self.domain, self.problem, self.atoms, self.index, init, self.goal_pos, self.goal_neg,
            self.actions, self.fixed_static,
        )


def bits(mask: int) -> Iterable[int]:
    """Indices of the set bits of ``mask``, ascending."""
    while mask:
        low = mask & -mask
        yield low.bit_length() - 1
        mask ^= low


def ground_atoms(domain: Domain, problem: Problem) -> list[Atom]:
    """Every type-correct ground atom of the domain's predicates, sorted."""
    by_type = objects_by_type(domain, problem)
    out: list[Atom] = []
    for pred in sorted(domain.predicates.values(), key=lambda p: p.name):
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
) -> GroundTask:
    """Ground ``problem`` over all type-correct atoms.

    Predicates in ``fixed`` that are also static keep their initial value in
    every state the task will be asked about, so actions whose static
    preconditions on them are false are pruned (as a planner's grounder does).
    ``actions`` overrides the domain's action list (e.g. with a skill removed).
    """
    atoms = ground_atoms(domain, problem)
    known = set(atoms)
    for atom in sorted(problem.init):
        if atom not in known:
            # Type-incorrect init atoms are kept, so that nothing the user wrote is dropped.
            atoms.append(atom)
    index = {a: i for i, a in enumerate(atoms)}
    static = static_predicates(domain) & set(fixed)
    schemas = domain.actions if actions is None else actions
    by_type = objects_by_type(domain, problem)
    ground_actions: list[GroundAction] = []
    for schema in schemas:
        ground_actions.extend(_ground_schema(schema, by_type, index, problem.init, static))
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
    return GroundTask(domain, problem, atoms, index, init, goal_pos, goal_neg, ground_actions, frozenset(static))


def _ground_schema(
    schema: ActionSchema,
    by_type: dict[str, list[str]],
    index: dict[Atom, int],
    init: frozenset[Atom],
    static: set[str],
) -> Iterable[GroundAction]:
    params = [v for v, _ in schema.params]
    domains = [by_type.get(t, []) for _, t in schema.params]
    # Check each precondition literal as soon as all its variables are bound.
    checks: list[list[Literal]] = [[] for _ in params]
    always: list[Literal] = []
    position = {v: i for i, v in enumerate(params)}
    for lit in schema.precondition:
        if lit.atom.predicate != EQUALITY and lit.atom.predicate not in static:
            continue
        positions = [position[a] for a in lit.atom.args if a in position]
        (checks[max(positions)] if positions else always).append(lit)
    binding: dict[str, str] = {}
    if not all(_holds(lit, binding, init) for lit in always):
        return

    def rec(i: int):
        if i == len(params):
            yield dict(binding)
            return
        for obj in domains[i]:
            binding[params[i]] = obj
            if all(_holds(lit, binding, init) for lit in checks[i]):
                yield from rec(i + 1)
        binding.pop(params[i], None)

    for b in rec(0):
        pre_pos = pre_neg = add = delete = 0
        ok = True
        for lit in schema.precondition:
            if lit.atom.predicate == EQUALITY or lit.atom.predicate in static:
                continue
            atom = lit.atom.substitute(b)
            idx = index.get(atom)
            if idx is None:
                # A precondition on an atom of the wrong type can never hold.
                ok = ok and not lit.positive
                continue
            if lit.positive:
                pre_pos |= 1 << idx
            else:
                pre_neg |= 1 << idx
        if not ok or pre_pos & pre_neg:
            continue
        for atom in schema.add:
            idx = index.get(atom.substitute(b))
            if idx is not None:
                add |= 1 << idx
        for atom in schema.delete:
            idx = index.get(atom.substitute(b))
            if idx is not None:
                delete |= 1 << idx
        args = tuple(b[v] for v in params)
        name = "(" + " ".join((schema.name, *args)) + ")"
        yield GroundAction(name, schema.name, args, pre_pos, pre_neg, add, delete)


def _holds(lit: Literal, binding: dict[str, str], init: frozenset[Atom]) -> bool:
    atom = lit.atom.substitute(binding)
    if atom.predicate == EQUALITY:
        value = atom.args[0] == atom.args[1]
    else:
        value = atom in init
    return value == lit.positive
