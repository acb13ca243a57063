"""The consistent semantics' laws of the world, derived by the independent checker.

The excuse engine's invariant groups (:mod:`guided_lfd.excuse.invariants`) are
not trusted here: the checker asks Fast Downward's invariant synthesis again,
from the lifted domain with each action's reverse and without any of the
problem's objects, and decides with code of its own which invariants bind the
excuse state:

* a lifted invariant is instantiated on the atoms that are true (no grounding);
* a group with two or more true atoms in the initial state constrains nothing;
* "exactly one" needs one true atom initially and a lifted proof that every
  action of the source domain keeps the group's count (each add of a group atom
  paired with the required delete of one under the same key, in every way the
  action's variables can coincide; a conditional effect on the group, or an
  action with too many variables, means no proof: the check then only asks for
  "at most one" there);
* an invariant the task's goal breaks is no law of the world and is dropped.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, replace

from guided_lfd.pddl.model import EQUALITY, ActionSchema, Atom, Domain, Literal, Predicate, Problem, objects_by_type
from guided_lfd.pddl.translator import find_invariants, parse_text, quiet
from guided_lfd.pddl.writer import domain_to_pddl

__all__ = ["WorldLaw", "WorldLaws", "derive_laws"]

#: FD marks the counted (omitted) argument of an invariant part with -1.
_COUNTED = -1
_GOAL_PREDICATE = "guided-lfd-check-goal"


@dataclass(frozen=True)
class WorldLaw:
    """One lifted invariant: ``parts`` are (predicate, argument roles), a role being the invariant's parameter
    number or -1 for the counted argument; ``exactly_one`` when every action provably keeps a group's count."""

    parts: tuple[tuple[str, tuple[int, ...]], ...]
    exactly_one: bool

    def __str__(self) -> str:
        shown = []
        for predicate, roles in self.parts:
            args = ["*" if r == _COUNTED else f"?v{r}" for r in roles]
            shown.append("(" + " ".join([predicate, *args]) + ")")
        return "{" + ", ".join(shown) + "}"

    def key(self, atom: Atom) -> tuple[str, ...] | None:
        """The group ``atom`` belongs to (its arguments in the invariant's parameters), None if in none."""
        for predicate, roles in self.parts:
            if atom.predicate == predicate and len(atom.args) == len(roles):
                return tuple(atom.args[roles.index(k)] for k in range(len(roles) - (_COUNTED in roles)))
        return None

    def groups(self, atoms: Iterable[Atom]) -> dict[tuple[str, ...], int]:
        """How many of ``atoms`` each group holds (groups without any left out)."""
        counts: dict[tuple[str, ...], int] = {}
        for atom in atoms:
            key = self.key(atom)
            if key is not None:
                counts[key] = counts.get(key, 0) + 1
        return counts

    def members(self, key: tuple[str, ...], objects: dict[str, list[str]], domain: Domain) -> list[Atom]:
        """Every type-correct atom of the group ``key``."""
        out = []
        for predicate, roles in self.parts:
            params = domain.predicates[predicate].params
            fill = [objects.get(t, []) for _, t in params]
            for pos, role in enumerate(roles):
                if role != _COUNTED:
                    fill[pos] = [key[role]]
            out += _product_atoms(predicate, fill)
        return out


def _product_atoms(predicate: str, fill: list[list[str]]) -> list[Atom]:
    rows: list[tuple[str, ...]] = [()]
    for choices in fill:
        rows = [row + (c,) for row in rows for c in choices]
    return [Atom(predicate, row) for row in rows]


@dataclass(frozen=True)
class WorldLaws:
    """The laws an excuse state must keep (consistent semantics), with the initial state's group counts."""

    laws: tuple[WorldLaw, ...]
    init_counts: tuple[dict[tuple[str, ...], int], ...]
    #: Invariants the goal breaks, left out.
    dropped: tuple[str, ...] = ()

    def broken(self, state: frozenset[Atom]) -> list[str]:
        """Each law ``state`` breaks, with the group and its number of true atoms."""
        problems = []
        for law, before in zip(self.laws, self.init_counts):
            after = law.groups(state)
            for key in sorted(set(after) | set(before)):
                if before.get(key, 0) > 1:
                    continue  # the initial state itself does not keep this group
                count = after.get(key, 0)
                if count > 1 or (law.exactly_one and before.get(key) == 1 and count == 0):
                    problems.append(f"{law} over {' '.join(key) or '()'} ({count} true)")
        return problems


