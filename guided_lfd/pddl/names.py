"""What both reading paths need to know about names beyond plain STRIPS.

Three things valid PDDL (and Fast Downward's translator) allows that tarski
refuses or reads otherwise:

* ``(either a b)`` types of predicate parameters;
* a name that is both a type and an object or constant (types and objects
  are separate namespaces in PDDL; tarski has one namespace for both);
* an action that uses an object the domain does not declare (older IPC
  domains leave it to the problem's objects): an *implicit constant*.

This module finds them on the source map (structure only: list heads,
``-`` in typed lists), so the fast path and the tarski path see the same
names, and builds the column-preserving substitutes the tarski path gives
tarski: an ``either`` list becomes ``object`` padded with spaces, a type
named like an object gets another name of the same length.
"""

from __future__ import annotations

import itertools
import re
import string
from dataclasses import dataclass
from typing import Iterable, Iterator

from guided_lfd.errors import Location, PddlSemanticError, PddlSyntaxError, UnsupportedFeatureError
from guided_lfd.pddl.model import PDDL_NAME, either_type, reached
from guided_lfd.pddl.source import SExpr, SourceMap, Token

#: Heads of lists in a STRIPS condition or effect that are not atoms.
_CONNECTIVES = {"and", "not"}
#: Lower-case words tarski or the reader take as keywords or built-in sorts: never a substitute name.
_NOT_A_SUBSTITUTE = {
    "and", "or", "not", "imply", "exists", "forall", "when", "either", "define", "domain", "problem", "object",
    "number", "int", "float", "increase", "decrease", "assign", "max", "min", "sin", "cos", "tan", "exp", "abs",
    "sqrt", "real", "integer", "natural", "at", "over", "all", "start", "end", "total-time", "is-violated",
}

#: Words tarski's lexer reads as keywords: never names on the fast path.
RESERVED_WORDS = {
    "define", "domain", "problem", "and", "not", "or", "imply", "exists", "forall", "when", "either", "object",
    "number", "int", "float", "assign", "increase", "decrease", "scale-up", "scale-down", "max", "min", "sin",
    "cos", "sqrt", "tan", "acos", "asin", "atan", "exp", "abs", "preference", "minimize", "maximize",
    "is-violated", "at-end", "always", "sometime", "within", "at-most-once", "sometime-after", "sometime-before",
    "always-within", "hold-during", "hold-after",
}


def typed_names(items: list[SExpr | Token]) -> list[tuple[Token, SExpr | Token | None]]:
    """(name, type) of a typed list's names, the type as written (a token, an ``either`` list) or None.

    Items that are not names (a stray list) are skipped: the parsers report them.
    """
    out: list[tuple[Token, SExpr | Token | None]] = []
    pending: list[Token] = []
    i = 0
    while i < len(items):
        item = items[i]
        if isinstance(item, Token) and item.text == "-" and i + 1 < len(items):
            out += [(name, items[i + 1]) for name in pending]
            pending = []
            i += 2
            continue
        if isinstance(item, Token):
            pending.append(item)
        i += 1
    return out + [(name, None) for name in pending]


def _predicate_declarations(src: SourceMap) -> list[SExpr]:
    section = src.section(":predicates")
    if section is None:
        return []
    return [p for p in section.items[1:] if isinstance(p, SExpr)]


def _either_lists(src: SourceMap) -> list[SExpr]:
    return [n for n in src.define().walk() if isinstance(n, SExpr) and n.head() == "either"]


def check_either(src: SourceMap) -> None:
    """``(either TYPE ...)`` only as the type of a predicate parameter (as Fast Downward allows it)."""
    allowed: set[int] = set()
    for pred in _predicate_declarations(src):
        for k, item in enumerate(pred.items[:-1]):
            if isinstance(item, Token) and item.text == "-" and isinstance(pred.items[k + 1], SExpr):
                allowed.add(id(pred.items[k + 1]))
    for node in _either_lists(src):
        tok = node.items[0]
        assert isinstance(tok, Token)
        if id(node) not in allowed:
            raise UnsupportedFeatureError(
                f"'{tok.text}' types are supported in predicate declarations only (expected a single type name)",
                src.location(tok.line, tok.col))
        members = node.items[1:]
        bad = next((m for m in members if not isinstance(m, Token) or not PDDL_NAME.fullmatch(m.text)), None)
        if not members or bad is not None:
            where = bad if bad is not None else node
            raise PddlSyntaxError(f"expected '({tok.text} TYPE ...)' with one or more type names",
                                  src.location(where.line, where.col))


