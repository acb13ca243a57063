"""Reading plain STRIPS PDDL fast, with Fast Downward's translator parser.

Tarski's ANTLR parser costs about 50 ms to import and tens of milliseconds
per small file (seconds on a household problem); Fast Downward's translator
parser (a dependency already, for invariant synthesis) reads the same files
in a fraction of that.  This module is the fast path of
:mod:`guided_lfd.pddl.reader`: it hands the s-expressions of the source map
to the translator's parsing functions, converts the result into the same
:mod:`guided_lfd.pddl.model` objects as the tarski path (same orders), and
checks everything tarski checks (its grammar's shape and names, declared
names, arities, argument types).

It only ever *accepts*: on anything unusual (a translator error or warning,
a construct outside plain STRIPS, a form tarski's grammar does not take, a
name it cannot type-check) it returns None and the
reader takes the tarski path, which gives the precise ``file:line:col``
error or the model.  Tests read every PDDL file of the repository, and
hundreds of damaged ones, both ways and require the same outcome.

Beyond plain STRIPS it reads what the translator reads and the reader
supports (see :mod:`guided_lfd.pddl.names`): ``(either a b)`` types of
predicate parameters, a type named like an object, and implicit constants
(declared for the translator, which refuses undeclared objects, then set apart).
"""

from __future__ import annotations

import re
import threading
from typing import Any

from guided_lfd.errors import SearchTimeout
from guided_lfd.pddl import costs, names
from guided_lfd.pddl.model import (EITHER_PREFIX, EQUALITY, TOTAL_COST, ActionSchema, Atom, Domain, Literal, Predicate, Problem,
                                   either_type, type_members)
from guided_lfd.pddl.source import SExpr, SourceMap, Token

#: A name as tarski's grammar reads it (NAME: a letter, then letters, digits, '-', '_').
_NAME = re.compile(r"[a-zA-Z][a-zA-Z0-9_-]*\Z")
_DOMAIN_SECTIONS = (":requirements", ":types", ":constants", ":predicates", ":functions")
_PROBLEM_SECTIONS = (":requirements", ":objects")

_strict = threading.local()  # set while this module parses: the translator's warnings then decline


class _NotPlain(Exception):
    """The input needs the full reader (its result or its error)."""


def _warning_declines(original):
    def print_warning(msg: str) -> None:
        if getattr(_strict, "on", False):
            raise _NotPlain(msg)
        original(msg)

    return print_warning


def _translator():
    """The translator's parsing functions, its warnings turned into declines (in this thread only)."""
    from fast_downward.translate.pddl_parser import parsing_functions

    if not getattr(parsing_functions.print_warning, "_declines", False):
        patched = _warning_declines(parsing_functions.print_warning)
        patched._declines = True  # type: ignore[attr-defined]
        parsing_functions.print_warning = patched
    return parsing_functions


def _nested(node: SExpr) -> list[Any]:
    """The translator's input: nested lists of lower-cased words."""
    out: list[Any] = []
    for item in node.items:
        if isinstance(item, Token):
            text = item.text
            low = text.lower()
            if not text.isascii() or "?" in text[1:]:
                raise _NotPlain(text)
            out.append(low)
        else:
            out.append(_nested(item))
    return out


def _name(word: Any) -> str:
    """A declared name tarski reads as a name."""
    if not isinstance(word, str) or not _NAME.match(word) or word in names.RESERVED_WORDS:
        raise _NotPlain(str(word))
    return word


def _typed_list(items: list[Any], variables: bool = False, any_order: bool = False, either: bool = False) -> None:
    """A typed list tarski reads in the order written: names, '- type' after each group, no list.

    ``any_order``: the order is not tarski's to keep (``:types``, which the
    reader reorders parents first for both paths).  ``either``: a type may
    be ``(either NAME ...)`` (predicate parameters).
    """
    groups_typed: list[bool] = []
    i = 0
    pending = False
    while i < len(items):
        word = items[i]
        if word == "-":
            if not pending or i + 1 >= len(items):
                raise _NotPlain("typed list")
            typ = items[i + 1]
            if either and isinstance(typ, list) and len(typ) > 1 and typ[0] == "either":
                for member in typ[1:]:
                    if member != "object":
                        _name(member)
            elif typ != "object":
                _name(typ)
            groups_typed.append(True)
            pending = False
            i += 2
            continue
        if variables:
            if not isinstance(word, str) or not word.startswith("?"):
                raise _NotPlain(str(word))
            _name(word[1:])
        else:
            _name(word)
        pending = True
        i += 1
    if pending and groups_typed and not any_order:
        raise _NotPlain("untyped names after typed ones")  # tarski lists those first


