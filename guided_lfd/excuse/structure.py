"""The world's structure, held fixed by default: excuses a person would accept.

An excuse that turns a truck into an airplane (``+(airplane t0)``) or adds a
door between two rooms (``+(adjacent r7 r4)``) is no request a person can
demonstrate.  Without a model of what the human can change (``--human``,
``--fixed-from``), the excuse keeps the static predicates that describe what
things are or how places connect:

* **kinds**: a one-argument predicate no action changes, true of some objects,
  and true of every object of a type it is true of, or of exactly the objects of a
  type another such predicate is false of (``is-goal`` beside ``is-nongoal``), unless the
  pair is over things that are no places and a skill that changes it seems missing
  (``door-open`` beside ``door-closed`` for a robot that cannot open doors:
  :meth:`_World.on_the_way`); in a domain without types, any such predicate (the domain's types are written as
  predicates there) but a marker of one place (``(at-robby rooma)``);
* **a fixed graph or map**: a predicate no action changes, with true atoms,
  relating two or more objects of one type (rooms, floors, grid positions),
  objects no action moves (no action's effect places an object of their types
  somewhere: ``(in-city ?l - location ?c - city)``), one object to several (a map
  or a capability: ``(reachable-floor ?lift ?floor)``), or each object to one
  that is no place (``(on_board ?camera ?rover)``).

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
    static = _static(domain)
    for model in models:
        static -= model.fluent_predicates()
    static -= _goal_predicates(problem)  # the task asks for it to change: the world can change it
    world = _World(domain, problem, static, models)
    out: dict[str, str] = {}
    for name in sorted(static):
        params = domain.predicates[name].params
        found = world.true_args.get(name, [])
        if params and name in domain.types:
            why: str | None = f"a kind: the type {name}"
        elif not found or not params:
            continue
        elif len(params) == 1:
            why = world.kind(name, params[0][1])
        else:
            why = world.relation(name, [t for _, t in params])
        if why:
            out[name] = why
    return out


def _static(domain: Domain) -> set[str]:
    """The predicates no action of ``domain`` changes (nor an axiom derives)."""
    return set(domain.predicates) - domain.fluent_predicates() - domain.derived_predicates() - {EQUALITY}


def _true_args(problem: Problem) -> dict[str, list[tuple[str, ...]]]:
    """The arguments of the initial state's true atoms, by predicate."""
    out: dict[str, list[tuple[str, ...]]] = {}
    for atom in problem.init:
        out.setdefault(atom.predicate, []).append(atom.args)
    return out


def _goal_predicates(problem: Problem) -> set[str]:
    """The predicates the task's goal names (an ADL goal's literals anywhere in its formula)."""
    names = {lit.atom.predicate for lit in problem.goal}
    if problem.goal_condition is not None:
        from guided_lfd.pddl.formula import literals_of

        names |= {lit.atom.predicate for lit in literals_of(problem.goal_condition)}
    return names


class _World:
    """What the structure rules look at: the objects, the true atoms of each predicate, which types move."""

    def __init__(self, domain: Domain, problem: Problem, static: set[str], models: Sequence[Domain]) -> None:
        self.domain, self.problem, self.static = domain, problem, static
        self.objects = {**domain.constants, **problem.objects}
        self.typed = any(t != "object" for t in self.objects.values())
        self.true_args = _true_args(problem)
        self.moved = set().union(*(_moved_types(d) for d in (domain, *models)))
        self._on_the_way: dict[frozenset[str], bool] = {}  # by pair: each of its two predicates asks
        self.places = _place_types(domain, static, models, self.true_args)

    def holders(self, name: str) -> set[str]:
        return {args[0] for args in self.true_args.get(name, [])}

    def kind(self, name: str, param_type: str) -> str | None:
        """Why a one-argument static predicate names a kind of thing (None: it names a state)."""
        holders = self.holders(name)
        unary = [p for p in self.static if p != name and len(self.domain.predicates[p].params) == 1]
        if not self.typed:
            # The types are predicates here; one object singled out within a kind ((at-robby rooma) among the
            # rooms) marks where something is, which a person can change.
            if len(holders) == 1 and any(holders < self.holders(p) for p in unary):
                return None
            return f"a kind: true of {len(holders)} object(s) in a domain whose types are predicates"
        below = self.domain.subtypes().get(param_type, {param_type})
        eligible = {o: t for o, t in self.objects.items() if t in below}
        kinds = {eligible[o] for o in holders if o in eligible}
        if not any((o in holders) != (t in kinds) for o, t in eligible.items()):
            return f"a kind: true of every {', '.join(sorted(kinds))}"
        # True of some objects of a type: a state ((clear d1), one drawer blocked), unless another static
        # predicate is true of exactly the others ((is-goal p) beside (is-nongoal p)): the two classify them.
        rest = set(eligible) - holders
        partner = next((p for p in sorted(unary) if self.holders(p) & set(eligible) == rest), None)
        # A pair over things that are no places (doors, lamps) is state where a skill that changes it seems
        # missing; one that classifies places (sokoban's goal squares) says what the places are.
        if partner is None or (param_type not in self.places and self.on_the_way(name, partner)):
            return None
        return f"a kind: classifies {param_type} objects with {partner}"

    def on_the_way(self, *pair: str) -> bool:
        """Whether a skill that changes ``pair`` seems missing: the delete-relaxed robot does not reach the goal
        with the pair as it is, and does with every atom of the pair made true (a door the robot cannot open,
        ``door-open`` beside ``door-closed``)."""
        key = frozenset(pair)
        if key not in self._on_the_way:
            self._on_the_way[key] = self._freeing_reaches_the_goal(key)
        return self._on_the_way[key]

    def _freeing_reaches_the_goal(self, pair: frozenset[str]) -> bool:
        task = self.ground_task(pair)
        if task is None or _relaxed_reaches(task.actions, task.init, task.goal_pos):
            return False
        freed = task.init
        for i, atom in enumerate(task.atoms):
            if atom.predicate in pair:
                freed |= 1 << i
        return _relaxed_reaches(task.actions, freed, task.goal_pos)

    def ground_task(self, pair: frozenset[str]):
        """The task grounded with the other static predicates kept as they are (None: too large to ground)."""
        from guided_lfd.errors import TaskTooLarge
        from guided_lfd.planning.grounding import ground

        try:
            return ground(self.domain, self.problem, fixed=sorted(self.static - set(pair)))
        except TaskTooLarge:
            return None

    def relation(self, name: str, types: list[str]) -> str | None:
        """Why a static relation over arguments of ``types`` is the world's structure (None: it may place things
        a person can move)."""
        repeated = sorted({t for t in types if types.count(t) > 1})
        if repeated:
            over = "objects" if not self.typed and repeated == ["object"] else f"{repeated[0]} objects"
            return f"a fixed graph over {over}"
        if self.typed and not self.moved & set(types):
            return f"a fixed relation of {', '.join(types)} objects, which no action moves"
        firsts = [args[0] for args in self.true_args[name]]
        if len(firsts) != len(set(firsts)):
            return f"a fixed relation: some {types[0]} related to several {types[1]} objects (a map or a capability)"
        if self.typed and not self.places & set(types[1:]):
            return f"a fixed attribute: each {types[0]} has one {types[1]}, which is no place things move to"
        return None


