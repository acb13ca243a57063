"""Reading ADL domains and problems with Fast Downward's translator parser.

Files that use quantifiers, disjunctions, ``imply``, conditional or
universal effects or derived predicates are read here, not by the STRIPS
paths of :mod:`guided_lfd.pddl.reader`: the translator's parser (a
dependency already) takes them, checks declared names and arities, and
leaves formulas in negation normal form.  They become the model's
:mod:`guided_lfd.pddl.formula` objects, so that every command shares one
reading.  The translator's errors become one line with the position of the
name they are about.
"""

from __future__ import annotations

import contextlib
import io
import re
from typing import Any

from typing import TYPE_CHECKING

from guided_lfd.errors import PddlSemanticError, PddlSyntaxError, SearchTimeout
from guided_lfd.pddl import derived
from guided_lfd.pddl.model import (EQUALITY, TOTAL_COST, ActionSchema, Atom, Domain, Literal, Predicate, Problem,
                                   either_type, type_members)
from guided_lfd.pddl.source import SExpr, SourceMap, Token
from guided_lfd.pddl.translator import quiet, translator_options

if TYPE_CHECKING:
    from guided_lfd.pddl.formula import Formula

# Every STRIPS file is asked needs_adl(); the rest of this module (formulas, the
# translator) is imported only when a file is ADL.

#: List heads that only ADL has (keywords count only at the head of a list: an object may be called 'or').
ADL_KEYWORDS = frozenset({"when", "forall", "exists", "or", "imply", ":derived"})


def needs_adl(src: SourceMap) -> bool:
    """Whether the file uses a construct beyond STRIPS that this module reads."""
    for node in src.define().walk():
        if isinstance(node, Token):
            continue
        head = node.head()
        if head in ADL_KEYWORDS:
            return True
        if head == "not" and len(node.items) == 2 and isinstance(node.items[1], SExpr):
            inner = node.items[1].head()
            if inner in ("and", "not") or inner in ADL_KEYWORDS:
                return True
    return False


def _nested(node: SExpr) -> list[Any]:
    """The translator's input: nested lists of lower-cased words.

    ``?x -type`` (no space after the dash, as in IPC's fridge domain) is
    ``?x - type``: no name starts with a dash, so the word can mean nothing else.
    """
    out: list[Any] = []
    for item in node.items:
        if isinstance(item, Token):
            word = item.lower
            if len(word) > 1 and word[0] == "-" and word[1].isalpha():
                out += ["-", word[1:]]
            else:
                out.append(word)
        else:
            out.append(_nested(item))
    return out


def _type_name(type_name: Any) -> str:
    if isinstance(type_name, list):  # (either a b)
        return either_type(type_name[1:])
    return type_name


def _variables(parameters: list[Any]) -> tuple[tuple[str, str], ...]:
    return tuple((p.name, _type_name(p.type_name)) for p in parameters)


def from_translator(cond: Any) -> Formula:
    """A translator condition as a model formula (same structure, negation normal form)."""
    from fast_downward.translate import pddl

    from guided_lfd.pddl.formula import FALSE, TRUE, Junction, Quantified

    if isinstance(cond, pddl.Truth):
        return TRUE
    if isinstance(cond, pddl.Falsity):
        return FALSE
    if isinstance(cond, (pddl.Atom, pddl.NegatedAtom)):
        return Literal(Atom(cond.predicate, tuple(cond.args)), not cond.negated)
    if isinstance(cond, pddl.Conjunction):
        return Junction("and", tuple(from_translator(p) for p in cond.parts))
    if isinstance(cond, pddl.Disjunction):
        return Junction("or", tuple(from_translator(p) for p in cond.parts))
    if isinstance(cond, pddl.UniversalCondition):
        return Quantified("forall", _variables(cond.parameters), from_translator(cond.parts[0]))
    if isinstance(cond, pddl.ExistentialCondition):
        return Quantified("exists", _variables(cond.parameters), from_translator(cond.parts[0]))
    raise TypeError(f"unexpected condition {cond!r}")


def _precondition(formula: Formula) -> tuple[tuple[Literal, ...], Formula | None]:
    """(top-level literals, the whole formula if it is more than those)."""
    from guided_lfd.pddl.formula import is_conjunction_of_literals, top_literals
    if is_conjunction_of_literals(formula):
        return top_literals(formula), None
    return top_literals(formula), formula


