"""The excuse checker derives the consistent semantics' invariants itself (#25), and --verify re-proves minimality.

The engine's invariant groups are not trusted: a mutation that empties the engine's invariant synthesis must be
caught by the checker, and the brute force of the property tests uses the checker's laws, not the engine's.
"""

from __future__ import annotations

import json
from dataclasses import replace

import pytest
from typer.testing import CliRunner

from cli.main import app
from conftest import DATA, kitchen
from guided_lfd.excuse import invariants
from guided_lfd.excuse.change import Change
from guided_lfd.excuse.check import check_excuse
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.laws import WorldLaw, _keeps_count, derive_laws
from guided_lfd.excuse.verify import verify_minimal
from guided_lfd.pddl.model import Atom
from guided_lfd.pddl.reader import parse_task

LAWS = DATA / "laws"
BLOCKS = DATA / "blocks"


def test_the_checker_derives_blocks_world_laws_itself():
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task03.pddl")
    laws = derive_laws(domain, problem)
    assert [(str(law), law.exactly_one) for law in laws.laws] == [
        ("{(clear ?v0), (holding ?v0), (on * ?v0)}", True),
        ("{(handempty), (holding *)}", True),
        ("{(holding ?v0), (on ?v0 *), (ontable ?v0)}", True),
    ]
    assert laws.broken(frozenset(problem.init)) == []
    on_two = frozenset(problem.init | {Atom("on", ("c", "a"))})  # c on b and on a
    assert laws.broken(on_two) == ["{(clear ?v0), (holding ?v0), (on * ?v0)} over a (2 true)",
                                   "{(holding ?v0), (on ?v0 *), (ontable ?v0)} over c (2 true)"]
    nowhere = frozenset(problem.init - {Atom("ontable", ("a",))})
    assert laws.broken(nowhere) == ["{(holding ?v0), (on ?v0 *), (ontable ?v0)} over a (0 true)"]


def test_a_move_to_the_same_room_keeps_the_robot_in_exactly_one_room():
    """move ?from ?to without an inequality: when ?from = ?to it adds and deletes the same atom (no change)."""
    domain, problem = parse_task(LAWS / "domain.pddl", LAWS / "problem.pddl")
    laws = {str(law): law.exactly_one for law in derive_laws(domain, problem).laws}
    assert laws == {"{(carried *), (free)}": True, "{(carried ?v0), (parcel-in ?v0 *)}": True,
                    "{(robot-in *)}": True}


def test_no_proof_for_an_action_that_changes_a_groups_count():
    domain, _ = parse_task(LAWS / "domain.pddl", LAWS / "problem.pddl")
    placed = WorldLaw((("carried", (0,)), ("parcel-in", (0, -1))), False)
    drop = next(a for a in domain.actions if a.name == "drop")
    assert _keeps_count(drop, placed)
    # Dropping without giving up the parcel: carried stays, parcel-in is added.
    keeps_carrying = replace(drop, delete=())
    assert not _keeps_count(keeps_carrying, placed)


def test_the_checker_catches_an_engine_without_invariants(monkeypatch):
    """Issue #25: with the engine's invariant synthesis emptied, the consistent semantics returned a block held
    and on another at once, and the check passed it.  Now the checker's own laws refuse it."""
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    assert find_excuses(domain, problem).status == "excuse-found"
    monkeypatch.setattr(invariants, "lifted_invariants", lambda *args, **kwargs: [])
    with pytest.raises(RuntimeError, match=r"internal check failed .* breaks the invariant \{\(clear"):
        find_excuses(domain, problem)


def test_check_excuse_refuses_a_state_that_breaks_a_law():
    domain, problem = parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    report = find_excuses(domain, problem)
    laws = derive_laws(domain, problem)
    excuse = report.excuse
    assert check_excuse(domain, problem, excuse.changes, excuse.plan, laws) == []
    held = [*excuse.changes, Change(Atom("holding", ("a",)), True)]
    problems = check_excuse(domain, problem, held, excuse.plan, laws)
    assert "the excuse state breaks the invariant {(handempty), (holding *)} over () (2 true)" in problems


def test_verify_finds_a_cheaper_excuse_when_the_claimed_cost_is_too_high():
    domain, problem = parse_task(*kitchen(1))
    found = verify_minimal(domain, problem, 2, derive_laws(domain, problem), [], [])
    assert found.outcome == "verified" and [str(c) for c in found.smaller] == ["+(open pinkdrawer)"]
    assert verify_minimal(domain, problem, 1, derive_laws(domain, problem), [], []).smaller is None


def test_verify_counts_the_cheaper_sets_and_refuses_to_enumerate_too_many():
    domain, problem = parse_task(LAWS / "robot.pddl", LAWS / "problem.pddl")
    report = find_excuses(domain, problem, ExcuseOptions(verify=True))
    assert report.statistics.minimality == "verified" and report.statistics.minimality_sets == 794
    many = verify_minimal(domain, problem, report.excuse.cost, None, [], [], cap=100)
    assert (many.outcome, many.sets) == ("too-many", 101)


def test_a_mutated_search_that_returns_a_non_minimal_excuse_is_caught(monkeypatch):
    """--verify does not trust the search's bounds: a search made to skip the size-1 level is refused."""
    from guided_lfd.excuse import engine

    domain, problem = parse_task(*kitchen(1))
    original = engine._Run.checked_excuse

    def padded(self, changes, plan, optimal):
        excuse = original(self, changes, plan, optimal)
        excuse.cost += 1  # what a search that missed the cheaper level would claim
        return excuse

    monkeypatch.setattr(engine._Run, "checked_excuse", padded)
    with pytest.raises(RuntimeError, match=r"cheaper change set \+\(open pinkdrawer\) is an excuse"):
        find_excuses(domain, problem, ExcuseOptions(verify=True))


def test_the_command_line_says_how_verify_went():
    result = CliRunner().invoke(app, ["excuse", *map(str, kitchen(1)), "--verify", "--json"])
    assert result.exit_code == 0, result.output
    statistics = json.loads(result.stdout)["statistics"]
    assert (statistics["minimality"], statistics["minimality_sets"]) == ("verified", 1)
