"""The world's structure, held fixed by default: excuses a person would accept.

An excuse that turns a truck into an airplane (``+(airplane t0)``) or adds a
door between two rooms (``+(adjacent r7 r4)``) is no request a person can
demonstrate.  Without a model of what the human can change (``--human``,
``--fixed-from``), the excuse keeps the static predicates that describe what
things are or how places connect:

* **kinds**: a one-argument predicate no action changes, true of some objects,
  and true of every object of a type it is true of (``(graspable ?x)`` true of
  each plate; in a domain without types, any such predicate: the domain's types
  are written as predicates there);
* **a fixed graph**: a predicate no action changes, with true atoms, relating
  two or more objects of one type (rooms, floors, grid positions), or objects
  no action moves (no action's effect places an object of their types
  somewhere: ``(in-city ?l - location ?c - city)``).

A static predicate true of nothing (``open`` in a kitchen where the robot cannot
open, no drawer open yet) or true of some objects of a type and not others
(``clear``: one drawer blocked) describes a state, not a kind, and stays
changeable.  ``--change-structure`` lets the excuse change them all; a
predicate given a ``--cost`` is changeable at that cost.
"""

from __future__ import annotations

from collections.abc import Sequence

from guided_lfd.pddl.model import EQUALITY, Domain, Problem

__all__ = ["placing_predicates", "structural_predicates"]


def structural_predicates(domain: Domain, problem: Problem, models: Sequence[Domain] = ()) -> dict[str, str]:
    """The static predicates of ``domain`` that describe the world's structure in ``problem``, each with why;
    what an action of another model given (``--invariants-from``, the human's) changes is no structure."""
    static = set(domain.predicates) - domain.fluent_predicates() - domain.derived_predicates() - {EQUALITY}
    for model in models:
        static -= model.fluent_predicates()
    objects = {**domain.constants, **problem.objects}
    typed = any(t != "object" for t in objects.values())
    true_args: dict[str, list[tuple[str, ...]]] = {}
    for atom in problem.init:
        true_args.setdefault(atom.predicate, []).append(atom.args)
    moved = set().union(*(_moved_types(d) for d in (domain, *models)))
    out: dict[str, str] = {}
    for name in sorted(static):
        params = domain.predicates[name].params
        found = true_args.get(name, [])
        if not found or not params:
            continue
        if len(params) == 1:
            why = _kind(domain, objects, params[0][1], {args[0] for args in found}, typed)
        else:
            why = _graph([t for _, t in params], typed, moved)
        if why:
            out[name] = why
    return out


def placing_predicates(source: Domain, problem: Problem) -> dict[str, str]:
    """The static two-argument predicates of ``source`` that place things, each with why: every object they say
    anything of is in exactly one place in ``problem``'s initial state (``(at bot hall)``), and no place is itself
    placed (a relation whose objects are also its places, ``(connected hall office)``, is a graph).  No action of
    ``source`` moves those objects (its skill to is missing), so no invariant synthesis keeps them in one place;
    under the consistent semantics the excuse keeps each in at most one all the same."""
    static = set(source.predicates) - source.fluent_predicates() - source.derived_predicates() - {EQUALITY}
    pairs: dict[str, list[tuple[str, ...]]] = {}
    for atom in problem.init:
        if atom.predicate in static and len(atom.args) == 2:
            pairs.setdefault(atom.predicate, []).append(atom.args)
    out = {}
    for name, found in sorted(pairs.items()):
        things = [args[0] for args in found]
        if (len(source.predicates[name].params) == 2 and len(set(things)) == len(things)
                and not set(things) & {args[1] for args in found}):
            out[name] = f"places things: each of {len(things)} object(s) in one place, and no action moves them"
    return out


def _kind(domain: Domain, objects: dict[str, str], param_type: str, holders: set[str], typed: bool) -> str | None:
    """Why a one-argument static predicate true of ``holders`` names a kind of thing (None: it names a state)."""
    if not typed:
        return f"a kind: true of {len(holders)} object(s) in a domain whose types are predicates"
    below = domain.subtypes().get(param_type, {param_type})
    eligible = {o: t for o, t in objects.items() if t in below}
    kinds = {eligible[o] for o in holders if o in eligible}
    if any((o in holders) != (t in kinds) for o, t in eligible.items()):
        return None  # true of some objects of a type and not of others: a state
    return f"a kind: true of every {', '.join(sorted(kinds))}"


def _graph(types: list[str], typed: bool, moved: set[str]) -> str | None:
    """Why a static relation over arguments of ``types`` is a fixed graph (None: it may relate things that move)."""
    repeated = sorted({t for t in types if types.count(t) > 1})
    if repeated:
        over = "objects" if not typed and repeated == ["object"] else f"{repeated[0]} objects"
        return f"a fixed graph over {over}"
    if typed and not moved & set(types):
        return f"a fixed relation of {', '.join(types)} objects, which no action moves"
    return None


def _moved_types(domain: Domain) -> set[str]:
    """The types of objects some action places: the first argument of a changing relation (``at ?x ?place``),
    with their super- and subtypes (an object of any of them may be one that moves)."""
    subtypes = domain.subtypes()
    placed = {domain.predicates[p].params[0][1] for p in domain.fluent_predicates()
              if p in domain.predicates and len(domain.predicates[p].params) >= 2}
    related = set(placed)
    for t in placed:
        related |= subtypes.get(t, {t})
        related |= {sup for sup, below in subtypes.items() if t in below}
    return related