def _cost(increase: Any) -> int | Atom | None:
    from fast_downward.translate import pddl

    if increase is None:
        return None
    expr = increase.expression
    if isinstance(expr, pddl.NumericConstant):
        return int(expr.value) or None
    return Atom(expr.symbol, tuple(expr.args))


def _action(act: Any) -> ActionSchema:
    """A translator action as the model has it."""
    from guided_lfd.pddl.formula import TRUE, ConditionalEffect
    pre, condition = _precondition(from_translator(act.precondition))
    add: list[Atom] = []
    delete: list[Atom] = []
    effects: list[ConditionalEffect] = []
    for eff in act.effects:
        literal = from_translator(eff.literal)
        assert isinstance(literal, Literal)
        condition_of = from_translator(eff.condition)
        if not eff.parameters and condition_of == TRUE:
            (add if literal.positive else delete).append(literal.atom)
        else:
            effects.append(ConditionalEffect(_variables(eff.parameters), condition_of, literal))
    return ActionSchema(act.name, _variables(act.parameters), pre, tuple(add), tuple(delete),
                        cost=_cost(act.cost), condition=condition, effects=tuple(effects))


_QUOTED = re.compile(r"'([^'\s]+)'")


def _translator_error(exc: Exception, src: SourceMap) -> PddlSyntaxError:
    """The translator's layered error as one line, at the name it is about.

    Its text is the layers it was in (``->Parsing action 'unload-all'``),
    then the reason, then often ``Got: WORD``.
    """
    lines = [line.strip() for line in str(exc).splitlines() if line.strip()]
    layers = [line.lstrip("->").strip() for line in lines if line.startswith("->") or line.startswith("Parsing")]
    rest = [line for line in lines if not (line.startswith("->") or line.startswith("Parsing"))]
    got = next((line[len("Got:"):].strip() for line in rest if line.startswith("Got:")), None)
    reason = " ".join(line.removeprefix("Reason:").strip() for line in rest if not line.startswith("Got:"))
    reason = reason.rstrip(".") or (layers[-1] if layers else type(exc).__name__)
    where_in = next((layer[len("Parsing "):] for layer in reversed(layers) if _QUOTED.search(layer)), None)
    message = reason + (f" '{got}'" if got else "") + (f" (in {where_in})" if where_in else "")
    names = [got] if got else _QUOTED.findall(" ".join(lines))
    where = src.locate(names[-1].lower()) if names else src.location(src.define().line, src.define().col)
    return PddlSyntaxError(f"{message} (as Fast Downward's parser reads ADL)", where)


@contextlib.contextmanager
def _keeping_actions_without_effects():
    """The translator's parser drops an action without effects unless its options say to keep it (and fails
    when no options are set at all); the model keeps every action, as the STRIPS paths do (an operator whose
    body ``learn-domain`` is to learn has none)."""
    options = translator_options()
    before = options.keep_no_ops
    options.keep_no_ops = True
    try:
        yield
    finally:
        options.keep_no_ops = before


@contextlib.contextmanager
def _translating(src: SourceMap, warnings: list[str]):
    """Run the translator's parser: its printed warnings kept, its errors as one-line ones at a position."""
    from fast_downward.translate.pddl_parser import warning

    warning.printed_warnings.clear()  # it prints each message once per process; each file gets its own
    out = io.StringIO()
    try:
        with quiet(out), _keeping_actions_without_effects():
            yield
    except (SearchTimeout, MemoryError, KeyboardInterrupt):
        raise
    except SystemExit as exc:  # the translator exits on some errors after printing them
        raise _translator_error(Exception(out.getvalue() or str(exc)), src) from None
    except Exception as exc:
        raise _translator_error(exc, src) from None
    # One warning per 'Warning:' (some run over two lines).
    for block in re.split(r"^Warning:", out.getvalue(), flags=re.MULTILINE):
        text = " ".join(block.split())
        if text:
            warnings.append(f"{src.path}: warning: {text}")