def _atom_shape(alist: Any) -> None:
    if not isinstance(alist, list) or not alist or not isinstance(alist[0], str):
        raise _NotPlain("atom")
    if alist[0] != "=":
        _name(alist[0])
    for term in alist[1:]:
        if not isinstance(term, str):
            raise _NotPlain("term")


def _condition_shape(alist: Any) -> None:
    """A conjunction (nested or not) of atoms and negated atoms, as tarski's goal grammar takes."""
    if not isinstance(alist, list):
        raise _NotPlain("condition")
    if not alist:
        return
    if alist[0] == "and":
        if len(alist) == 1:
            raise _NotPlain("empty and")
        for part in alist[1:]:
            if not part:
                raise _NotPlain("empty part")
            _condition_shape(part)
    elif alist[0] == "not":
        if len(alist) != 2:
            raise _NotPlain("not")
        _atom_shape(alist[1])
    else:
        _atom_shape(alist)


def _is_cost_effect(part: Any) -> bool:
    return isinstance(part, list) and len(part) == 3 and part[0] == "increase" and part[1] == [TOTAL_COST]


def _cost_effect(alist: Any) -> int | Atom | None:
    """The ``(increase (total-cost) X)`` of an effect as the model has it (none or 0: None)."""
    parts = alist[1:] if isinstance(alist, list) and alist[:1] == ["and"] else [alist]
    costs = [part[2] for part in parts if _is_cost_effect(part)]
    if not costs:
        return None
    if len(costs) > 1:
        raise _NotPlain("two cost effects")
    cost = costs[0]
    if isinstance(cost, str):
        if not cost.isdigit():
            raise _NotPlain("cost")
        return int(cost) or None
    if not cost or not all(isinstance(w, str) for w in cost):
        raise _NotPlain("cost term")
    return Atom(_name(cost[0]), tuple(cost[1:]))


def _effect_literals(alist: Any) -> list[tuple[bool, list[str]]]:
    """(positive?, atom) of a plain STRIPS effect in the order written (one 'and' at most, as in tarski's grammar)."""
    if not isinstance(alist, list) or not alist:
        raise _NotPlain("effect")
    parts = alist[1:] if alist[0] == "and" else [alist]
    parts = [part for part in parts if not _is_cost_effect(part)]
    out: list[tuple[bool, list[str]]] = []
    for part in parts:
        if not isinstance(part, list) or not part or part[0] == "and":
            raise _NotPlain("effect part")
        positive = part[0] != "not"
        atom = part if positive else (part[1] if len(part) == 2 else None)
        _atom_shape(atom)
        if atom[0] == "=":
            raise _NotPlain("equality effect")
        out.append((positive, atom))
    if len({(pos, tuple(atom)) for pos, atom in out}) != len(out):
        raise _NotPlain("an effect written twice")
    return out


def _sections_in_order(entries: list[Any], allowed: tuple[str, ...]) -> None:
    """Sections appear at most once and in the order tarski's grammar has them."""
    last = -1
    for entry in entries:
        if not isinstance(entry, list) or not entry or entry[0] not in allowed:
            raise _NotPlain("section")
        k = allowed.index(entry[0])
        if k <= last:
            raise _NotPlain("section order")
        last = k


def _literals(cond) -> list[Literal]:
    """A condition that is a conjunction of literals, flattened in order."""
    from fast_downward.translate import pddl

    if isinstance(cond, pddl.Truth):
        return []
    if isinstance(cond, pddl.Conjunction):
        out: list[Literal] = []
        for part in cond.parts:
            out += _literals(part)
        return out
    if isinstance(cond, (pddl.Atom, pddl.NegatedAtom)):
        return [Literal(Atom(cond.predicate, tuple(cond.args)), not cond.negated)]
    raise _NotPlain(type(cond).__name__)


def _unique(names: list[str]) -> None:
    if len(set(names)) != len(names):
        raise _NotPlain("declared twice")


