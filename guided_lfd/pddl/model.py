"""The lifted planning model guided-lfd works on.

A deliberately small STRIPS model (typing, negative preconditions, equality,
constants, action costs): enough for the robot's skill library and everything the tool
derives from it (excuses, learned and merged domains).  All names are
lower-case, as PDDL is case-insensitive; ``spellings`` remembers how a name
was first written (``PinkDrawer``) for messages meant for people.

Beyond plain STRIPS the model keeps what valid PDDL allows and Fast
Downward reads: a predicate parameter of type ``(either a b)`` (the type
string as written, see :func:`type_members`), a type and an object of the
same name (separate dictionaries), and objects an action names without the
domain declaring them (:attr:`Domain.implicit_constants`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from guided_lfd.errors import Location
from guided_lfd.pddl.atoms import EQUALITY, Atom, Literal
from guided_lfd.pddl.formula import ConditionalEffect, DerivedRule, Formula

#: The PDDL requirements guided-lfd accepts: STRIPS with typing, negative preconditions, equality and
#: action costs, and the ADL ones (read with Fast Downward's translator, see :mod:`guided_lfd.pddl.formula`).
STRIPS_REQUIREMENTS = (":strips", ":typing", ":negative-preconditions", ":equality", ":action-costs")
ADL_REQUIREMENTS = (":adl", ":disjunctive-preconditions", ":existential-preconditions", ":universal-preconditions",
                    ":quantified-preconditions", ":conditional-effects", ":derived-predicates")
SUPPORTED_REQUIREMENTS = STRIPS_REQUIREMENTS + ADL_REQUIREMENTS

#: The one numeric fluent guided-lfd supports: the accumulated action cost of :action-costs.
TOTAL_COST = "total-cost"

#: What a name (domain, predicate, type) must look like to be written as PDDL.
PDDL_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_-]*")
#: Words PDDL readers take as keywords: no predicate or type may be called so.
PDDL_RESERVED = frozenset({
    "and", "or", "not", "imply", "exists", "forall", "when", "either", "define", "domain", "problem", "object",
    "number", "int", "float", "increase", "decrease", "assign", "scale-up", "scale-down", "preference", "minimize",
    "maximize", "sometime", "always", "within", "hold-during", "hold-after"})


#: How an ``either`` type is written in the model: ``(either person aircraft)``.
EITHER_PREFIX = "(either "


def either_type(members: list[str] | tuple[str, ...]) -> str:
    """The model's name of the type ``(either m1 m2 ...)`` (members lower-case, in written order)."""
    return EITHER_PREFIX + " ".join(m.lower() for m in members) + ")"


def type_members(t: str) -> tuple[str, ...]:
    """The member types of an ``either`` type, or ``(t,)`` for a plain type."""
    if t.startswith(EITHER_PREFIX) and t.endswith(")"):
        return tuple(t[len(EITHER_PREFIX):-1].split())
    return (t,)


def pddl_name_defect(name: str) -> str | None:
    """Why ``name`` cannot be written as a PDDL name (domain, predicate, type), else None."""
    if not PDDL_NAME.fullmatch(name):
        return "a PDDL name (an ASCII letter, then letters, digits, '-' or '_')"
    if name in PDDL_RESERVED:
        return "a name that is not a PDDL keyword"
    return None


@dataclass(frozen=True)
class Predicate:
    """A predicate declaration: name and typed parameters."""

    name: str
    params: tuple[tuple[str, str], ...] = ()

    @property
    def arity(self) -> int:
        return len(self.params)


