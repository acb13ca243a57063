"""Parsing PDDL domains and problems (with tarski) into :mod:`guided_lfd.pddl.model`.

Tarski does the parsing; this module checks what guided-lfd supports,
converts tarski's first-order structures into the small STRIPS model, and
turns every failure into a one-line error with ``file:line:col``.
"""

from __future__ import annotations

import logging
import os
import re
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Iterator

from guided_lfd.errors import (
    GuidedLfdError,
    Location,
    MismatchError,
    PddlSemanticError,
    PddlSyntaxError,
    SearchTimeout,
    UnsupportedFeatureError,
)
from guided_lfd.pddl.model import (
    EQUALITY,
    SUPPORTED_REQUIREMENTS,
    ActionSchema,
    Atom,
    Domain,
    Literal,
    Predicate,
    Problem,
    type_members,
)
from guided_lfd.pddl import adl_reader, costs, fast_reader, names
from guided_lfd.pddl.evidence import with_evidence_comments
from guided_lfd.pddl.source import SExpr, SourceMap, Token, check_ascii
from guided_lfd.io import read_text

# Keywords of PDDL features beyond STRIPS and ADL, with the requirement they belong to.
_UNSUPPORTED_KEYWORDS = {
    "decrease": ":numeric-fluents",
    "assign": ":numeric-fluents",
    "scale-up": ":numeric-fluents",
    "scale-down": ":numeric-fluents",
    "<": ":numeric-fluents",
    ">": ":numeric-fluents",
    "<=": ":numeric-fluents",
    ">=": ":numeric-fluents",
    ":durative-action": ":durative-actions",
    "probabilistic": ":probabilistic-effects",
    ":constraints": ":constraints",
}


@contextmanager
def _quiet_tarski() -> Iterator[None]:
    """Tarski logs warnings on the root logger; keep them off the user's stderr."""
    previous = logging.root.manager.disable
    logging.disable(logging.CRITICAL)
    try:
        yield
    finally:
        logging.disable(previous)


def _check_features(src: SourceMap, what: str) -> None:
    """Reject requirements and constructs outside guided-lfd's STRIPS fragment."""
    head = src.define().items
    if not head or not isinstance(head[0], Token) or head[0].lower != "define":
        first = src.define()
        raise PddlSyntaxError(f"expected '(define ({what} NAME) ...)'", src.location(first.line, first.col))
    reqs = src.section(":requirements")
    if reqs is not None:
        for tok in reqs.items[1:]:
            if isinstance(tok, Token) and tok.lower not in SUPPORTED_REQUIREMENTS:
                raise UnsupportedFeatureError(
                    f"unsupported requirement {tok.lower} "
                    f"(guided-lfd supports {' '.join(SUPPORTED_REQUIREMENTS)})",
                    src.location(tok.line, tok.col),
                )
    _check_numeric(src)
    if what == "domain":
        costs.check_cost_effects(src)
    # Keywords only count at the head of a list: an object may be called 'or'.
    for node in _lists(src):
        name = node.head()
        if name in _UNSUPPORTED_KEYWORDS:
            tok = node.items[0]
            assert isinstance(tok, Token)
            raise UnsupportedFeatureError(
                f"'{tok.text}' needs {_UNSUPPORTED_KEYWORDS[name]}, which guided-lfd does not support "
                f"(expected STRIPS with typing, negative preconditions, equality and action costs, or ADL)",
                src.location(tok.line, tok.col),
            )
    names.check_either(src)  # '(either a b)' as a predicate parameter's type only, as Fast Downward has it


def _numeric_error(tok: Token, src: SourceMap, what: str) -> UnsupportedFeatureError:
    return UnsupportedFeatureError(
        f"{what}: guided-lfd supports numbers only as :action-costs (expected '(increase (total-cost) N)' "
        f"or '(increase (total-cost) (f ?x ...))' effects, '(= (f obj ...) N)' in :init and "
        f"'(:metric minimize (total-cost))')",
        src.location(tok.line, tok.col),
    )


def _check_numeric(src: SourceMap) -> None:
    """Numbers only as :action-costs uses them; any other numeric fluent is a clean refusal."""
    init = src.section(":init")
    in_init = {id(n) for n in init.walk()} if init is not None else set()
    functions = src.section(":functions")
    if functions is not None:
        items = functions.items
        for i, item in enumerate(items[1:], start=1):
            if isinstance(item, Token) and item.lower == "-" and i + 1 < len(items):
                kind = items[i + 1]
                if not isinstance(kind, Token) or kind.lower != "number":
                    tok = kind if isinstance(kind, Token) else items[i]
                    raise _numeric_error(tok, src, "a function whose values are not numbers (object fluents)")
    for node in _lists(src):
        head = node.head()
        tok = node.items[0] if node.items else None
        if not isinstance(tok, Token):
            continue
        if head == "increase":
            target = node.items[1] if len(node.items) == 3 else None
            if not (isinstance(target, SExpr) and len(target.items) == 1 and isinstance(target.items[0], Token)
                    and target.items[0].lower == "total-cost"):
                raise _numeric_error(tok, src, "'increase' of a fluent other than total-cost")
        elif head == ":metric":
            words = [t.lower if isinstance(t, Token) else (t.head() if len(t.items) == 1 else "?")
                     for t in node.items[1:]]
            if words != ["minimize", "total-cost"]:
                raise _numeric_error(tok, src, "a metric other than '(:metric minimize (total-cost))'")
        elif head == "=" and id(node) not in in_init and any(isinstance(t, SExpr) for t in node.items[1:]):
            raise _numeric_error(tok, src, "a numeric comparison")


def _lists(src: SourceMap):
    yield src.define()
    for item in src.define().walk():
        if not isinstance(item, Token):
            yield item