def predicate_either_types(src: SourceMap) -> dict[str, dict[int, tuple[str, SExpr]]]:
    """Per predicate (lower-case), the parameters typed ``(either ...)``: index -> (model type, the list)."""
    out: dict[str, dict[int, tuple[str, SExpr]]] = {}
    for pred in _predicate_declarations(src):
        if pred.head() is None:
            continue
        for k, (_, typ) in enumerate(typed_names(pred.items[1:])):
            if isinstance(typ, SExpr) and typ.head() == "either":
                members = [m.text for m in typ.items[1:] if isinstance(m, Token)]
                out.setdefault(pred.head() or "", {})[k] = (either_type(members), typ)
    return out


def check_either_members(src: SourceMap, types: dict[str, str | None]) -> None:
    """Every member of an ``either`` type is a declared type (tarski is given ``object`` instead)."""
    for node in _either_lists(src):
        for member in node.items[1:]:
            if isinstance(member, Token) and member.lower not in types and member.lower != "object":
                raise PddlSemanticError(f"unknown type '{member.text}' (expected a type declared in :types)",
                                        src.location(member.line, member.col))


def declared_constants(src: SourceMap, section: str = ":constants") -> list[tuple[Token, SExpr | Token | None]]:
    """The names (and types as written) a ``:constants`` or ``:objects`` section declares."""
    node = src.section(section)
    return typed_names(node.items[1:]) if node is not None else []


def declared_twice(name: str, where: Location) -> PddlSemanticError:
    """The error for a name declared twice in one namespace (both reading paths word it so)."""
    return PddlSemanticError(f"'{name}' is declared twice (expected each type, constant, object, predicate and action "
                             "name once)", where)


def check_objects_once(src: SourceMap, section: str, taken: Iterable[str] = ()) -> None:
    """Refuse (exit 32, at the second declaration) a name ``section`` (``:constants``, ``:objects``) declares twice,
    or one of ``taken`` (the domain's constants), as Fast Downward's translator does ("duplicate objects")."""
    seen = set(taken)
    for tok, _ in declared_constants(src, section):
        if tok.lower in seen:
            raise declared_twice(tok.text, Location(src.path, tok.line, tok.col))
        seen.add(tok.lower)


def _action_parts(act: SExpr) -> tuple[list[str], list[SExpr]]:
    """An action's parameter names (lower-case) and its precondition and effect lists."""
    params: list[str] = []
    bodies: list[SExpr] = []
    items = act.items
    for k, item in enumerate(items[:-1]):
        if not isinstance(item, Token):
            continue
        value = items[k + 1]
        if item.lower == ":parameters" and isinstance(value, SExpr):
            params = [t.lower for t in value.items if isinstance(t, Token) and t.text.startswith("?")]
        elif item.lower in (":precondition", ":effect") and isinstance(value, SExpr):
            bodies.append(value)
    return params, bodies


@dataclass(frozen=True)
class ImplicitUse:
    """The first use of an implicit constant: in which action, at which token."""

    name: str
    action: str
    token: Token


def _action_atoms(src: SourceMap) -> Iterator[tuple[str, list[str], SExpr]]:
    """(action name, its parameters, atom) of every atom in the actions' preconditions and effects."""
    for act in src.define().items:
        if not isinstance(act, SExpr) or act.head() != ":action" or len(act.items) < 2:
            continue
        name = act.items[1].lower if isinstance(act.items[1], Token) else "?"
        params, bodies = _action_parts(act)
        for body in bodies:
            for node in (body, *body.walk()):
                if isinstance(node, SExpr) and node.head() not in _CONNECTIVES and node.head() is not None:
                    yield name, params, node


def implicit_constant_uses(src: SourceMap) -> dict[str, ImplicitUse]:
    """Names the domain's actions use as arguments that are neither their parameters nor declared constants.

    In order of first use.  Only words that are PDDL names count (a number,
    say, is left to the parsers to refuse).
    """
    constants = {tok.lower for tok, _ in declared_constants(src)}
    out: dict[str, ImplicitUse] = {}
    for action, params, atom in _action_atoms(src):
        for arg in atom.items[1:]:
            if (isinstance(arg, Token) and arg.lower not in constants and arg.lower not in params
                    and PDDL_NAME.fullmatch(arg.text) and arg.lower not in out):
                out[arg.lower] = ImplicitUse(arg.lower, action, arg)
    return out


