"""The learner core: what observed steps teach about an action's preconditions and effects.

Both kinds of demonstration come down to steps: a state, an action applied to
some objects, the state after it.  A VR segment's objects are those the hand
handles (:mod:`guided_lfd.demonstration.learn`); a trajectory's are the
operator's arguments (:mod:`guided_lfd.demonstration.trajectory`).  Two rules
are shared:

* **Effects** are the atoms that change over a step and are *bound* by the
  action: every argument one of its objects (atoms without arguments
  included).  A segment also counts atoms that share one object with what the
  hand handles, their other objects becoming parameters.
* **Preconditions** are the facts about the action's objects true before it
  (:func:`facts_about`), generalised over every observation of the action.
  A learned action is never more general than shown: every static relation
  (a fact no step changes) among two or more of its objects that held in all
  its observations stays a precondition, the other objects it needs
  becoming parameters (:func:`static_relations`: opening a door from a room
  keeps ``(connects ?d ?from ?to)``, the door's other room a parameter).  A
  trajectory's operator has these among its parameters already (its
  signature), so lifting keeps them; a segment's objects are only those the
  hand handles, so :mod:`guided_lfd.demonstration.learn` adds them.

For operators with known signatures (trajectories), :func:`learn_operators`
learns lifted actions as SAM does (Juba, Le and Stern, KR 2021): a lifted
literal is a precondition when it held before every observed step, an effect
when it changed in some step and held after every one.  Two models:

* ``safe`` (default): every plan the learned model finds is valid in the
  true domain (SAM's guarantee) for actions on distinct objects (none of
  them a constant), provided that the true domain has negative
  preconditions only where the prior declares ``:negative-preconditions``
  and that the problem's initial state is like the observed ones: it
  satisfies the invariants the learner proves (Fast Downward's, forward
  only, each checked on every observed state) and its static facts follow
  every trajectory's pattern (:mod:`guided_lfd.demonstration.static_facts`).
  Atoms about the prior's constants are learned as such.  What the steps
  cannot rule out stays a condition: an atom false before every step is a
  negative precondition (``:negative-preconditions`` is added to the
  requirements where one remains), so the action never runs where it might
  need that atom false or delete it unseen (a laser that clears rock may
  also destroy gold no step showed beside it).  It is dropped where a
  proven invariant rules the atom out beside a positive precondition
  (:mod:`guided_lfd.demonstration.mutex`; on distinct objects, a mover is
  at one place, so not at the other), or where it is a static fact no
  observed world has beside the action's static preconditions (no cell is
  above itself).  A step that passes one object twice, or a constant, may
  not tell which parameter a change is about; it is learned from only where
  the other steps tell (of the ways the change lifts, one alone fits every
  step: TPP's ``load`` moves goods up a level while the market's stock goes
  down, in steps where the levels coincide one way or another), else left
  out as SAM leaves it, with a note.  A delete that fits more than one way
  keeps them all where no negative precondition is declared, the ways a
  proven mutex rules out dropped (:func:`mutex.drop_idle_deletes`).  The
  guarantee is for actions applied to distinct objects.
* ``general``: what the steps show: preconditions that held before every
  step, effects seen to change.  The one guard it keeps is for actions seen
  clearing whatever is there: when a delete was seen where its fact was not
  true before every step (a laser clears soft rock in one step, hard rock in
  another), the facts about the same objects false before every step are
  guarded (the gold no step showed the laser hit).  No guarantee: a plan may
  still rely on an effect no step showed.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from functools import cache
from itertools import product

from guided_lfd.demonstration.static_facts import drop_ruled_out_static_guards
from guided_lfd.pddl.model import ActionSchema, Atom, Domain, Evidence, Literal

__all__ = ["Observation", "MODELS", "bound_by", "facts_about", "static_relations", "changes", "learn_operators"]

#: The models :func:`learn_operators` can learn, with what each guarantees.
MODELS: dict[str, str] = {
    "safe": "every plan it finds is valid in the true domain, for actions on distinct objects (SAM's guarantee)",
    "general": "what the steps show, guarded only where an action clears whatever is there; a plan may rely on an "
               "effect no step showed",
}


@dataclass(frozen=True)
class Observation:
    """One observed step: ``operator`` applied to ``objects`` took ``before`` to ``after``."""

    operator: str
    objects: tuple[str, ...]
    before: frozenset[Atom]
    after: frozenset[Atom]
    where: str = ""


def bound_by(atom: Atom, objects: set[str] | frozenset[str], any_argument: bool = False) -> bool:
    """Whether every argument of ``atom`` is one of ``objects`` (with ``any_argument``: at least one is);
    an atom without arguments is bound by every action."""
    if not atom.args:
        return True
    return any(a in objects for a in atom.args) if any_argument else all(a in objects for a in atom.args)


def facts_about(state: Iterable[Atom], objects: set[str] | frozenset[str]) -> set[Atom]:
    """The atoms of ``state`` all of whose arguments are ``objects`` (atoms without arguments included)."""
    return {a for a in state if bound_by(a, objects)}


def static_relations(state: Iterable[Atom], objects: set[str] | frozenset[str], static: set[str]) -> set[Atom]:
    """The atoms of ``state`` over ``static`` predicates that relate two or more of ``objects`` and need others
    too (``(connects door hall kitchen)`` for the door and the hall): what a learned action keeps beside its
    facts about ``objects``, the other objects becoming its parameters (see the module).  A relation of one
    of ``objects`` alone (the cupboard's other, closed door) says nothing of what the action needs."""
    return {a for a in state if a.predicate in static and len(set(a.args) & objects) >= 2
            and not set(a.args) <= objects}


def changes(before: frozenset[Atom] | set[Atom], after: frozenset[Atom] | set[Atom],
            objects: set[str] | frozenset[str], any_argument: bool = False) -> tuple[set[Atom], set[Atom]]:
    """(made true, made false) over a step: the changed atoms bound by ``objects`` (see :func:`bound_by`)."""
    return ({a for a in after - before if bound_by(a, objects, any_argument)},
            {a for a in before - after if bound_by(a, objects, any_argument)})


class _Lifting:
    """Ground atoms of one step <-> lifted atoms over an operator's parameters and the domain's constants
    (an object passed twice, or a constant passed as an argument, lifts more than one way)."""

    def __init__(self, params: tuple[tuple[str, str], ...], objects: tuple[str, ...],
                 constants: frozenset[str] = frozenset()) -> None:
        self.binding = {var: obj for (var, _), obj in zip(params, objects)}
        self.vars_of: dict[str, list[str]] = {c: [c] for c in constants}
        for (var, _), obj in zip(params, objects):
            self.vars_of.setdefault(obj, []).append(var)
        self.objects = frozenset(objects) | constants

    def lifted(self, atoms: Iterable[Atom]) -> set[Atom]:
        out: set[Atom] = set()
        for atom in atoms:
            if bound_by(atom, self.objects):
                for args in product(*(self.vars_of[a] for a in atom.args)):
                    out.add(Atom(atom.predicate, args))
        return out

    def ground(self, atom: Atom) -> Atom:
        return atom.substitute(self.binding)


#: Lifted atoms an operator's guards may range over, at most (the count grows as parameters ** arity).
MAX_CANDIDATES = 200_000


def _candidates(schema: ActionSchema, domain: Domain) -> list[Atom]:
    """Every well-typed lifted atom over ``schema``'s parameters and the domain's constants (each term's type
    within the predicate's); TaskTooLarge past :data:`MAX_CANDIDATES`."""
    from guided_lfd.errors import TaskTooLarge

    sub = domain.subtypes()
    terms = [*schema.params, *domain.constants.items()]
    count = 0
    options_of = {}
    for pred in domain.predicates.values():
        options = [[v for v, t in terms if t in sub.get(pt, {pt})] for _, pt in pred.params]
        n = 1
        for o in options:
            n *= len(o)
        count += n
        options_of[pred.name] = options
    if count > MAX_CANDIDATES:
        raise TaskTooLarge(f"operator {schema.name}: {count:,} lifted atoms over its parameters to learn about "
                           f"(at most {MAX_CANDIDATES:,}); expected fewer parameters or lower arities",
                           domain.locate(schema.name))
    return [Atom(name, args) for name, options in options_of.items() for args in product(*options)]


@dataclass
class _Evidence:
    """What the observations of one operator show, lifted over its ``schema``'s parameters and ``constants``
    (``candidates``: every well-typed lifted atom, see :func:`_candidates`)."""

    schema: ActionSchema
    candidates: list[Atom]
    constants: frozenset[str] = frozenset()
    seen: int = 0
    before_always: set[Atom] = field(default_factory=set)  # true before every step
    never_before: set[Atom] = field(default_factory=set)   # false before every step (of the candidates)
    after_always: set[Atom] = field(default_factory=set)
    made_true: set[Atom] = field(default_factory=set)      # changed in some step, lifted one way only
    made_false: set[Atom] = field(default_factory=set)
    # Changes an object passed twice lets lift more than one way, resolved by the steps that do not.
    ambiguous_true: list[frozenset[Atom]] = field(default_factory=list)
    ambiguous_false: list[frozenset[Atom]] = field(default_factory=list)
    steps: list[tuple[_Lifting, Observation]] = field(default_factory=list)
    held: Counter[Atom] = field(default_factory=Counter)   # in how many steps each lifted atom held before

    def __post_init__(self) -> None:
        # Only well-typed atoms: a shaker's fact is no fact of every container passed where a shaker was.
        self.typed = frozenset(self.candidates)

    def add(self, obs: Observation) -> None:
        """Take one observed step of the operator into account."""
        lift = _Lifting(self.schema.params, obs.objects, self.constants)
        typed = self.typed
        before, after = lift.lifted(obs.before) & typed, lift.lifted(obs.after) & typed
        added, deleted = changes(obs.before, obs.after, lift.objects)
        false_before = {c for c in self.candidates if lift.ground(c) not in obs.before}
        self.held.update(before)
        if self.seen == 0:
            self.before_always, self.after_always, self.never_before = before, after, false_before
        else:
            self.before_always &= before
            self.after_always &= after
            self.never_before &= false_before
        for atoms, sure, unsure in ((added, self.made_true, self.ambiguous_true),
                                    (deleted, self.made_false, self.ambiguous_false)):
            for atom in atoms:
                ways = lift.lifted([atom]) & typed
                if len(ways) == 1:
                    sure |= ways
                elif ways:
                    unsure.append(frozenset(ways))
        self.steps.append((lift, obs))
        self.seen += 1

    def changed(self, made: set[Atom], unsure: list[frozenset[Atom]]) -> set[Atom]:
        """Lifted atoms some step changed: those lifted one way, and every way of an ambiguous change no step
        resolves."""
        return made.union(*(ways for ways in unsure if not ways & made))

    def adds(self) -> set[Atom]:
        """Made true in some step, true after every one (a change only ever lifted two ways: both ways; the
        safe model takes no such step)."""
        return self.changed(self.made_true, self.ambiguous_true) & self.after_always

    def deletes(self, among: set[Atom]) -> set[Atom]:
        """Those of ``among`` false after every step, except a step where the atom lifts more than one way:
        there another of its ways may be an add that made it true again (PDDL applies deletes first: moving
        from a place to itself leaves the mover there)."""
        return {atom for atom in among if _fits(atom, self.steps, added=False)}


def _fits(way: Atom, steps: list[tuple[_Lifting, Observation]], added: bool) -> bool:
    """Whether every step allows lifted atom ``way`` as an effect: an add true after every step, a delete false
    after every step but where its ground atom lifts more than one way (an add may have made it true again)."""
    if added:
        return all(lift.ground(way) in obs.after for lift, obs in steps)
    return all((g := lift.ground(way)) not in obs.after or len(lift.lifted([g])) > 1 for lift, obs in steps)


def _admit(ev: _Evidence, steps: list[Observation], negative: bool) -> int:
    """Add to ``ev`` those of ``steps`` (each passing one object twice, or a constant) whose every change the
    steps tell apart: of the ways an added atom lifts, exactly one is allowed by every step taken (see
    :func:`_fits`); the true effect is among the allowed ways, so a single one is it.  A deleted
    atom may lift to several allowed ways where no negative precondition is declared (``negative`` false):
    every allowed way is learned as a delete, since a model that believes less than is true still finds only
    plans the true domain runs (the true action then needs only positive facts).  Steps that leave a change
    ambiguous are left out and the rest checked again (fewer steps allow more ways), until none is left out.
    Returns how many were left out.

    Preconditions gain nothing unsafe from such a step: a true precondition holds before it under one of
    its ways, so the intersection over steps keeps it; a guard stays where the step could hide a delete
    (see :func:`_unguarded_by`).
    """
    taken = [(_Lifting(ev.schema.params, obs.objects, ev.constants), obs) for obs in steps]
    resolved: list[tuple[_Lifting, Observation, set[Atom], set[Atom]]] = []
    while taken:
        every = ev.steps + taken
        fit = cache(lambda way, added: _fits(way, every, added))  # a way's verdict depends on the steps only

        def allowed(lifted: set[Atom], added: bool) -> set[Atom]:
            return {w for w in lifted & ev.typed if fit(w, added)}

        resolved = []
        for lift, obs in taken:
            added, deleted = changes(obs.before, obs.after, lift.objects)
            ways = [(allowed(lift.lifted([a]), True), True) for a in added]
            ways += [(allowed(lift.lifted([a]), False), False) for a in deleted]
            if all(len(w) == 1 or (w and not up and not negative) for w, up in ways):
                resolved.append((lift, obs, set().union(*(w for w, up in ways if up)),
                                 set().union(*(w for w, up in ways if not up))))
        if len(resolved) == len(taken):
            break
        kept = {id(obs) for _, obs, _, _ in resolved}
        taken = [(lift, obs) for lift, obs in taken if id(obs) in kept]
    guarded = set(ev.never_before) if ev.seen else set(ev.candidates)
    for _, obs, adds, deletes in resolved:
        ev.add(obs)
        ev.made_true |= adds
        ev.made_false |= deletes
    if resolved:
        ev.never_before = guarded.intersection(*(_unguarded_by(ev, lift, obs) for lift, obs, _, _ in resolved))
    return len(steps) - len(resolved)


def _unguarded_by(ev: _Evidence, lift: _Lifting, obs: Observation) -> set[Atom]:
    """The candidates step ``obs`` (lifted by ``lift``) leaves a guard on: those false before it, and those true
    before and after it whose atom lifts another way that may be an add (true after every step): the action may
    delete the atom under one way and add it again under the other, so the step does not show it needs no guard."""
    out = set()
    for c in ev.candidates:
        g = lift.ground(c)
        if g not in obs.before or (g in obs.after and any(w != c and w in ev.after_always
                                                          for w in lift.lifted([g]) & ev.typed)):
            out.add(c)
    return out


def _guards(ev: _Evidence, model: str, negative: bool, adds: set[Atom], delete: set[Atom]) -> list[Atom]:
    """The atoms a learned action must find false (negative preconditions), by ``model``."""
    if model == "safe":
        # What no step rules out: the action may need it false, or delete it (unseen: it was false already).
        # Facts no step changes too: a laser that clears rock may also destroy the gold no step showed it at.
        # An atom the action makes true needs no guard unless the true domain may require it false first.
        return [a for a in sorted(ev.never_before) if negative or a not in adds]
    # A delete seen where its fact was not always true marks an action that clears whatever is there (a laser
    # clears soft rock or hard rock): it may clear other facts about the same objects that no step showed there.
    clearing = {d.args for d in delete if d not in ev.before_always}
    return [a for a in sorted(ev.never_before) if a.args in clearing and a not in adds]


def _learned(schema: ActionSchema, ev: _Evidence, model: str, negative: bool) -> ActionSchema:
    adds = ev.adds()
    delete = ev.deletes(ev.changed(ev.made_false, ev.ambiguous_false) - adds)
    pre = [Literal(a) for a in sorted(ev.before_always)]
    pre += [Literal(a, False) for a in _guards(ev, model, negative, adds, delete)]
    # The shared evidence rule: a precondition held in every step (a guard's atom was false in every one);
    # atoms that held in some steps only were varied.
    varied = [Evidence(Literal(a), n, ev.seen) for a, n in sorted(ev.held.items()) if n < ev.seen]
    evidence = tuple(Evidence(l, ev.seen, ev.seen) for l in pre) + tuple(varied)
    return replace(schema, precondition=tuple(pre), add=tuple(sorted(adds)), delete=tuple(sorted(delete)),
                   origin=f"learned from {ev.seen} observed step(s)", evidence=evidence)


def _unobserved(schema: ActionSchema, ev: _Evidence) -> ActionSchema:
    """An operator no step shows, as SAM writes it: every well-typed literal over its parameters a precondition,
    positive and negative, and no effect.  The most specific model there is: it never applies (an atom and its
    negation are both required), so no plan relies on effects nobody has seen, and a plan or problem that names
    the operator still reads."""
    atoms = sorted(ev.candidates)
    return replace(schema, precondition=tuple(Literal(a) for a in atoms) + tuple(Literal(a, False) for a in atoms),
                   add=(), delete=(), origin="never observed: every literal required, so it never applies",
                   evidence=())


def learn_operators(prior: Domain, observations: Iterable[Observation], objects: dict[str, str],
                    model: str = "safe", states: Iterable[frozenset[Atom]] = ()) -> tuple[Domain, list[str]]:
    """``prior`` with the actions that have empty bodies learned from ``observations`` (see the module).

    ``objects``: every observed object's type (for proving invariants); ``states``: every observed state
    (an invariant they break is not used).  Returns the domain and notes for the user (operators never
    observed, left out).  Actions of ``prior`` with a body are kept as they are.
    """
    states = list(states)
    observations = list(observations)
    if model not in MODELS:
        raise ValueError(f"unknown model {model!r}, expected one of {', '.join(MODELS)}")
    # An action whose only effect is its cost is to learn too (its cost is kept).
    to_learn = [a for a in prior.actions if not a.precondition and not a.add and not a.delete]
    constants = frozenset(prior.constants)
    evidence = {a.name: _Evidence(a, _candidates(a, prior), constants) for a in to_learn}
    held_back: dict[str, list[Observation]] = {name: [] for name in evidence}
    for obs in observations:
        if obs.operator not in evidence:
            continue
        if model == "safe" and (len(set(obs.objects)) < len(obs.objects) or constants & set(obs.objects)):
            # A step that passes one object twice may not tell which parameter an effect is about (SAM leaves
            # it out): the safe model takes it only where the other steps tell (see _admit).
            held_back[obs.operator].append(obs)
        else:
            evidence[obs.operator].add(obs)
    negative = any(r in prior.requirements for r in (":negative-preconditions", ":adl"))
    repeated = sum(_admit(evidence[name], steps, negative) for name, steps in held_back.items() if steps)
    notes = [f"{repeated} step(s) passing one object twice (or a constant) left out: the other steps do not tell "
             "which parameter a change in them is about (the safe model's guarantee is for actions on distinct "
             "objects)"] if repeated else []
    if not to_learn:
        notes.append(f"every action of {prior.path} has a body: nothing to learn (the prior is written as it is)")
    notes += [f"{a.name}: never observed (or only in steps left out): written with every literal as a precondition, "
              "so it never applies until a step shows what it needs and does" for a in to_learn if evidence[a.name].seen == 0]
    learned = {a.name: _learned(a, evidence[a.name], model, negative) if evidence[a.name].seen
               else _unobserved(a, evidence[a.name]) for a in to_learn}
    actions = [learned.get(a.name, a) for a in prior.actions if a.name in learned or a not in to_learn]
    domain = replace(prior, actions=actions, path="<learned>", source=None, warnings=())
    seen = {name for name in learned if evidence[name].seen}  # an operator never observed keeps every literal
    if _guarded(domain, seen) or (model == "safe" and _loose_deletes(domain, seen)):
        domain = _without_implied_negatives(domain, seen, objects, states)
        changed = (atom for obs in observations for atom in obs.before ^ obs.after)
        domain, assumed = drop_ruled_out_static_guards(domain, seen, states, changed)
        if assumed:
            notes.append(f"{len(assumed)} guard(s) on static facts left out: no trajectory's world has them beside "
                         "the action's static preconditions (the problems' static facts are assumed alike)")
    if _guarded(domain, learned):
        # The guards are negative preconditions, as SAM writes them, whatever the prior declares.
        domain = replace(domain, requirements=tuple(dict.fromkeys([*domain.requirements,
                                                                   ":negative-preconditions"])))
    return domain, notes


def _guarded(domain: Domain, names: Iterable[str]) -> bool:
    """Whether an action of ``names`` in ``domain`` has a negative precondition."""
    return any(not l.positive for a in domain.actions if a.name in names for l in a.precondition)


def _loose_deletes(domain: Domain, names: Iterable[str]) -> bool:
    """Whether an action of ``names`` in ``domain`` deletes an atom it does not require."""
    return any(d not in {l.atom for l in a.precondition if l.positive}
               for a in domain.actions if a.name in names for d in a.delete)


def _without_implied_negatives(domain: Domain, names: set[str], objects: dict[str, str],
                               states: Iterable[frozenset[Atom]]) -> Domain:
    """Negative preconditions a positive one implies through a proven mutex, and deletes of atoms it rules out,
    dropped (see :mod:`guided_lfd.demonstration.mutex`)."""
    from guided_lfd.demonstration.mutex import (drop_idle_deletes, drop_implied_negative_preconditions,
                                                pair_invariants, proven_invariants)

    states = list(states)
    reqs = tuple(dict.fromkeys([*domain.requirements, ":negative-preconditions"]))
    invariants = proven_invariants(replace(domain, requirements=reqs), objects, states, reverse=False)
    invariants += pair_invariants(domain, states)
    domain = drop_idle_deletes(domain, names, invariants)
    return drop_implied_negative_preconditions(domain, names, invariants, distinct=True)
