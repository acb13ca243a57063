"""Admissible excuse bounds and landmarks: LM-cut on the compiled relaxed task.

Following Göbelbecker et al. (2010), the excuse search is compiled into one
planning task: a *change* action per atom flip (cost = its weight, no
precondition) and the robot's actions (cost 0).  Its delete relaxation,
evaluated with LM-cut, gives

* ``h``: a lower bound on the weight of any excuse extending a change set, and
* disjunctive landmarks: sets of changes of which every such excuse must make
  at least one.  Branching on a landmark keeps the search complete while only
  trying changes that can matter.

Negative preconditions and goals are handled with complement facts ("not p"),
which a change can also make true (deleting p).

The index tables, the closure, h^max and the LM-cut loop are the core's
(:mod:`guided_lfd.planning.relaxation`): changes are h^max seeds at their
cost.  Because robot actions cost 0, h^max of a fact is a *bottleneck* value:
the smallest change cost c such that the fact is relaxed-reachable using only
changes of cost <= c, a few incremental relaxed closures, one per distinct
change cost.  On large tasks the same closures run a layer at a time on numpy
arrays over sparse precondition/effect tables (arrays pay from about 1,500
actions); this keeps LM-cut cheap on tasks with 100k ground actions.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass

import math
from typing import TYPE_CHECKING, Iterator

from guided_lfd.excuse.space import ChangeSpace
from guided_lfd.planning.relaxation import INF, close, hmax, index_facts, lmcut
from guided_lfd.planning.task import bits

if TYPE_CHECKING:
    import numpy as np
else:
    # numpy is imported by load_numpy() for the first task large enough to use it:
    # small tasks (the kitchen ones, most of a user's) never pay its ~0.1 s import.
    np = None

#: Below this many relaxed actions LM-cut runs on plain Python lists (the
#: numpy version pays ~10 us per array call, too much for small tasks).
SMALL_TASK_ACTIONS = 1500


def load_numpy() -> None:
    """Import numpy for the large-task tables (no-op once done).

    Also imports ``numpy.ma``, which numpy would otherwise import on first use,
    in the middle of a timed search.  Callers that time whole runs (the
    benchmark runner) call this up front.
    """
    global np
    if np is None:
        import numpy
        import numpy.ma  # noqa: F401

        np = numpy


@dataclass
class Bound:
    """LM-cut result: ``h`` (INF = no excuse extends the change set) and landmarks."""

    h: float
    landmarks: list[list[int]]
    costs: list[int]  # the cost share of each landmark, in the task's scaled units


def _csr(rows: list[list[int]]) -> tuple[np.ndarray, np.ndarray]:
    ptr = np.zeros(len(rows) + 1, dtype=np.int64)
    ptr[1:] = np.cumsum([len(r) for r in rows])
    flat = np.fromiter((x for r in rows for x in r), dtype=np.int64, count=int(ptr[-1]))
    return ptr, flat


def _gather(ptr: np.ndarray, flat: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """Concatenation of the CSR rows ``rows`` (vectorised)."""
    if rows.size == 0:
        return flat[:0]
    starts = ptr[rows]
    lens = ptr[rows + 1] - starts
    total = int(lens.sum())
    if total == 0:
        return flat[:0]
    offsets = np.repeat(starts - np.concatenate(([0], np.cumsum(lens)[:-1])), lens)
    return flat[offsets + np.arange(total)]


def bitmask_to_array(mask: int, n: int) -> np.ndarray:
    """The bits 0..n-1 of ``mask`` as a boolean array."""
    load_numpy()
    nbytes = (n + 7) // 8
    raw = np.frombuffer((mask & ((1 << n) - 1)).to_bytes(nbytes or 1, "little"), dtype=np.uint8)
    return np.unpackbits(raw, bitorder="little")[:n].astype(bool)


class RelaxedExcuseTask:
    """The delete relaxation of the compiled excuse task, over relevant facts only."""

    def __init__(self, space: ChangeSpace) -> None:
        self.space = space
        task = space.task
        self.n_atoms = len(task.atoms)
        pre, add = self._facts_and_actions(space)
        self._relevant = space.relevant_atoms
        self._goal_pos, self._goal_neg = task.goal_pos, task.goal_neg
        self._index_tables(pre, add)
        pos_id, neg_id = self._pos_id, self._neg_id
        self.goal_list = [pos_id[i] for i in bits(task.goal_pos)] + [neg_id[i] for i in bits(task.goal_neg)]
        self.goal_set = frozenset(self.goal_list)
        self.neg_mask = space.negation_needed
        self._group_charges_tables(space)
        if not self.small:  # the numpy versions of the tables above
            self.goal = np.array(self.goal_list, dtype=np.int64)
            self.changeable = bitmask_to_array(space.changeable, self.n_atoms)

    def without_invariants(self, space: ChangeSpace) -> RelaxedExcuseTask:
        """This relaxed task for ``space``: the same task, relevance and changeable atoms without the mutex
        groups (the literal question beside a consistent one); the fact and action tables are shared."""
        other = copy.copy(self)
        other.space = space
        other._first_hmax = None
        other._group_charges_tables(space)
        return other

    def _facts_and_actions(self, space: ChangeSpace) -> tuple[list[list[int]], list[list[int]]]:
        """Number the relevant facts (atoms, then negations needed) and list each relevant action's
        precondition and add facts over them."""
        pos = list(bits(space.relevant_atoms))
        neg = list(bits(space.negation_needed))
        pos_id = {a: f for f, a in enumerate(pos)}
        neg_id = {a: len(pos) + f for f, a in enumerate(neg)}
        self.fact_atom_list = pos + neg
        self._pos_id, self._neg_id = pos_id, neg_id
        self.n_pos = len(pos)
        self.n_facts = len(pos) + len(neg)
        pre: list[list[int]] = []
        add: list[list[int]] = []
        for act in space.relevant_actions:
            pre.append([pos_id[i] for i in act.pre_pos_ids] + [neg_id[i] for i in act.pre_neg_ids])
            e = [pos_id[i] for i in act.add_ids if i in pos_id]
            adds = act.add_ids
            e += [neg_id[i] for i in act.delete_ids if i in neg_id and i not in adds]
            add.append(e)
        return pre, add

    def _index_tables(self, pre: list[list[int]], add: list[list[int]]) -> None:
        """Each fact's consumers and achievers, as lists, and as numpy arrays on large tasks."""
        n_actions = len(pre)
        self.n_actions = n_actions
        prec_of, achievers = index_facts(self.n_facts, pre, add)
        # Small tasks: numpy's per-call overhead dominates; plain lists are faster.
        self.small = n_actions < SMALL_TASK_ACTIONS
        self.pre_lists, self.add_lists = pre, add
        self.n_pre_list = [len(p) for p in pre]
        self.free_cost = [0] * n_actions  # the robot's actions: the compiled task charges changes only
        self.free_adds = sorted({q for p, e in zip(pre, add) if not p for q in e})
        self._first_hmax = None
        self.prec_of_lists, self.achiever_lists = prec_of, achievers
        if not self.small:
            load_numpy()
            self.fact_atom = np.array(self.fact_atom_list, dtype=np.int64)
            self.pre_ptr, self.pre_flat = _csr(pre)
            self.add_ptr, self.add_flat = _csr(add)
            self.n_pre = np.diff(self.pre_ptr)
            self.pre_owner = np.repeat(np.arange(n_actions, dtype=np.int64), self.n_pre)
            self.prec_ptr, self.prec_flat = _csr(prec_of)
            self.ach_ptr, self.ach_flat = _csr(achievers)
            self.pre_achievers = np.diff(self.ach_ptr)[self.pre_flat]  # per precondition entry
            self.free_add_facts = np.array(self.free_adds, dtype=np.int64)
            self.nonempty = np.flatnonzero(self.n_pre > 0)

    def _group_charges_tables(self, space: ChangeSpace) -> None:
        """The mutex groups' facts and the scaled fact weights the forced-removal charges need."""
        # Consistent semantics: making an atom of a mutex group true forces the
        # removal of the group's true atom q.  That removal is charged to the
        # change, split over the k groups q belongs to (so it is never charged
        # more than once in total): costs are scaled by lcm(k) to stay integral.
        # Landmark cost shares then include these charges, so a child whose
        # change removes such a q must not inherit them (see static_groups.py).
        pos_id = self._pos_id
        self.groups = [g.mask for g in space.groups]
        membership: dict[int, int] = {}
        for mask in self.groups:
            for i in bits(mask):
                membership[i] = membership.get(i, 0) + 1
        self.scale = math.lcm(*membership.values()) if membership else 1
        self.membership = membership
        self.group_fact_lists = [[pos_id[i] for i in bits(mask) if i in pos_id] for mask in self.groups]
        # Only the facts' weights matter (the task may have many irrelevant atoms).
        self.fact_weight_list = [float(space.weights.get(a, 0) * self.scale) for a in self.fact_atom_list]
        if not self.small:  # their numpy versions
            self.group_facts = [np.array(f, dtype=np.int64) for f in self.group_fact_lists]
            self.fact_weight = np.array(self.fact_weight_list, dtype=np.float64)

    def _initial_lists(self, state: int, changes: int, pinned: int = 0) -> tuple[list[bool], list[float]]:
        """:meth:`_initial` on plain lists, for small tasks (no numpy call overhead).

        Walks the set bits of the masks instead of testing every fact.
        """
        pos_id, neg_id, weight = self._pos_id, self._neg_id, self.fact_weight_list
        n_pos = self.n_pos
        true = [False] * n_pos + [True] * (self.n_facts - n_pos)
        cost = [INF] * self.n_facts
        relevant, neg_mask = self._relevant, self.neg_mask
        for a in bits(state & relevant):
            true[pos_id[a]] = True
        for a in bits(state & neg_mask):
            true[neg_id[a]] = False
        flippable = self.space.changeable & ~changes & ~pinned
        for a in bits(flippable & relevant & ~state):  # "p" can be made true
            f = pos_id[a]
            cost[f] = weight[f]
        for a in bits(flippable & neg_mask & state):  # "not p" can be made true
            f = neg_id[a]
            cost[f] = weight[f]
        for k, charge in self._group_charges(state, changes, pinned):
            for f in self.group_fact_lists[k]:
                cost[f] = INF if charge is None else cost[f] + charge
        return true, cost

    def _group_charges(self, state: int, changes: int, pinned: int = 0):
        """Per mutex group with one true atom q: (group index, charge on making another atom true).

        ``None`` pins the group's other atoms (q was made true by the change
        set, or is ``pinned``, and must stay).  Otherwise making one of them true forces q's
        removal, charged only when "not q" is no relaxed fact of its own: its
        change already costs w(q), and a relaxed plan may use both.
        """
        for k, mask in enumerate(self.groups):
            if not self.group_fact_lists[k]:
                continue
            present = state & mask
            if present.bit_count() != 1:
                continue
            q = present.bit_length() - 1
            if ((changes | pinned) >> q) & 1 or q not in self.space.weights:
                # q was made true by the change set, or may not change at all (fixed): it stays,
                # so no other atom of its group can be made true.
                yield k, None
            elif not (self.neg_mask >> q) & 1:
                yield k, self.space.weights[q] * self.scale / self.membership[q]

    def _initial(self, state: int, changes: int, pinned: int = 0) -> tuple[np.ndarray, np.ndarray]:
        """Facts true in ``state`` and the change cost of each other fact (INF = not changeable, or ``pinned``:
        an atom the change sets in question leave as it is)."""
        true = self._true_facts(state)
        flippable = (self.changeable & ~bitmask_to_array(changes | pinned, self.n_atoms))[self.fact_atom] & ~true
        cost = np.where(flippable, self.fact_weight, INF)
        for k, charge in self._group_charges(state, changes, pinned):
            facts = self.group_facts[k]
            cost[facts] = INF if charge is None else cost[facts] + charge
        return true, cost

    def _true_facts(self, state: int) -> np.ndarray:
        """The facts true in ``state`` ("p" for its relevant atoms, "not p" for the negations needed)."""
        true = bitmask_to_array(state, self.n_atoms)[self.fact_atom]
        true[self.n_pos :] = ~true[self.n_pos :]
        return true

    def _closure(self, frontier: np.ndarray, reached: np.ndarray, unsat: np.ndarray) -> Iterator[np.ndarray]:
        """From the newly reached facts ``frontier``, each further layer of facts the robot's actions reach with
        no change (marked in ``reached``; ``unsat``: each action's preconditions not reached yet, updated)."""
        while frontier.size:
            acts = _gather(self.prec_ptr, self.prec_flat, frontier)
            if acts.size == 0:
                return
            unsat -= np.bincount(acts, minlength=self.n_actions)
            fired = acts[unsat[acts] == 0]  # may repeat an action; its adds dedupe below
            new = _gather(self.add_ptr, self.add_flat, fired)
            new = new[~reached[new]]
            if new.size == 0:
                return
            frontier = np.unique(new)
            reached[frontier] = True
            yield frontier

    def _hmax(self, true: np.ndarray, cost: np.ndarray) -> np.ndarray:
        """h^max of every fact (bottleneck change cost), by thresholded closures."""
        h = np.full(self.n_facts, INF)
        unsat = self.n_pre.copy()
        reached = np.zeros(self.n_facts, dtype=bool)
        seed_cost = np.where(true, 0.0, cost)
        seed_cost[self.free_add_facts] = 0.0
        for c in np.unique(seed_cost[np.isfinite(seed_cost)]):
            frontier = np.flatnonzero((seed_cost <= c) & ~reached)
            reached[frontier] = True
            h[frontier] = c
            for layer in self._closure(frontier, reached, unsat):
                h[layer] = c
        return h

    def _pcf(self, h: np.ndarray, last: bool, fewest: bool = False) -> np.ndarray:
        """Precondition choice function: for each action, a precondition of maximal h (-1 if none).

        Ties go to the first (or, with ``last``, the last) such precondition; with ``fewest``, first to
        those with the fewest achievers (see :meth:`_packed_goal_landmarks`).
        """
        pcf = np.full(self.n_actions, -1, dtype=np.int64)
        if self.pre_flat.size == 0:
            return pcf
        vals = h[self.pre_flat]
        starts = self.pre_ptr[self.nonempty]
        amax = np.maximum.reduceat(vals, starts)
        best = np.full(self.n_actions, INF)
        best[self.nonempty] = amax
        is_max = vals == best[self.pre_owner]
        if fewest:  # then the first of the tied entries with the fewest achievers (``last`` is not used)
            size = vals.size
            key = np.where(is_max, self.pre_achievers * (size + 1) + np.arange(size), np.iinfo(np.int64).max)
            pcf[self.nonempty] = self.pre_flat[np.minimum.reduceat(key, starts) % (size + 1)]
            return pcf
        if last:
            pos = np.where(is_max, np.arange(vals.size), -1)
            chosen = np.maximum.reduceat(pos, starts)
        else:
            pos = np.where(is_max, np.arange(vals.size), vals.size)
            chosen = np.minimum.reduceat(pos, starts)
        pcf[self.nonempty] = self.pre_flat[chosen]
        return pcf

    def reaches_goal_unchanged(self, state: int) -> bool:
        """Whether the relaxed task reaches the goal from ``state`` with no change (LM-cut h = 0).

        A counter-based closure over the fact lists (linear in the relaxed
        task), much cheaper than an h^max pass; on a large task the same
        closure a layer at a time on arrays (depot: 1.4 ms a call on lists).
        """
        if not self.small:
            return self._reaches_goal_unchanged_arrays(state)
        return RelaxedClosure(self, state).left == 0

    def _reaches_goal_unchanged_arrays(self, state: int) -> bool:
        reached = self._true_facts(state)
        reached[self.free_add_facts] = True
        goal = self.goal
        if reached[goal].all():
            return True
        return any(reached[goal].all() for _ in self._closure(np.flatnonzero(reached), reached, self.n_pre.copy()))

    def bound(self, state: int, changes: int, pinned: int = 0) -> Bound:
        """LM-cut value and landmarks (as atom indices to flip) for excuses extending ``changes`` that flip no
        atom of ``pinned``.

        At the root (no changes yet) LM-cut is computed with two tie-breaking
        rules for the precondition choice function; both are admissible and
        the stronger is kept (the choice decides whether goals share one weak
        landmark or get their own).  The root's landmarks are inherited by the
        whole search, so that is where the stronger set pays; at other nodes
        the second run rarely wins and would cost a third of the bound.
        """
        if not self.goal_list:
            return Bound(0, [], [])
        if self.small:
            true, cost = self._initial_lists(state, changes, pinned)
        else:
            true, cost = self._initial(state, changes, pinned)
        self._first_hmax = None
        first = self._lmcut(true, cost.copy(), last=False)
        if not changes and not pinned and not (first.h == INF or first.h == 0):
            packed = self._packed_goal_landmarks(self._first_hmax, cost)  # reads cost; the run below consumes it
            # The second run starts from the same costs: its first h^max pass
            # is the first run's, only the tie-breaking differs.
            second = self._lmcut(true, cost, last=True, initial_h=self._first_hmax)
            first = max((first, second, packed), key=lambda b: b.h)  # the first of equals
        if first.h != INF:
            first.h = self.unscale(first.h)
        return first

    def _packed_goal_landmarks(self, h, cost) -> Bound:
        """Disjoint landmarks of single goals, each its own share of the changes' costs.

        LM-cut's first cut can take in changes every goal shares (a truck "moved" to every place serves
        every package: transport's root bound is one change while each package needs its own), and its
        costs then make the rest free.  Here each goal fact gets its own cut from the same h^max (the goal
        zone choosing, among tied preconditions, those with the fewest achievers: a package's place
        rather than a truck's); cuts sharing no change are packed, smallest first, each worth its
        cheapest change (a cost partition: no change is counted twice).
        """
        pcf = None if self.small else self._pcf(h, last=False, fewest=True)
        cuts = []
        for goal_fact in dict.fromkeys(self.goal_list):
            if h[goal_fact] == 0 or h[goal_fact] == INF:
                continue
            if self.small:
                zone = self._goal_zone_lists(goal_fact, h, last=False, fewest=True)
                cut = sorted(f for f in zone if 0 < cost[f] < INF)
            else:
                zone = self._goal_zone(goal_fact, h, pcf)
                cut = np.flatnonzero(zone & (cost > 0) & np.isfinite(cost)).tolist()
            if cut:
                cuts.append(cut)
        chosen: list[list[int]] = []
        used: set[int] = set()
        for cut in sorted(cuts, key=len):
            if used.isdisjoint(cut):
                chosen.append(cut)
                used.update(cut)
        shares = [min(float(cost[f]) for f in cut) for cut in chosen]
        return Bound(sum(shares), [sorted(self.fact_atom_list[f] for f in cut) for cut in chosen],
                     [int(m) for m in shares])

    def unscale(self, value: float) -> int:
        """A bound in scaled cost units as an admissible bound in weight units."""
        return int(math.floor(value / self.scale + 1e-9))

    def _lmcut(self, true, cost, last: bool, initial_h=None) -> Bound:
        """LM-cut from the facts ``true`` under the change costs ``cost`` (consumed): h^max on lists or arrays,
        the goal zone of its costliest goal fact, cut at the changes entering it."""
        small = self.small
        goal = self.goal_list if small else self.goal
        first = [initial_h]

        def hmax_of(cost):
            """h^max and its costliest goal fact (the first of equals, as np.argmax)."""
            if first[0] is not None:
                h, first[0] = first[0], None
            else:
                h = self._hmax_lists(true, cost) if small else self._hmax(true, cost)
                if self._first_hmax is None:
                    self._first_hmax = h
            return h, (max(goal, key=lambda g: h[g]) if small else int(goal[int(np.argmax(h[goal]))]))

        def cut_of(h_goal, cost) -> list[int]:
            h, goal_fact = h_goal
            if small:
                zone = self._goal_zone_lists(goal_fact, h, last)
                return sorted(f for f in zone if cost[f] > 0 and cost[f] != INF)
            zone = self._goal_zone(goal_fact, h, self._pcf(h, last))
            return np.flatnonzero(zone & (cost > 0) & np.isfinite(cost)).tolist()

        total, cuts = lmcut(hmax_of, lambda h_goal: h_goal[0][h_goal[1]], cut_of, cost)
        if total == INF:
            return Bound(INF, [], [])
        atoms = self.fact_atom_list
        return Bound(total, [sorted(atoms[f] for f in cut) for cut, _ in cuts], [int(m) for _, m in cuts])

    def _goal_zone(self, goal_fact: int, h: np.ndarray, pcf: np.ndarray) -> np.ndarray:
        """The goal zone: facts from which ``goal_fact`` is reached through zero-cost robot actions.

        Any zone works whose zero-cost achievers each have a precondition in
        it (every relaxed plan then enters it by a change: the cut is a
        landmark).  So an achiever with a precondition already in the zone
        adds nothing to it, and of one frontier's achievers those with one
        choice (a single precondition not reached for free) go first: the
        zone stays on the goal's own facts instead of leaking through an
        achiever that also needs another goal's fact (depot: dropping crate9
        onto crate0 needs crate0 there too), and the cut stays tight.
        """
        zone = np.zeros(self.n_facts, dtype=bool)
        zone[goal_fact] = True
        frontier = np.array([goal_fact], dtype=np.int64)
        while frontier.size:
            # Only the frontier's achievers and their preconditions are looked at
            # (not every action's: a house has 180,000).
            acts = np.unique(_gather(self.ach_ptr, self.ach_flat, frontier))
            owner = np.repeat(np.arange(acts.size), self.n_pre[acts])
            pres = _gather(self.pre_ptr, self.pre_flat, acts)
            choices = np.bincount(owner[h[pres] > 0], minlength=acts.size)
            added = []
            for first_pass in (True, False):
                covered = np.bincount(owner[zone[pres]], minlength=acts.size) > 0
                open_ = ~covered & (choices == 1) if first_pass else ~covered
                src = pcf[acts[open_]]
                src = src[src >= 0]
                src = np.unique(src[(h[src] > 0) & ~zone[src]])
                zone[src] = True
                added.append(src)
            frontier = np.concatenate(added)
        return zone

    # -- the same LM-cut on plain lists, for small tasks ------------------------
    def _hmax_lists(self, true: list[bool], cost: list[float]) -> list[float]:
        """h^max of every fact (as :meth:`_hmax`, on lists): the core's h^max, seeded with the true facts, the
        facts the robot adds with no precondition, and each other fact at its change cost."""
        seeds = [(0.0, f) for f, t in enumerate(true) if t]
        seeds += [(0.0, f) for f in self.free_adds]
        seeds += [(c, f) for f, c in enumerate(cost) if c != INF and not true[f]]
        return hmax(seeds, self.n_facts, self.prec_of_lists, self.add_lists, self.n_pre_list, self.free_cost)[0]

    def _goal_zone_lists(self, goal_fact: int, h: list[float], last: bool, fewest: bool = False) -> set[int]:
        """:meth:`_goal_zone` on lists, for small tasks: the precondition choice function only for the
        achievers the zone meets.

        Unlike the numpy version, which checks a pass's achievers against the zone as it stood when the
        pass began, each achiever here is checked when its turn comes, so facts added earlier in the same
        pass can cover it: the zone may be smaller and the bound higher.  Both zones are closed (every
        zero-cost achiever has a precondition inside), so both cuts are landmarks.
        """
        pre, achievers = self.pre_lists, self.achiever_lists
        zone = {goal_fact}
        frontier = [goal_fact]
        while frontier:
            acts = sorted({ai for q in frontier for ai in self.achiever_lists[q]})
            frontier = []
            for first_pass in (True, False):
                for ai in acts:
                    p = pre[ai]
                    if not p or any(x in zone for x in p):
                        continue
                    if first_pass and sum(1 for x in p if h[x] > 0) != 1:
                        continue
                    if len(p) == 1:
                        f = p[0]
                    elif fewest:
                        best = max(h[x] for x in p)
                        f = min((x for x in p if h[x] == best), key=lambda x: len(achievers[x]))
                    else:
                        vals = [h[x] for x in p]
                        best = max(vals)
                        if last:
                            f = p[len(vals) - 1 - vals[::-1].index(best)]
                        else:
                            f = p[vals.index(best)]
                    if f not in zone and h[f] > 0:
                        zone.add(f)
                        frontier.append(f)
        return zone


