"""Shared fixtures: paths to the PDDL corpus, a CLI runner, the --slow switch, reproducible property tests.

Property tests are reproducible: Hypothesis runs under the ``reproducible`` profile (``derandomize``: the
examples are drawn from a seed fixed by each test, the same on every run and machine; no example database
replays earlier failures first), and every other random generator in the tests is seeded.  ``--slow``
also runs the long explorations: the property tests whose example counts the environment sets
(``GUIDED_LFD_FUZZ_EXAMPLES``, ``GUIDED_LFD_ADL_EXAMPLES``) take 1,000 examples unless it says otherwise, as
``make test-slow`` asks.  ``--hypothesis-profile NAME`` still chooses another profile.
"""

from __future__ import annotations

import os
import random
import subprocess
import sys
from pathlib import Path
from typing import Iterator

import pytest
from hypothesis import settings

ROOT = Path(__file__).resolve().parent.parent
DATA = Path(__file__).resolve().parent / "data"
DOMAINS = ROOT / "data" / "domains"
#: The examples of a long exploration (--slow), where the environment does not say.
SLOW_EXAMPLES = "1000"

settings.register_profile("reproducible", derandomize=True, database=None)
settings.load_profile("reproducible")


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--slow", action="store_true", default=False, help="also run tests marked slow")


def pytest_configure(config: pytest.Config) -> None:
    # Before the test modules are imported: they read their example counts from the environment then.
    if config.getoption("--slow"):
        for name in ("GUIDED_LFD_FUZZ_EXAMPLES", "GUIDED_LFD_ADL_EXAMPLES"):
            os.environ.setdefault(name, SLOW_EXAMPLES)
    if config.getoption("hypothesis_profile", None) is None:
        settings.load_profile("reproducible")


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


def load_script(path: Path, name: str):
    """A script that is not a package module (a benchmark, a generator) as a module, its ``main`` not run;
    registered under ``name`` (dataclasses look their module up)."""
    import importlib.util

    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)  # type: ignore[union-attr]
    return module


def fresh_interpreter(code: str) -> str:
    """What a fresh interpreter prints running ``code`` (for process-wide state: limits, lingering)."""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=60)
    assert out.returncode == 0, out.stderr
    return out.stdout


def damaged_tasks(tmp_path: Path, domain_text: str, problem_text: str, pieces: list[str], seed: int,
                  count: int) -> Iterator[tuple[str, str]]:
    """``count`` seeded damages (1-3 inserted pieces or deleted characters) of a domain (70%) or its problem.

    Yields the (domain, problem) paths under ``tmp_path``, rewritten for each damage.
    """
    rng = random.Random(seed)
    domain, problem = tmp_path / "d.pddl", tmp_path / "p.pddl"
    for _ in range(count):
        damage_domain = rng.random() < 0.7
        chars = list(domain_text if damage_domain else problem_text)
        for _ in range(rng.randint(1, 3)):
            at = rng.randrange(len(chars))
            if rng.random() < 0.6:
                chars.insert(at, rng.choice(pieces))
            else:
                del chars[at]
        damaged = "".join(chars)
        domain.write_text(damaged if damage_domain else domain_text)
        problem.write_text(problem_text if damage_domain else damaged)
        yield str(domain), str(problem)


def record_figures(monkeypatch: pytest.MonkeyPatch, module: object) -> dict[str, object]:
    """Draw with ``module.save_figure`` recording each figure by file name (and still saving it)."""
    drawn = {}
    save = module.save_figure

    def record(fig, path, dpi):
        drawn[path.name] = fig
        axes = fig.axes  # kept for inspection: save_figure closes the figure, not its artists
        drawn[path.name + ":axes"] = axes
        return save(fig, path, dpi)

    monkeypatch.setattr(module, "save_figure", record)
    return drawn


def assert_brute_force_outcome(report, size: int | None, expected: list[list[str]]) -> None:
    """``report`` says what a brute force found: already solvable (size 0), no excuse within its size (None), or
    exactly the ``expected`` minimal excuses (each a sorted list of change strings)."""
    if size == 0:
        assert report.status == "already-solvable"
    elif size is None:
        assert report.status in ("no-excuse", "no-excuse-within-size")
    else:
        assert report.status == "excuse-found"
        assert sorted(sorted(str(c) for c in e.changes) for e in report.excuses) == expected