def _relaxed_reaches(actions, state: int, goal: int) -> bool:
    """Whether ``actions``, deletes and negative preconditions ignored, reach the ``goal`` atoms from ``state``."""
    from guided_lfd.planning.search import relaxed_reach

    return goal & ~relaxed_reach(actions, state)[0] == 0


def placing_predicates(source: Domain, problem: Problem) -> dict[str, str]:
    """The static predicates of ``source`` that place things, each with why.

    * Two arguments: every object they say anything of is in exactly one place in ``problem``'s initial state
      (``(at bot hall)``), and no place is itself placed (a relation whose objects are also its places,
      ``(connected hall office)``, is a graph).
    * One argument, in a domain whose types are predicates: true of exactly one object, a place (where a changing
      relation puts things: ``(at-robby rooma)`` beside ``(at ball1 rooma)``): it says where the robot is.

    No action of ``source`` moves those objects (its skill to is missing), so no invariant synthesis keeps them in
    one place; under the consistent semantics the excuse keeps each in at most one all the same."""
    static = _static(source)
    found = _true_args(problem)
    objects = {**source.constants, **problem.objects}
    untyped = all(t == "object" for t in objects.values())
    places = {args[1] for name in source.fluent_predicates() for args in found.get(name, []) if len(args) == 2}
    out = {}
    for name in sorted(static & set(found)):
        arity, args = len(source.predicates[name].params), found[name]
        if arity not in (1, 2):
            continue
        things = [a[0] for a in args]
        if arity == 2 and len(set(things)) == len(things) and not set(things) & {a[1] for a in args}:
            out[name] = f"places things: each of {len(things)} object(s) in one place, and no action moves them"
        elif arity == 1 and untyped and len(things) == 1 and things[0] in places:
            out[name] = f"marks where something is: true of one place ({things[0]}), and no action moves it"
    return out


def _place_types(domain: Domain, static: set[str], models: Sequence[Domain],
                 true_args: dict[str, list[tuple[str, ...]]]) -> set[str]:
    """The types of places, with their subtypes: nodes of a static graph (a type repeated in a static relation:
    rooms, waypoints), and where a changing relation of two arguments puts each thing it names once initially
    (the rooms of ``(lies ?i ?room)``; not the rovers of ``(calibrated ?c ?r)``, true of nothing yet)."""
    subtypes = domain.subtypes()
    places: set[str] = set()
    for name, predicate in domain.predicates.items():
        types = [t for _, t in predicate.params]
        if name in static and len(types) >= 2:
            places |= {t for t in types if types.count(t) > 1}
    for model in (domain, *models):
        for name in model.fluent_predicates():
            if name not in model.predicates or len(model.predicates[name].params) != 2:
                continue
            firsts = [args[0] for args in true_args.get(name, []) if len(args) == 2]
            if firsts and len(firsts) == len(set(firsts)):
                places.add(model.predicates[name].params[1][1])
    return set().union(*(subtypes.get(t, {t}) for t in places)) if places else set()


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