class RelaxedClosure:
    """The facts the relaxed robot reaches from a state with no change, on the fact lists, grown in place by
    :meth:`add` (copy it first to try a set of facts and keep the old closure)."""

    __slots__ = ("relaxed", "reached", "unsat", "left")

    def __init__(self, relaxed: RelaxedExcuseTask, state: int) -> None:
        self.relaxed = relaxed
        self.reached = bytearray(relaxed.n_facts)
        self.unsat = list(relaxed.n_pre_list)
        self.left = len(relaxed.goal_set)  # goal facts not reached yet
        pos_id, neg_id = relaxed._pos_id, relaxed._neg_id
        facts = [pos_id[a] for a in bits(state & relaxed._relevant)]
        facts += [neg_id[a] for a in bits(relaxed.neg_mask & ~state)]
        self.add(facts + relaxed.free_adds)

    def copy(self) -> RelaxedClosure:
        """An independent copy."""
        other = RelaxedClosure.__new__(RelaxedClosure)
        other.relaxed, other.left = self.relaxed, self.left
        other.reached, other.unsat = bytearray(self.reached), list(self.unsat)
        return other

    def add(self, facts: list[int]) -> bool:
        """Make ``facts`` true and close under the relaxed actions; whether the goal is reached.  Reaching it
        stops the closure there: a closure that reaches the goal is only asked that, never grown further."""
        relaxed = self.relaxed
        self.left = close(facts, self.reached, self.unsat, relaxed.prec_of_lists, relaxed.add_lists,
                          relaxed.goal_set, self.left)[1]
        return self.left == 0