def derive_laws(source: Domain, problem: Problem, max_time: float = 300.0, one_place: bool = True) -> WorldLaws:
    """The laws from ``source`` (the robot's domain, or ``--invariants-from``) for ``problem``; with ``one_place``,
    also "in at most one place" for each static two-argument relation of ``source`` that holds of each object it
    names exactly once in the initial state (nothing in ``source`` moves those objects)."""
    kept: list[WorldLaw] = []
    counts: list[dict[tuple[str, ...], int]] = []
    dropped: list[str] = []
    objects = objects_by_type(source, problem)
    placing = [(part,) for part in _placing(source, problem)] if one_place else []
    for parts in [*_synthesised(source, max_time), *placing]:
        law = WorldLaw(parts, False)
        if parts not in placing:  # "one place" asks for at most one: an excuse may take the thing away
            law = replace(law, exactly_one=all(_keeps_count(action, law) for action in source.actions))
        before = law.groups(problem.init)
        if _goal_breaks(law, before, problem, objects, source):
            dropped.append(str(law))
            continue
        kept.append(law)
        counts.append(before)
    return WorldLaws(tuple(kept), tuple(counts), tuple(dropped))


def _placing(source: Domain, problem: Problem) -> list[tuple[str, tuple[int, ...]]]:
    """The static predicates that place things, as (predicate, argument roles) of an "at most one" law: relations
    of two arguments true of each object they name first exactly once initially, none of those objects also
    named second (that would be a graph over them); and, where all objects are untyped, a one-argument
    predicate true of exactly one object that a changing relation names second (where the robot is)."""
    changed = {a.predicate for action in source.actions for a in (*action.add, *action.delete)}
    changed |= {e.literal.atom.predicate for action in source.actions for e in action.effects}
    changed |= set(source.derived_predicates())
    args_of: dict[str, list[tuple[str, ...]]] = {}
    for atom in problem.init:
        args_of.setdefault(atom.predicate, []).append(atom.args)
    untyped = all(t == "object" for t in (*problem.objects.values(), *source.constants.values()))
    places = {args[1] for name in changed for args in args_of.get(name, []) if len(args) == 2}
    out: list[tuple[str, tuple[int, ...]]] = []
    for name, rows in sorted(args_of.items()):
        if name in changed or name == EQUALITY or name not in source.predicates:
            continue
        width = len(source.predicates[name].params)
        firsts = [row[0] for row in rows if row]
        if width == 2 and len(firsts) == len(set(firsts)) and not {row[1] for row in rows} & set(firsts):
            out.append((name, (0, _COUNTED)))
        elif width == 1 and untyped and len(rows) == 1 and rows[0][0] in places:
            out.append((name, (_COUNTED,)))
    return out


def _goal_breaks(law: WorldLaw, before: dict, problem: Problem, objects: dict[str, list[str]], domain: Domain) -> bool:
    """Whether no goal state keeps some group the initial state keeps (see the engine's rule it re-derives)."""
    goal = _goal_literals(problem)
    wanted = law.groups(lit.atom for lit in goal if lit.positive)
    if any(n > 1 and before.get(key, 0) <= 1 for key, n in wanted.items()):
        return True
    if not law.exactly_one:
        return False
    unwanted = {lit.atom for lit in goal if not lit.positive}
    return any(n == 1 and all(a in unwanted for a in law.members(key, objects, domain))
               for key, n in before.items())


def _goal_literals(problem: Problem) -> list[Literal]:
    """The goal's literals: an ADL goal's top-level conjunction of literals (a deeper formula: none, which
    keeps more laws, as the engine does for a goal it compiles into an axiom)."""
    if problem.goal_condition is None:
        return list(problem.goal)
    from guided_lfd.pddl.formula import Junction

    goal = problem.goal_condition
    parts = goal.parts if isinstance(goal, Junction) and goal.kind == "and" else (goal,)
    return [p for p in parts if isinstance(p, Literal)]


