"""Code structure: no function body longer than 60 lines.

Every module under ``guided_lfd/`` and ``cli/`` is parsed with :mod:`ast`.
A function's body is measured in source lines from its first statement
after the docstring to the end of its last statement (blank lines and
comments in between count; the signature and docstring do not).  A long
function is split into named steps: small private helpers, each saying what
it does.  Two exceptions:

* a measured hot loop may stay long and must say so: a comment line starting
  with ``# Hot loop`` in the function's own body (not in a nested function);
* :data:`LONG_FUNCTIONS_ALLOWED`, functions not split yet (none today).
"""

from __future__ import annotations

import ast
from pathlib import Path

from conftest import ROOT

#: The longest function body allowed, in lines (after the docstring).
MAX_BODY_LINES = 60
#: The packages checked.
PACKAGES = ("guided_lfd", "cli")
#: The marker that keeps a measured hot loop long on purpose.
HOT_LOOP = "# Hot loop"

#: Functions allowed to stay long for now, as ``path::qualified name`` (none: every long
#: function has been split).  An entry whose function is no longer long (or gone) fails
#: test_allowlist_is_current, so the list only shrinks.
LONG_FUNCTIONS_ALLOWED: frozenset[str] = frozenset()

_FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)


def _first_line(node: ast.stmt) -> int:
    """The first source line of a statement, its decorators included."""
    decorators = getattr(node, "decorator_list", [])
    return min([node.lineno] + [d.lineno for d in decorators])


def _docstring_end(fn: ast.FunctionDef | ast.AsyncFunctionDef) -> int | None:
    """The last line of ``fn``'s docstring (None: it has none)."""
    first = fn.body[0]
    if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) and isinstance(first.value.value, str):
        return first.end_lineno or first.lineno
    return None


def _body_span(fn: ast.FunctionDef | ast.AsyncFunctionDef) -> tuple[int, int] | None:
    """First and last line of ``fn``'s body after its docstring (None: the docstring is all there is)."""
    body = fn.body[1:] if _docstring_end(fn) is not None else fn.body
    if not body:
        return None
    return _first_line(body[0]), body[-1].end_lineno or body[-1].lineno


def _nested_spans(fn: ast.AST) -> list[tuple[int, int]]:
    """Line spans of the functions defined inside ``fn`` (at any depth)."""
    return [(_first_line(node), node.end_lineno or node.lineno)
            for node in ast.walk(fn) if node is not fn and isinstance(node, _FUNCTIONS)]


def _says_hot_loop(fn: ast.FunctionDef | ast.AsyncFunctionDef, lines: list[str]) -> bool:
    """Whether a line of ``fn``'s own body (after the docstring, not in a nested function) is a ``# Hot loop``
    comment."""
    doc_end = _docstring_end(fn)
    start = doc_end + 1 if doc_end is not None else fn.lineno
    nested = _nested_spans(fn)
    return any(lines[n - 1].strip().startswith(HOT_LOOP)
               for n in range(start, (fn.end_lineno or fn.lineno) + 1) if not any(a <= n <= b for a, b in nested))


def _functions(tree: ast.Module):
    """(qualified name, node) of every function in ``tree``, methods and nested functions included."""
    def walk(node: ast.AST, prefix: str):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, _FUNCTIONS):
                yield prefix + child.name, child
                yield from walk(child, f"{prefix}{child.name}.<locals>.")
            elif isinstance(child, ast.ClassDef):
                yield from walk(child, f"{prefix}{child.name}.")
            else:
                yield from walk(child, prefix)
    yield from walk(tree, "")


def long_functions(source: str) -> list[tuple[str, int, int]]:
    """(qualified name, line, body length) of the functions in ``source`` over the limit, hot loops excepted."""
    lines = source.splitlines()
    out = []
    for name, fn in _functions(ast.parse(source)):
        span = _body_span(fn)
        if span is None:
            continue
        length = span[1] - span[0] + 1
        if length > MAX_BODY_LINES and not _says_hot_loop(fn, lines):
            out.append((name, fn.lineno, length))
    return out


def _modules() -> list[Path]:
    return sorted(p for package in PACKAGES for p in (ROOT / package).rglob("*.py"))


def _long_in_tree() -> dict[str, tuple[int, int]]:
    """``path::name`` -> (line, body length) of every long function under :data:`PACKAGES`."""
    found = {}
    for path in _modules():
        rel = path.relative_to(ROOT).as_posix()
        for name, line, length in long_functions(path.read_text(encoding="utf-8")):
            found[f"{rel}::{name}"] = (line, length)
    return found


def test_modules_found() -> None:
    assert len(_modules()) > 20
    assert (ROOT / "guided_lfd" / "benchmark" / "household.py") in _modules()


def test_no_long_functions() -> None:
    offenders = {key: where for key, where in _long_in_tree().items() if key not in LONG_FUNCTIONS_ALLOWED}
    assert not offenders, (
        f"function bodies over {MAX_BODY_LINES} lines (after the docstring); split them into named steps, or, "
        f"for a measured hot loop, say so with a '{HOT_LOOP}' comment in its body:\n"
        + "\n".join(f"  {key.split('::')[0]}:{line}: {key.split('::')[1]} ({length} lines)"
                    for key, (line, length) in sorted(offenders.items())))


def test_allowlist_is_current() -> None:
    stale = sorted(LONG_FUNCTIONS_ALLOWED - set(_long_in_tree()))
    assert not stale, ("LONG_FUNCTIONS_ALLOWED names functions that are no longer over the limit (or gone); "
                       "remove them:\n" + "\n".join(f"  {key}" for key in stale))


def _function(name: str, body_lines: int, docstring: bool = True, extra: str = "") -> str:
    doc = '    """Doc."""\n' if docstring else ""
    return f"def {name}():\n{doc}{extra}" + "".join(f"    x{k} = {k}\n" for k in range(body_lines))


def test_measure() -> None:
    assert long_functions(_function("ok", 60)) == []
    assert long_functions(_function("long", 61)) == [("long", 1, 61)]
    assert long_functions(_function("long", 60, docstring=False, extra="    y = 0\n")) == [("long", 1, 61)]
    # A hot loop may stay long when it says so; a nested function's marker does not count for its parent.
    assert long_functions(_function("hot", 80, extra="    # Hot loop: measured, plain locals on purpose.\n")) == []
    assert long_functions(_function("hot", 80) + "    # Hot loop (at the end)\n    pass\n") == []
    assert long_functions(_function("hot", 80) + "    # hot loop, not the marker\n    pass\n") == [("hot", 1, 82)]
    nested = ("def outer():\n    def inner():\n        # Hot loop: inner only.\n        pass\n"
              + "".join(f"    x{k} = {k}\n" for k in range(60)))
    assert long_functions(nested) == [("outer", 1, 63)]
    method = "class C:\n" + "\n".join("    " + line for line in _function("m", 61).splitlines()) + "\n"
    assert long_functions(method) == [("C.m", 2, 61)]
