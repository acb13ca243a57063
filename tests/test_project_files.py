"""The files beside the code: the licence and citation agree with pyproject.toml."""

from __future__ import annotations

import re
import tomllib

from conftest import ROOT


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