class _Types:
    """Subtype checks over a domain's (acyclic) type hierarchy."""

    def __init__(self, types: dict[str, str | None]) -> None:
        self.types = types
        for name in types:
            seen = {name}
            up = types[name]
            while up is not None:
                if up in seen:
                    raise _NotPlain("type cycle")
                seen.add(up)
                up = types.get(up)

    def known(self, name: str) -> None:
        for member in type_members(name):
            if member not in self.types:
                raise _NotPlain(f"type {member}")

    def below(self, name: str, ancestor: str) -> bool:
        if ancestor.startswith(EITHER_PREFIX):
            return any(self.below(name, member) for member in type_members(ancestor))
        while name is not None:
            if name == ancestor:
                return True
            name = self.types.get(name)  # type: ignore[assignment]
        return ancestor == "object"


def _check_literals(literals: list[Literal], terms: dict[str, str], predicates: dict[str, Predicate],
                    types: _Types, loose: tuple[str, ...] = ()) -> None:
    """Every literal names a declared predicate with the right number of well-typed arguments.

    ``loose``: names whose type is not known yet (implicit constants without
    a problem), not checked against ``either`` parameters, as the tarski path does.
    """
    for lit in literals:
        atom = lit.atom
        if any(arg not in terms for arg in atom.args):
            raise _NotPlain(str(atom))
        if atom.predicate == EQUALITY:
            if len(atom.args) != 2:
                raise _NotPlain(str(atom))
            continue
        pred = predicates.get(atom.predicate)
        if pred is None or len(pred.params) != len(atom.args):
            raise _NotPlain(str(atom))
        for arg, (_, expected) in zip(atom.args, pred.params):
            if arg in loose and expected.startswith(EITHER_PREFIX):
                continue
            if not types.below(terms[arg], expected):
                raise _NotPlain(str(atom))


def read_domain(src: SourceMap, path: str) -> Domain | None:
    """The domain of ``src`` (already checked for features), or None: use the full reader."""
    _strict.on = True
    try:
        return _domain(src, path)
    except (SearchTimeout, MemoryError, KeyboardInterrupt):
        raise  # a limit or the user, not a reason to read again
    except Exception:  # _NotPlain, the translator's ParseError, anything: the full reader decides
        return None
    finally:
        _strict.on = False


def _domain(src: SourceMap, path: str) -> Domain:
    lists = _nested(src.define())
    if len(lists) < 2 or lists[0] != "define" or not isinstance(lists[1], list) or len(lists[1]) != 2:
        raise _NotPlain("header")
    name = _name(lists[1][1])
    first_action, declared_actions = _domain_shape(lists[2:])
    from fast_downward.translate.pddl_parser.parsing_functions import Context

    implicit = names.implicit_constant_uses(src)
    pf = _translator()
    (_, _, fd_types, _, fd_constants, fd_predicates, _, functions, fd_actions, axioms) = pf.parse_domain_pddl(
        Context(), _with_constants(lists, first_action, list(implicit)))
    if axioms or len(declared_actions) != len(fd_actions):
        raise _NotPlain("axioms or an action without effects")
    # The tarski path's type order: object, then the declarations parents first.
    ordered = src.types_parents_first() or []
    types: dict[str, str | None] = {"object": None}
    for tname, parent in ordered:
        types[tname.lower()] = parent.lower() if parent else "object"
    fd_parents = {t.name: (None if t.name == "object" else t.basetype_name or "object") for t in fd_types}
    if len(fd_types) != len(types) or fd_parents != types:
        raise _NotPlain("types")
    checker = _Types(types)
    for parent in types.values():
        if parent is not None:
            checker.known(parent)
    _unique([c.name for c in fd_constants])
    constants = {c.name: c.type_name for c in fd_constants if c.name not in implicit}
    for t in constants.values():
        checker.known(t)
    predicates = _predicates(fd_predicates, checker)
    declared_functions = _functions(functions, checker)
    if set(declared_functions) & (set(types) | set(constants) | set(predicates)):
        raise _NotPlain("a function named like a type, constant or predicate")
    # Types and objects are separate namespaces (a type and an object 'cart'); predicates are not.
    if set(types) & set(predicates) or (set(constants) | set(implicit)) & set(predicates):
        raise _NotPlain("a name used twice")
    # Implicit constants are checked with the type their uses need (the problem's comes later).
    loose = {n: names.implicit_constant_type(src, n) for n in implicit}
    actions = _actions(declared_actions, fd_actions, {**loose, **constants}, predicates, checker, tuple(loose),
                       declared_functions)
    reqs = src.section(":requirements")
    requirements = tuple(t.lower for t in reqs.items[1:] if isinstance(t, Token)) if reqs else ()
    return Domain(name=name, requirements=requirements, types=types, constants=constants, predicates=predicates,
                  actions=actions, path=path, spellings=src.spellings(), source=src,
                  implicit_constants=tuple(implicit), functions=declared_functions,
                  warnings=tuple(names.implicit_constant_warning(src, use) for use in implicit.values()))


