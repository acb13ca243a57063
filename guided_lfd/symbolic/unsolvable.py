"""Symbolic proofs that a planning task has no plan (``plan``'s unsolvability check).

The searches run over the actions an optimal plan may use (reachable, then
relevant) and the atoms they touch.  States outside Fast Downward's
invariants (synthesised from the robot's actions as they are; each ground
group at most one true atom where the initial state has at most one) are
never reached from the initial state, so both directions leave them out:
backward search from a partial goal would otherwise wade through states no
plan can pass (a block in two places).
"""

from __future__ import annotations

import time
from typing import Any, Iterable

from guided_lfd.planning.task import GroundAction, GroundTask, bits
from guided_lfd.symbolic.encoding import SymbolicTask, variable_order
from guided_lfd.symbolic.reach import Proof, prove_unsolvable


def reachable_invariants(task: GroundTask, deadline: float | None = None) -> list[int]:
    """Masks of ground groups of which at most one atom holds in every state reachable from ``task.init``."""
    from guided_lfd.excuse.invariants import atoms_by_predicate, invariant_instances, lifted_invariants

    remaining = None if deadline is None else max(1.0, deadline - time.monotonic())
    atoms_of = atoms_by_predicate(task)
    masks = set()
    for inv in lifted_invariants(task.domain, task.problem, remaining, reverse=False):
        for mask in invariant_instances(inv, task, atoms_of).values():
            if mask.bit_count() > 1 and (task.init & mask).bit_count() <= 1:
                masks.add(mask)
    return sorted(masks)


def prover_variables(task: GroundTask, actions: Iterable[GroundAction]) -> set[int]:
    """The atoms the prover's diagrams have a variable for: the goal's and those the actions touch."""
    atoms = set(bits(task.goal_pos | task.goal_neg))
    for a in actions:
        atoms.update(a.pre_pos_ids, a.pre_neg_ids, a.add_ids, a.delete_ids)
    return atoms


def symbolic_task(task: GroundTask, actions: Iterable[GroundAction], groups: list[int],
                  library: str | None = None) -> SymbolicTask:
    """``task`` over ``actions`` and the atoms they touch, ordered from the causal graph."""
    actions = list(actions)
    goal = list(bits(task.goal_pos | task.goal_neg))
    order = variable_order(prover_variables(task, actions), actions, first=goal, groups=groups)
    return SymbolicTask(task, order, actions) if library is None else SymbolicTask(task, order, actions, library)


def decide(task: GroundTask, actions: list[GroundAction], deadline: float | None = None,
           library: str | None = None) -> Proof:
    """Whether ``task`` is solvable from its initial state, decided by bidirectional symbolic search."""
    from guided_lfd.symbolic.diagrams import memory_as_memout

    groups = reachable_invariants(task, deadline)
    with memory_as_memout():
        sym = symbolic_task(task, actions, groups, library)
        constraint = sym.invariants((m, False) for m in groups) & _pairs_apart(sym, task, actions, groups)
        return prove_unsolvable(sym, task.init, deadline, constraint)


def _pairs_apart(sym: SymbolicTask, task: GroundTask, actions: list[GroundAction], groups: list[int]) -> Any:
    """The states holding no h^2 mutex pair of atoms (those no invariant group already keeps apart)."""
    from guided_lfd.planning.h2 import PairReachability
    from guided_lfd.planning.relaxation import RelaxedTask

    grouped: dict[int, int] = {}
    for mask in groups:
        for i in bits(mask):
            grouped[i] = grouped.get(i, 0) | mask
    apart: dict[int, list[int]] = {}
    for x, y in PairReachability(RelaxedTask(actions, task.goal_pos, task.goal_neg)).mutex_pairs(task.init):
        if x in sym.var_of and y in sym.var_of and not grouped.get(x, 0) >> y & 1:
            first, second = sorted((x, y), key=sym.var_of.__getitem__)
            apart.setdefault(first, []).append(second)
    dd, out = sym.dd, sym.dd.true
    for x in sorted(apart, key=sym.var_of.__getitem__, reverse=True):
        others = dd.false
        for y in apart[x]:
            others = others | dd.var(sym.var_of[y])
        out = out & (~dd.var(sym.var_of[x]) | ~others)
    return out