def _cost_alone_in_and(lists: list[Any]) -> list[Any]:
    """``lists`` with an action's effect that is a cost alone, ``:effect (increase (total-cost) 1)``, written as
    ``(and (increase ...))``: valid PDDL, on which the translator's parser fails (an AssertionError)."""
    for item in lists:
        if isinstance(item, list) and item[:1] == [":action"]:
            for k in range(len(item) - 1):
                effect = item[k + 1]
                if item[k] == ":effect" and isinstance(effect, list) and effect[:1] == ["increase"]:
                    item[k + 1] = ["and", effect]
    return lists


def _parse_domain_lists(src: SourceMap, warnings: list[str]) -> tuple:
    from fast_downward.translate.pddl_parser.parsing_functions import Context, parse_domain_pddl

    with _translating(src, warnings):
        return tuple(parse_domain_pddl(Context(), _cost_alone_in_and(_nested(src.define()))))


def read_domain(src: SourceMap, path: str) -> Domain:
    """The ADL domain of ``src`` (see the module's docstring)."""
    warnings: list[str] = []
    (name, _, fd_types, _, fd_constants, fd_predicates, _, fd_functions, fd_actions,
     fd_axioms) = _parse_domain_lists(src, warnings)
    types: dict[str, str | None] = {"object": None}
    for t in fd_types:
        if t.name == "object":
            continue
        parent = t.basetype_name or "object"
        if types.get(t.name, parent) != parent:  # declared twice alike is one declaration
            raise PddlSemanticError(f"type '{t.name}' is declared twice in :types, with parents "
                                    f"'{types[t.name]}' and '{parent}'", src.locate_second(t.name))
        types[t.name] = parent
    for parent in [p for p in types.values() if p is not None and p not in types]:
        types.setdefault(parent, "object")  # a parent only named after '-' is a type (as Fast Downward reads it)
    predicates = {p.name: Predicate(p.name, _variables(p.arguments)) for p in fd_predicates if p.name != EQUALITY}
    functions = {f.name: Predicate(f.name, _variables(f.arguments)) for f in fd_functions}
    actions = [_action(act) for act in fd_actions]
    seen: set[str] = set()
    for act in actions:
        if act.name in seen:
            raise PddlSemanticError(f"action '{act.name}' is declared twice (names are case-insensitive)",
                                    src.locate_second_action(act.name))
        seen.add(act.name)
    from guided_lfd.pddl.formula import DerivedRule

    axioms = tuple(DerivedRule(ax.name, _variables(ax.parameters[:ax.num_external_parameters]),
                               from_translator(ax.condition)) for ax in fd_axioms)
    reqs = src.section(":requirements")
    requirements = tuple(t.lower for t in reqs.items[1:] if isinstance(t, Token)) if reqs else ()
    domain = Domain(name=name, requirements=requirements, types=types,
                    constants={c.name: _type_name(c.type_name) for c in fd_constants}, predicates=predicates,
                    actions=actions, path=path, spellings=src.spellings(), source=src, functions=functions,
                    warnings=tuple(warnings), axioms=axioms)
    _check_domain_types(domain, src)
    derived.check_domain(domain)
    return domain


def read_problem(psrc: SourceMap, path: str, domain: Domain) -> Problem:
    """The problem of ``psrc`` for ``domain`` (read by :func:`read_domain` or any other path)."""
    from fast_downward.translate import pddl
    from fast_downward.translate.pddl_parser.parsing_functions import Context, parse_problem_pddl

    type_dict = {t: pddl.Type(t, parent) for t, parent in domain.types.items()}
    predicate_dict = {p: pddl.Predicate(p, [pddl.TypedObject(v, t) for v, t in pred.params])
                      for p, pred in domain.predicates.items()}
    predicate_dict[EQUALITY] = pddl.Predicate(EQUALITY, [pddl.TypedObject("?x", "object"),
                                                         pddl.TypedObject("?y", "object")])
    warnings: list[str] = []
    with _translating(psrc, warnings):
        (name, domain_name, _, fd_objects, fd_init, fd_goal, metric) = tuple(parse_problem_pddl(
            Context(), _nested(psrc.define()), type_dict, predicate_dict, set(domain.constants)))
    objects = {o.name: _type_name(o.type_name) for o in fd_objects}
    init = frozenset(Atom(a.predicate, tuple(a.args)) for a in fd_init
                     if isinstance(a, pddl.Atom) and a.predicate != EQUALITY)
    formula = from_translator(fd_goal)
    goal, goal_condition = _precondition(formula)
    if goal_condition is None and any(lit.atom.predicate == EQUALITY for lit in goal):
        goal_condition = formula  # '(= a b)' is no atom of a state: the formula's paths evaluate it, the STRIPS ones not
    from guided_lfd.pddl import costs

    values = costs.read_function_values(psrc, domain, objects) if domain.functions else {}
    problem = Problem(name=name, domain_name=domain_name, objects=objects, init=init, goal=goal, path=path,
                      spellings=psrc.spellings(), function_values=values,
                      metric=bool(metric) and TOTAL_COST in domain.functions, goal_condition=goal_condition)
    _check_problem_types(domain, problem, psrc)
    derived.check_init(domain, problem, psrc)
    return problem