_TARSKI_POS = re.compile(r"line (\d+):(\d+) (.*)")


@contextmanager
def _temp_pddl(text: str) -> Iterator[str]:
    """A temporary file holding ``text``: tarski reads files, we have text (stdin too)."""
    import tempfile

    fd, tmp = tempfile.mkstemp(suffix=".pddl", text=True)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
        yield tmp
    finally:
        os.unlink(tmp)


#: A line comment as tarski's lexer reads it: ';' up to a line break, which must follow.
_LINE_COMMENT = re.compile(r";[^\r\n]*(?=\r?\n)")
#: A line comment that ends the file without a line break.
_FINAL_COMMENT = re.compile(r";[^\r\n]*\Z")


def without_comments(text: str) -> str:
    """``text`` with each line comment emptied, its line break kept.

    Tarski's lexer puts comments on a hidden channel, so it reads the same
    tokens at the same lines and columns; but lexing a comment costs as much
    as lexing code (a commented kitchen domain parses ~8 ms faster on a cold
    start without).  A comment tarski would not accept as one (at the end of
    the file with no line break) is left for tarski to reject.
    """
    return _LINE_COMMENT.sub("", text)


#: A comment, a parenthesis, or a word (comments are matched first and kept).
_TOKEN_OR_COMMENT = re.compile(r";[^\r\n]*|[()]|[^\s();]+")
#: Type words tarski reads as keywords after '-' in a typed list.
_KEYWORD_TYPES = {"object", "number"}


def keywords_lowered(text: str) -> str:
    """``text`` with every PDDL keyword in lower case, nothing else changed, no token moved.

    PDDL is case-insensitive and Fast Downward reads ``DOMAIN`` or
    ``:REQUIREMENTS``; tarski's grammar has some keywords in lower case only.
    Lowered are ``:``-words (never names), reserved words where a keyword
    goes (first in a list: ``(AND``, ``(DOMAIN``) and ``OBJECT`` after
    ``-``; a name such as ``Max`` elsewhere keeps its spelling.
    """
    previous = ""

    def lower(match: re.Match) -> str:
        nonlocal previous
        word = match.group(0)
        if word.startswith(";"):
            return word
        before, previous = previous, word
        low = word.lower()
        if low == word or len(low) != len(word):
            return word  # already lower case, or a word whose lower case is not the same length
        if low.startswith(":"):
            return low
        if before == "(" and low in names.RESERVED_WORDS or before == "-" and low in _KEYWORD_TYPES:
            return low
        if before.lower() == ":metric" and low in ("minimize", "maximize"):
            return low
        return word

    return _TOKEN_OR_COMMENT.sub(lower, text)


#: What tarski is given for an action written without ``:precondition``.
_EMPTY_PRECONDITION = ":precondition (and) "


def with_empty_preconditions(src: SourceMap) -> tuple[str, list[tuple[int, int, int]]]:
    """The text of ``src`` with ``:precondition (and)`` before the ``:effect`` of each action that has none.

    The precondition is optional in PDDL (and in Fast Downward); tarski's
    grammar requires it.  Returns the text and the (line, column, width) of
    each insertion, so positions tarski reports can be mapped back
    (:func:`_as_in_source`).
    """
    return _with_inserts(src, _precondition_inserts(src))


def _precondition_inserts(src: SourceMap) -> list[tuple[int, str]]:
    """(offset, text) of the ``:precondition (and)`` each action without one gets.

    Only actions after the ``:types`` section get one, so that section's
    offsets stay valid for
    :meth:`~guided_lfd.pddl.source.SourceMap.text_with_types_parents_first`.
    """
    types = src.section(":types")
    starts = _line_starts(src.text)
    inserts: list[tuple[int, str]] = []
    for act in src.define().items:
        if not isinstance(act, SExpr) or act.head() != ":action":
            continue
        if types is not None and act.start < types.end:
            continue  # out of order: tarski's error stands
        words = [t for t in act.items if isinstance(t, Token)]
        if any(t.lower == ":precondition" for t in words):
            continue
        effect = next((t for t in words if t.lower == ":effect"), None)
        if effect is not None:
            inserts.append((starts[effect.line - 1] + effect.col - 1, _EMPTY_PRECONDITION))
    return inserts


def _line_starts(text: str) -> list[int]:
    return [0] + [m.end() for m in re.finditer("\n", text)]


def _with_inserts(src: SourceMap, inserts: list[tuple[int, str]]) -> tuple[str, list[tuple[int, int, int]]]:
    """The text of ``src`` with one-line ``inserts`` (offset, text), and their (line, column, width)."""
    text = src.text
    if not inserts:
        return text, []
    starts = _line_starts(text)
    import bisect

    pieces, last, where = [], 0, []
    for offset, piece in sorted(inserts):
        line = bisect.bisect_right(starts, offset)
        where.append((line, offset - starts[line - 1] + 1, len(piece)))
        pieces += [text[last:offset], piece]
        last = offset
    pieces.append(text[last:])
    return "".join(pieces), where


def _as_in_source(line: int, col: int, inserts: list[tuple[int, int, int]]) -> tuple[int, int]:
    """A (line, 1-based column) of the text given to tarski, in the file as written."""
    shift = 0
    for at_line, at_col, width in inserts:  # in order of position
        if at_line != line:
            continue
        start = at_col + shift  # where this insertion begins in the text tarski read
        if col < start:
            break
        if col < start + width:
            return line, at_col  # inside the insertion: at what it precedes
        shift += width
    return line, col - shift


