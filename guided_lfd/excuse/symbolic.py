"""The symbolic excuse search: every state the robot can reach the goal from, as one diagram.

Backward reachability over the robot's relevant actions gives the set R of
states from which the goal can be reached (its layers give a plan from any of
them).  The excuse states are R without the goal states, inside the
invariants (consistent semantics), with every atom that may not change at its
initial value; the minimal excuses are its members nearest to the initial
state (:mod:`guided_lfd.symbolic.nearest`), in the order of the searches'
weight (cost first, size second).  No candidate is checked on its own.

The variables are the relevant atoms and, under the consistent semantics,
the atoms of their invariant groups that repairing a group can need to
change though no action reads them (:func:`excuse_atoms`).  The diagram
library is imported here, when this strategy runs, and nowhere else on an
excuse run.
"""

from __future__ import annotations

import time
from typing import Any

from guided_lfd.deadline import check
from guided_lfd.errors import SearchTimeout, UnsupportedFeatureError
from guided_lfd.excuse.outcome import SearchLimits, SearchOutcome
from guided_lfd.excuse.progress import ProgressMeter
from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.planning.task import GroundAction, bits

#: The most nodes of the invariants' diagram the backward search keeps inside (each image step is
#: intersected with it); groups beyond it are applied to the reached set afterwards.
CONSTRAINT_NODES = 50_000


def excuse_atoms(space: ChangeSpace) -> set[int]:
    """The atoms the symbolic search keeps as variables: the relevant ones, and what repairing their groups
    may need.

    The set A grows from the relevant atoms: a group with an atom in A adds its atoms true initially and, when
    exactly one of its atoms must hold, all of them; until nothing is added.  Undoing all of a consistent
    excuse's changes outside A at once leaves an excuse no heavier: the goal does not depend on those atoms; a
    group with an atom in A has its atoms outside A false again (its initially true ones are in A), so at most
    one holds where at most one did, and an exactly-one group lies wholly in A; a group with no atom in A
    is back at its initial atoms, which keep it (the synthesised groups are those the initial state keeps).
    So every minimal excuse changes atoms of A only, and every other atom keeps its initial value (false, in
    a group with an atom in A).
    """
    init = space.task.init
    atoms = set(bits(space.relevant_atoms))
    frontier = list(atoms)
    while frontier:
        i = frontier.pop()
        for gi in space.groups_of.get(i, ()):
            group = space.groups[gi]
            for j in bits(group.mask if group.exactly_one else group.mask & init):
                if j not in atoms:
                    atoms.add(j)
                    frontier.append(j)
    return atoms


def keeps_group(action: GroundAction, mask: int, exactly_one: bool) -> bool:
    """Whether ``action`` keeps the group ``mask`` (at most one atom true; ``exactly_one``: exactly one) in
    every state that keeps it and meets its precondition (sufficient: False may be a group it keeps).

    It may add one atom of the group, where the precondition says which atom was the true one (the added
    atom itself, or one it deletes) or every other atom ends false; under exactly-one, one it deletes must
    be replaced.
    """
    needed = action.pre_pos & mask
    if needed & (needed - 1):
        return True  # it needs two atoms of the group: it never applies in a state that keeps it
    adds = action.add & mask
    deletes = action.delete & mask & ~action.add  # an atom both added and deleted stays true (PDDL)
    if not adds:
        return not (exactly_one and deletes)
    if adds & (adds - 1):
        return False  # two atoms of the group at once
    if action.pre_pos & adds or action.pre_pos & deletes:
        return True  # the one true atom is known: the added one, or one the action removes
    return not mask & ~adds & ~(action.delete | action.pre_neg)


def split_by_actions(groups: list[tuple[int, bool]], actions: list[GroundAction]
                     ) -> tuple[list[tuple[int, bool]], list[tuple[int, bool]]]:
    """``groups`` (mask, exactly-one) as those every one of ``actions`` keeps (:func:`keeps_group`) and the
    others.  Only the actions that add or delete an atom of a group are asked: the others keep it."""
    touching: dict[int, list[GroundAction]] = {}
    for act in actions:
        for i in {*act.add_ids, *act.delete_ids}:
            touching.setdefault(i, []).append(act)
    kept: list[tuple[int, bool]] = []
    other: list[tuple[int, bool]] = []
    for mask, exactly_one in groups:
        asked = {id(a): a for i in bits(mask) for a in touching.get(i, ())}
        keeps = all(keeps_group(a, mask, exactly_one) for a in asked.values())
        (kept if keeps else other).append((mask, exactly_one))
    return kept, other