@dataclass(frozen=True)
class Evidence:
    """What the demonstrations of a learned action showed about one of its conditions: ``literal`` held in
    ``shown`` of its ``demonstrations`` (segments, or a trajectory's steps).  ``varied``: some demonstration
    showed it false, so the action does not require it; a learned precondition held in every one.
    ``confirmed``: the teacher answered that the action cannot be done without it (a request to show it there
    was refused), so it is required for certain, never relaxed by a skill excuse."""

    literal: Literal
    shown: int
    demonstrations: int
    confirmed: bool = False

    @property
    def varied(self) -> bool:
        return self.shown < self.demonstrations

    @property
    def untested(self) -> bool:
        """Held in every demonstration and never refused without: whether the action needs it is not known."""
        return not self.varied and not self.confirmed

    def substitute(self, mapping: dict[str, str]) -> "Evidence":
        return Evidence(self.literal.substitute(mapping), self.shown, self.demonstrations, self.confirmed)

    def __str__(self) -> str:
        return f"{self.literal} {self.shown}/{self.demonstrations}{' confirmed' if self.confirmed else ''}"

    def to_json(self) -> dict[str, Any]:
        return {"literal": str(self.literal), "shown": self.shown, "demonstrations": self.demonstrations,
                "varied": self.varied, "confirmed": self.confirmed}


@dataclass(frozen=True)
class ActionSchema:
    """A lifted STRIPS action (a robot skill or a demonstrated one).

    ``precondition`` may contain equality literals (predicate ``=``).
    ``origin`` says where the action came from (a merge keeps it as a comment).
    ``cost`` is the action's ``(increase (total-cost) COST)`` under
    :action-costs: a number, or a numeric function applied to the action's
    parameters and constants (an :class:`Atom` over a function, its values in
    the problem's ``:init``); None when the action has no cost effect.

    ADL: ``condition`` is the whole precondition when it is more than a
    conjunction of literals (``precondition`` then holds its top-level
    literals, which every state it applies in satisfies); ``effects`` are the
    conditional and universally quantified effects (``add`` and ``delete``
    hold the plain ones).

    ``evidence``: for a learned action, what its demonstrations showed about each precondition and each
    condition they varied (see :class:`Evidence`; the writer prints it as comments); not compared.
    """

    name: str
    params: tuple[tuple[str, str], ...]
    precondition: tuple[Literal, ...]
    add: tuple[Atom, ...]
    delete: tuple[Atom, ...]
    origin: str | None = None
    cost: "int | Atom | None" = None
    condition: "Formula | None" = None
    effects: "tuple[ConditionalEffect, ...]" = ()
    evidence: tuple[Evidence, ...] = field(default=(), compare=False)

    @property
    def is_adl(self) -> bool:
        """Whether the action needs more than STRIPS (a formula precondition or conditional effects)."""
        return self.condition is not None or bool(self.effects)

    def learned_evidence(self) -> tuple[list[Evidence], list[Evidence]]:
        """(evidence of each precondition it has, in its order; of each condition its demonstrations varied)."""
        by_literal = {e.literal: e for e in self.evidence}
        return ([by_literal[l] for l in self.precondition if l in by_literal],
                [e for e in self.evidence if e.varied])

    def reversed(self) -> "ActionSchema":
        """The action undone: pre' = pre - del + add, add' = del, del' = add - pre.

        Used for invariant synthesis, so that an invariant that only holds
        because a skill is missing (nobody can undo the effect) is not found.
        An ADL action's reverse undoes each conditional effect under the same
        variables and condition, and keeps only the top-level literals of its
        precondition: more actions, and weaker ones, can only remove invariants.
        """
        pos_pre = {lit.atom for lit in self.precondition if lit.positive and lit.atom.predicate != EQUALITY}
        dels = set(self.delete)
        adds = set(self.add)
        new_pre: list[Literal] = [l for l in self.precondition if l.atom.predicate == EQUALITY]
        new_pre += [Literal(a) for a in sorted((pos_pre - dels) | adds)]
        # After the action, deleted atoms (not re-added) are false.
        neg_pre = {lit.atom for lit in self.precondition if not lit.positive and lit.atom.predicate != EQUALITY}
        new_pre += [Literal(a, False) for a in sorted(((neg_pre - adds) | (dels - adds)) - ((pos_pre - dels) | adds))]
        effects = tuple(type(e)(e.variables, e.condition, Literal(e.literal.atom, not e.literal.positive))
                        for e in self.effects)
        return ActionSchema(
            name=f"{self.name}__reversed",
            params=self.params,
            precondition=tuple(new_pre),
            add=tuple(sorted(dels - adds)),
            delete=tuple(sorted(adds - pos_pre)),
            origin=f"reverse of {self.name}",
            cost=self.cost,
            effects=effects,
        )


