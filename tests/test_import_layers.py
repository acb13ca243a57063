"""The library's imports flow one way: no module imports itself back, and no layer imports a higher one.

Every import of ``guided_lfd`` is read from the source (at module level and inside functions alike), so an
import hidden in a function to dodge a circle still counts.  Imports under ``if TYPE_CHECKING:`` are never
run: they name a type for annotations (a renderer names the report it reads) and are not counted.

The layers, lowest first (a module may import its own layer and those below):

0. errors, reporting, memory, deadline, io, paths: what every part uses
1. pddl: the lifted model and its readers and writers
2. planning: ground tasks, relaxations, search, validation
3. symbolic, excuse: the decision-diagram engine and the excuse search
4. demonstration, merge: segmenting, learning and merging skills
5. teach (session, request, human, learning, folder, loop), evaluate, preference: the loop with a person, the
   paper's measures, the human model
6. api, up, the package itself: the library's faces
7. benchmark (with benchmark/household, the household series' tasks), study: measurements over everything below
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from conftest import ROOT

PACKAGE = ROOT / "guided_lfd"

LAYERS: dict[str, int] = {
    "errors": 0, "reporting": 0, "memory": 0, "deadline": 0, "io": 0, "paths": 0,
    "pddl": 1,
    "planning": 2,
    "symbolic": 3, "excuse": 3,
    "demonstration": 4, "merge": 4,
    "teach": 5, "evaluate": 5, "preference": 5,
    "api": 6, "up": 6, "": 6,
    "benchmark": 7, "study": 7,
}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def library_modules() -> dict[str, Path]:
    return {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def _type_checking_nodes(tree: ast.AST) -> set[int]:
    """The ids of the nodes under ``if TYPE_CHECKING:`` (never run)."""
    skipped: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING":
            for statement in node.body:
                skipped.update(id(n) for n in ast.walk(statement))
    return skipped


def imported_modules(name: str, path: Path, modules: dict[str, Path]) -> dict[str, int]:
    """The library modules ``name`` imports (module -> first line), wherever in the file the import stands."""

    def resolve(target: str) -> str | None:
        while target and target not in modules:
            target = target.rpartition(".")[0]
        return target or None

    tree = ast.parse(path.read_text(encoding="utf-8"))
    skipped = _type_checking_nodes(tree)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out: dict[str, int] = {}
    for node in ast.walk(tree):
        if id(node) in skipped:
            continue
        targets: list[str] = []
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package
                for _ in range(node.level - 1):
                    anchor = anchor.rpartition(".")[0]
                base = f"{anchor}.{base}" if base else anchor
            # `from guided_lfd.excuse import outcome` imports the module guided_lfd.excuse.outcome.
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names]
        for target in targets:
            if target.startswith("guided_lfd"):
                found = resolve(target)
                if found and found != name:
                    out.setdefault(found, node.lineno)
    return out


def import_graph() -> dict[str, dict[str, int]]:
    modules = library_modules()
    return {name: imported_modules(name, path, modules) for name, path in modules.items()}


def circles(graph: dict[str, dict[str, int]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm, iteratively)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    counter = 0
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(graph[root]))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(graph.get(child, ()))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def layer(module: str) -> int:
    parts = module.split(".")
    return LAYERS[parts[1] if len(parts) > 1 else ""]


def test_every_library_module_has_a_layer():
    unplaced = sorted({m.split(".")[1] for m in library_modules() if "." in m} - set(LAYERS))
    assert not unplaced, f"add these to LAYERS (and the docstring): {unplaced}"


def test_no_module_imports_itself_back_through_others():
    assert circles(import_graph()) == []


def test_no_layer_imports_a_higher_one():
    upward = [f"{m} (layer {layer(m)}) imports {t} (layer {layer(t)}) at line {line}"
              for m, targets in import_graph().items() for t, line in targets.items() if layer(t) > layer(m)]
    assert upward == []


def test_the_front_door_does_not_import_unified_plannings_package():
    """``up/`` builds on ``api`` (its engines plan and validate through it), never the other way: the package's
    face reads a unified-planning problem through ``up``."""
    graph = import_graph()
    assert [t for t in graph["guided_lfd.api"] if t.startswith("guided_lfd.up")] == []
    assert "guided_lfd.api" in graph["guided_lfd.up.engines"]


@pytest.mark.parametrize("source, expected", [
    # a circle hidden inside functions is still a circle
    ({"a": "def f():\n    from guided_lfd.b import x\n", "b": "from guided_lfd.a import f\n"}, [["guided_lfd.a", "guided_lfd.b"]]),
    # a type named for annotations only is not
    ({"a": "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from guided_lfd.b import X\n",
      "b": "from guided_lfd.a import f\n"}, []),
    # `from package import module` is an import of the module
    ({"a": "from guided_lfd import b\n", "b": "def g():\n    from guided_lfd.a import f\n"},
     [["guided_lfd.a", "guided_lfd.b"]]),
])
def test_the_check_sees_circles_wherever_the_import_stands(tmp_path, source, expected):
    package = tmp_path / "guided_lfd"
    package.mkdir()
    (package / "__init__.py").write_text("")
    paths = {}
    for name, text in source.items():
        (package / f"{name}.py").write_text(text)
        paths[f"guided_lfd.{name}"] = package / f"{name}.py"
    modules = {"guided_lfd": package / "__init__.py", **paths}
    graph = {name: imported_modules(name, path, modules) for name, path in paths.items()}
    assert circles(graph) == expected
