"""Guards on static facts that every observed world rules out.

A safe model's guard ``(not g)`` keeps an action from running where it might
need ``g`` false or delete ``g`` unseen.  When ``g``'s predicate is *static*
(no observed step and no action of the domain changes it), ``g`` is true in a
reachable state exactly where it is true in the initial state, beside the
action's other static preconditions.  If no observed world has objects that
satisfy the action's static preconditions and ``g`` together (``(up ?x ?y)``
with ``(down ?x ?y)`` on a grid, ``(adjacent ?x ?x)``), the guard is dropped:
the learned model then assumes the problem's static facts follow the same
pattern as every trajectory's (a grid stays a grid), as a learner assumes its
test problems come from the distribution it learned from.  Guards on facts
some action changes are never dropped here (a laser may destroy gold no step
showed it at).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace

from guided_lfd.pddl.model import ActionSchema, Atom, Domain, Literal

__all__ = ["static_predicates", "drop_ruled_out_static_guards"]


def static_predicates(domain: Domain, changed: Iterable[Atom]) -> set[str]:
    """Predicates of ``domain`` that no action's effects and none of the ``changed`` atoms mention."""
    moving = {a.predicate for a in changed}
    for action in domain.actions:
        moving |= {a.predicate for a in (*action.add, *action.delete)}
    return set(domain.predicates) - moving


def _bindings(pattern: list[Atom], world: dict[str, set[tuple[str, ...]]],
              binding: dict[str, str]) -> Iterable[dict[str, str]]:
    """Every extension of ``binding`` (one object per parameter, a different one for each) under which each atom
    of ``pattern`` is true in ``world``."""
    if not pattern:
        yield binding
        return
    first, rest = pattern[0], pattern[1:]
    for args in world.get(first.predicate, ()):
        extended = dict(binding)
        for term, obj in zip(first.args, args):
            if not term.startswith("?"):
                if term != obj:
                    break
            elif term in extended:
                if extended[term] != obj:
                    break
            elif obj in extended.values():
                break  # distinct parameters, distinct objects (the safe model's scope)
            else:
                extended[term] = obj
        else:
            yield from _bindings(rest, world, extended)


def _ruled_out(guard: Atom, static_pre: list[Atom], worlds: list[dict[str, set[tuple[str, ...]]]]) -> bool:
    """Whether no world has objects making ``guard`` and every one of ``static_pre`` true at once."""
    return not any(next(iter(_bindings([guard, *static_pre], world, {})), None) is not None for world in worlds)


def drop_ruled_out_static_guards(domain: Domain, names: set[str], states: Iterable[frozenset[Atom]],
                                 changed: Iterable[Atom]) -> tuple[Domain, list[str]]:
    """``domain`` with the guards of the actions in ``names`` on static facts that no observed state allows
    beside the action's static preconditions dropped (see the module), and one line per dropped guard."""
    static = static_predicates(domain, changed)
    worlds: list[dict[str, set[tuple[str, ...]]]] = []
    seen: set[frozenset[Atom]] = set()
    for state in states:
        facts = frozenset(a for a in state if a.predicate in static)
        if facts not in seen:  # a trajectory's static facts are the same in each of its states
            seen.add(facts)
            world: dict[str, set[tuple[str, ...]]] = {}
            for atom in facts:
                world.setdefault(atom.predicate, set()).add(atom.args)
            worlds.append(world)
    actions: list[ActionSchema] = []
    dropped: list[str] = []
    for action in domain.actions:
        if action.name in names:
            static_pre = [l.atom for l in action.precondition if l.positive and l.atom.predicate in static]
            kept: list[Literal] = []
            for lit in action.precondition:
                if not lit.positive and lit.atom.predicate in static and _ruled_out(lit.atom, static_pre, worlds):
                    dropped.append(f"{action.name}: {lit.atom}")
                    continue
                kept.append(lit)
            action = replace(action, precondition=tuple(kept))
        actions.append(action)
    return replace(domain, actions=actions), dropped