def implicit_constant_type(src: SourceMap, name: str) -> str:
    """The type an implicit constant is read with when no problem declares it (lower-case).

    The most specific of the types its uses need (predicate and cost-function parameters; an
    ``either`` parameter needs none), so that every use that some object
    could fit type-checks; with no such type the first one needed (a use then
    does not type-check, which no object could fix).
    """
    declared: dict[str, list[str | None]] = {}
    functions = src.section(":functions")
    cost_functions = [f for f in functions.items[1:] if isinstance(f, SExpr)] if functions is not None else []
    for pred in [*_predicate_declarations(src), *cost_functions]:  # a cost term's arguments need types too
        declared[pred.head() or ""] = [None if isinstance(t, SExpr) else (t.lower if t is not None else "object")
                                       for _, t in typed_names(pred.items[1:])]
    try:
        parents = {n.lower(): (p or "object").lower() for n, p in src.types_parents_first() or []}
    except PddlSemanticError:
        parents = {}  # a cycle or a type declared twice: the parsers report it
    needed: list[str] = []
    for _, _, atom in _action_atoms(src):
        types = declared.get(atom.head() or "", [])
        for k, arg in enumerate(atom.items[1:]):
            if isinstance(arg, Token) and arg.lower == name and k < len(types) and types[k] is not None:
                needed.append(types[k])  # type: ignore[arg-type]
    for t in needed:
        if all(r in _ancestors(t, parents) for r in needed):
            return t
    return needed[0] if needed else "object"


def _ancestors(t: str, parents: dict[str, str]) -> set[str]:
    out = {t, "object"}
    while t in parents and parents[t] not in out:
        t = parents[t]
        out.add(t)
    return out


def implicit_constant_warning(src: SourceMap, use: ImplicitUse) -> str:
    """The one-line warning about an implicit constant, at its first use."""
    where = Location(src.path, use.token.line, use.token.col)
    return (f"{where}: warning: '{use.token.text}' in action '{use.action}' is not a declared constant; "
            f"it is read as one, its type taken from the problem's objects")


def undeclared_implicit_constant(src: SourceMap, use: ImplicitUse) -> PddlSemanticError:
    """The error for an implicit constant the problem does not declare either."""
    return PddlSemanticError(
        f"unknown object '{use.token.text}' in action '{use.action}' (expected a domain constant, "
        f"or an object declared in the problem's :objects)",
        Location(src.path, use.token.line, use.token.col))


def type_names(src: SourceMap) -> set[str]:
    """The types a domain declares in ``:types`` (lower-case), parents included, ``object`` (built in) not."""
    section = src.section(":types")
    if section is None:
        return set()
    return {t.lower for t in section.items[1:] if isinstance(t, Token) and t.text != "-"} - {"object"}


def predicate_names(src: SourceMap) -> set[str]:
    """The predicates a domain declares (lower-case)."""
    return {p.head() or "" for p in _predicate_declarations(src)}


def object_names(dsrc: SourceMap, psrc: SourceMap | None) -> set[str]:
    """Domain constants, implicit constants and (with a problem) its objects (lower-case)."""
    names = {tok.lower for tok, _ in declared_constants(dsrc)} | set(implicit_constant_uses(dsrc))
    if psrc is not None:
        names |= {tok.lower for tok, _ in declared_constants(psrc, ":objects")}
    return names


def shared_type_names(dsrc: SourceMap, psrc: SourceMap | None = None) -> set[str]:
    """Types also used as the name of an object or constant (a type named like a predicate is left as it is)."""
    return (type_names(dsrc) & object_names(dsrc, psrc)) - predicate_names(dsrc)


def fresh_names(wanted: list[str], *sources: SourceMap | None) -> list[str]:
    """For each name in ``wanted``, an unused name of the same length (so no column moves), all different.

    Unused: no token of ``sources`` is spelled so, nor a keyword; the names
    are lower-case, as tarski reads names.  Longer only when every name of
    that length is taken (then columns after it on its line move).
    """
    if not wanted:
        return []  # (no walk over a large problem's tokens)
    taken = set(_NOT_A_SUBSTITUTE) | RESERVED_WORDS
    for src in sources:
        if src is not None:
            taken |= {t.lower for t in src.define().walk() if isinstance(t, Token)}
    out: list[str] = []
    for name in wanted:
        out.append(_unused(len(name), taken))
        taken.add(out[-1])
    return out


def _unused(length: int, taken: set[str]) -> str:
    tail = string.ascii_lowercase + string.digits
    for size in itertools.count(max(1, length)):
        # 'z' first: real names rarely start with it, so the first candidates are usually free.
        for first in "zqxjkvwyubcdefghilmnoprsta":
            for rest in itertools.product(tail, repeat=size - 1):
                candidate = first + "".join(rest)
                if candidate not in taken:
                    return candidate
    raise AssertionError("unreachable")


