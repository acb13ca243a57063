"""Negative preconditions a learned action need not state: implied through a mutex.

A learned action says what was false before it made something true (the
drawer was closed before it was opened), so a Put learns ``(not (inside ?i
?d))`` next to ``(in_hand ?i)``.  When ``p`` and ``q`` can never both be true
(a *mutex*: the plate is either in the hand, in a drawer or on a surface), a
positive precondition ``q`` already implies ``(not p)``; stating it again only
makes the action model wordier than the one a person would write.

The mutexes are Fast Downward's lifted invariants (Helmert 2009, invariant
synthesis), found by :func:`guided_lfd.excuse.invariants.lifted_invariants` on
the domain the learned actions end up in (with the prior's actions, if any,
and the reverse of every action).  An invariant only says "at most one atom of
each group is true" for states reachable from states where that already holds,
so it is kept only when no observed state of the demonstrations violates it.
Dropping ``(not p)`` is then sound: in every state the actions can reach from
such states, ``q`` true means ``p`` false, and the action applies exactly
when it did before.  When synthesis fails nothing is dropped.  For trajectories
(:mod:`guided_lfd.demonstration.action_model`), :func:`pair_invariants` adds
the pairs the synthesis misses, and :func:`drop_idle_deletes` the deletes of
atoms a precondition rules out.
"""

from __future__ import annotations

from collections.abc import Iterable
from itertools import combinations
from dataclasses import replace

from guided_lfd.errors import MismatchError
from guided_lfd.pddl.model import EQUALITY, ActionSchema, Atom, Domain, Problem


def proven_invariants(domain: Domain, objects: dict[str, str], states: Iterable[frozenset[Atom]],
                      reverse: bool = True) -> list:
    """Fast Downward's lifted invariants of ``domain`` that every state in ``states`` satisfies (``reverse``:
    only those the reverse of every action keeps too, see :func:`guided_lfd.excuse.invariants.lifted_invariants`)."""
    from guided_lfd.excuse.invariants import lifted_invariants

    problem = Problem("learned-invariants", domain.name, dict(objects), frozenset(), ())
    try:
        found = lifted_invariants(domain, problem, reverse=reverse)
    except MismatchError:
        return []
    observed = list(states)
    return [inv for inv in found if all(_holds(inv, state) for state in observed)]


def pair_invariants(domain: Domain, states: Iterable[frozenset[Atom]]) -> list:
    """Invariants "never both ``p(x...)`` and ``q(x...)``" over two predicates of one arity, proven together by
    induction over ``domain``'s actions on distinct objects, none a constant, where no state of ``states``
    breaks them (as :func:`proven_invariants`' are).

    Fast Downward's synthesis balances an add only by a delete of a precondition, so it misses a group an
    action enters by deleting every other member (a laser makes a cell ``clear`` and deletes its soft and
    hard rock, whichever was there).  Here an action that makes ``p(t)`` true keeps the pair when it does not
    make ``q(t)`` true and makes it false (a delete) or needs a fact that rules it out: ``p(t)`` itself, or
    ``r(t)`` of a pair ``(r, q)`` kept too (a bomb needs soft rock, which no hard rock is beside).  The
    pairs are a greatest fixpoint: every candidate the states allow, less those some action breaks given the
    rest, until none is.  Negative preconditions are not used: a learned one is a guard that later steps may
    drop.  A domain with an ADL action proves none.
    """
    from fast_downward.translate.invariants import Invariant, InvariantPart

    if any(a.is_adl for a in domain.actions):
        return []
    by_arity: dict[int, list[str]] = {}
    for pred in sorted(domain.predicates.values(), key=lambda x: x.name):
        if pred.name != EQUALITY:
            by_arity.setdefault(len(pred.params), []).append(pred.name)
    pairs = {frozenset((p, q)) for names in by_arity.values() for i, p in enumerate(names) for q in names[i + 1:]}
    pairs -= _together(states)
    while True:
        broken = {pair for pair in pairs if not _pair_kept(domain.actions, pair, pairs)}
        if not broken:
            break
        pairs -= broken
    arity = {p: len(domain.predicates[p].params) for pair in pairs for p in pair}
    return [Invariant([InvariantPart(p, tuple(range(arity[p]))) for p in sorted(pair)]) for pair in sorted(pairs, key=sorted)]


def _pair_kept(actions: Iterable[ActionSchema], pair: frozenset[str], pairs: set[frozenset[str]]) -> bool:
    """Whether no action of ``actions`` makes both atoms of ``pair`` true over one tuple of arguments, given that
    every pair of ``pairs`` holds before it (see :func:`pair_invariants`)."""
    p, q = sorted(pair)
    for action in actions:
        positives = {l.atom for l in action.precondition if l.positive}
        for added in action.add:
            for other in ((q,) if added.predicate == p else (p,) if added.predicate == q else ()):
                partner = Atom(other, added.args)
                if partner in action.add:
                    return False
                if partner in action.delete or added in positives:
                    continue
                if not any(r.args == added.args and r.predicate != other and frozenset((r.predicate, other)) in pairs
                           for r in positives):
                    return False
    return True