class _TypeCheck:
    """Declared types and well-typed atoms, as the STRIPS paths check them (the translator does not).

    An object must be of the parameter's type (or below it); a variable's type
    must meet the parameter's (one below the other: IPC ADL domains quantify
    over a supertype and use the variable where a subtype is expected, which
    Fast Downward reads).
    """

    def __init__(self, domain: Domain, src: SourceMap, sections: tuple[str, ...] = ()) -> None:
        from guided_lfd.pddl.fast_reader import _Types

        self.domain, self.src, self.sections = domain, src, sections
        self.types = _Types(domain.types)

    def known(self, typ: str) -> None:
        for member in type_members(typ):
            if member not in self.domain.types:
                raise PddlSemanticError(f"unknown type '{member}'", self.src.locate(member))

    def variables(self, variables: tuple[tuple[str, str], ...], scope: dict[str, str]) -> dict[str, str]:
        for name, typ in variables:
            self.known(typ)
        return {**scope, **dict(variables)}

    def formula(self, formula: Formula, scope: dict[str, str], objects: dict[str, str]) -> None:
        from guided_lfd.pddl.formula import Junction

        if isinstance(formula, Literal):
            self.atom(formula.atom, scope, objects)
        elif isinstance(formula, Junction):
            for part in formula.parts:
                self.formula(part, scope, objects)
        else:
            self.formula(formula.body, self.variables(formula.variables, scope), objects)

    def atom(self, atom: Atom, scope: dict[str, str], objects: dict[str, str]) -> None:
        pred = self.domain.predicates.get(atom.predicate)
        if pred is None:  # '=' (the translator has checked names and arities)
            return
        for arg, (_, expected) in zip(atom.args, pred.params):
            if arg in scope:
                actual = scope[arg]
                if self.types.below(actual, expected) or self.types.below(expected, actual):
                    continue
            elif arg not in objects or self.types.below(objects[arg], expected):
                continue
            else:
                actual = objects[arg]
            raise PddlSemanticError(f"'{arg}' is a {actual}, expected a {expected} (in {atom})",
                                    self.src.locate(arg.lower(), *self.sections))


def _check_domain_types(domain: Domain, src: SourceMap) -> None:
    check = _TypeCheck(domain, src)
    for parent in domain.types.values():
        if parent is not None:
            check.known(parent)
    for typ in domain.constants.values():
        check.known(typ)
    for pred in domain.predicates.values():
        check.variables(pred.params, {})
    for act in domain.actions:
        scope = check.variables(act.params, {})
        for lit in act.precondition:
            check.atom(lit.atom, scope, domain.constants)
        if act.condition is not None:
            check.formula(act.condition, scope, domain.constants)
        for atom in (*act.add, *act.delete):
            check.atom(atom, scope, domain.constants)
        for eff in act.effects:
            inner = check.variables(eff.variables, scope)
            check.formula(eff.condition, inner, domain.constants)
            check.atom(eff.literal.atom, inner, domain.constants)
    for rule in domain.axioms:
        check.formula(rule.condition, check.variables(rule.params, {}), domain.constants)


def _check_problem_types(domain: Domain, problem: Problem, src: SourceMap) -> None:
    check = _TypeCheck(domain, src, (":init", ":goal"))
    objects = {**domain.constants, **problem.objects}
    for typ in problem.objects.values():
        check.known(typ)
    for atom in problem.init:
        check.atom(atom, {}, objects)
    from guided_lfd.pddl.formula import Junction

    check.formula(problem.goal_condition or Junction("and", problem.goal), {}, objects)