@dataclass
class _Rewrite:
    """What the tarski path changes in the text it gives tarski, to undo in the model and messages.

    ``types``: types also named like an object, to their substitute (tarski
    has one namespace for sorts and constants).  ``implicit``: the domain's
    implicit constants; ``declared``: for each the type tarski is told (the
    problem's, else the most specific its uses need); ``fresh``: the name the
    problem's own declaration of one is given, so that tarski sees it once.
    """

    types: dict[str, str] = field(default_factory=dict)
    implicit: dict[str, names.ImplicitUse] = field(default_factory=dict)
    declared: dict[str, str] = field(default_factory=dict)
    fresh: dict[str, str] = field(default_factory=dict)

    def type_name(self, name: str) -> str:
        """A sort name tarski gives back, as the file has it (lower-case)."""
        name = str(name).lower()
        return self._type_back.get(name, name)

    def in_message(self, text: str) -> str:
        """A message of tarski's with the substitute names as the files have them."""
        back = {**self._type_back, **{v: k for k, v in self.fresh.items()}}
        if not back:
            return text
        return re.sub(r"[A-Za-z][A-Za-z0-9_-]*", lambda m: back.get(m.group(0), m.group(0)), text)

    @property
    def _type_back(self) -> dict[str, str]:
        return {v: k for k, v in self.types.items()}


def _rewrite_for(dsrc: SourceMap, psrc: SourceMap | None) -> _Rewrite:
    """The substitutes tarski needs for this domain (and problem), found on the source maps."""
    shared = sorted(names.shared_type_names(dsrc, psrc))
    implicit = names.implicit_constant_uses(dsrc)
    objects = {}
    for tok, typ in names.declared_constants(psrc, ":objects") if psrc is not None else []:
        objects.setdefault(tok.lower, typ)
    redeclared = [n for n in implicit if n in objects]
    substitutes = names.fresh_names(shared + redeclared, dsrc, psrc)
    rewrite = _Rewrite(types=dict(zip(shared, substitutes)), implicit=implicit,
                       fresh=dict(zip(redeclared, substitutes[len(shared):])))
    known = names.type_names(dsrc) | {"object"}
    for name in implicit:
        if name not in objects:
            rewrite.declared[name] = names.implicit_constant_type(dsrc, name)
            continue
        typ = objects[name]
        wanted = typ.lower if isinstance(typ, Token) else "object"
        # A type the domain does not declare: the problem's own declaration gets tarski's error.
        rewrite.declared[name] = wanted if wanted in known else names.implicit_constant_type(dsrc, name)
    return rewrite


def _tarski_text(src: SourceMap, kind: str, rewrite: _Rewrite) -> tuple[str, list[tuple[int, int, int]]]:
    """The text tarski is given for ``src`` and the (line, col, width) of what was inserted.

    Same-length substitutes first (types named like objects, ``either``
    lists, a problem's declaration of an implicit constant), then insertions
    (empty preconditions, the implicit constants' declaration), then
    ``:types`` parents first and keywords in lower case.
    """
    if kind == "problem" and costs.assignment_lists(src):
        # The values are read from the source for both paths (guided_lfd.pddl.costs).
        src = SourceMap(src.path, costs.without_assignments(src))
    respelled = [(tok, rewrite.types[tok.lower]) for tok in names.type_positions(src, set(rewrite.types))]
    eithers = names.either_lists(src) if kind == "domain" else []
    if kind == "problem" and rewrite.fresh:
        first = {}
        for tok, _ in names.declared_constants(src, ":objects"):
            first.setdefault(tok.lower, tok)
        respelled += [(first[n], new) for n, new in rewrite.fresh.items() if n in first]
    if respelled or eithers:
        src = SourceMap(src.path, names.substituted(src.text, src, respelled, eithers))
    inserts = _precondition_inserts(src) if kind == "domain" else []
    if kind == "domain" and rewrite.implicit:
        inserts += _constant_inserts(src, rewrite)
    text, where = _with_inserts(src, inserts)
    return keywords_lowered(src.text_with_types_parents_first(text)), where


def _constant_inserts(src: SourceMap, rewrite: _Rewrite) -> list[tuple[int, str]]:
    """Where the implicit constants are declared for tarski: in ``:constants``, else a section before the predicates."""
    decl = " ".join(f"{n} - {rewrite.types.get(t, t)}" for n, t in rewrite.declared.items())
    types = src.section(":types")
    constants = src.section(":constants")
    if constants is not None:
        return [(constants.end, " " + decl)]
    follower = src.section(":predicates") or next(
        (i for i in src.define().items if isinstance(i, SExpr) and i.head() == ":action"), None)
    if follower is None or (types is not None and follower.start < types.end):
        return []  # out of order: tarski's error stands
    return [(follower.start, f"(:constants {decl}) ")]


def _tarski_parse(reader, kind: str, src: SourceMap, rewrite: _Rewrite) -> None:
    """Run tarski on the text of ``src`` (with ``rewrite``'s substitutes) and translate its errors."""
    try:
        _tarski_parse_text(reader, kind, src, rewrite)
    except GuidedLfdError as exc:
        message = rewrite.in_message(exc.message)
        if message != exc.message:
            raise type(exc)(message, exc.location) from None
        raise


def _tarski_parse_text(reader, kind: str, src: SourceMap, rewrite: _Rewrite) -> None:
    text, inserts = _tarski_text(src, kind, rewrite)
    if _FINAL_COMMENT.search(text):
        # A line comment may end the file (PDDL comments run to the end of the
        # line); tarski's lexer wants a line break after it.  Adding one moves no token.
        text += "\n"
    try:
        with _quiet_tarski():
            # Tarski's string entry points: the file ones would read back a temporary copy of the text.
            if kind == "domain":
                reader.parse_domain_string(without_comments(text))
            else:
                reader.parse_instance_string(without_comments(text))
    except (GuidedLfdError, MemoryError):
        raise  # ours (a time limit too), or a resource limit: not a syntax error
    except RecursionError:
        raise PddlSyntaxError("nested too deeply to parse", src.location(src.define().line, src.define().col)) from None
    except Exception as exc:  # tarski's errors, ParsingError and anything else it raises
        raise _semantic_error(exc, src, rewrite.in_message) or _syntax_error(exc, src, text, kind, inserts) from None