def _together(states: Iterable[frozenset[Atom]]) -> set[frozenset[str]]:
    """The pairs of predicates some state of ``states`` makes true over the same arguments (one pass per state)."""
    out: set[frozenset[str]] = set()
    for state in states:
        by_args: dict[tuple[str, ...], set[str]] = {}
        for atom in state:
            by_args.setdefault(atom.args, set()).add(atom.predicate)
        for names in by_args.values():
            if len(names) > 1:
                out.update(frozenset(pair) for pair in combinations(sorted(names), 2))
    return out


def _key(part, atom: Atom) -> tuple[str, ...] | None:
    """The group instance ``atom`` belongs to under invariant part ``part`` (None: it does not)."""
    if part.predicate != atom.predicate or len(part.args) != len(atom.args):
        return None
    return tuple(atom.args[pos] for index in range(part.arity()) for pos, arg in enumerate(part.args) if arg == index)


def _holds(inv, state: frozenset[Atom]) -> bool:
    """Whether at most one atom of each of ``inv``'s groups is true in ``state``."""
    seen: set[tuple[str, ...]] = set()
    for atom in state:
        for part in inv.parts:
            key = _key(part, atom)
            if key is None:
                continue
            if key in seen:
                return False
            seen.add(key)
    return True


def mutex(p: Atom, q: Atom, invariants: list) -> object | None:
    """An invariant under which lifted atoms ``p`` and ``q`` are never both true, else None.

    Both must fall into the same group for every binding of their variables
    (the same group key, variable for variable).  Atoms of one predicate are
    never reported: under a binding that makes them equal, "not both" fails.
    """
    if p.predicate == q.predicate:
        return None
    return _shared_group(p, q, invariants)


def _shared_group(p: Atom, q: Atom, invariants: list) -> object | None:
    for inv in invariants:
        keys_p = {_key(part, p) for part in inv.parts} - {None}
        keys_q = {_key(part, q) for part in inv.parts} - {None}
        if keys_p & keys_q:
            return inv
    return None


def group_key_matches(p: Atom, q: Atom, invariants: list) -> bool:
    """Whether lifted atoms ``p`` and ``q`` fall into one at-most-one group for every binding: they are never
    both true unless some binding makes them the same atom (same predicate), which the caller must rule out."""
    return _shared_group(p, q, invariants) is not None


def drop_implied_negative_preconditions(domain: Domain, names: set[str], invariants: list,
                                        distinct: bool = False) -> Domain:
    """``domain`` with each ``(not p)`` of the actions in ``names`` dropped when a positive precondition implies it.

    ``distinct``: the actions are only applied to distinct objects, none a constant, so two different lifted atoms
    are never the same ground atom and atoms of one predicate in one group are mutex too."""
    def implied(p: Atom, q: Atom) -> bool:
        if distinct and p != q:
            return group_key_matches(p, q, invariants)
        return mutex(p, q, invariants) is not None

    actions: list[ActionSchema] = []
    for action in domain.actions:
        if action.name in names:
            positives = [l.atom for l in action.precondition if l.positive and l.atom.predicate != EQUALITY]
            kept = tuple(l for l in action.precondition
                         if l.positive or l.atom.predicate == EQUALITY
                         or not any(implied(l.atom, q) for q in positives))
            if kept != action.precondition:
                action = replace(action, precondition=kept)
        actions.append(action)
    return replace(domain, actions=actions)


def drop_idle_deletes(domain: Domain, names: set[str], invariants: list) -> Domain:
    """``domain`` with each delete of the actions in ``names`` dropped when a positive precondition rules its atom
    out (a mutex, on distinct objects): the atom is false whenever the action runs, so deleting it changes
    nothing.  A step that passes one object twice may leave such deletes (see
    :func:`guided_lfd.demonstration.action_model.learn_operators`): moving goods up from level 0 to 1 while
    the market's stock goes from 1 to 0 cannot tell which level was deleted, so both are, and the one that is
    not the goods' level before goes here.  A delete stays where it is the last change to its predicate:
    without it the predicate would be static, and its invariants, which justify the drop, unprovable."""
    def idle(d: Atom, positives: list[Atom]) -> bool:
        return d not in positives and any(d != q and group_key_matches(d, q, invariants) for q in positives)

    def positives(action: ActionSchema) -> list[Atom]:
        return [l.atom for l in action.precondition if l.positive and l.atom.predicate != EQUALITY]

    dropped = {a.name: [d for d in a.delete if idle(d, positives(a))] for a in domain.actions if a.name in names}
    still = {x.predicate for a in domain.actions for x in (*a.add, *a.delete) if x not in dropped.get(a.name, ())}
    actions: list[ActionSchema] = []
    for action in domain.actions:
        gone = [d for d in dropped.get(action.name, ()) if d.predicate in still]
        if gone:
            action = replace(action, delete=tuple(d for d in action.delete if d not in gone))
        actions.append(action)
    return replace(domain, actions=actions)


__all__ = ["proven_invariants", "pair_invariants", "mutex", "group_key_matches", "drop_implied_negative_preconditions",
           "drop_idle_deletes"]