@dataclass
class Domain:
    """A PDDL domain."""

    name: str
    requirements: tuple[str, ...]
    types: dict[str, str | None]
    constants: dict[str, str]
    predicates: dict[str, Predicate]
    actions: list[ActionSchema]
    path: str = "<domain>"
    spellings: dict[str, str] = field(default_factory=dict)
    #: The parsed file's source map (positions for error messages), if read from a file.
    source: Any = field(default=None, repr=False, compare=False)
    #: Numeric functions declared in ``:functions`` (``total-cost`` and the static
    #: ones action costs are made of), with their typed parameters.
    functions: dict[str, Predicate] = field(default_factory=dict)
    #: Names the actions use as objects that are neither parameters nor declared constants
    #: (older IPC domains leave them to the problem's objects), in order of first use.
    #: They are not in ``constants``: their type is the problem's (``object`` until then).
    implicit_constants: tuple[str, ...] = ()
    #: One-line diagnostics of reading the file (``file:line:col: warning: ...``), for the user.
    warnings: tuple[str, ...] = field(default=(), compare=False)
    #: Derived predicates' rules (``:derived``); their predicates are in ``predicates`` too.
    axioms: "tuple[DerivedRule, ...]" = ()

    @property
    def is_adl(self) -> bool:
        """Whether the domain needs more than STRIPS (see :class:`ActionSchema`)."""
        return bool(self.axioms) or any(act.is_adl for act in self.actions)

    def derived_predicates(self) -> set[str]:
        """Predicates defined by ``:derived`` rules (never changed by an action or an excuse directly)."""
        return {rule.predicate for rule in self.axioms}

    def locate(self, name: str, *sections: str) -> Location:
        """Where ``name`` is written in the domain file (searched in ``sections`` first)."""
        if self.source is None:
            return Location(self.path)
        return self.source.locate(name, *sections)

    def action(self, name: str) -> ActionSchema:
        """The action schema called ``name`` (KeyError if there is none)."""
        for act in self.actions:
            if act.name == name:
                return act
        raise KeyError(name)

    def subtypes(self) -> dict[str, set[str]]:
        """Map each type to itself and all its (transitive) subtypes.

        An ``either`` type of a predicate parameter maps to the union of its
        members' subtypes, so that grounding and type checks treat it as any other.
        """
        out: dict[str, set[str]] = {t: {t} for t in self.types}
        out.setdefault("object", {"object"})
        for t in self.types:
            parent = self.types[t]
            seen = set()
            while parent is not None and parent not in seen:
                seen.add(parent)
                out.setdefault(parent, {parent}).add(t)
                parent = self.types.get(parent)
        for t in self.either_types():
            out[t] = set().union(*(out.get(m, {m}) for m in type_members(t)))
        return out

    def either_types(self) -> list[str]:
        """The ``either`` types the predicates use, in order of first use."""
        found = [t for pred in self.predicates.values() for _, t in pred.params if t.startswith(EITHER_PREFIX)]
        return list(dict.fromkeys(found))

    def fluent_predicates(self) -> set[str]:
        """Predicates some action adds or deletes (conditional effects included)."""
        plain = {a.predicate for act in self.actions for a in (*act.add, *act.delete)}
        return plain | {eff.literal.atom.predicate for act in self.actions for eff in act.effects}


