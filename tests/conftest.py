"""Shared fixtures: paths to the PDDL corpus, a CLI runner, the --slow switch."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DATA = Path(__file__).resolve().parent / "data"
DOMAINS = ROOT / "data" / "domains"


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--slow", action="store_true", default=False, help="also run tests marked slow")


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    if config.getoption("--slow"):
        return
    skip = pytest.mark.skip(reason="slow: run with --slow")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)


@pytest.fixture
def runner():
    from typer.testing import CliRunner

    return CliRunner()


@pytest.fixture
def app():
    from cli.main import app as the_app

    return the_app


def kitchen(n: int, who: str = "robot") -> tuple[str, str]:
    """(domain, problem) paths of a shipped kitchen scenario."""
    return str(DOMAINS / f"kitchen-{n}" / f"{who}.pddl"), str(DOMAINS / f"kitchen-{n}" / "problem.pddl")


BLOCKS = DATA / "blocks"