def _semantic_error(exc: Exception, src: SourceMap, orig) -> PddlSemanticError | None:
    """Tarski's semantic error ``exc`` as a one-line error at its place (names as written); None for others."""
    from tarski import errors as terr

    if isinstance(exc, terr.UndefinedSort):
        name = orig(_element_name(exc))
        return PddlSemanticError(f"unknown type '{name}' (expected a type declared in :types)",
                                 src.locate(name, ":types", ":objects", ":constants"))
    if isinstance(exc, terr.UndefinedPredicate):
        name = orig(_element_name(exc))
        return PddlSemanticError(f"unknown predicate '{name}' (expected a predicate declared in the domain's "
                                 ":predicates)", src.locate_head(name, ":init", ":goal", ":action"))
    if isinstance(exc, terr.UndefinedConstant):
        name = orig(_element_name(exc))
        return PddlSemanticError(f"unknown object '{name}' (expected an object declared in :objects or a domain "
                                 "constant)", src.locate_argument(name, ":init", ":goal", ":action"))
    if isinstance(exc, terr.UndefinedElement):
        name = orig(_element_name(exc))
        return PddlSemanticError(f"unknown name '{name}'", src.locate_argument(name, ":init", ":goal", ":action"))
    if isinstance(exc, terr.ArityMismatch):
        match = re.search(r"element (\S+)/(\d+)", str(exc))
        pred = match.group(1) if match else "?"
        arity = match.group(2) if match else "?"
        return PddlSemanticError(f"wrong number of arguments for '{pred}' (expected {arity})",
                                 _locate_application(src, pred, int(arity) if arity.isdigit() else None))
    if isinstance(exc, terr.SortMismatch):
        match = re.search(r'element (\S+?)\.? Expected sort was "([^"]*)", element has sort "([^"]*)"', str(exc))
        if not match:
            return PddlSemanticError(f"type mismatch: {exc}", src.location(src.define().line, src.define().col))
        # Sorts of variables come as 'Sort(name)'.
        expected, actual = (re.sub(r"^Sort\((.*)\)$", r"\1", match.group(k)) for k in (2, 3))
        element, expected, actual = orig(match.group(1)), orig(expected), orig(actual)
        element = element.split("(")[0]
        return PddlSemanticError(f"'{element}' is a {actual}, expected a {expected}",
                                 src.locate_argument(element, ":init", ":goal"))
    if isinstance(exc, terr.DuplicateDefinition):
        name = orig(str(getattr(exc, "name", _element_name(exc))))
        return names.declared_twice(name, src.locate_second(name))
    return None


def _syntax_error(exc: Exception, src: SourceMap, text: str, kind: str,
                  inserts: list[tuple[int, int, int]]) -> PddlSyntaxError:
    """Tarski's syntax error (or anything else it raised) as a one-line error at its place in the file."""
    exc = _as_written(exc, text, kind)
    first = str(exc).split("\n")[0] if str(exc) else type(exc).__name__
    match = _TARSKI_POS.search(first)
    if match:
        line, col = _as_in_source(int(match.group(1)), int(match.group(2)) + 1, inserts)
        return PddlSyntaxError(f"{match.group(3)} (expected a well-formed PDDL {kind})", src.location(line, col))
    return PddlSyntaxError(f"cannot parse {kind}: {first}", src.location(src.define().line, src.define().col))


def _as_written(exc: Exception, text: str, kind: str) -> Exception:
    """Tarski's syntax error ``exc`` as it reads for ``text`` with its comments.

    A syntax error can quote the input around it ("no viable alternative at
    input ..."), comments included; tarski's parse of the text as written
    (syntax only: it fails before building anything) gives that wording.
    """
    if not _TARSKI_POS.search(str(exc)) or without_comments(text) == text:
        return exc
    from tarski.io import PDDLReader

    fresh = PDDLReader(raise_on_error=True, strict_with_requirements=False)
    try:
        with _quiet_tarski():
            fresh.parser.parse_string(text, kind)
    except MemoryError:
        raise
    except Exception as original:
        if _TARSKI_POS.search(str(original)):
            return original
    return exc


def _element_name(exc: Exception) -> str:
    match = re.search(r'"([^"]*)"', str(exc))
    return match.group(1) if match else str(exc)


def _locate_application(src: SourceMap, pred: str, arity: int | None = None) -> Location:
    """Where ``(pred ...)`` is applied, preferring an application with the wrong arity."""
    first = None
    declarations = src.section(":predicates")
    skip = {id(n) for n in declarations.walk()} if declarations is not None else set()
    for node in _lists(src):
        if id(node) in skip:
            continue
        if node.head() == pred.lower():
            if arity is None or len(node.items) - 1 != arity:
                return src.location(node.line, node.col)
            first = first or src.location(node.line, node.col)
    return first or src.locate(pred)


def _term_name(term) -> str:
    from tarski.syntax import Variable

    if isinstance(term, Variable):
        return term.symbol if term.symbol.startswith("?") else "?" + term.symbol
    return str(term.name).lower()


def _pred_name(pred) -> str:
    from tarski.syntax import builtins

    if builtins.is_builtin_predicate(pred):
        if pred.symbol == builtins.BuiltinPredicateSymbol.EQ:
            return EQUALITY
        raise ValueError(str(pred.symbol))
    return str(pred.name).lower()