def _domain_shape(body: list[Any]) -> tuple[int, list[Any]]:
    """Sections and actions in the shape tarski's grammar has them; (index of the first action, the actions)."""
    first_action = next((k for k, e in enumerate(body) if isinstance(e, list) and e[:1] == [":action"]), len(body))
    _sections_in_order(body[:first_action], _DOMAIN_SECTIONS)
    declared_actions = body[first_action:]
    for raw in declared_actions:
        # (:action NAME :parameters (...) :precondition P :effect E), as tarski's grammar has it
        if (not isinstance(raw, list) or len(raw) != 8 or raw[0] != ":action" or raw[2] != ":parameters"
                or raw[4] != ":precondition" or raw[6] != ":effect" or not isinstance(raw[3], list)):
            raise _NotPlain("action shape")
        _name(raw[1])
        _typed_list(raw[3], variables=True)
        _condition_shape(raw[5])
    sections = {e[0]: e for e in body[:first_action]}
    if ":types" in sections:
        _typed_list(sections[":types"][1:], any_order=True)
    if ":constants" in sections:
        _typed_list(sections[":constants"][1:])
    for pred in sections.get(":predicates", [None])[1:]:
        if not isinstance(pred, list) or not pred:
            raise _NotPlain("predicate")
        _name(pred[0])
        _typed_list(pred[1:], variables=True, either=True)
    _function_shapes(sections.get(":functions", [None])[1:])
    return first_action, declared_actions


def _predicates(fd_predicates: list[Any], checker: _Types) -> dict[str, Predicate]:
    """The translator's predicates; an ``(either a b)`` type (a list there) as the model writes it."""
    predicates: dict[str, Predicate] = {}
    for pred in fd_predicates:
        if pred.name == EQUALITY:
            continue
        if pred.name in predicates:
            raise _NotPlain("predicate declared twice")
        params = tuple((f"?x{i}", arg.type_name if isinstance(arg.type_name, str) else either_type(arg.type_name[1:]))
                       for i, arg in enumerate(pred.arguments))
        for _, t in params:
            checker.known(t)
        predicates[pred.name] = Predicate(pred.name, params)
    return predicates


def _actions(declared_actions: list[Any], fd_actions: list[Any], objects: dict[str, str],
             predicates: dict[str, Predicate], checker: _Types, loose: tuple[str, ...],
             functions: dict[str, Predicate]) -> list[ActionSchema]:
    """The translator's actions as the model has them, type-checked (``objects``: constants and implicit ones)."""
    _unique([a.name for a in fd_actions])
    actions: list[ActionSchema] = []
    for raw, act in zip(declared_actions, fd_actions):
        params = tuple((p.name, p.type_name) for p in act.parameters)
        _unique([p for p, _ in params])
        for _, t in params:
            checker.known(t)
        terms = {**objects, **dict(params)}
        pre = _literals(act.precondition)
        if any(eff.parameters or not _is_truth(eff.condition) for eff in act.effects):
            raise _NotPlain("quantified or conditional effects")
        cost = _cost_effect(raw[7])
        if (act.cost is not None) != _has_cost_effect(raw[7]):
            raise _NotPlain("a cost effect the translator reads otherwise")
        if isinstance(cost, Atom):
            _check_literals([Literal(cost)], terms, functions, checker, loose)
        # The effects as written: the translator drops a delete its action also adds
        # (add-after-delete); the model keeps both, as tarski's does.
        add: list[Atom] = []
        delete: list[Atom] = []
        for positive, atom in _effect_literals(raw[7]):
            (add if positive else delete).append(Atom(atom[0], tuple(atom[1:])))
        _check_literals(pre + [Literal(a) for a in add + delete], terms, predicates, checker, loose)
        actions.append(ActionSchema(act.name, params, tuple(pre), tuple(add), tuple(delete), cost=cost))
    return actions


