"""Regression tests named after the bug they pin; their PDDL is in tests/data/regressions/."""

from __future__ import annotations

import pytest

from conftest import DATA
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.space import MutexGroup, Semantics, build_space
from guided_lfd.excuse.strategies import STRATEGIES
from guided_lfd.excuse.outcome import SearchLimits
from guided_lfd.planning.grounding import ground
from guided_lfd.pddl.reader import parse_task

REG = DATA / "regressions"


def load(name):
    return parse_task(REG / f"{name}.pddl", REG / f"{name}-problem.pddl")


@pytest.mark.parametrize("all_minimal", [False, True])
def test_removal_is_not_charged_twice_with_negative_preconditions(all_minimal):
    domain, problem = load("removal-charged-twice")
    results = {}
    for strategy in STRATEGIES:
        report = find_excuses(domain, problem, ExcuseOptions(strategy=strategy, costs=["s=3", "g=100", "k=10"],
                                                             all_minimal=all_minimal))
        results[strategy] = [([str(c) for c in e.changes], e.cost) for e in report.excuses]
    assert results["landmark"] == results["baseline"]
    assert results["landmark"][0] == (["+(p)", "-(q)"], 2)


@pytest.mark.parametrize("all_minimal", [False, True])
def test_child_removing_a_group_atom_does_not_inherit_its_charge(all_minimal):
    domain, problem = load("inherited-removal-share")
    task = ground(domain, problem)
    idx = {str(a): i for i, a in enumerate(task.atoms)}
    groups = [MutexGroup(sum(1 << idx[a] for a in atoms), False, "test")
              for atoms in (["(p1)", "(p2)", "(q)"], ["(q)", "(r)"])]
    space = build_space(task, Semantics.CONSISTENT, [], ["p2=2", "q=4", "g=100"], groups)
    found = {name: [space.cost(c) for c in s.search(space, SearchLimits(all_minimal=all_minimal)).solutions]
             for name, s in STRATEGIES.items()}
    assert found["landmark"] == found["baseline"] == [6]