def _literals(formula, src: SourceMap, where: str) -> list[Literal]:
    """Flatten a conjunction of literals; anything else is unsupported."""
    from tarski.syntax import CompoundFormula, Connective, Tautology
    from tarski.syntax import Atom as TAtom

    if isinstance(formula, Tautology):
        return []
    if isinstance(formula, TAtom):
        return [Literal(Atom(_pred_name(formula.predicate), tuple(_term_name(t) for t in formula.subterms)))]
    if isinstance(formula, CompoundFormula):
        if formula.connective == Connective.And:
            out: list[Literal] = []
            for sub in formula.subformulas:
                out += _literals(sub, src, where)
            return out
        if formula.connective == Connective.Not and isinstance(formula.subformulas[0], TAtom):
            (lit,) = _literals(formula.subformulas[0], src, where)
            return [Literal(lit.atom, False)]
    raise UnsupportedFeatureError(
        f"{where} is not a conjunction of literals (expected STRIPS with negative preconditions)",
        src.location(src.define().line, src.define().col),
    )


def _declared_types(lang, rewrite: _Rewrite) -> dict[str, str | None]:
    builtin = {"Real", "Integer", "Natural", "number"}
    out: dict[str, str | None] = {}
    for sort in lang.sorts:
        if sort.name in builtin:
            continue
        parent = lang.immediate_parent.get(sort)
        out[rewrite.type_name(sort.name)] = rewrite.type_name(parent.name) if parent is not None else None
    return out


def _tarski_predicates(lang, src: SourceMap, rewrite: _Rewrite) -> dict[str, Predicate]:
    """The predicates tarski read, each ``either`` parameter type restored (tarski was given ``object``)."""
    from tarski.syntax import builtins

    eithers = names.predicate_either_types(src)
    predicates: dict[str, Predicate] = {}
    for pred in lang.predicates:
        if builtins.is_builtin_predicate(pred):
            continue
        name = str(pred.name).lower()
        written = eithers.get(name, {})
        predicates[name] = Predicate(name, tuple(
            (f"?x{i}", written[i][0] if i in written else rewrite.type_name(s.name)) for i, s in enumerate(pred.sort)))
    return predicates


def _domain_from_tarski(reader, src: SourceMap, path: str, rewrite: _Rewrite) -> Domain:
    lang = reader.problem.language
    implicit = rewrite.implicit
    reqs = src.section(":requirements")
    requirements = tuple(t.lower for t in reqs.items[1:] if isinstance(t, Token)) if reqs else ()
    domain = Domain(
        name=str(reader.problem.domain_name).lower(),
        requirements=requirements,
        types=_declared_types(lang, rewrite),
        constants={str(c.name).lower(): rewrite.type_name(c.sort.name) for c in lang.constants()
                   if str(c.name).lower() not in implicit},
        predicates=_tarski_predicates(lang, src, rewrite),
        actions=_tarski_actions(reader, src, rewrite),
        path=path,
        spellings=src.spellings(),
        source=src,
        implicit_constants=tuple(implicit),
        warnings=tuple(names.implicit_constant_warning(src, use) for use in implicit.values()),
        functions=_tarski_functions(lang, src, rewrite),
    )
    names.check_either_members(src, domain.types)
    _check_either_arguments(domain, src, None)
    return domain


def _tarski_actions(reader, src: SourceMap, rewrite: _Rewrite) -> list[ActionSchema]:
    from tarski.fstrips import AddEffect, DelEffect
    from tarski.syntax import Tautology

    actions: list[ActionSchema] = []
    seen_actions: set[str] = set()
    for act in reader.problem.actions.values():
        lname = str(act.name).lower()
        node = src.action(lname)
        where_node = src.location(node.line, node.col) if node else src.location(src.define().line, src.define().col)
        if lname in seen_actions:
            raise PddlSemanticError(
                f"action '{act.name}' is declared twice (names are case-insensitive)", src.locate_second_action(lname)
            )
        seen_actions.add(lname)
        param_names = [_term_name(v) for v in act.parameters]
        if len(set(param_names)) != len(param_names):
            dup = next(n for n in param_names if param_names.count(n) > 1)
            raise PddlSemanticError(f"parameter {dup} of action '{act.name}' is declared twice", where_node)
        where = f"precondition of action '{act.name}'"
        params = tuple((_term_name(v), rewrite.type_name(v.sort.name)) for v in act.parameters)
        pre = tuple(_literals(act.precondition, src, where))
        add: list[Atom] = []
        dele: list[Atom] = []
        for eff in act.effects:
            if not isinstance(eff, (AddEffect, DelEffect)):
                raise UnsupportedFeatureError(
                    f"effect {eff} of action '{act.name}' is not a STRIPS add or delete effect", where_node
                )
            if not isinstance(eff.condition, Tautology):
                raise UnsupportedFeatureError(
                    f"conditional effect in action '{act.name}' (needs :conditional-effects, unsupported)", where_node
                )
            atom = Atom(_pred_name(eff.atom.predicate), tuple(_term_name(t) for t in eff.atom.subterms))
            (add if isinstance(eff, AddEffect) else dele).append(atom)
        cost = _tarski_cost(act, src, where_node)
        actions.append(ActionSchema(str(act.name).lower(), params, pre, tuple(add), tuple(dele), cost=cost))
    return actions