@dataclass
class Problem:
    """A PDDL problem: objects, initial state and a conjunctive goal.

    ``function_values`` are the initial ``(= (f obj ...) N)`` of numeric
    functions other than ``total-cost``; ``metric`` is whether the problem
    asks to ``(:metric minimize (total-cost))``.  As in Fast Downward, action
    costs count only under that metric: without it every action costs 1.
    """

    name: str
    domain_name: str
    objects: dict[str, str]
    init: frozenset[Atom]
    goal: tuple[Literal, ...]
    path: str = "<problem>"
    spellings: dict[str, str] = field(default_factory=dict)
    function_values: dict[Atom, int] = field(default_factory=dict)
    metric: bool = False
    #: ADL: the whole goal when it is more than a conjunction of literals (``goal`` then holds its
    #: top-level literals).
    goal_condition: "Formula | None" = None


class MissingCostError(KeyError):
    """A cost function has no value for a ground action's arguments (see :func:`action_cost`)."""

    def __init__(self, term: Atom) -> None:
        super().__init__(str(term))
        self.term = term
        self.step: int | None = None  # the plan step that needed it, when a plan is costed


def action_cost(schema: ActionSchema, binding: dict[str, str], problem: Problem) -> int:
    """The cost of ``schema`` applied with ``binding`` in ``problem`` (Fast Downward's semantics).

    Without ``(:metric minimize (total-cost))`` every action costs 1; with
    it, an action without a cost effect costs 0.  Raises
    :class:`MissingCostError` when the problem gives no value for the term.
    """
    if not problem.metric:
        return 1
    cost = schema.cost
    if cost is None:
        return 0
    if isinstance(cost, int):
        return cost
    term = cost.substitute(binding)
    value = problem.function_values.get(term)
    if value is None:
        raise MissingCostError(term)
    return value


def type_ancestors(types: dict[str, str | None], t: str) -> list[str]:
    """``t``, its parent, grandparent, ... ending with ``object`` (cycles cut)."""
    out = [t]
    while True:
        parent = types.get(out[-1])
        if parent is None or parent in out:
            break
        out.append(parent)
    if out[-1] != "object":
        out.append("object")
    return out


def reached(start: str, edges: dict[str, set[str]]) -> set[str]:
    """``start`` and every name ``edges`` lead to from it, in any number of steps (cycles cut): the types above a
    type declared with several parents, the derived predicates a rule depends on."""
    seen, todo = {start}, [start]
    while todo:
        for nxt in edges.get(todo.pop(), ()):
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen


def common_supertype(types: dict[str, str | None], a: str, b: str) -> str:
    """The closest type both ``a`` and ``b`` belong to (``object`` at worst).

    An ``either`` type covers a type below one of its members (and another
    ``either`` whose members it covers).
    """
    for wide, narrow in ((a, b), (b, a)):
        if wide.startswith(EITHER_PREFIX):
            members = type_members(wide)
            if all(any(m in type_ancestors(types, n) for m in members) for n in type_members(narrow)):
                return wide
    up = type_ancestors(types, b)
    return next((t for t in type_ancestors(types, a) if t in up), "object")


def objects_by_type(domain: Domain, problem: Problem) -> dict[str, list[str]]:
    """All objects (constants included) of each type, subtypes included, sorted."""
    every = {**domain.constants, **problem.objects}
    subtypes = domain.subtypes()
    out: dict[str, list[str]] = {}
    for t, subs in subtypes.items():
        out[t] = sorted(o for o, ot in every.items() if ot in subs)
    out["object"] = sorted(every)
    return out


def pretty_atom(atom: Atom, spellings: dict[str, str]) -> str:
    """An atom in the paper's words: ``(open pinkdrawer)`` -> ``Open PinkDrawer``."""
    words = [spellings.get(atom.predicate, atom.predicate)]
    words[0] = words[0][:1].upper() + words[0][1:]
    args = [spellings.get(a, a) for a in atom.args]
    if len(args) <= 1:
        return " ".join(words + args)
    return words[0] + " " + ", ".join(args)