def _keeps_count(action: ActionSchema, law: WorldLaw) -> bool:
    """A lifted proof that ``action`` keeps every group's count of ``law`` (False: no proof).

    Each way the action's variables can coincide (with each other or with a constant) is one case, decided as
    a ground action would be: what it adds that it did not require, against what it deletes and does not re-add,
    counted per group.  Types are ignored, so an impossible case can only deny the proof.
    """
    touches = {p for p, _ in law.parts}
    if action.is_adl:
        return not any(e.literal.atom.predicate in touches for e in action.effects) and not any(
            a.predicate in touches for a in (*action.add, *action.delete))
    if not any(a.predicate in touches for a in (*action.add, *action.delete)):
        return True
    variables = [v for v, _ in action.params]
    constants = sorted({t for lit in action.precondition for t in lit.atom.args if not t.startswith("?")}
                       | {t for a in (*action.add, *action.delete) for t in a.args if not t.startswith("?")})
    if len(variables) + len(constants) > _MAX_PROOF_TERMS:
        return False
    return all(_case_keeps_count(action, law, same) for same in _coincidences(variables, constants))


#: More terms than this in one action: too many cases, no proof (the check asks for "at most one" only).
_MAX_PROOF_TERMS = 9


def _coincidences(variables: list[str], constants: list[str]) -> Iterable[dict[str, str]]:
    """Every way to map ``variables`` to a representative: a constant or the first variable of its class."""
    def extend(i: int, chosen: dict[str, str], reps: list[str]) -> Iterable[dict[str, str]]:
        if i == len(variables):
            yield dict(chosen)
            return
        var = variables[i]
        for rep in [*constants, *reps, var]:
            chosen[var] = rep
            yield from extend(i + 1, chosen, reps + [var] if rep == var else reps)
        del chosen[var]

    yield from extend(0, {}, [])


def _case_keeps_count(action: ActionSchema, law: WorldLaw, same: dict[str, str]) -> bool:
    """Whether ``action`` keeps the count of every group of ``law`` when its variables coincide as ``same``."""
    def term(t: str) -> str:
        return same.get(t, t)

    def atom(a: Atom) -> Atom:
        return Atom(a.predicate, tuple(term(t) for t in a.args))

    for lit in action.precondition:
        if lit.atom.predicate == EQUALITY:
            left, right = (term(t) for t in lit.atom.args)
            if (left == right) != lit.positive:
                return True  # this case cannot happen
    required = {atom(l.atom) for l in action.precondition if l.positive and l.atom.predicate != EQUALITY}
    adds = {atom(a) for a in action.add}
    deletes = {atom(d) for d in action.delete}
    added = [a for a in adds if law.key(a) is not None and a not in required]
    removed = [d for d in deletes if law.key(d) is not None and d not in adds]
    if any(d not in required for d in removed):
        return False  # it may delete a group atom that was false: the count may stay or drop
    balance: dict[tuple[str, ...], int] = {}
    for changed, step in [(a, 1) for a in added] + [(d, -1) for d in removed]:
        key = law.key(changed)
        balance[key] = balance.get(key, 0) + step
    return not any(balance.values())


def _synthesised(source: Domain, max_time: float) -> list[tuple[tuple[str, tuple[int, ...]], ...]]:
    """Fast Downward's lifted invariants of ``source`` with each action's reverse, as plain parts."""
    actions = list(source.actions)
    names = {a.name for a in actions}
    for number, action in enumerate(source.actions):
        actions.append(replace(action.reversed(), name=_fresh(f"undo{number}-{action.name}", names)))
    constants = {**{c: "object" for c in source.implicit_constants}, **source.constants}
    goal = Predicate(_GOAL_PREDICATE)
    written = domain_to_pddl(replace(source, actions=actions, constants=constants, implicit_constants=(),
                                     predicates={**source.predicates, goal.name: goal}))
    task_text = f"(define (problem check) (:domain {source.name}) (:init) (:goal ({_GOAL_PREDICATE})))"
    try:
        with quiet():
            found = find_invariants(parse_text(written, task_text), max(1, int(max_time)))
    except (Exception, SystemExit) as exc:  # the engine synthesised from the same domain: a bug if it fails here
        raise RuntimeError(f"the checker cannot synthesise invariants of '{source.name}': {exc}") from None
    return sorted(tuple(sorted((part.predicate, tuple(part.args)) for part in inv.parts)) for inv in found)


def _fresh(name: str, taken: set[str]) -> str:
    while name in taken:
        name += "-"
    taken.add(name)
    return name
