"""Golden files for the JSON and PDDL guided-lfd writes, and determinism.

Regenerate after an intended format change with:
    GUIDED_LFD_REGOLD=1 python -m pytest tests/test_golden.py
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from conftest import BLOCKS, DATA, kitchen
from guided_lfd.pddl.reader import parse_task
from guided_lfd.pddl.writer import domain_to_pddl

GOLDEN = DATA / "golden"
VOLATILE = {"time_s", "setup_time_s", "search_time_s"}
# Search effort changes with every optimisation; the golden files pin results.
EFFORT = {"candidates", "planner_calls", "nodes_expanded", "evaluations", "oracle_expanded", "oracle_memo_hits"}


def stable(doc: dict, drop: set[str] = VOLATILE) -> dict:
    """The document without timings (they differ run to run), or without ``drop``."""
    doc = dict(doc)
    doc["statistics"] = {k: v for k, v in doc["statistics"].items() if k not in drop}
    return doc


def check_golden(name: str, text: str) -> None:
    path = GOLDEN / name
    if os.environ.get("GUIDED_LFD_REGOLD"):
        path.write_text(text)
    assert path.exists(), f"missing golden file {path}; run with GUIDED_LFD_REGOLD=1"
    assert text == path.read_text()


@pytest.mark.parametrize(
    "name,args",
    [
        ("excuse-kitchen-1.json", [*kitchen(1)]),
        ("excuse-kitchen-2.json", [*kitchen(2)]),
        ("excuse-blocks-literal-all.json",
         [str(BLOCKS / "domain-no-unstack.pddl"), str(BLOCKS / "task03.pddl"), "--semantics", "literal", "--all"]),
    ],
)
def test_excuse_json_matches_golden_and_is_deterministic(runner, app, name, args):
    root = Path(__file__).resolve().parent.parent
    rel = [os.path.relpath(a, root) if a.endswith(".pddl") else a for a in args]
    cwd = os.getcwd()
    os.chdir(root)
    try:
        first = runner.invoke(app, ["excuse", *rel, "--json"])
        second = runner.invoke(app, ["excuse", *rel, "--json"])
    finally:
        os.chdir(cwd)
    assert first.exit_code == 0, first.stderr
    a, b = stable(json.loads(first.stdout)), stable(json.loads(second.stdout))
    assert a == b  # deterministic, search effort included
    check_golden(name, json.dumps(stable(a, VOLATILE | EFFORT), indent=2) + "\n")


def test_domain_writer_matches_golden():
    domain, _ = parse_task(*kitchen(2, "human"))
    check_golden("kitchen-2-human.pddl", domain_to_pddl(domain))


def _run_in_root(runner, app, args: list[str]) -> dict:
    root = Path(__file__).resolve().parent.parent
    cwd = os.getcwd()
    os.chdir(root)
    try:
        result = runner.invoke(app, args)
    finally:
        os.chdir(cwd)
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_plan_json_matches_golden(runner, app):
    doc = _run_in_root(runner, app, ["plan", "tests/data/costs/domain.pddl", "tests/data/costs/problem.pddl", "--json"])
    doc.pop("time_s")
    check_golden("plan-costs.json", json.dumps(doc, indent=2) + "\n")


def test_evaluate_json_matches_golden(runner, app, tmp_path):
    root = Path(__file__).resolve().parent.parent
    segments = tmp_path / "p1.json"
    learned, merged = tmp_path / "p1.pddl", tmp_path / "merged.pddl"
    k2 = "data/domains/kitchen-2"
    for args in (["segment", f"{root}/data/demos/kitchen-2/P1-excuse.csv", "-o", str(segments)],
                 ["learn-domain", str(segments), "-o", str(learned)],
                 ["merge", f"{root}/{k2}/robot.pddl", str(learned), "-o", str(merged)]):
        assert runner.invoke(app, [*args, "--quiet"]).exit_code == 0
    doc = _run_in_root(runner, app, ["evaluate", f"{k2}/robot.pddl", f"{k2}/problem.pddl", "--human",
                                     f"{k2}/human.pddl", "-d", str(segments), "--merged", str(merged), "--json"])
    # The temporary folder is the test's, not the result's.
    text = json.dumps(doc, indent=2).replace(f"{tmp_path}/", "")
    check_golden("evaluate-kitchen-2.json", text + "\n")
