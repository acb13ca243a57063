"""Reading PDDL text and mapping names back to file positions.

The PDDL itself is parsed by tarski.  Tarski reports syntax errors with a
position but semantic errors ("undefined element z") without one, so this
module keeps a *source map*: the text split into s-expressions that remember
their line and column.  It answers "where is the token ``z`` inside the
``:init`` section?" and catches unbalanced parentheses with a precise
position before the parser sees the text.  It does not interpret PDDL.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from guided_lfd.errors import Location, PddlSemanticError, PddlSyntaxError

_TOKEN = re.compile(r";[^\n]*|\(|\)|[^\s()]+")

#: Deeper nesting is refused: real PDDL stays far below, and parsers recurse.
MAX_DEPTH = 64


def check_ascii(path: str, text: str) -> None:
    """Refuse (:class:`PddlSyntaxError`, exit 31) a character outside ASCII before a line's ``;`` comment.

    Fast Downward's translator refuses such a file ("Non-ASCII character
    outside comment"), and every command hands the translator what it reads
    (invariants, ADL grounding), so a name such as ``tür`` or ``盘子``, or a
    right-to-left override, is one syntax error at its line and column for
    every command.  Comments may hold any character.
    """
    if text.isascii():
        return
    for number, line in enumerate(text.split("\n"), start=1):
        code = line.split(";", 1)[0]
        if not code.isascii():
            col, char = next((k, c) for k, c in enumerate(code, start=1) if not c.isascii())
            raise PddlSyntaxError(
                f"non-ASCII character {char!r} (U+{ord(char):04X}) outside a comment, expected ASCII (Fast "
                "Downward's translator reads no other; comments may hold any character)", Location(path, number, col))


@dataclass
class SExpr:
    """A parenthesised list with the position of its opening parenthesis."""

    line: int
    col: int
    items: list["SExpr | Token"] = field(default_factory=list)
    start: int = 0  # character offsets of '(' and of the matching ')'
    end: int = 0

    def head(self) -> str | None:
        """The lower-cased first token, if the list starts with a token."""
        if self.items and isinstance(self.items[0], Token):
            return self.items[0].lower
        return None

    def walk(self):
        """Yield every token and list below this one, depth first."""
        for item in self.items:
            yield item
            if isinstance(item, SExpr):
                yield from item.walk()


@dataclass
class Token:
    """A single symbol with its 1-based position."""

    text: str
    line: int
    col: int

    @property
    def lower(self) -> str:
        return self.text.lower()


class SourceMap:
    """The s-expression structure of one PDDL file, with positions."""

    def __init__(self, path: str, text: str, definition: str = "(define ...)") -> None:
        self.path = path
        self.text = text
        #: What the file's one top-level list should be, for error messages.
        self.definition = definition
        self.roots: list[SExpr] = []
        self._build()

    def location(self, line: int | None = None, col: int | None = None) -> Location:
        """A :class:`Location` in this file."""
        return Location(self.path, line, col)

    def _build(self) -> None:
        line_starts = [0]
        for match in re.finditer("\n", self.text):
            line_starts.append(match.end())
        import bisect

        stack: list[SExpr] = []
        for match in _TOKEN.finditer(self.text):
            tok = match.group()
            if tok.startswith(";"):
                continue
            offset = match.start()
            line = bisect.bisect_right(line_starts, offset)
            col = offset - line_starts[line - 1] + 1
            if tok == "(":
                node = SExpr(line, col, start=offset)
                if stack:
                    stack[-1].items.append(node)
                else:
                    self.roots.append(node)
                stack.append(node)
                if len(stack) > MAX_DEPTH:
                    raise PddlSyntaxError(
                        f"nested more than {MAX_DEPTH} levels deep, expected PDDL of reasonable depth",
                        self.location(line, col),
                    )
            elif tok == ")":
                if not stack:
                    raise PddlSyntaxError("unexpected ')' with no matching '('", self.location(line, col))
                stack.pop().end = offset
            else:
                if not stack:
                    raise PddlSyntaxError(
                        f"unexpected '{tok}' outside of any parenthesis, expected '('",
                        self.location(line, col),
                    )
                stack[-1].items.append(Token(tok, line, col))
        if stack:
            node = stack[-1]
            raise PddlSyntaxError(
                "'(' is never closed, expected ')' before the end of the file",
                self.location(node.line, node.col),
            )
        if not self.roots:
            raise PddlSyntaxError(f"no PDDL definition found, expected '{self.definition}'", self.location(1, 1))
        if len(self.roots) > 1:
            extra = self.roots[1]
            raise PddlSyntaxError(
                f"text after the end of the definition, expected one '{self.definition}'",
                self.location(extra.line, extra.col),
            )

    # -- queries -----------------------------------------------------------
    def define(self) -> SExpr:
        """The top-level ``(define ...)`` list."""
        return self.roots[0]

    def section(self, keyword: str) -> SExpr | None:
        """The top-level section starting with ``keyword`` (e.g. ``:init``)."""
        keyword = keyword.lower()
        for item in self.define().items:
            if isinstance(item, SExpr) and item.head() == keyword:
                return item
        return None

    def action(self, name: str) -> SExpr | None:
        """The ``(:action name ...)`` list."""
        for item in self.define().items:
            if isinstance(item, SExpr) and item.head() == ":action":
                if len(item.items) > 1 and isinstance(item.items[1], Token) and item.items[1].lower == name.lower():
                    return item
        return None

    def find_token(self, name: str, within: SExpr | None = None) -> Token | None:
        """The first token spelled ``name`` (case-insensitive) inside ``within``."""
        scope = within if within is not None else self.define()
        name = name.lower()
        for item in scope.walk():
            if isinstance(item, Token) and item.lower == name:
                return item
        return None

    def locate(self, name: str, *sections: str) -> Location:
        """Best position of ``name``: searched in ``sections`` first, then anywhere."""
        for keyword in sections:
            scope = self.section(keyword)
            if scope is not None:
                tok = self.find_token(name, scope)
                if tok is not None:
                    return self.location(tok.line, tok.col)
        tok = self.find_token(name)
        if tok is not None:
            return self.location(tok.line, tok.col)
        return self.location(self.define().line, self.define().col)

    def types_parents_first(self) -> list[tuple[str, str | None]] | None:
        """The ``:types`` declarations as (name, parent or None), parents before children.

        None when there is no ``:types`` section or it holds a list (``either``,
        left for the feature check).  Raises :class:`PddlSemanticError` on a
        cycle or a type declared twice.
        """
        section = self.section(":types")
        if section is None:
            return None
        names: list[str] = []
        parent: dict[str, str] = {}
        pending: list[str] = []
        items = section.items[1:]
        i = 0
        while i < len(items):
            item = items[i]
            if isinstance(item, Token) and item.text == "-" and i + 1 < len(items) and isinstance(items[i + 1], Token):
                for name in pending:
                    parent[name] = items[i + 1].text  # type: ignore[union-attr]
                pending = []
                i += 2
                continue
            if not isinstance(item, Token):
                return None
            if item.lower in {n.lower() for n in names}:
                raise PddlSemanticError(f"type '{item.text}' is declared twice in :types",
                                        self.location(item.line, item.col))
            names.append(item.text)
            pending.append(item.text)
            i += 1
        lower = {n.lower() for n in names}
        ordered: list[str] = []
        done: set[str] = set()
        while len(ordered) < len(names):
            progress = False
            for name in names:
                if name.lower() in done:
                    continue
                up = parent.get(name)
                if up is None or up.lower() not in lower or up.lower() in done:
                    ordered.append(name)
                    done.add(name.lower())
                    progress = True
            if not progress:
                cycle = [n for n in names if n.lower() not in done]
                raise PddlSemanticError(
                    "type hierarchy has a cycle: " + ", ".join(f"{n} - {parent[n]}" for n in cycle),
                    self.location(section.line, section.col),
                )
        return [(n, parent.get(n)) for n in ordered]

    def text_with_types_parents_first(self, text: str | None = None) -> str:
        """The text (or ``text``, the same up to the section's end) with ``:types`` reordered so parents come first.

        PDDL allows ``(:types truck - vehicle vehicle - object)``; tarski needs
        ``vehicle`` declared before it is used as a parent.  A type declared
        without a parent is written ``- object`` (bare, the next group would
        take it in).  Line breaks are kept, so positions outside the section
        do not move.
        """
        text = self.text if text is None else text
        ordered = self.types_parents_first()
        if ordered is None:
            return text
        section = self.section(":types")
        assert section is not None
        decl = " ".join(n if up is None and n.lower() == "object" else f"{n} - {up or 'object'}" for n, up in ordered)
        old = text[section.start : section.end + 1]
        new = f"(:types {decl}" + "\n" * old.count("\n") + ")"
        return text[: section.start] + new + text[section.end + 1 :]

    def _sections(self, sections: tuple[str, ...]) -> list[SExpr]:
        out = []
        for keyword in sections:
            if keyword == ":action":
                out += [i for i in self.define().items if isinstance(i, SExpr) and i.head() == ":action"]
            else:
                scope = self.section(keyword)
                if scope is not None:
                    out.append(scope)
        return out

    def locate_head(self, name: str, *sections: str) -> Location:
        """Where ``(name ...)`` is applied (a predicate), searched in ``sections`` first."""
        name = name.lower()
        for scope in self._sections(sections):
            for item in scope.walk():
                if isinstance(item, SExpr) and item.head() == name:
                    tok = item.items[0]
                    return self.location(tok.line, tok.col)  # type: ignore[union-attr]
        return self.locate(name)

    def locate_argument(self, name: str, *sections: str) -> Location:
        """Where ``name`` is used as an argument (not a list head), in ``sections`` first."""
        name = name.lower()
        for scope in self._sections(sections):
            for item in scope.walk():
                if isinstance(item, SExpr):
                    for tok in item.items[1:]:
                        if isinstance(tok, Token) and tok.lower == name:
                            return self.location(tok.line, tok.col)
        return self.locate(name)

    def locate_second(self, name: str) -> Location:
        """The second occurrence of ``name`` (a duplicate declaration), else the first."""
        name = name.lower()
        found = [t for t in self.define().walk() if isinstance(t, Token) and t.lower == name]
        tok = found[1] if len(found) > 1 else (found[0] if found else None)
        if tok is None:
            return self.location(self.define().line, self.define().col)
        return self.location(tok.line, tok.col)

    def locate_second_action(self, name: str) -> Location:
        """The second ``(:action name`` (case-insensitive)."""
        found = [i for i in self.define().items if isinstance(i, SExpr) and i.head() == ":action"
                 and len(i.items) > 1 and isinstance(i.items[1], Token) and i.items[1].lower == name.lower()]
        node = found[1] if len(found) > 1 else (found[0] if found else self.define())
        return self.location(node.line, node.col)

    def spellings(self) -> dict[str, str]:
        """Map lower-case names to their first spelling in the file (``PinkDrawer``)."""
        out: dict[str, str] = {}
        for item in self.define().walk():
            if isinstance(item, Token):
                out.setdefault(item.lower, item.text)
        return out
