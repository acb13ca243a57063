"""Positive preconditions a learned action need not state.

The nodes-of-interest rule keeps every fact about the objects a skill
handles, so facts that hold whenever the skill can run at all become
preconditions too: the held block is ``clear`` and ``graspable``, the block
below it is ``graspable``.  Two rules drop them; both leave the action
applicable in exactly the states it was, among the demonstrated states and
every state the actions reach from them:

* **Implied by holding.**  ``(in_hand ?b)`` implies ``(clear ?b)`` when every
  demonstrated state satisfies "whatever is held is clear" and every action
  preserves it (one that makes ``in_hand x`` true has ``clear x`` true after
  it; one that makes ``clear x`` false leaves ``x`` not held, by a delete, a
  negative precondition or an at-most-one group of Fast Downward's invariant
  synthesis, :mod:`guided_lfd.demonstration.mutex`).  A precondition about
  the held object that holding it implies is dropped.  Only the hand's
  state is a premise: facts about the furniture the hand acts on stay, as
  the nodes-of-interest rule wants (``clear`` of the drawer).
* **A grasp affordance is about what is grasped.**  A one-argument fact no
  action changes and every object ever held has (``graspable``) is a
  condition of grasping: a skill keeps it only on the object it grasps (a
  Take keeps ``graspable`` of what it picks up, the check the robot needs on
  an object it has not seen handled), not on the block below or the block
  it stacks onto (objects of a kind the hand holds); a skill on something of
  a kind never held (pushing the chair) keeps it.

Facts that are static for other reasons (every surface of Kitchen I stays
``clear``) are kept: the demonstrations cannot tell them from conditions.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace

from guided_lfd.demonstration.mutex import group_key_matches
from guided_lfd.pddl.model import EQUALITY, ActionSchema, Atom, Domain, Literal, type_ancestors

#: The hand predicate whose addition marks the object a skill grasps.
GRASPED = "in_hand"


@dataclass(frozen=True)
class Implication:
    """``premise(x1 ... xn)`` implies ``conclusion(x_positions...)`` for every binding."""

    premise: str
    arity: int
    conclusion: str
    positions: tuple[int, ...]

    def concluded(self, atom: Atom) -> Atom:
        """The conclusion for a premise atom."""
        return Atom(self.conclusion, tuple(atom.args[i] for i in self.positions))

    def premised(self, atom: Atom) -> Atom | None:
        """The one premise atom whose conclusion is ``atom`` (None: not one-to-one)."""
        if sorted(self.positions) != list(range(self.arity)):
            return None
        args = [""] * self.arity
        for i, pos in enumerate(self.positions):
            args[pos] = atom.args[i]
        return Atom(self.premise, tuple(args))

    def holds(self, state: frozenset[Atom]) -> bool:
        """Whether ``state`` satisfies the implication."""
        return all(self.concluded(a) in state for a in state if a.predicate == self.premise and len(a.args) == self.arity)


def _candidates(actions: Iterable[ActionSchema], premises: set[str]) -> set[Implication]:
    """Implications from a positive precondition of one of the ``premises`` predicates to another of the same
    action, the conclusion's arguments among the premise's."""
    out: set[Implication] = set()
    for action in actions:
        positives = [l.atom for l in action.precondition if l.positive and l.atom.predicate != EQUALITY]
        for p in positives:
            for q in positives:
                if (p.predicate in premises and p.predicate != q.predicate and q.args
                        and set(q.args) <= set(p.args)):
                    out.add(Implication(p.predicate, len(p.args), q.predicate, tuple(p.args.index(x) for x in q.args)))
    return out


def _may_equal(a: Atom, b: Atom) -> bool:
    """Whether some binding of the variables makes ``a`` and ``b`` the same atom."""
    return a.predicate == b.predicate and len(a.args) == len(b.args) and all(
        x == y or x.startswith("?") or y.startswith("?") for x, y in zip(a.args, b.args))


def _false_before_or_deleted(atom: Atom, action: ActionSchema, invariants: list) -> bool:
    """Whether ``atom`` is false after ``action`` (given that no add of the action makes it true)."""
    if atom in action.delete or Literal(atom, False) in action.precondition:
        return True
    for lit in action.precondition:
        # A precondition in one at-most-one group with it: both true is impossible, unless they are the
        # same atom under some binding, and then the action deletes it.
        if (lit.positive and lit.atom.predicate != EQUALITY and group_key_matches(lit.atom, atom, invariants)
                and (not _may_equal(lit.atom, atom) or lit.atom in action.delete)):
            return True
    return False


def _preserves(action: ActionSchema, imp: Implication, invariants: list) -> bool:
    """Whether ``action`` keeps ``imp`` true in every state where it held before."""
    for added in action.add:
        if added.predicate == imp.premise and len(added.args) == imp.arity:
            needed = imp.concluded(added)
            deleted = any(_may_equal(needed, d) for d in action.delete)
            if needed not in action.add and (Literal(needed) not in action.precondition or deleted):
                return False
    for deleted in action.delete:
        if deleted.predicate != imp.conclusion or len(deleted.args) != len(imp.positions) or deleted in action.add:
            continue
        premise = imp.premised(deleted)
        if premise is None or any(_may_equal(premise, a) for a in action.add):
            return False
        if not _false_before_or_deleted(premise, action, invariants):
            return False
    return True


def proven_implications(domain: Domain, states: Iterable[frozenset[Atom]], invariants: list,
                        premises: frozenset[str] = frozenset({GRASPED})) -> list[Implication]:
    """Implications from ``premises`` to other preconditions of ``domain``'s actions that every state in
    ``states`` satisfies and every action preserves."""
    observed = list(states)
    return sorted((imp for imp in _candidates(domain.actions, set(premises))
                   if all(imp.holds(s) for s in observed) and all(_preserves(a, imp, invariants) for a in domain.actions)),
                  key=lambda i: (i.premise, i.conclusion, i.positions))


def _held(states: list[frozenset[Atom]], grasped: frozenset[str] = frozenset({GRASPED})
          ) -> list[tuple[str, frozenset[Atom]]]:
    """(object, state) for every object held in a state (the held object is a ``grasped`` fact's last argument)."""
    return [(a.args[-1], s) for s in states for a in s if a.predicate in grasped and 1 <= len(a.args) <= 2]


def grasp_affordances(domain: Domain, states: list[frozenset[Atom]],
                      held: list[tuple[str, frozenset[Atom]]] | None = None,
                      grasped: frozenset[str] = frozenset({GRASPED})) -> set[str]:
    """One-argument predicates no action changes that every object held in a state has there (``graspable``).

    ``held``: :func:`_held` of ``states``, when the caller has it already.
    """
    changed = {a.predicate for act in domain.actions for a in (*act.add, *act.delete)}
    held = _held(states, grasped) if held is None else held
    candidates = {l.atom.predicate for act in domain.actions for l in act.precondition
                  if l.positive and len(l.atom.args) == 1} - changed - set(grasped)
    return {p for p in candidates if held and all(Atom(p, (x,)) in s for x, s in held)}


def held_types(domain: Domain, states: list[frozenset[Atom]], objects: dict[str, str],
               held: list[tuple[str, frozenset[Atom]]] | None = None) -> set[str]:
    """The types of the objects held in some state, with their supertypes (``held`` as in :func:`grasp_affordances`)."""
    held_objects = {x for x, _ in (_held(states) if held is None else held)}
    return {t for x in held_objects for t in type_ancestors(domain.types, objects.get(x, "object"))}


def drop_implied_preconditions(domain: Domain, names: set[str], states: Iterable[frozenset[Atom]],
                               invariants: list, objects: dict[str, str] | None = None,
                               grasped: frozenset[str] = frozenset({GRASPED})) -> Domain:
    """``domain`` with the actions in ``names`` rid of positive preconditions the module's two rules make
    redundant (``objects``: every demonstrated object's type; ``grasped``: the hand's held predicates)."""
    observed = list(states)
    implications = proven_implications(domain, observed, invariants, grasped)
    held = _held(observed, grasped)  # walked once for both rules
    affordances = grasp_affordances(domain, observed, held, grasped)
    graspable_types = held_types(domain, observed, objects or {}, held)
    actions: list[ActionSchema] = []
    for action in domain.actions:
        if action.name in names:
            action = _simplified(action, implications, affordances, graspable_types, grasped)
        actions.append(action)
    return replace(domain, actions=actions)


def _simplified(action: ActionSchema, implications: list[Implication], affordances: set[str],
                graspable_types: set[str], held_predicates: frozenset[str] = frozenset({GRASPED})) -> ActionSchema:
    types = dict(action.params)
    grasped = {a.args[-1] for a in action.add if a.predicate in held_predicates and 1 <= len(a.args) <= 2}
    # An affordance goes only where it is not what this skill grasps, on objects of a kind the hand holds
    # (the block below); a skill on something never held (pushing the chair) keeps it.
    kept = [l for l in action.precondition
            if not (l.positive and l.atom.predicate in affordances and l.atom.args[0] not in grasped
                    and types.get(l.atom.args[0], "object") in graspable_types)]
    changed = True
    while changed:  # one at a time, so two facts that imply each other do not both go
        changed = False
        for lit in kept:
            if lit.positive and any(other.positive and other != lit and imp.premise == other.atom.predicate
                                    and len(other.atom.args) == imp.arity and imp.concluded(other.atom) == lit.atom
                                    for other in kept for imp in implications):
                kept.remove(lit)
                changed = True
                break
    return action if tuple(kept) == action.precondition else replace(action, precondition=tuple(kept))


__all__ = ["Implication", "proven_implications", "grasp_affordances", "held_types", "drop_implied_preconditions"]
