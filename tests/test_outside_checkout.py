"""``study``, ``quality``, ``demos`` and ``bench`` from any working folder (issue #25): they find the shipped data
in the installed checkout, or name the file that is missing (30); an output that is a file is refused (40) and
kept; a suite CSV that is missing or malformed, an ``--only`` that matches nothing, an unknown strategy or a
time limit that is not a number are one-line errors.  Each was ``internal error`` (exit 1), or replaced the file."""

from __future__ import annotations

import pytest

from conftest import DATA, ROOT
from guided_lfd.errors import EXIT_BAD_OPTION, EXIT_INPUT_FILE, EXIT_OUTPUT


@pytest.fixture
def elsewhere(tmp_path, monkeypatch):
    """A working folder outside the checkout."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_quality_and_demos_find_the_shipped_data_from_elsewhere(runner, app, elsewhere):
    from_elsewhere = runner.invoke(app, ["quality"])
    assert from_elsewhere.exit_code == 0, from_elsewhere.stderr
    at_home = runner.invoke(app, ["quality", "--demos", str(ROOT / "data/demos"),
                                  "--domains", str(ROOT / "data/domains")])
    assert from_elsewhere.stdout == at_home.stdout
    rendered = runner.invoke(app, ["demos", "traces"])
    assert rendered.exit_code == 0, rendered.stderr
    shipped = ROOT / "data" / "demos" / "kitchen-1" / "P1-excuse.csv"
    assert (elsewhere / "traces" / "kitchen-1" / "P1-excuse.csv").read_bytes() == shipped.read_bytes()


@pytest.mark.parametrize("args, code, message", [
    (["study", "--root", "."], EXIT_INPUT_FILE, "data/study/table1-demonstration-time.csv: input error: not found"),
    (["study", "--out", "taken"], EXIT_OUTPUT, "taken: output error: --out: is a file, expected a folder"),
    (["demos", "taken"], EXIT_OUTPUT, "taken: output error: OUT: is a file, expected a folder"),
    (["quality", "--demos", "nowhere"], EXIT_INPUT_FILE, "nowhere: input error: not found"),
    (["bench", "run", "--suite", "missing.csv"], EXIT_INPUT_FILE, "missing.csv: input error: not found"),
    (["bench", "run", "--suite", "bad.csv"], EXIT_INPUT_FILE, "bad.csv:1: input error: missing column(s) task"),
    (["bench", "run", "--suite", "short.csv"], EXIT_INPUT_FILE, "short.csv:2: input error: expected 7 cells"),
    (["bench", "run", "--only", "no-such-task"], EXIT_BAD_OPTION, "'no-such-task' matches no task of"),
    (["bench", "run", "--strategies", "nope"], EXIT_BAD_OPTION, "unknown strategy 'nope'"),
    (["bench", "run", "--semantics", "nope"], EXIT_BAD_OPTION, "unknown semantics 'nope'"),
    (["bench", "run", "--time-limit", "nan"], EXIT_BAD_OPTION, "--time-limit nan: expected a number of seconds"),
    (["bench", "run", "--results", "taken"], EXIT_OUTPUT, "taken: output error: --results: is a file"),
    (["demos", "taken/traces"], EXIT_OUTPUT, "OUT: taken is a file, expected a folder"),
    (["bench", "generate", "--ipc", ".", "--suite", "taken"], EXIT_BAD_OPTION, "--suite taken: lies in ."),
    (["bench", "run", "--suite", "res/results.csv", "--results", "res"], EXIT_BAD_OPTION,
     "--suite res/results.csv: lies in res"),
    (["bench", "report", "--results", "empty"], EXIT_INPUT_FILE, "empty/results.csv: input error: not found"),
    (["quality", "--traces", "taken"], EXIT_INPUT_FILE, "taken: input error: is a file, expected a folder of trace "
                                                        "sources"),
    # A file where a folder is expected was internal error (NotADirectoryError).
    (["quality", "--demos", "taken", "--domains", str(ROOT / "data" / "domains")], EXIT_INPUT_FILE,
     "taken: input error: is a file, expected a folder of labelled demonstrations"),
    (["quality", "--demos", str(ROOT / "data" / "demos"), "--domains", "taken"], EXIT_INPUT_FILE,
     "taken: input error: is a file, expected a folder of the kitchens' domains"),
    (["study", "--out", "taken/results"], EXIT_OUTPUT, "--out: taken is a file, expected a folder"),
    # An empty name was the working folder: teach -o '' wrote its session over the files there.
    (["study", "--out", ""], EXIT_BAD_OPTION, "'--out': expected a file or folder name, got an empty one"),
    (["demos", ""], EXIT_BAD_OPTION, "'OUT': expected a file or folder name, got an empty one"),
    (["quality", "--demos", " "], EXIT_BAD_OPTION, "'--demos': expected a file or folder name, got an empty one"),
    (["bench", "run", "--results", ""], EXIT_BAD_OPTION, "'--results': expected a file or folder name"),
    (["teach", "robot.pddl", "problem.pddl", "-o", ""], EXIT_BAD_OPTION, "expected a file or folder name, got an"),
    (["bench", "run", "--suite", "fly.csv", "--only", "blocks-task01-pick-up"], EXIT_INPUT_FILE,
     "fly.csv: input error: task blocks-task01-pick-up: removed_action 'fly' is no action of"),
    (["bench", "report", "--results", "nan"], EXIT_INPUT_FILE, "results.csv:2: input error: wall_s 'nan': expected a "
                                                                "number (at least 0)"),
    (["bench", "report", "--results", "words"], EXIT_INPUT_FILE, "results.csv:2: input error: size 'big': expected a "
                                                                  "whole number"),
    (["bench", "report", "--results", "status"], EXIT_INPUT_FILE, "results.csv:2: input error: status 'fine': expected"),
    (["bench", "report", "--results", "columns"], EXIT_INPUT_FILE, "results.csv:1: input error: missing column(s) "
                                                                    "strategy, semantics, status"),
    # Third round: outputs mixed into the run's own inputs (new files beside the data), unknown names accepted.
    (["study", "--root", str(ROOT), "--out", str(ROOT)], EXIT_BAD_OPTION, "is the data's root"),
    (["study", "--root", str(ROOT), "--out", str(ROOT / "data" / "new")], EXIT_BAD_OPTION,
     "which this run reads; expected a folder elsewhere"),
    (["demos", str(ROOT / "data" / "domains" / "new"), "--domains", str(ROOT / "data" / "domains")], EXIT_BAD_OPTION,
     "which this run reads; expected a folder elsewhere"),
    (["bench", "run", "--root", str(ROOT), "--results", str(ROOT / "data" / "new")], EXIT_BAD_OPTION,
     "which this run reads; expected a folder elsewhere"),
    (["bench", "generate", "--suite", "s.csv", "--tasks", "nope"], EXIT_BAD_OPTION, "has a task 'nope'"),
    (["bench", "generate", "--suite", "s.csv", "--tasks", ","], EXIT_BAD_OPTION, "expected comma-separated task"),
    (["bench", "run", "--stop-after-unfinished", "nope"], EXIT_BAD_OPTION, "unknown strategy 'nope'"),
    (["bench", "run", "--tasks", ""], EXIT_BAD_OPTION, "only 'bench generate' reads it"),
    (["bench", "generate", "--ipc", "taken", "--suite", "s.csv"], EXIT_INPUT_FILE,
     "taken: input error: is a file, expected a folder of IPC domains"),
    (["quality", "--demos", "empty", "--domains", str(ROOT / "data" / "domains")], EXIT_INPUT_FILE,
     "empty: input error: holds no labelled demonstrations"),
])
def test_bad_data_and_outputs_are_one_line_errors_and_nothing_is_replaced(runner, app, elsewhere, args, code,
                                                                        message):
    (elsewhere / "taken").write_text("mine")
    (elsewhere / "res").mkdir()
    (elsewhere / "empty").mkdir()
    (elsewhere / "res" / "results.csv").write_text((ROOT / "benchmarks" / "suite.csv").read_text())
    (elsewhere / "bad.csv").write_text("id,domain\nx,y\n")
    (elsewhere / "short.csv").write_text("id,domain,task,removed_action,domain_file,problem_file,fixed_from\na,b\n")
    header, first = (ROOT / "benchmarks" / "suite.csv").read_text().splitlines()[:2]
    (elsewhere / "fly.csv").write_text(f"{header}\n{first.replace(',pick-up,', ',fly,')}\n")
    head = "id,domain,task,removed_action,semantics,strategy,status,size,cost,wall_s\n"
    for name, row in (("nan", "a,b,c,d,literal,landmark,excuse-found,1,1,nan"),
                      ("words", "a,b,c,d,literal,landmark,excuse-found,big,1,1.0"),
                      ("status", "a,b,c,d,literal,landmark,fine,1,1,1.0")):
        (elsewhere / name).mkdir()
        (elsewhere / name / "results.csv").write_text(head + row + "\n")
    (elsewhere / "columns").mkdir()
    (elsewhere / "columns" / "results.csv").write_text("id,domain\na,b\n")
    before = sorted(p.name for p in elsewhere.iterdir())
    result = runner.invoke(app, args)
    assert result.exit_code == code, result.output
    assert message in result.stderr and len(result.stderr.strip().splitlines()) == 1, result.stderr
    assert (elsewhere / "taken").read_text() == "mine"
    assert (elsewhere / "res" / "results.csv").read_text() == (ROOT / "benchmarks" / "suite.csv").read_text()
    assert sorted(p.name for p in elsewhere.iterdir()) == before


def test_quality_takes_the_domains_beside_the_demos_it_is_given(runner, app, elsewhere):
    """``--demos`` elsewhere without ``--domains``: the domains folder beside it, named when missing (it took the
    checkout's without a word)."""
    import shutil

    shutil.copytree(ROOT / "data" / "demos" / "kitchen-1", elsewhere / "data" / "demos" / "kitchen-1")
    result = runner.invoke(app, ["quality", "--demos", str(elsewhere / "data" / "demos")])
    assert result.exit_code == EXIT_INPUT_FILE
    assert f"{elsewhere / 'data' / 'domains'}: input error: not found" in result.stderr


@pytest.mark.parametrize("table, fixture, message", [
    ("table2-demonstration-size.csv", "table2-without-p5.csv",
     "table2-demonstration-size.csv: input error: no row for kitchen-1 P5 (expected sizes for each kitchen and "
     "demonstrator: kitchens kitchen-1, kitchen-2, demonstrators P1, P2, P3, P4, P5)"),
    ("table1-demonstration-time.csv", "table1-not-a-number.csv",
     "table1-demonstration-time.csv:15: input error: 'eight' in column time_s is not a number (expected a number)"),
])
def test_study_tables_without_a_demonstrator_or_a_number_are_named_before_any_work(runner, app, elsewhere, table,
                                                                                   fixture, message):
    """A table lacking a demonstrator the study needs was internal error (KeyError) after the whole chain ran."""
    import shutil

    shutil.copytree(ROOT / "data" / "study", elsewhere / "data" / "study")
    shutil.copy(DATA / "study-tables" / fixture, elsewhere / "data" / "study" / table)
    for folder in ("demos", "domains"):  # there, but empty: the tables are read first
        (elsewhere / "data" / folder).mkdir()
    result = runner.invoke(app, ["study", "--root", ".", "--out", "results"])
    assert result.exit_code == EXIT_INPUT_FILE, result.output
    assert result.stderr == f"data/study/{message}\n"
    assert not (elsewhere / "results").exists()


def test_a_suite_csv_saved_with_a_byte_order_mark_is_read(tmp_path):
    """A spreadsheet saves CSV with a byte-order mark: the first column is still ``id``."""
    from guided_lfd.benchmark import read_suite

    text = (ROOT / "benchmarks" / "suite.csv").read_text(encoding="utf-8")
    (tmp_path / "suite.csv").write_text("\ufeff" + text, encoding="utf-8")
    assert read_suite(tmp_path / "suite.csv", ROOT) == read_suite(ROOT / "benchmarks" / "suite.csv", ROOT)


@pytest.mark.parametrize("labels, message", [(None, "cannot read the labels"),
                                             ("x,y\n1,2\n", "missing column(s) time, hand, activity")])
def test_a_trace_source_without_good_labels_is_named(runner, app, elsewhere, labels, message):
    """``quality --traces`` on a tree whose trace lacks its labels, or has labels of another shape: it was
    ``internal error`` (FileNotFoundError, KeyError)."""
    import shutil

    folder = elsewhere / "tr" / "kitchen-2" / "cond"
    folder.mkdir(parents=True)
    for suffix in (".csv", ".state.csv"):
        shutil.copy(ROOT / "data" / "demos" / "kitchen-2" / f"P1-complete{suffix}", folder / f"P1-complete{suffix}")
    if labels is not None:
        (folder / "P1-complete.labels.csv").write_text(labels)
    result = runner.invoke(app, ["quality", "--traces", "tr"])
    assert result.exit_code == EXIT_INPUT_FILE, result.output
    assert message in result.stderr and "P1-complete.labels.csv" in result.stderr


def test_generate_takes_task_names_with_spaces_around_them(runner, app, elsewhere):
    """Review of this change: '--tasks "task01, task02"' checked ' task02' stripped but generated without it."""
    result = runner.invoke(app, ["bench", "generate", "--root", str(ROOT), "--tasks", "task01, task02",
                                 "--suite", "s.csv", "--quiet"])
    assert result.exit_code == 0, result.stderr
    text = (elsewhere / "s.csv").read_text()
    assert "-task02-" in text and "-task01-" in text