def _check_either_arguments(domain: Domain, src: SourceMap, objects: dict[str, str] | None,
                            problem: tuple[SourceMap, Problem] | None = None) -> None:
    """Arguments at ``either`` parameters belong to a member type (tarski was given ``object`` there).

    Without ``objects`` (the problem's), the domain's actions are checked,
    implicit constants left out (their type is the problem's); with them,
    the actions' uses of implicit constants, and ``problem``'s init and goal.
    """
    subtypes = domain.subtypes()
    eithers = {p.name: {k: t for k, (_, t) in enumerate(p.params) if t in subtypes and t.startswith("(either ")}
               for p in domain.predicates.values()}
    if not any(eithers.values()):
        return
    for act in domain.actions:
        terms = {**domain.constants, **dict(act.params)}
        if objects is not None:
            terms = {n: objects[n] for n in domain.implicit_constants if n in objects}
        literals = [*act.precondition, *map(Literal, act.add), *map(Literal, act.delete)]
        node = src.action(act.name)
        _check_either_literals(literals, terms, eithers, subtypes, src, [node] if node is not None else [])
    if problem is not None:
        psrc, prob = problem
        terms = {**domain.constants, **prob.objects}
        scopes = [n for n in (psrc.section(":init"), psrc.section(":goal")) if n is not None]
        literals = [*map(Literal, sorted(prob.init)), *prob.goal]
        _check_either_literals(literals, terms, eithers, subtypes, psrc, scopes)


def _check_either_literals(literals: list[Literal], terms: dict[str, str], eithers: dict[str, dict[int, str]],
                           subtypes: dict[str, set[str]], src: SourceMap, scopes: list[SExpr]) -> None:
    for lit in literals:
        for k, t in eithers.get(lit.atom.predicate, {}).items():
            arg = lit.atom.args[k]
            if arg in terms and terms[arg] not in subtypes[t]:
                *first, last = type_members(t)
                members = f"{', '.join(first)} or {last}" if first else last
                raise PddlSemanticError(f"'{arg}' is a {terms[arg]}, expected either {members}",
                                        _locate_atom_argument(src, scopes, lit.atom.predicate, k, arg))


def _locate_atom_argument(src: SourceMap, scopes: list[SExpr], pred: str, index: int, arg: str) -> Location:
    """Where ``arg`` is argument ``index`` of an application of ``pred`` inside ``scopes``."""
    for scope in scopes:
        for node in (scope, *scope.walk()):
            if isinstance(node, SExpr) and node.head() == pred and len(node.items) > index + 1:
                tok = node.items[index + 1]
                if isinstance(tok, Token) and tok.lower == arg:
                    return src.location(tok.line, tok.col)
    return src.locate(arg)


def _tarski_functions(lang, src: SourceMap, rewrite: _Rewrite) -> dict[str, Predicate]:
    """The functions of the ``:functions`` section (tarski's language adds built-ins such as ``ite``)."""
    section = src.section(":functions")
    declared = {item.head() for item in section.items[1:] if isinstance(item, SExpr)} if section else set()
    out: dict[str, Predicate] = {}
    for fun in lang.functions:
        name = str(fun.name).lower()
        if name not in declared:
            continue
        out[name] = Predicate(name, tuple((f"?x{i}", rewrite.type_name(s.name)) for i, s in enumerate(fun.domain)))
    return out


def as_cost_number(value: float, what: str, where: Location) -> int:
    """A cost or function value as the non-negative integer action costs need."""
    if value != int(value) or value < 0:
        raise UnsupportedFeatureError(f"{what} {value:g} is not a non-negative integer "
                                      "(expected whole-number action costs)", where)
    return int(value)


def _tarski_cost(act, src: SourceMap, where: Location) -> int | Atom | None:
    """The action's ``(increase (total-cost) X)`` as the model has it (0 and none alike: None)."""
    from tarski.syntax import CompoundTerm, Constant

    if act.cost is None:
        return None
    addend = act.cost.addend
    if isinstance(addend, Constant):
        number = as_cost_number(float(addend.name), f"the cost of action '{act.name}'", where)
        return number or None
    if isinstance(addend, CompoundTerm):
        return Atom(str(addend.symbol.name).lower(), tuple(_term_name(t) for t in addend.subterms))
    raise UnsupportedFeatureError(f"the cost of action '{act.name}' is not a number or a function term", where)


def _new_reader():
    from tarski.io import PDDLReader

    return PDDLReader(raise_on_error=True, strict_with_requirements=False)


#: Files up to this size get tarski's opinion on where an unclosed list went
#: wrong; beyond it a second parse costs seconds (19 s on 10 MB), and the
#: list left open is reported at once.
SECOND_OPINION_MAX_CHARS = 1_000_000


def _source_map(path: str, kind: str, text: str | None = None) -> SourceMap:
    """Read ``path`` (or take ``text``, named ``path`` in messages) into a :class:`SourceMap`.

    For an unclosed parenthesis the source map can only point at the list
    left open at the end of the file; tarski's grammar often pins the real
    mistake (``((and``) earlier, so its position wins when it has one.
    """
    text = read_text(path) if text is None else text
    check_ascii(path, text)
    try:
        return SourceMap(path, text)
    except PddlSyntaxError as exc:
        if "never closed" not in exc.message or len(text) > SECOND_OPINION_MAX_CHARS:
            raise
        better = _tarski_syntax_error(text, kind, path)
        if better is not None and better.location is not None and exc.location is not None:
            if (better.location.line or 0) > (exc.location.line or 0) and "<EOF>" not in better.message:
                raise better from None
        raise


def _tarski_syntax_error(text: str, kind: str, path: str) -> PddlSyntaxError | None:
    from tarski.io import PDDLReader

    reader = PDDLReader(raise_on_error=True, strict_with_requirements=False)
    with _temp_pddl(text) as tmp, _quiet_tarski():
        try:
            reader.parser.parse_file(tmp, kind)
        except (MemoryError, SearchTimeout):
            raise
        except Exception as exc:  # tarski's ParsingError
            match = _TARSKI_POS.search(str(exc).splitlines()[0] if str(exc) else "")
            if match:
                return PddlSyntaxError(
                    f"{match.group(3)} (expected a well-formed PDDL {kind})",
                    Location(path, int(match.group(1)), int(match.group(2)) + 1),
                )
    return None