def _has_cost_effect(alist: Any) -> bool:
    parts = alist[1:] if isinstance(alist, list) and alist[:1] == ["and"] else [alist]
    return any(_is_cost_effect(part) for part in parts)


def _function_shapes(entries: list[Any]) -> None:
    """``(:functions (f ?x - t ...) - number ...)`` as tarski's grammar takes it: numbers only."""
    i = 0
    while i < len(entries):
        entry = entries[i]
        if not isinstance(entry, list) or not entry:
            raise _NotPlain("function")
        _name(entry[0])
        _typed_list(entry[1:], variables=True)
        if entries[i + 1:i + 2] == ["-"]:
            if entries[i + 2:i + 3] != ["number"]:
                raise _NotPlain("function type")
            i += 3
        else:
            i += 1


def _functions(functions: list[Any], checker: "_Types") -> dict[str, Predicate]:
    """The translator's functions as the model has them (numbers only, in declaration order)."""
    out: dict[str, Predicate] = {}
    for fun in functions:
        if fun.name in out or fun.type_name != "number":
            raise _NotPlain("function")
        params = tuple((f"?x{i}", arg.type_name) for i, arg in enumerate(fun.arguments))
        for _, t in params:
            checker.known(t)
        out[fun.name] = Predicate(fun.name, params)
    return out


def _with_constants(lists: list[Any], first_action: int, implicit: list[str]) -> list[Any]:
    """The domain's lists with ``implicit`` constants declared (the translator refuses undeclared objects)."""
    if not implicit:
        return lists
    body = lists[2:]
    at = next((k for k, e in enumerate(body[:first_action]) if e[0] == ":constants"), None)
    if at is not None:
        body = body[:at] + [body[at] + implicit] + body[at + 1:]  # untyped, last: of type object
    else:
        at = next((k for k, e in enumerate(body[:first_action]) if e[0] == ":predicates"), first_action)
        body = body[:at] + [[":constants", *implicit]] + body[at:]
    return lists[:2] + body


def _check_implicit_constants(domain: Domain, objects: dict[str, str], checker: _Types) -> None:
    """The problem declares each implicit constant, with a type every use in the actions fits."""
    if not domain.implicit_constants:
        return
    if any(name not in objects for name in domain.implicit_constants):
        raise _NotPlain("an implicit constant the problem does not declare")
    for act in domain.actions:
        terms = {**{n: objects[n] for n in domain.implicit_constants}, **domain.constants, **dict(act.params)}
        _check_literals([*act.precondition, *map(Literal, act.add + act.delete)], terms, domain.predicates, checker)
        if isinstance(act.cost, Atom):
            _check_literals([Literal(act.cost)], terms, domain.functions, checker)


def _is_truth(cond) -> bool:
    from fast_downward.translate import pddl

    return isinstance(cond, pddl.Truth)


def read_problem(src: SourceMap, path: str, domain: Domain) -> Problem | None:
    """The problem of ``src`` for ``domain``, or None: use the full reader."""
    _strict.on = True
    try:
        return _problem(src, path, domain)
    except (SearchTimeout, MemoryError, KeyboardInterrupt):
        raise
    except Exception:  # _NotPlain, the translator's ParseError, anything: the full reader decides
        return None
    finally:
        _strict.on = False


