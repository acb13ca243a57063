"""The safe model's guarantee, checked on random STRIPS domains (issue #31).

A random domain (actions that may delete atoms they do not require; walks that pass one object twice) makes
random walks; the safe model learned from them is then walked at random from the same initial states (and
from fresh ones with a training state's static facts that satisfy the invariants the learner proved), with
actions on distinct objects (the guarantee's scope, as SAM's), and every step it takes must run in the true
domain, with every atom the learned model believes true there too (so every plan it finds is valid).
"""

from __future__ import annotations

import os
import random
from itertools import product

from hypothesis import given, settings
from hypothesis import strategies as st

from guided_lfd.demonstration.action_model import Observation, learn_operators
from guided_lfd.pddl.model import ActionSchema, Atom, Domain, Literal, Predicate

OBJECTS = ("a", "b", "c")
PREDICATES = {"p": 0, "q": 1, "r": 1, "s": 2}
EXAMPLES = int(os.environ.get("GUIDED_LFD_FUZZ_EXAMPLES", "60"))


def _atoms(params: tuple[str, ...], rng: random.Random, k: int) -> list[Atom]:
    out = []
    for _ in range(k):
        name = rng.choice(sorted(PREDICATES))
        out.append(Atom(name, tuple(rng.choice(params) for _ in range(PREDICATES[name]))))
    return sorted(set(out))


def _domain(seed: int) -> Domain:
    rng = random.Random(seed)
    actions = []
    for i in range(3):
        params = tuple(f"?x{j}" for j in range(rng.randint(1, 2)))
        pre = _atoms(params, rng, rng.randint(0, 2))
        add = _atoms(params, rng, rng.randint(1, 2))
        delete = [a for a in _atoms(params, rng, rng.randint(0, 2)) if a not in add]
        actions.append(ActionSchema(f"act{i}", tuple((v, "object") for v in params),
                                    tuple(Literal(a) for a in pre), tuple(add), tuple(delete)))
    predicates = {n: Predicate(n, tuple((f"?v{i}", "object") for i in range(k))) for n, k in PREDICATES.items()}
    return Domain("random", (":strips", ":typing"), {"object": None}, {}, predicates, actions)


def _ground(action: ActionSchema, objects: tuple[str, ...]) -> tuple[set[Atom], set[Atom], set[Atom], bool]:
    binding = {v: o for (v, _), o in zip(action.params, objects)}
    pos = {l.atom.substitute(binding) for l in action.precondition if l.positive}
    neg = {l.atom.substitute(binding) for l in action.precondition if not l.positive}
    return pos, {a.substitute(binding) for a in action.add}, {a.substitute(binding) for a in action.delete}, bool(neg)


def _applicable(action: ActionSchema, objects: tuple[str, ...], state: frozenset[Atom]) -> bool:
    binding = {v: o for (v, _), o in zip(action.params, objects)}
    return all((l.atom.substitute(binding) in state) == l.positive for l in action.precondition)


def _apply(action: ActionSchema, objects: tuple[str, ...], state: frozenset[Atom]) -> frozenset[Atom]:
    _, add, delete, _ = _ground(action, objects)
    return frozenset((state - delete) | add)


def _moves(domain: Domain, state: frozenset[Atom], distinct: bool = False) -> list[tuple[ActionSchema, tuple[str, ...]]]:
    return [(a, objs) for a in domain.actions for objs in product(OBJECTS, repeat=len(a.params))
            if (not distinct or len(set(objs)) == len(objs)) and _applicable(a, objs, state)]


def _walk(domain: Domain, init: frozenset[Atom], rng: random.Random, length: int) -> list[Observation]:
    steps, state = [], init
    for _ in range(length):
        moves = _moves(domain, state)
        if not moves:
            break
        action, objs = rng.choice(moves)
        after = _apply(action, objs, state)
        steps.append(Observation(action.name, objs, state, after))
        state = after
    return steps


def _alike(learned: Domain, steps: list[Observation], states: list[frozenset[Atom]], inits: list[frozenset[Atom]],
           rng: random.Random) -> list[frozenset[Atom]]:
    """Fresh initial states within the guarantee's assumptions: a training state's static facts, other facts at
    random, where they satisfy every invariant the learner proved and checked on the observed states."""
    from guided_lfd.demonstration.mutex import _holds, pair_invariants, proven_invariants
    from guided_lfd.demonstration.static_facts import static_predicates

    static = static_predicates(learned, (a for s in steps for a in s.before ^ s.after))
    invariants = proven_invariants(learned, {o: "object" for o in OBJECTS}, states, reverse=False)
    invariants += pair_invariants(learned, states)
    fluents = [Atom(n, args) for n, k in PREDICATES.items() if n not in static for args in product(OBJECTS, repeat=k)]
    out = []
    for init in inits:
        for _ in range(3):
            fresh = frozenset({a for a in init if a.predicate in static} | {a for a in fluents if rng.random() < 0.4})
            if all(_holds(inv, fresh) for inv in invariants):
                out.append(fresh)
    return out


@settings(max_examples=EXAMPLES, deadline=None)
@given(st.integers(0, 10**6), st.booleans())
def test_every_walk_of_the_safe_model_runs_in_the_true_domain(seed, negative):
    """With a STRIPS prior (guards become deletes) and with ``:negative-preconditions`` (guards stay guards)."""
    rng = random.Random(seed)
    true = _domain(seed)
    all_atoms = [Atom(n, args) for n, k in PREDICATES.items() for args in product(OBJECTS, repeat=k)]
    inits = [frozenset(a for a in all_atoms if rng.random() < 0.4) for _ in range(3)]
    steps = [s for init in inits for s in _walk(true, init, rng, 8)]
    requirements = (*true.requirements, ":negative-preconditions") if negative else true.requirements
    prior = Domain(true.name, requirements, true.types, {}, true.predicates,
                   [ActionSchema(a.name, a.params, (), (), ()) for a in true.actions])
    states = list(inits) + [s.after for s in steps]
    learned, _ = learn_operators(prior, steps, {o: "object" for o in OBJECTS}, "safe", states)
    for init in [*inits, *_alike(learned, steps, states, inits, rng)]:
        believed, real = init, init
        for _ in range(10):
            moves = _moves(learned, believed, distinct=True)  # the guarantee is for distinct objects
            if not moves:
                break
            action, objs = rng.choice(moves)
            truth = true.action(action.name)
            assert _applicable(truth, objs, real), f"({action.name} {' '.join(objs)}) cannot run in the true domain"
            believed, real = _apply(action, objs, believed), _apply(truth, objs, real)
            assert believed <= real, f"believed true but false: {sorted(map(str, believed - real))}"
