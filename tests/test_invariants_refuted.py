"""Invariants that hold only because a skill is missing (issue #25).

Without pick-up, a newspaper robot never carries a paper again once one is delivered, so "at most one of
(carrying *) and (satisfied *)" is an invariant of its skills, and the reversed-action rule keeps it (delivering
backwards is balanced too).  The task wants two houses satisfied: the goal itself breaks it, so it is no law of the
world and is left out (named in the statistics); the excuse is the literal one, as with the complete domain's
invariants.  Where the goal keeps every invariant but no excuse state does (a press needing both of a single
arm's positions), the run says that only the invariants stand in the way and names them.
"""

from __future__ import annotations

import json

import pytest

from conftest import DATA
from guided_lfd.errors import EXIT_NO_EXCUSE
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.strategies import STRATEGIES
from guided_lfd.pddl.reader import parse_domain, parse_task

NEWS = DATA / "newspapers"
PRESS = DATA / "in-the-way"


@pytest.mark.parametrize("strategy", sorted(STRATEGIES))
def test_an_invariant_the_goal_breaks_is_left_out_and_named(strategy):
    task = parse_task(str(NEWS / "robot.pddl"), str(NEWS / "problem.pddl"))
    report = find_excuses(*task, ExcuseOptions(strategy=strategy))
    # Strategies may break ties between minimal excuses differently (the hitting-set search takes its program's).
    minimal = find_excuses(*task, ExcuseOptions(strategy=strategy, all_minimal=True))
    listed = [[str(c) for c in e.changes] for e in minimal.excuses]
    assert ["+(carrying paper-0)", "+(carrying paper-1)"] in listed
    assert [str(c) for c in report.excuse.changes] in listed and report.excuse.size == 2
    assert report.statistics.invariants_refuted_by_goal == ["{(carrying *), (satisfied *)}"]


def test_the_complete_domains_invariants_give_the_same_excuse():
    domain, problem = parse_task(str(NEWS / "robot.pddl"), str(NEWS / "problem.pddl"))
    report = find_excuses(domain, problem, ExcuseOptions(invariants_from=parse_domain(str(NEWS / "domain.pddl"))))
    assert [str(c) for c in report.excuse.changes] == ["+(carrying paper-0)", "+(carrying paper-1)"]
    assert report.statistics.invariants_refuted_by_goal is None


def test_when_only_invariants_stand_in_the_way_the_run_says_so_and_names_them(runner, app):
    args = ["excuse", str(PRESS / "domain.pddl"), str(PRESS / "problem.pddl")]
    result = runner.invoke(app, args)
    assert result.exit_code == EXIT_NO_EXCUSE
    assert result.stderr.splitlines()[0] == (
        "no excuse keeps the state invariants: only the invariants {(at-left), (at-right)} stand in the way (the "
        "literal semantics' excuse +(at-right) breaks them; they may hold only because a skill is missing: try "
        "--semantics literal, or --invariants-from the complete domain)")
    stats = json.loads(runner.invoke(app, [*args, "--json"]).stdout)["statistics"]
    assert stats["invariants_in_the_way"] == ["{(at-left), (at-right)}"]
    assert stats["literal_excuse"] == ["+(at-right)"]
    literal = runner.invoke(app, [*args, "--semantics", "literal"])
    assert literal.exit_code == 0 and "+(at-right)" in literal.stdout