def parse_domain(path: str | Path) -> Domain:
    """Parse a domain file (``-`` for stdin) into a :class:`Domain`."""
    name = str(path)
    src = _source_map(name, "domain")
    _check_kind(src, "domain")
    _check_features(src, "domain")
    src, notes = _declared_once(src)
    return with_evidence_comments(_noted(_domain_of(src, name), notes), src.text)


def _domain_of(src: SourceMap, name: str) -> Domain:
    if adl_reader.needs_adl(src):
        return adl_reader.read_domain(src, name)
    try:
        return _strips_domain(src, name)
    except (PddlSyntaxError, PddlSemanticError) as exc:
        if not _translator_may_read(exc, src):
            raise
        return _or_raise(exc, lambda: adl_reader.read_domain(src, name))


def _declared_once(dsrc: SourceMap, psrc: SourceMap | None = None) -> tuple[SourceMap, list[str]]:
    """Duplicate declarations as Fast Downward reads them, for every reading path: a type declared again is one
    type (``dsrc`` with the declarations merged, and a warning for each); a constant or object declared again
    (the problem's objects after the domain's constants) is an error at the second declaration."""
    names.check_objects_once(dsrc, ":constants")
    if psrc is not None:
        names.check_objects_once(psrc, ":objects", (tok.lower for tok, _ in names.declared_constants(dsrc)))
    return names.types_declared_once(dsrc)


def _noted(domain: Domain, notes: list[str]) -> Domain:
    """``domain`` with the reading's ``notes`` (warnings about its file) before its own."""
    return replace(domain, warnings=(*notes, *domain.warnings)) if notes else domain


def _translator_may_read(exc: GuidedLfdError, dsrc: SourceMap, psrc: SourceMap | None = None) -> bool:
    """Whether Fast Downward's parser may read what tarski's grammar refused: valid PDDL that tarski
    does not take (names starting with a digit or called 'domain', 'object' among the types, a type
    declared twice alike, a predicate named like a type, an object or a constant: Fast Downward keeps
    predicates apart from both, tarski has one namespace)."""
    if isinstance(exc, PddlSyntaxError) or "is declared twice in :types" in exc.message:
        return True
    match = re.match(r"'([^']+)' is declared twice \(expected", exc.message)
    if match is None or match.group(1).lower() not in names.predicate_names(dsrc):
        return False
    name = match.group(1).lower()
    try:
        types = {t.lower() for t, _ in (dsrc.types_parents_first() or [])}
    except GuidedLfdError:
        return False
    return name in types or name in names.object_names(dsrc, psrc)


def _or_raise(exc: GuidedLfdError, read):
    """What ``read`` (the translator's reading) gives, or ``exc`` (the precise error) if it fails too."""
    try:
        return read()
    except GuidedLfdError:
        raise exc from None


def _strips_domain(src: SourceMap, name: str) -> Domain:
    """A STRIPS domain from its source map: the fast path, else tarski's."""
    fast = fast_reader.read_domain(src, name)
    if fast is not None:
        return fast
    reader = _new_reader()
    rewrite = _rewrite_for(src, None)
    _tarski_parse(reader, "domain", src, rewrite)
    return _domain_from_tarski(reader, src, name, rewrite)


def _check_kind(src: SourceMap, kind: str) -> None:
    root = src.define()
    for item in root.items[1:2]:
        if not isinstance(item, Token) and item.head() in ("domain", "problem"):
            if item.head() != kind:
                raise PddlSyntaxError(
                    f"this is a {item.head()} file, expected a {kind} file",
                    src.location(item.line, item.col),
                )
            return


def parse_task(domain_path: str | Path, problem_path: str | Path, *, domain_text: str | None = None,
               problem_text: str | None = None) -> tuple[Domain, Problem]:
    """Parse a domain and a problem of it; checks that they belong together.

    ``domain_text``/``problem_text`` give the PDDL itself instead of reading
    the files; the paths then only name them in messages (``<domain>:3:4``).
    """
    dname = str(domain_path)
    pname = str(problem_path)
    dsrc = _source_map(dname, "domain", domain_text)
    _check_kind(dsrc, "domain")
    _check_features(dsrc, "domain")
    psrc = _source_map(pname, "problem", problem_text)
    _check_kind(psrc, "problem")
    _check_features(psrc, "problem")
    dsrc, notes = _declared_once(dsrc, psrc)
    domain, problem = _task_of(dsrc, dname, psrc, pname)
    return with_evidence_comments(_noted(domain, notes), dsrc.text), problem


def _task_of(dsrc: SourceMap, dname: str, psrc: SourceMap, pname: str) -> tuple[Domain, Problem]:
    if adl_reader.needs_adl(dsrc):
        domain = adl_reader.read_domain(dsrc, dname)
        _check_domain_reference(psrc, domain)
        return domain, adl_reader.read_problem(psrc, pname, domain)
    if adl_reader.needs_adl(psrc) or _equality_in_goal(psrc):  # a STRIPS domain, an ADL goal (or one with '=')
        domain = _strips_domain(dsrc, dname)
        _check_domain_reference(psrc, domain)
        return domain, adl_reader.read_problem(psrc, pname, domain)
    try:
        return _strips_task(dsrc, dname, psrc, pname)
    except (PddlSyntaxError, PddlSemanticError) as exc:
        if not _translator_may_read(exc, dsrc, psrc):
            raise

        def read() -> tuple[Domain, Problem]:
            try:
                domain = _strips_domain(dsrc, dname)
            except (PddlSyntaxError, PddlSemanticError):
                domain = adl_reader.read_domain(dsrc, dname)
            _check_domain_reference(psrc, domain)
            return domain, adl_reader.read_problem(psrc, pname, domain)

        return _or_raise(exc, read)


