"""A ground STRIPS task as diagrams: one variable per atom, in an order from the causal graph.

Only the atoms a question needs become variables (backward relevance for
"can the goal be reached from here?"; every atom an action touches for
forward search).  The order matters more than anything else for diagram
sizes: atoms that one action reads or writes together should sit close.  The
order here is a bandwidth-reducing sweep over the causal graph (atoms linked
when one action reads or writes both), started from the goal; atoms of one
mutex group (one object's position, say) are kept together, as Fast
Downward's finite-domain variables would be.

An action is kept as two diagrams, its precondition and its effect cube, and
the variables its effects set.  Then (adds win over deletes, as in PDDL)

* preimage(S, a) = pre(a) and exists eff_vars(a) (S and eff(a)),
* image(S, a)    = eff(a) and exists eff_vars(a) (S and pre(a)),

with no copy of the variables and no frame axioms: both are one relational
product each.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Any, Iterable, Sequence

from guided_lfd.errors import UnsupportedFeatureError
from guided_lfd.planning.task import GroundAction, GroundTask, bits
from guided_lfd.symbolic.diagrams import DEFAULT_LIBRARY, Diagrams, open_diagrams


@dataclass
class SymbolicAction:
    """A ground action's diagrams (see the module docstring)."""

    action: GroundAction
    pre: Any
    effect: Any
    effect_vars: Any


#: The most variables (atoms) of a task on which the default searches (``excuse``'s portfolio, ``plan``'s
#: prover) start the symbolic engine beside their own search.  Past it the engine's diagrams grow beyond what
#: it answers in a minute (benchmarks/household: alone, it answers no house of 8 items or more, 201 relevant
#: atoms, within 60 s) while its worker would take a core and as much memory again as the search beside it;
#: ``--strategy symbolic`` still runs it on any size.
DEFAULT_MAX_VARIABLES = 1_500


def worth_running(variables: int) -> bool:
    """Whether the default searches start the symbolic engine on a task of this many variables (atoms)."""
    return variables <= DEFAULT_MAX_VARIABLES


def supports(task: GroundTask) -> bool:
    """Whether the symbolic engine handles ``task`` (STRIPS with negative preconditions: no conditional effects,
    no derived atoms)."""
    return not task.is_adl


def variable_order(atoms: Iterable[int], actions: Sequence[GroundAction], first: Iterable[int] = (),
                   groups: Sequence[int] = ()) -> list[int]:
    """``atoms`` ordered by a breadth-first sweep of the causal graph from ``first`` (the goal's atoms).

    Atoms are linked when one action reads or writes both; each group (a mask of atoms, e.g. a mutex group)
    stays together.  Among the atoms next to the order so far, the sweep takes those linked to the most recent
    ones first (a Cuthill-McKee order: linked atoms end up close).
    """
    wanted = set(atoms)
    cluster_of: dict[int, int] = {}
    clusters: list[list[int]] = []
    for mask in groups:
        members = [i for i in bits(mask) if i in wanted and i not in cluster_of]
        if members:
            for i in members:
                cluster_of[i] = len(clusters)
            clusters.append(members)
    for i in sorted(wanted):
        if i not in cluster_of:
            cluster_of[i] = len(clusters)
            clusters.append([i])
    links: list[set[int]] = [set() for _ in clusters]
    for act in actions:
        touched = {cluster_of[i] for i in (*act.pre_pos_ids, *act.pre_neg_ids, *act.add_ids, *act.delete_ids)
                   if i in cluster_of}
        if len(touched) > 1:
            for c in touched:
                links[c] |= touched
    placed = [False] * len(clusters)
    order: list[int] = []
    starts = [cluster_of[i] for i in first if i in cluster_of]
    starts += sorted(range(len(clusters)), key=lambda c: -len(links[c]))
    for start in starts:
        if placed[start]:
            continue
        placed[start] = True
        queue = deque([start])
        while queue:
            c = queue.popleft()
            order.extend(clusters[c])
            for d in sorted(links[c] - {c}, key=lambda d: -len(links[d])):
                if not placed[d]:
                    placed[d] = True
                    queue.append(d)
    return order