class SymbolicRun:
    """One symbolic excuse search: the diagrams of the task, the reached set R and its excuse states."""

    def __init__(self, space: ChangeSpace, deadline: float | None) -> None:
        from guided_lfd.symbolic.encoding import SymbolicTask, supports, variable_order

        task = space.task
        if not supports(task):
            raise UnsupportedFeatureError("the symbolic strategy handles STRIPS tasks (no conditional effects, "
                                          "no derived predicates)")
        self.space, self.deadline = space, deadline
        goal = list(bits(task.goal_pos | task.goal_neg))
        atoms = excuse_atoms(space)
        order = variable_order(atoms, space.relevant_actions, first=goal, groups=[g.mask for g in space.groups])
        self.sym = SymbolicTask(task, order, space.relevant_actions)

    def excuse_states(self) -> Any:
        """R minus the goal, inside the invariants, with every unchangeable variable at its initial value."""
        from guided_lfd.symbolic.reach import backward_layers

        sym, space, task = self.sym, self.space, self.space.task
        # A group with no variable keeps its initial atoms, which keep it; one with a variable has its other
        # atoms false (excuse_atoms took its true ones, and all of an exactly-one group), as the diagram's
        # at_most_one reads atoms that are no variables.
        variables = sum(1 << atom for atom in sym.atoms)
        kept = [(g.mask, g.exactly_one) for g in space.groups if g.mask & variables]
        # A group every robot action keeps (always so for groups synthesised from the robot's own domain;
        # not for those of --invariants-from's model) the robot never leaves: searching backward inside
        # such groups reaches exactly R's states that keep them, and spares the diagram the states no
        # excuse may have (miconic without up: a lift at many floors at once; 0.2 s, not minutes).  The
        # other groups, and those whose conjunction outgrows the budget (depot's crates, hoists and
        # surfaces), are applied to the reached set instead, one at a time.
        inductive, other = split_by_actions(kept, [sa.action for sa in sym.actions])
        inside, rest = self.constraint(inductive)
        rest += other
        self.layers = backward_layers(sym, constraint=inside, deadline=self.deadline)
        states = self.layers.reached & ~sym.goal()
        for mask, exactly in rest:
            check(self.deadline, "symbolic excuse search")
            states = states & sym.at_most_one(mask, exactly)
        fixed = {v: bool(task.init >> atom & 1) for v, atom in enumerate(sym.atoms)
                 if not space.changeable >> atom & 1}
        return states & sym.dd.cube(fixed)

    def constraint(self, groups: list[tuple[int, bool]]) -> tuple[Any | None, list[tuple[int, bool]]]:
        """The conjunction of as many of ``groups`` as stay within :data:`CONSTRAINT_NODES` (in their order;
        None: none), and the groups left out."""
        dd, inside, rest = self.sym.dd, None, []
        for mask, exactly in groups:
            check(self.deadline, "symbolic excuse search")
            group = self.sym.at_most_one(mask, exactly)
            both = group if inside is None else inside & group
            if dd.size(both) > CONSTRAINT_NODES:
                rest.append((mask, exactly))
            else:
                inside = both
        return inside, rest

    def plan(self, changes: int) -> list[GroundAction]:
        """A plan from the excuse state of ``changes``, read off the backward layers."""
        from guided_lfd.symbolic.reach import plan_from

        plan = plan_from(self.sym, self.layers, self.space.task.init ^ changes)
        if plan is None:
            raise RuntimeError("internal check failed: an excuse state outside the reached set")
        return plan