def _equality_in_goal(psrc: SourceMap) -> bool:
    """Whether the problem's goal compares objects, ``(= a b)``: valid PDDL with ``:equality`` that the STRIPS
    paths do not read (their goal is a list of atoms); the ADL reader's goal formula holds it."""
    goal = psrc.section(":goal")
    return goal is not None and any(not isinstance(node, Token) and node.head() == EQUALITY for node in goal.walk())


def _strips_task(dsrc: SourceMap, dname: str, psrc: SourceMap, pname: str) -> tuple[Domain, Problem]:
    """The STRIPS paths: Fast Downward's translator parser as tarski reads, else tarski itself."""
    # The fast path first (Fast Downward's translator parser); anything it
    # does not accept goes through tarski, for its result or its error.
    domain = fast_reader.read_domain(dsrc, dname)
    if domain is not None:
        _check_domain_reference(psrc, domain)
        problem = fast_reader.read_problem(psrc, pname, domain)
        if problem is not None:
            return domain, problem
    reader = _new_reader()
    rewrite = _rewrite_for(dsrc, psrc)
    if rewrite.fresh:
        # Tarski is told the problem's types of implicit constants; the domain's own
        # errors come first all the same, as the domain alone has them (the fast path's order).
        alone = _rewrite_for(dsrc, None)
        _tarski_parse(reader, "domain", dsrc, alone)
        _check_belongs(psrc, _domain_from_tarski(reader, dsrc, dname, alone), rewrite)
        reader = _new_reader()
    _tarski_parse(reader, "domain", dsrc, rewrite)
    domain = _domain_from_tarski(reader, dsrc, dname, rewrite)
    domain_constants = dict(domain.constants)
    _check_belongs(psrc, domain, rewrite)
    _tarski_parse(reader, "problem", psrc, rewrite)
    problem = _problem_from_tarski(reader, psrc, pname, domain_constants, rewrite)
    _check_either_arguments(domain, dsrc, problem.objects, (psrc, problem))
    problem = replace(problem, function_values=costs.read_function_values(psrc, domain, problem.objects))
    return domain, problem


def _check_belongs(psrc: SourceMap, domain: Domain, rewrite: _Rewrite) -> None:
    """The problem names the domain and declares every implicit constant of it."""
    _check_domain_reference(psrc, domain)
    for name, use in rewrite.implicit.items():
        if name not in rewrite.fresh:  # the problem does not declare it either
            raise names.undeclared_implicit_constant(domain.source, use)


def _check_domain_reference(psrc: SourceMap, domain: Domain) -> None:
    """The problem must name the domain it was given with."""
    dom_ref = psrc.section(":domain")
    if dom_ref is not None and len(dom_ref.items) > 1 and isinstance(dom_ref.items[1], Token):
        ref = dom_ref.items[1]
        if ref.lower != domain.name:
            raise MismatchError(
                f"problem is for domain '{ref.text}', but the domain file defines '{domain.spellings.get(domain.name, domain.name)}'",
                psrc.location(ref.line, ref.col),
            )


def _problem_from_tarski(reader, src: SourceMap, path: str, domain_constants: dict[str, str],
                         rewrite: _Rewrite) -> Problem:
    lang = reader.problem.language
    # Tarski has each implicit constant as a domain constant (of the problem's
    # type) and the problem's declaration of it under a fresh name, which
    # keeps its place in the order of the problem's objects.
    back = {new: old for old, new in rewrite.fresh.items()}
    objects = {
        back.get(str(c.name).lower(), str(c.name).lower()): rewrite.type_name(c.sort.name)
        for c in lang.constants()
        if str(c.name).lower() not in domain_constants and str(c.name).lower() not in rewrite.implicit
    }
    init: set[Atom] = set()
    for atom in reader.problem.init.as_atoms():
        if not hasattr(atom, "predicate"):
            continue
        name = _pred_name(atom.predicate)
        init.add(Atom(name, tuple(_term_name(t) for t in atom.subterms)))
    goal = tuple(_literals(reader.problem.goal, src, "the goal"))
    metric = src.section(":metric") is not None
    for lit in goal:
        if lit.atom.predicate == EQUALITY:
            raise UnsupportedFeatureError("equality in the goal is not supported", src.locate("=", ":goal"))
    return Problem(
        name=str(reader.problem.name).lower(),
        domain_name=str(reader.problem.domain_name).lower(),
        objects=objects,
        init=frozenset(init),
        goal=goal,
        path=path,
        spellings=src.spellings(),
        metric=metric,
    )


def parse_problem_for(domain: Domain, problem_path: str | Path) -> Problem:
    """Parse a problem against an in-memory domain (e.g. a merged one)."""
    from dataclasses import replace

    from guided_lfd.pddl.writer import domain_to_pddl

    # Written under the name the problem expects: only the content must match.
    declared = SourceMap(str(problem_path), read_text(problem_path)).section(":domain")
    if declared is not None and len(declared.items) > 1 and isinstance(declared.items[1], Token):
        domain = replace(domain, name=declared.items[1].lower)
    with _temp_pddl(domain_to_pddl(domain)) as tmp:
        try:
            _, problem = parse_task(tmp, problem_path)
        except GuidedLfdError as exc:
            if exc.location is not None and exc.location.path == tmp:
                raise type(exc)(f"{exc.message} (in the domain {domain.path})", Location(domain.path)) from None
            raise
    return problem

