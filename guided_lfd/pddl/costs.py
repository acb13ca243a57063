""":action-costs on the source map: what both reading paths check and read the same way.

Cost effects are checked here before either parser sees them (a cost term
is a declared function of the action's terms, a number is whole), so that
neither Fast Downward's translator nor tarski meets a form it would crash on
or read otherwise; the problem's ``(= (f obj ...) N)`` values are read here
for both paths, and tarski is given the problem without them
(:func:`without_assignments`), as its function tables choke on some of them.
"""

from __future__ import annotations

import re

from guided_lfd.errors import PddlSemanticError, PddlSyntaxError, UnsupportedFeatureError
from guided_lfd.pddl.model import TOTAL_COST, Atom, Domain
from guided_lfd.pddl.source import SExpr, SourceMap, Token

__all__ = ["check_cost_effects", "read_function_values", "without_assignments"]

#: A whole number as action costs need it (Fast Downward refuses fractions and signs).
_WHOLE = re.compile(r"[0-9]+\Z")


def _function_arities(src: SourceMap) -> dict[str, int]:
    """Each function of the domain's ``:functions`` section and its number of parameters."""
    section = src.section(":functions")
    out: dict[str, int] = {}
    for item in section.items[1:] if section is not None else []:
        if isinstance(item, SExpr) and item.head() is not None:
            out[item.head() or ""] = sum(1 for t in item.items[1:] if isinstance(t, Token) and t.text.startswith("?"))
    return out


def check_cost_effects(src: SourceMap) -> None:
    """``total-cost`` takes no arguments, and every ``(increase (total-cost) X)`` has a cost the model can hold."""
    arities = _function_arities(src)
    section = src.section(":functions")
    for item in section.items[1:] if section is not None else []:
        if isinstance(item, SExpr) and item.head() == TOTAL_COST and len(item.items) > 1:
            raise UnsupportedFeatureError(
                "total-cost takes no arguments (it is the plan's accumulated cost)",
                src.location(item.line, item.col))
    for act in src.define().items:
        if not isinstance(act, SExpr) or act.head() != ":action":
            continue
        increases = [n for n in act.walk() if isinstance(n, SExpr) and n.head() == "increase"]
        for node in increases:
            if len(node.items) == 3:
                _check_cost(node.items[2], arities, src)
        if len(increases) > 1:
            second = increases[1]
            raise PddlSemanticError("an action increases total-cost twice (expected one cost effect per action)",
                                    src.location(second.line, second.col))


def _check_cost(cost: SExpr | Token, arities: dict[str, int], src: SourceMap) -> None:
    if isinstance(cost, Token):
        if not _WHOLE.match(cost.text):
            raise UnsupportedFeatureError(f"cost {cost.text} is not a whole number >= 0 (expected whole-number "
                                          "action costs)", src.location(cost.line, cost.col))
        return
    head = cost.items[0] if cost.items else None
    name = head.lower if isinstance(head, Token) else None
    if (name is None or name == TOTAL_COST or name not in arities
            or not all(isinstance(t, Token) for t in cost.items[1:])):
        raise UnsupportedFeatureError(
            "a cost must be a whole number or a declared function of the action's parameters and constants, "
            "e.g. '(road-length ?from ?to)' (no arithmetic, no total-cost)", src.location(cost.line, cost.col))
    if len(cost.items) - 1 != arities[name]:
        raise PddlSemanticError(f"wrong number of arguments for '{name}' (expected {arities[name]})",
                                src.location(cost.line, cost.col))


def assignment_lists(src: SourceMap) -> list[SExpr]:
    """The ``(= ...)`` facts of the problem's ``:init``."""
    init = src.section(":init")
    return [item for item in init.items[1:] if isinstance(item, SExpr) and item.head() == "="] if init else []


def without_assignments(src: SourceMap) -> str:
    """The problem's text with its ``:init`` assignments blanked out, every other character where it was."""
    text = src.text
    for node in sorted(assignment_lists(src), key=lambda n: n.start, reverse=True):
        text = text[:node.start] + re.sub(r"[^\n]", " ", text[node.start:node.end + 1]) + text[node.end + 1:]
    return text


def read_function_values(src: SourceMap, domain: Domain, objects: dict[str, str]) -> dict[Atom, int]:
    """The problem's ``(= (f obj ...) N)`` values (``total-cost``'s left out), each checked against ``domain``.

    Raises a one-line error at the fact for an unknown function or object, a
    wrong number or type of arguments, a value that is not a whole number,
    or two different values for one term (the same value twice is allowed).
    """
    terms = {**domain.constants, **objects}
    subtypes = domain.subtypes()
    values: dict[Atom, int] = {}
    for node in assignment_lists(src):
        where = src.location(node.line, node.col)
        if (len(node.items) != 3 or not isinstance(node.items[1], SExpr) or not isinstance(node.items[2], Token)
                or not node.items[1].items or not all(isinstance(t, Token) for t in node.items[1].items)):
            raise PddlSyntaxError("expected '(= (function object ...) N)' in :init", where)
        term, number = node.items[1], node.items[2]
        words = [t for t in term.items if isinstance(t, Token)]
        name, args = words[0].lower, words[1:]
        fun = domain.functions.get(name)
        if fun is None:
            raise PddlSemanticError(f"unknown function '{words[0].text}' (expected a function declared in the "
                                    "domain's :functions)", src.location(words[0].line, words[0].col))
        if len(args) != fun.arity:
            raise PddlSemanticError(f"wrong number of arguments for '{name}' (expected {fun.arity})", where)
        for arg, (_, expected) in zip(args, fun.params):
            actual = terms.get(arg.lower)
            if actual is None:
                raise PddlSemanticError(f"unknown object '{arg.text}' (expected an object declared in :objects or "
                                        "a domain constant)", src.location(arg.line, arg.col))
            if actual not in subtypes.get(expected, {expected}):
                raise PddlSemanticError(f"'{arg.lower}' is a {actual}, expected a {expected}",
                                        src.location(arg.line, arg.col))
        if not _WHOLE.match(number.text):
            raise UnsupportedFeatureError(f"value {number.text} is not a whole number >= 0 (expected whole-number "
                                          "action costs)", src.location(number.line, number.col))
        if name == TOTAL_COST:
            continue
        atom = Atom(name, tuple(a.lower for a in args))
        value = int(number.text)
        if values.get(atom, value) != value:
            raise PddlSemanticError(f"two values for {atom} in :init: {values[atom]} and {value}", where)
        values[atom] = value
    return values
