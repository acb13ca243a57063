"""``--all`` at its cap says so (issue #25): it listed 1,000 of 10,200 minimal excuses as "every minimal excuse"
with no sign of the cut.  Eight keys, each a minimal excuse of its own; the cap lowered to 5 for the test."""

from __future__ import annotations

import json

import pytest

from conftest import DATA
from guided_lfd.excuse import outcome
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.strategies import STRATEGIES
from guided_lfd.pddl.reader import parse_task

TASK = [str(DATA / "many-excuses" / "domain.pddl"), str(DATA / "many-excuses" / "problem.pddl")]


@pytest.mark.parametrize("strategy", sorted(STRATEGIES))
def test_all_stops_at_the_cap_and_says_so(monkeypatch, strategy):
    monkeypatch.setattr(outcome, "MAX_EXCUSES", 5)
    report = find_excuses(*parse_task(*TASK), ExcuseOptions(all_minimal=True, strategy=strategy))
    assert len(report.excuses) == 5
    assert report.statistics.truncated is True and report.statistics.max_excuses == 5


@pytest.mark.parametrize("strategy", sorted(STRATEGIES))
def test_all_below_the_cap_is_not_truncated(strategy):
    report = find_excuses(*parse_task(*TASK), ExcuseOptions(all_minimal=True, strategy=strategy))
    assert len(report.excuses) == 8 and report.statistics.truncated is None


def test_the_text_and_the_json_say_it_and_stderr_warns_beside_json(runner, app, monkeypatch):
    monkeypatch.setattr(outcome, "MAX_EXCUSES", 5)
    text = runner.invoke(app, ["excuse", *TASK, "--all"])
    assert text.exit_code == 0
    assert text.stdout.rstrip().endswith("(--all stopped at 5 excuses: more minimal excuses may exist)")
    assert "stopped at" not in text.stderr
    doc = runner.invoke(app, ["excuse", *TASK, "--all", "--json"])
    stats = json.loads(doc.stdout)["statistics"]
    assert stats["truncated"] is True and stats["max_excuses"] == 5
    assert "warning: --all stopped at 5 excuses: more minimal excuses may exist" in doc.stderr


def test_a_search_the_time_limit_ended_says_the_list_may_not_be_all():
    from guided_lfd.excuse.document import cut_short

    report = find_excuses(*parse_task(*TASK), ExcuseOptions(all_minimal=True))
    assert cut_short(report) == []
    report.statistics.incomplete = True
    assert cut_short(report) == ["the time limit ended the search: the excuses listed are minimal, but maybe not "
                                 "all of them"]



SLACK_TASK = [str(DATA / "many-excuses-slack" / "domain.pddl"), str(DATA / "many-excuses-slack" / "problem.pddl")]


def test_slack_without_a_time_limit_stops_at_the_cap_and_says_so(runner, app, monkeypatch):
    """#25: --all --slack lists the minimal excuses and the ones within the slack; the cap holds for both and
    the warning speaks of the slack, not of minimal excuses."""
    report = find_excuses(*parse_task(*SLACK_TASK), ExcuseOptions(all_minimal=True, slack=1))
    assert sorted(e.size for e in report.excuses) == [1] * 3 + [2] * 15 and report.statistics.truncated is None
    monkeypatch.setattr(outcome, "MAX_EXCUSES", 10)
    doc = runner.invoke(app, ["excuse", *SLACK_TASK, "--all", "--slack", "1", "--json"])
    assert doc.exit_code == 0
    assert len(json.loads(doc.stdout)["alternatives"]) == 9
    assert "warning: --all stopped at 10 excuses: more excuses within --slack 1 may exist" in doc.stderr


@pytest.mark.parametrize("strategy", sorted(STRATEGIES))
def test_a_list_of_exactly_the_cap_is_not_called_cut(monkeypatch, strategy):
    """#25 second round: 1,000 excuses of a task with exactly 1,000 were reported as 'stopped at 1,000'."""
    monkeypatch.setattr(outcome, "MAX_EXCUSES", 8)
    report = find_excuses(*parse_task(*TASK), ExcuseOptions(all_minimal=True, strategy=strategy))
    assert len(report.excuses) == 8 and report.statistics.truncated is None
    monkeypatch.setattr(outcome, "MAX_EXCUSES", 7)
    report = find_excuses(*parse_task(*TASK), ExcuseOptions(all_minimal=True, strategy=strategy))
    assert len(report.excuses) == 7 and report.statistics.truncated is True
