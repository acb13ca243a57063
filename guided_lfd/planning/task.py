"""The ground task: atoms by index, actions and axioms over bit-set states, and the typed atoms a task has.

States are Python ``int`` bit sets over an atom index: subset tests and
updates are single big-integer operations, which keeps the pure-Python
searches of guided-lfd fast.  The grounders (:mod:`guided_lfd.planning.grounding`
for STRIPS, :mod:`guided_lfd.planning.adl` through Fast Downward's translator)
build these; every search reads them.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from itertools import product
from typing import Iterable

from guided_lfd.errors import Location, TaskTooLarge
from guided_lfd.pddl.model import Atom, Domain, Problem, objects_by_type

#: The goal of a task whose goal the translator proves can never hold (an atom nothing makes true).
UNREACHABLE_GOAL = Atom("guided-lfd-unreachable-goal")

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