def type_positions(src: SourceMap, renamed: set[str]) -> list[Token]:
    """Tokens of ``src`` that name a type in ``renamed``: in ``:types``, after ``-``, inside ``either``."""
    out: list[Token] = []
    if not renamed:
        return out
    types = src.section(":types")
    in_types = {id(t) for t in types.items[1:]} if types is not None else set()
    for node in (src.define(), *src.define().walk()):
        if not isinstance(node, SExpr):
            continue
        either = node.head() == "either"
        for k, item in enumerate(node.items):
            if isinstance(item, Token) and item.lower in renamed:
                after_dash = k > 0 and isinstance(node.items[k - 1], Token) and node.items[k - 1].text == "-"
                if id(item) in in_types or after_dash or (either and k > 0):
                    out.append(item)
    return out


def substituted(text: str, src: SourceMap, tokens: list[tuple[Token, str]], eithers: list[SExpr]) -> str:
    """``text`` (offsets as ``src``'s) with ``tokens`` respelled and each ``either`` list as padded ``object``."""
    starts = [0] + [m.end() for m in re.finditer("\n", text)]
    edits: list[tuple[int, int, str]] = []
    for tok, new in tokens:
        at = starts[tok.line - 1] + tok.col - 1
        if not any(node.start <= at <= node.end for node in eithers):  # an either list goes as a whole
            edits.append((at, at + len(tok.text), new))
    for node in eithers:
        old = text[node.start:node.end + 1]
        # Line breaks stay where they were: nothing after the list moves.
        edits.append((node.start, node.end + 1, "object" + "".join(c if c in "\r\n" else " " for c in old[6:])))
    pieces, last = [], 0
    for begin, end, new in sorted(edits):
        pieces += [text[last:begin], new]
        last = end
    pieces.append(text[last:])
    return "".join(pieces)


def either_lists(src: SourceMap) -> list[SExpr]:
    """Every ``(either ...)`` list of ``src`` (after :func:`check_either`, all in predicate declarations)."""
    return _either_lists(src)


# -- a type declared twice ------------------------------------------------------------------------------------------

def _type_groups(items: list[SExpr | Token]) -> list[tuple[list[Token], Token | None, Token | None]] | None:
    """The ``:types`` section's groups: (names, the ``-``, the parent), parent None where none is written;
    None when a list stands among them (``either``: the feature check refuses it)."""
    groups: list[tuple[list[Token], Token | None, Token | None]] = []
    pending: list[Token] = []
    i = 0
    while i < len(items):
        item = items[i]
        if not isinstance(item, Token):
            return None
        if item.text == "-" and i + 1 < len(items) and isinstance(items[i + 1], Token):
            groups.append((pending, item, items[i + 1]))  # type: ignore[arg-type]
            pending = []
            i += 2
            continue
        pending.append(item)
        i += 1
    return groups + [(pending, None, None)] if pending else groups


def types_declared_once(src: SourceMap) -> tuple[SourceMap, list[str]]:
    """``src`` with each type ``:types`` declares more than once declared once, and a warning for each.

    Fast Downward reads such a type as one, below every parent it is given;
    the model has one parent per type, so of parents one below the other
    (``area - object`` and ``area - place``) the lowest is kept, which is the
    same type.  Parents neither below the other are left for the readers'
    "declared twice" error.  The other declarations become spaces (no
    position moves), with their ``- parent`` where no other name shares it.
    """
    section = src.section(":types")
    groups = _type_groups(section.items[1:]) if section is not None else None
    if not groups:
        return src, []
    found: dict[str, list[tuple[Token, str]]] = {}
    for names, _, parent in groups:
        for tok in names:
            found.setdefault(tok.lower, []).append((tok, parent.lower if parent is not None else "object"))
    parents = {name: {up for _, up in decls if up != name} for name, decls in found.items()}
    blank: set[int] = set()
    warnings: list[str] = []
    for name, decls in found.items():
        if len(decls) < 2:
            continue
        kept = next((d for d in decls if all(up in reached(d[1], parents) for _, up in decls)), None)
        if kept is None:
            continue
        blank |= {id(tok) for tok, _ in decls if tok is not kept[0]}
        first, again = decls[0][0], decls[1][0]
        warnings.append(f"{src.path}:{again.line}:{again.col}: warning: type '{again.text}' is declared again (first "
                        f"at {first.line}:{first.col}); read as one type below '{kept[1]}', as Fast Downward reads it")
    if not blank:
        return src, []
    tokens = [tok for names, _, _ in groups for tok in names if id(tok) in blank]
    for names, dash, parent in groups:
        if dash is not None and parent is not None and all(id(tok) in blank for tok in names):
            tokens += [dash, parent]
    text = substituted(src.text, src, [(tok, " " * len(tok.text)) for tok in tokens], [])
    return SourceMap(src.path, text), warnings
