"""The files beside the code: the licence and citation agree with pyproject.toml; no issue numbers where users
read."""

from __future__ import annotations

import ast
import re
import tomllib
from pathlib import Path

from conftest import ROOT

#: an issue number (#14, issue 14), not a link to a page's own heading (](#section))
ISSUE = re.compile(r"(?<![(\w])#\d+\b|\bissues? #?\d+", re.IGNORECASE)


def _pyproject() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]


def _top_level(cff: str, key: str) -> str:
    match = re.search(rf"^{key}: (.+)$", cff, re.MULTILINE)
    assert match, f"CITATION.cff has no top-level {key}"
    return match.group(1).strip().strip('"')


def test_licence_file_is_the_gpl_version_3_that_pyproject_declares():
    text = (ROOT / "LICENSE").read_text()
    assert _pyproject()["license"] == "GPL-3.0-or-later"
    assert text.lstrip().startswith("GNU GENERAL PUBLIC LICENSE\n                       Version 3, 29 June 2007")
    assert "END OF TERMS AND CONDITIONS" in text and len(text) > 30_000


def test_citation_file_names_this_version_and_licence_and_the_paper():
    cff = (ROOT / "CITATION.cff").read_text()
    project = _pyproject()
    assert _top_level(cff, "cff-version") == "1.2.0"
    assert _top_level(cff, "title") == project["name"]
    assert _top_level(cff, "version") == project["version"]
    assert _top_level(cff, "license") == project["license"]
    paper = cff.split("\npreferred-citation:\n", 1)[1]
    title = " ".join(paper.split("title: >-\n", 1)[1].split("\n  authors:", 1)[0].split())
    assert title == ("Enabling Robots to Identify Missing Steps in Robot Tasks for Guided Learning from "
                     "Demonstration")
    assert re.findall(r"family-names: (\S+)", paper) == ["Diehl", "Chakraborti", "Ramirez-Amaro"]


def _strings(path: Path, *, docstrings: bool) -> list[tuple[int, str]]:
    tree = ast.parse(path.read_text())
    skip = set()
    if not docstrings:
        for node in ast.walk(tree):
            body = getattr(node, "body", None)
            first = body[0] if isinstance(body, list) and body else None
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                skip.add(id(first.value))
    return [(n.lineno, n.value) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in skip]


def test_no_issue_number_in_what_the_program_prints():
    """Messages, tables and help say what they mean, not which tracker issue asked for them; in cli/ the
    docstrings are help text too."""
    found = []
    for root, docstrings in (("cli", True), ("guided_lfd", False)):
        for path in sorted((ROOT / root).rglob("*.py")):
            name = str(path.relative_to(ROOT))
            found += [(name, line, text[:60]) for line, text in _strings(path, docstrings=docstrings)
                      if ISSUE.search(text)]
    assert found == []


def test_no_issue_number_in_the_documentation():
    pages = [ROOT / "README.md", ROOT / "benchmarks" / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    found = [(p.name, m.group(0)) for p in pages for m in ISSUE.finditer(p.read_text())]
    assert found == []


def test_the_readme_fits_and_its_command_table_names_every_subcommand():
    from cli.main import SUBCOMMANDS

    readme = (ROOT / "README.md").read_text()
    assert len(readme.splitlines()) <= 300
    table = readme.split("\n## Commands\n", 1)[1].split("\n## ", 1)[0]
    listed = re.findall(r"^\| `([a-z-]+)[ `]", table, re.MULTILINE)
    assert sorted(listed) == sorted(SUBCOMMANDS), listed
    for section in ("Set up and run", "Bring your own robot", "From Python", "Supported PDDL", "Documentation",
                    "Citing", "Licence"):
        assert f"\n## {section}" in readme, section