def _problem(src: SourceMap, path: str, domain: Domain) -> Problem:
    from fast_downward.translate import pddl

    lists = _nested(src.define())
    # (define (problem N) (:domain D) [(:requirements ..)] [(:objects ..)] (:init ..) (:goal G) [(:metric ..)])
    if (len(lists) < 5 or lists[0] != "define" or not isinstance(lists[1], list) or lists[1][:1] != ["problem"]
            or len(lists[1]) != 2 or not isinstance(lists[2], list) or lists[2][:1] != [":domain"]):
        raise _NotPlain("header")
    name = _name(lists[1][1])
    metric = lists[-1] == [":metric", "minimize", [TOTAL_COST]]
    if metric:
        lists = lists[:-1]
    init_section = _problem_shape(lists, domain)
    domain_name, fd_objects, fd_init, fd_goal = _translate_problem(lists, domain, metric)
    _unique([o.name for o in fd_objects])
    objects = {o.name: o.type_name for o in fd_objects}
    if set(objects) & (set(domain.constants) | set(domain.predicates) | set(domain.functions)):
        raise _NotPlain("an object named like a constant or predicate")
    checker = _Types(domain.types)
    for t in objects.values():
        checker.known(t)
    _check_implicit_constants(domain, objects, checker)
    terms = {**domain.constants, **objects}
    facts = [a for a in fd_init if not isinstance(a, pddl.Assign)]
    if len(fd_init) != len(init_section) - 1 or any(not isinstance(a, pddl.Atom) for a in facts):
        raise _NotPlain("repeated or non-atomic initial facts")
    init = [Literal(Atom(a.predicate, tuple(a.args))) for a in facts]
    values = costs.read_function_values(src, domain, objects)
    goal = _literals(fd_goal)
    if any(lit.atom.predicate == EQUALITY for lit in init + goal):
        raise _NotPlain("equality in the initial state or goal")
    _check_literals(init + goal, terms, domain.predicates, checker)
    return Problem(name=name, domain_name=domain_name, objects=objects, init=frozenset(l.atom for l in init),
                   goal=tuple(goal), path=path, spellings=src.spellings(), function_values=values, metric=metric)


def _problem_shape(lists: list[Any], domain: Domain) -> list[Any]:
    """The problem's sections in the shape tarski's grammar has them (the metric taken off); its ``:init``."""
    init_section, goal_section = lists[-2], lists[-1]
    if (not isinstance(init_section, list) or init_section[:1] != [":init"] or not isinstance(goal_section, list)
            or goal_section[:1] != [":goal"] or len(goal_section) != 2):
        raise _NotPlain("init and goal")
    middle = lists[3:-2]
    _sections_in_order(middle, _PROBLEM_SECTIONS)
    objects_section = next((e for e in middle if e[0] == ":objects"), None)
    if objects_section is not None:
        _typed_list(objects_section[1:])
    for fact in init_section[1:]:
        if isinstance(fact, list) and fact[:1] == ["="]:
            _assignment_shape(fact, domain)
            continue
        if not isinstance(fact, list) or not fact or fact[0] == "not":
            raise _NotPlain("negative initial facts")
        _atom_shape(fact)
    if not goal_section[1]:
        raise _NotPlain("empty goal")
    _condition_shape(goal_section[1])
    return init_section


def _translate_problem(lists: list[Any], domain: Domain, metric: bool) -> tuple[str, list[Any], list[Any], Any]:
    """The translator's reading of the problem against ``domain``: (domain name, objects, init, goal)."""
    from fast_downward.translate import pddl
    from fast_downward.translate.pddl_parser.parsing_functions import Context

    type_dict = {tname: pddl.Type(tname, parent) for tname, parent in domain.types.items()}
    predicate_dict = {pname: pddl.Predicate(pname, [pddl.TypedObject(p, t) for p, t in pred.params])
                      for pname, pred in domain.predicates.items()}
    predicate_dict[EQUALITY] = pddl.Predicate(EQUALITY, [pddl.TypedObject("?x", "object"),
                                                         pddl.TypedObject("?y", "object")])
    full = lists + [[":metric", "minimize", [TOTAL_COST]]] if metric else lists
    (_, domain_name, _, fd_objects, fd_init, fd_goal, use_metric) = _translator().parse_problem_pddl(
        Context(), full, type_dict, predicate_dict, set(domain.constants))
    if use_metric != metric or (metric and TOTAL_COST not in domain.functions):
        raise _NotPlain("metric")
    return domain_name, fd_objects, fd_init, fd_goal


def _assignment_shape(fact: list[Any], domain: Domain) -> None:
    """``(= (f obj ...) N)``: a declared function, a whole number."""
    if (len(fact) != 3 or not isinstance(fact[1], list) or not fact[1] or not isinstance(fact[2], str)
            or not fact[2].isdigit() or fact[1][0] not in domain.functions):
        raise _NotPlain("assignment")
    if not all(isinstance(w, str) for w in fact[1]):
        raise _NotPlain("assignment term")