class SymbolicSearch:
    """Backward symbolic reachability, then the reached states nearest to the initial state."""

    name = "symbolic"
    description = "one backward search over sets of states (decision diagrams); excuses are its nearest members"
    lists_slack = True

    def search(self, space: ChangeSpace, limits: SearchLimits, progress: ProgressMeter | None = None,
               oracle: Any = None, relaxed: Any = None) -> Any:
        """Minimal change sets for ``space``; ``oracle`` and ``relaxed`` are unused (no candidate is checked).

        With a deadline the search runs in a forked worker, ended at the deadline: one diagram operation is a
        C call that no deadline check or signal interrupts.
        """
        if limits.deadline is None:
            return self.search_here(space, limits)
        from guided_lfd.symbolic.worker import Forked

        worker = Forked(symbolic_outcome, space, limits)
        try:
            # The worker's own deadline checks end it on time, unless a long C call holds it: then the wait does.
            if worker.poll(timeout=max(0.0, limits.deadline - time.monotonic()) + 0.2):
                value = worker.value()
                if value is None:
                    message = str(worker.answer[1]) if worker.answer else "no answer"
                    if message.startswith("MemoryError"):
                        raise MemoryError(message)
                    raise RuntimeError(f"symbolic search failed: {message}")
                return outcome_of(space, value, "")
            return SearchOutcome([], {}, ExcuseStatus.TIMEOUT)
        finally:
            worker.stop()

    def search_here(self, space: ChangeSpace, limits: SearchLimits) -> Any:
        """:meth:`search` in this process."""
        from guided_lfd.symbolic.diagrams import memory_as_memout

        try:
            with memory_as_memout():
                return self._search(space, limits)
        except SearchTimeout:
            return SearchOutcome([], {}, ExcuseStatus.TIMEOUT)

    def _search(self, space: ChangeSpace, limits: SearchLimits) -> Any:
        from guided_lfd.symbolic.nearest import nearest

        run = SymbolicRun(space, limits.deadline)
        states = run.excuse_states()
        solutions: list[int] = []
        limit: float | None = None
        size_pruned = False
        for weight, changes in nearest(run.sym.dd, states, run.sym.atoms, space.weights, space.task.init,
                                       limits.max_size):
            if limit is not None and weight > limit:
                break
            check(limits.deadline, "symbolic excuse search")
            if any(changes & s == s for s in solutions):
                continue  # an excuse with changes added: no other choice
            if limit is None:
                slack = limits.slack
                limit = weight if not slack else (space.cost(changes) + slack + 1) * space.size_factor - 1
            solutions.append(changes)
            if not limits.all_minimal or len(solutions) >= limits.max_solutions:
                break
        if not solutions and limits.max_size is not None:
            size_pruned = bool(states != run.sym.dd.false)
        plans = {c: run.plan(c) for c in solutions}
        status = (ExcuseStatus.FOUND if solutions
                  else ExcuseStatus.NONE_WITHIN_SIZE if size_pruned else ExcuseStatus.NONE)
        extra = {"symbolic_layers": len(run.layers.layers), "symbolic_nodes": run.sym.dd.size(run.layers.reached),
                 "symbolic_variables": len(run.sym.atoms)}
        return SearchOutcome(sorted(solutions), plans, status, 0, 0, 0, extra)


def symbolic_outcome(space: ChangeSpace,
                     limits: SearchLimits) -> tuple[str, list[int], dict[int, list[int]], dict[str, int]]:
    """In the worker: the symbolic search's outcome, its plans as indices into the task's actions (a small,
    picklable answer)."""
    outcome = SymbolicSearch().search_here(space, limits)
    index = {id(a): k for k, a in enumerate(space.task.actions)}
    plans = {c: [index[id(a)] for a in plan] for c, plan in outcome.plans.items()}
    return outcome.status.value, outcome.solutions, plans, outcome.extra


def outcome_of(space: ChangeSpace, value: tuple, answered_by: str) -> Any:
    """A :func:`symbolic_outcome` value as the searches' outcome (plans back to the task's actions)."""
    status, solutions, plans, extra = value
    actions = space.task.actions
    return SearchOutcome(solutions, {c: [actions[k] for k in p] for c, p in plans.items()},
                         ExcuseStatus(status), 0, 0, 0, dict(extra), answered_by=answered_by)