class SymbolicTask:
    """A ground task's atoms and actions as diagrams over a chosen set of atoms.

    ``atoms`` are the task's atom indices that become variables, in diagram
    order; effects on other atoms are ignored (the caller chose the atoms that
    matter), and a precondition on another atom makes the action unusable.
    """

    def __init__(self, task: GroundTask, atoms: Sequence[int], actions: Sequence[GroundAction],
                 library: str = DEFAULT_LIBRARY) -> None:
        if not supports(task):
            raise UnsupportedFeatureError("the symbolic engine handles STRIPS tasks (no conditional effects, "
                                          "no derived predicates)")
        self.task = task
        self.atoms = list(atoms)
        self.var_of = {atom: v for v, atom in enumerate(self.atoms)}
        self.dd: Diagrams = open_diagrams(len(self.atoms), library)
        self.actions = [sa for sa in (self._action(a) for a in actions) if sa is not None]

    def _action(self, act: GroundAction) -> SymbolicAction | None:
        var_of, dd = self.var_of, self.dd
        pre: dict[int, bool] = {}
        for i in act.pre_pos_ids:
            if i not in var_of:
                return None
            pre[var_of[i]] = True
        for i in act.pre_neg_ids:
            if i in var_of:
                if pre.get(var_of[i]):
                    return None  # requires an atom and its absence
                pre[var_of[i]] = False
        effect = {var_of[i]: False for i in act.delete_ids if i in var_of}
        effect.update({var_of[i]: True for i in act.add_ids if i in var_of})
        return SymbolicAction(act, dd.cube(pre), dd.cube(effect), dd.varset(sorted(effect)))

    # -- sets of states ----------------------------------------------------------------
    def literals(self, pos: int, neg: int) -> Any:
        """The states where every atom of ``pos`` holds and none of ``neg`` (atoms that are no variables: a
        positive one makes the set empty, a negative one is dropped)."""
        values: dict[int, bool] = {}
        for i in bits(neg):
            if i in self.var_of:
                values[self.var_of[i]] = False
        for i in bits(pos):
            if i not in self.var_of:
                return self.dd.false
            if values.get(self.var_of[i]) is False:
                return self.dd.false
            values[self.var_of[i]] = True
        return self.dd.cube(values)

    def goal(self) -> Any:
        """The goal states."""
        return self.literals(self.task.goal_pos, self.task.goal_neg)

    def state(self, state: int) -> Any:
        """The one state ``state`` (restricted to the variables)."""
        return self.dd.cube({v: bool(state >> atom & 1) for atom, v in self.var_of.items()})

    def contains(self, f: Any, state: int) -> bool:
        """Whether ``state`` (a bit set over the task's atoms) is in the set ``f``: one walk from the root."""
        dd, atoms = self.dd, self.atoms
        node = dd.top(f)
        while node is not None:
            level, high, low = node
            f = high if state >> atoms[level] & 1 else low
            node = dd.top(f)
        return f == dd.true

    # -- invariants ----------------------------------------------------------------------
    def at_most_one(self, mask: int, exactly: bool = False) -> Any:
        """The states with at most one (``exactly``: exactly one) atom of ``mask`` true (atoms that are no
        variables are false)."""
        dd = self.dd
        members = sorted((self.var_of[i] for i in bits(mask) if i in self.var_of), reverse=True)
        some, none = dd.false, dd.true  # over the variables below: exactly one / none true
        for v in members:  # bottom-up: each step adds two nodes
            x = dd.var(v)
            some, none = (x & none) | (~x & some), ~x & none
        return some if exactly else some | none

    def invariants(self, groups: Iterable[tuple[int, bool]]) -> Any:
        """The states keeping every group ``(mask, exactly_one)``."""
        out = self.dd.true
        for mask, exactly in groups:
            out = out & self.at_most_one(mask, exactly)
        return out
