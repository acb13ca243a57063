"""Regression tests from an adversarial hunt: every bad input is one line on
stderr with a documented exit code, and outputs are never damaged."""

from __future__ import annotations

import os
import re
import stat

import pytest

from conftest import BLOCKS, DATA, ROOT, kitchen
from guided_lfd.io import write_text

DOMAIN, PROBLEM = kitchen(1)


def one_line(result) -> str:
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert "Traceback" not in result.stderr
    return lines[0]


def test_write_through_symlink_keeps_the_link(tmp_path):
    target = tmp_path / "real.txt"
    target.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_text(link, "new")
    assert link.is_symlink() and target.read_text() == "new"


def test_an_output_through_a_loop_of_links_is_refused_and_the_links_kept(tmp_path):
    """It replaced the first link with a regular file (exit 0; issue #25)."""
    from guided_lfd.errors import OutputError

    (tmp_path / "a").symlink_to(tmp_path / "b")
    (tmp_path / "b").symlink_to(tmp_path / "a")
    with pytest.raises(OutputError, match="a loop of symbolic links"):
        write_text(tmp_path / "a", "new")
    assert (tmp_path / "a").is_symlink() and (tmp_path / "b").is_symlink()


def test_write_to_device_writes_in_place(tmp_path):
    """A device or FIFO is written in place, never replaced by a regular file (and gets the whole text)."""
    import threading

    write_text("/dev/null", "data")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received: list[str] = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_text()))
    reader.start()
    write_text(fifo, "data through a pipe\n")
    reader.join(timeout=10)
    assert received == ["data through a pipe\n"] and stat.S_ISFIFO(os.stat(fifo).st_mode)


def test_write_keeps_permissions(tmp_path):
    target = tmp_path / "out.txt"
    target.write_text("old")
    target.chmod(0o644)
    write_text(target, "new")
    assert stat.S_IMODE(target.stat().st_mode) == 0o644


@pytest.mark.parametrize(
    "args,code,message",
    [
        (["--strategy", "zz"], 37, "--strategy zz: unknown strategy"),
        (["--time-limit", "inf"], 37, "--time-limit inf: expected a number of seconds > 0"),
        (["--time-limit", "nan"], 37, "--time-limit nan: expected a number of seconds > 0"),
        (["--time-limit", "-1"], 37, "--time-limit -1: expected a number of seconds > 0"),
        (["--max-size", "-1"], 37, "--max-size -1: expected a number of changes >= 0"),
        (["--max-size", "x"], 37, "option error: Invalid value for '--max-size'"),
        (["--semantics", "zz"], 37, "option error: Invalid value for '--semantics'"),
        (["--cost", "open=\u0661"], 37, "is not a whole number"),
        (["--cost", "((open pinkdrawer))=1"], 37, "expected one atom"),
        (["--fixed", "OPEN", "--fixed", "sofa"], 37, "--fixed 'sofa': unknown predicate"),
    ],
)
def test_bad_option_values(runner, app, args, code, message):
    result = runner.invoke(app, ["excuse", DOMAIN, PROBLEM, *args])
    assert result.exit_code == code
    assert message in one_line(result)


@pytest.mark.parametrize("args", [
    ["plan", DOMAIN, PROBLEM, "--time-limit", "soon"],
    ["plan", DOMAIN, PROBLEM, "--search", "zz"],
    ["evaluate", DOMAIN, PROBLEM, "--human", DOMAIN, "--bound", "many"],
    ["evaluate", DOMAIN, PROBLEM, "--human", DOMAIN, "--bound", "0"],
    ["excuse", DOMAIN, PROBLEM, "--semantics", "zz"],
    ["excuse", DOMAIN, PROBLEM, "--strategy", "zz"],
])
def test_a_bad_option_value_is_one_exit_code_in_every_subcommand(runner, app, args):
    """The parser's refusals (not a number, not a choice) and the commands' own are both 37."""
    result = runner.invoke(app, [str(a) for a in args])
    assert result.exit_code == 37, result.stderr
    assert "option error" in one_line(result)


def test_unknown_options_and_missing_arguments_stay_usage_errors(runner, app):
    for args in (["excuse", DOMAIN, PROBLEM, "--bogus"], ["excuse", DOMAIN]):
        result = runner.invoke(app, [str(a) for a in args])
        assert result.exit_code == 2 and "usage error" in one_line(result)


def test_plan_unknown_search_and_huge_time_limit(runner, app):
    assert runner.invoke(app, ["plan", DOMAIN, PROBLEM, "--search", "zz"]).exit_code == 37
    assert runner.invoke(app, ["plan", DOMAIN, PROBLEM, "--time-limit", "1e10"]).exit_code == 37


def test_stdin_twice_is_refused(runner, app):
    result = runner.invoke(app, ["plan", "-", "-"], input="")
    assert result.exit_code == 37
    assert "standard input" in one_line(result)


@pytest.mark.parametrize("json_out", [False, True])
@pytest.mark.parametrize("args,code,status,reason", [
    (["--max-size", "0"], 13, "no-excuse-within-size", "no excuse within --max-size"),
    (["--time-limit", "0.000001"], 20, "timeout", "time limit"),
])
def test_a_non_zero_excuse_result_writes_its_document_and_says_why(runner, app, tmp_path, args, code, status,
                                                                    reason, json_out):
    """The document is the result (its status says what happened); the reason is on stderr, --quiet too."""
    import json

    out = tmp_path / ("out.json" if json_out else "out.txt")
    out.write_text("old")
    result = runner.invoke(app, ["excuse", *map(str, (BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")),
                                 "--strategy", "baseline", "-o", str(out), "--quiet", *args])
    assert result.exit_code == code
    assert reason in one_line(result)
    text = out.read_text()
    if json_out:
        assert json.loads(text)["status"] == status
    else:
        assert reason in text


def test_a_non_zero_text_result_on_stdout_is_not_said_twice(runner, app):
    result = runner.invoke(app, ["excuse", *map(str, (BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")),
                                 "--max-size", "0", "-q"])
    assert result.exit_code == 13
    assert "no excuse within --max-size" in one_line(result)
    assert result.stdout == ""


def test_an_invalid_plan_writes_its_report_and_names_the_step_on_stderr(runner, app, tmp_path):
    import json

    domain, problem = kitchen(1, "human")
    plan = tmp_path / "bad.plan"
    plan.write_text("(close_drawer pinkdrawer)\n")
    for json_out in (False, True):
        out = tmp_path / ("v.json" if json_out else "v.txt")
        result = runner.invoke(app, ["validate", str(domain), str(problem), str(plan), "-o", str(out), "-q",
                                     *(["--json"] if json_out else [])])
        assert result.exit_code == 12
        line = one_line(result)
        assert f"{plan}:1:1: invalid: step 1" in line and "does not hold" in line
        if json_out:
            assert json.loads(out.read_text())["valid"] is False
        else:
            assert out.read_text() == line + "\n"


def test_an_unsolvable_plan_json_is_written_with_its_reason(runner, app, tmp_path):
    import json

    out = tmp_path / "plan.json"
    result = runner.invoke(app, ["plan", str(DATA / "oracle" / "tokens-domain.pddl"),
                                 str(DATA / "oracle" / "tokens-problem.pddl"), "--json", "-o", str(out), "-q"])
    assert result.exit_code == 10
    assert one_line(result).startswith("unsolvable:")
    doc = json.loads(out.read_text())
    assert doc["status"] == "unsolvable" and doc["plan"] is None


def test_unwritable_second_output_fails_before_anything_is_written(runner, app, tmp_path):
    out = tmp_path / "keep.txt"
    out.write_text("precious")
    result = runner.invoke(app, ["excuse", DOMAIN, PROBLEM, "-o", str(out), "--excuse-problem", str(tmp_path)])
    assert result.exit_code == 40
    assert out.read_text() == "precious"
    assert "is a directory" in one_line(result)


def test_output_folder_name_is_an_error(runner, app, tmp_path):
    result = runner.invoke(app, ["plan", *kitchen(1, "human"), "-o", str(tmp_path / "nodir") + "/"])
    assert result.exit_code == 40


def test_deep_nesting_is_a_syntax_error(runner, app, tmp_path):
    problem = tmp_path / "deep.pddl"
    problem.write_text("(define (problem p) (:domain kitchen) (:goal " + "(and " * 200 + ")" * 200 + "))")
    result = runner.invoke(app, ["excuse", DOMAIN, str(problem)])
    assert result.exit_code == 31
    assert "nested more than 64 levels" in one_line(result)


def test_empty_goal_is_already_solvable(runner, app, tmp_path):
    problem = tmp_path / "p.pddl"
    problem.write_text(open(PROBLEM).read().replace("(:goal (and (inside RedPlate PinkDrawer)))", "(:goal (and))"))
    result = runner.invoke(app, ["excuse", DOMAIN, str(problem), "--json"])
    assert result.exit_code == 0, result.stderr
    assert '"already-solvable"' in result.stdout


def test_invariants_from_an_unrelated_domain_is_a_mismatch_in_one_line(runner, app):
    """Blocks' (clear ?x - block) beside the kitchen's (clear ?f - furniture): no kitchen object is a block, so
    the invariants would mean nothing (it ran, exit 0, before types neither domain relates were a clash)."""
    result = runner.invoke(app, ["excuse", DOMAIN, PROBLEM, "--invariants-from", str(BLOCKS / "domain.pddl")])
    assert result.exit_code == 34, result.stderr
    assert "argument 1 of predicate clear is of type block here and of type furniture" in one_line(result)


def test_action_names_differing_in_case_are_duplicates(runner, app, tmp_path):
    domain = tmp_path / "d.pddl"
    text = open(DOMAIN).read().replace("(:action put_on", "(:action TAKE")
    domain.write_text(text)
    result = runner.invoke(app, ["plan", str(domain), PROBLEM])
    assert result.exit_code == 32
    assert "d.pddl:26:3: semantic error: action 'TAKE' is declared twice" in one_line(result)


def test_action_named_like_a_reversed_action_is_fine(runner, app, tmp_path):
    domain = tmp_path / "d.pddl"
    domain.write_text(open(DOMAIN).read().replace("(:action put_on", "(:action take__reversed"))
    result = runner.invoke(app, ["excuse", str(domain), PROBLEM])
    assert result.exit_code == 0
    said = [line for line in result.stderr.splitlines() if not line.startswith("held fixed")]
    assert len(said) <= 1  # the search's effort; no translator warnings


def test_endless_input_is_refused(runner, app):
    result = runner.invoke(app, ["plan", "/dev/zero", PROBLEM])
    assert result.exit_code == 30
    assert "larger than 64 MiB" in one_line(result)


def test_too_many_atoms_is_refused_quickly(runner, app, tmp_path):
    domain = tmp_path / "big.pddl"
    domain.write_text("(define (domain big) (:requirements :strips :typing) (:types t) "
                      "(:predicates (p ?a ?b ?c ?d ?e ?f - t) (q)) "
                      "(:action a :parameters (?x - t) :precondition (q) :effect (p ?x ?x ?x ?x ?x ?x)))")
    problem = tmp_path / "p.pddl"
    objects = " ".join(f"o{i}" for i in range(12))
    problem.write_text(f"(define (problem p) (:domain big) (:objects {objects} - t) (:init) (:goal (q)))")
    result = runner.invoke(app, ["excuse", str(domain), str(problem)])
    assert result.exit_code == 21
    assert "exceed the limit" in one_line(result)


def test_type_cycle_is_named(runner, app, tmp_path):
    domain = tmp_path / "d.pddl"
    domain.write_text("(define (domain d) (:requirements :strips :typing) (:types t - u u - t) "
                      "(:predicates (p ?x - t)) (:action a :parameters (?x - t) :precondition (p ?x) :effect (not (p ?x))))")
    result = runner.invoke(app, ["plan", str(domain), PROBLEM])
    assert result.exit_code == 32
    assert "type hierarchy has a cycle" in one_line(result)


def test_a_type_declared_twice_is_named(runner, app, tmp_path):
    # Read as "type hierarchy has a cycle:" with an empty list before; declared alike, it is one type, as Fast
    # Downward reads it, with a warning at the second declaration (#57).
    domain = tmp_path / "d.pddl"
    domain.write_text("(define (domain d) (:requirements :strips :typing)\n  (:types t u - object t)\n"
                      "  (:predicates (p ?x - t)) (:action a :parameters (?x - t) :precondition (p ?x) :effect (not (p ?x))))")
    result = runner.invoke(app, ["merge", str(domain), str(domain)])
    assert result.exit_code == 0, result.output
    assert result.stderr.splitlines()[0] == (f"{domain}:2:24: warning: type 't' is declared again (first at 2:11); "
                                             "read as one type below 'object', as Fast Downward reads it")
    domain.write_text(domain.read_text().replace("t u - object t)", "t - v u v - object t - u)"))  # u or v?
    result = runner.invoke(app, ["plan", str(domain), PROBLEM])
    assert result.exit_code == 32
    assert one_line(result) == f"{domain}:2:30: semantic error: type 't' is declared twice in :types"


# --- segment / learn-domain / evaluate on hand-made demonstrations -------------------------------------------

DEMO = DATA / "demo" / "open-drawer.csv"


def _segments(runner, app) -> dict:
    import json

    result = runner.invoke(app, ["segment", str(DEMO)])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_segment_from_stdin_needs_state(runner, app):
    result = runner.invoke(app, ["segment", "-"], input=DEMO.read_text())
    assert result.exit_code == 37
    assert "expected --state FILE" in one_line(result)


def _broken(doc: dict, how: str) -> dict:
    seg = next(s for s in doc["segments"] if s["added"])
    if how == "segments-null":
        doc["segments"] = None
    elif how == "segment-int":
        doc["segments"].append(5)
    elif how == "missing-activity":
        del seg["activity"]
    elif how == "before-null":
        seg["before"] = None
    elif how == "nested-atom":
        seg["after"].append("(open (f x))")
    elif how == "no-parens":
        seg["after"].append("open pinkdrawer")
    elif how == "keyword-predicate":
        seg["after"].append("(and pinkdrawer)")
    elif how == "arity":
        seg["after"].append("(open pinkdrawer table)")
    elif how == "activity":
        seg["activity"] = "Open Drawer!"
    elif how == "type":
        doc["objects"]["pinkdrawer"] = "pink drawer"
    elif how == "type-null":
        doc["objects"]["pinkdrawer"] = None
    elif how == "object-int":
        seg["object"] = 7
    return doc


@pytest.mark.parametrize("how,message", [
    ("segments-null", "segments: expected a list of segments, got null"),
    ("segment-int", "segments[2]: expected a segment"),
    ("missing-activity", "segments[1]: missing key 'activity'"),
    ("before-null", "segments[1].before: expected a list of fluents"),
    ("nested-atom", 'segments[1].after[5]: expected a fluent like "(open pinkdrawer)", got "(open (f x))"'),
    ("no-parens", "segments[1].after[5]: expected a fluent like"),
    ("keyword-predicate", 'segments[1].after[5]: predicate "and": expected a name that is not a PDDL keyword'),
    ("arity", "segments[1].after[5]: open has 2 argument(s) here and 1 elsewhere"),
    ("activity", "segments[1].activity: expected an activity name"),
    ("type", "objects.pinkdrawer: type of pinkdrawer: expected a PDDL name"),
    ("type-null", "objects.pinkdrawer: type of pinkdrawer: expected a string, got null"),
    ("object-int", 'segments[1].object: expected an object name or "", got 7'),
])
def test_hand_edited_segments_are_trace_errors_with_a_position(runner, app, tmp_path, how, message):
    import json

    bad = tmp_path / "s.json"
    bad.write_text(json.dumps(_broken(_segments(runner, app), how), indent=2))
    out = tmp_path / "keep.pddl"
    out.write_text("precious")
    result = runner.invoke(app, ["learn-domain", str(bad), "-o", str(out)])
    assert result.exit_code == 36, result.stderr
    line = one_line(result)
    assert re.match(r".*s\.json:\d+:\d+: trace error: ", line) and message in line, line
    assert out.read_text() == "precious"
    robot, problem = kitchen(1)
    result = runner.invoke(app, ["evaluate", robot, problem, "--human", kitchen(1, "human")[0], "-d", str(bad)])
    assert result.exit_code == 36 and message in one_line(result)


def test_deeply_nested_segments_are_a_trace_error(runner, app, tmp_path):
    bad = tmp_path / "s.json"
    bad.write_text("[" * 100000 + "]" * 100000)
    result = runner.invoke(app, ["learn-domain", str(bad)])
    assert result.exit_code == 36
    assert "nested too deeply" in one_line(result)


@pytest.mark.parametrize("name", ["x y", "lérnt", "a)", "", "and"])
def test_learn_domain_name_must_be_a_pddl_name(runner, app, tmp_path, name):
    import json

    segments = tmp_path / "s.json"
    segments.write_text(json.dumps(_segments(runner, app)))
    result = runner.invoke(app, ["learn-domain", str(segments), "--name", name])
    assert result.exit_code == 37
    assert "--name" in one_line(result)


def test_learn_domain_with_prior_counts_its_skills_and_refuses_clashes(runner, app, tmp_path):
    import json

    doc = _segments(runner, app)
    good = tmp_path / "s.json"
    good.write_text(json.dumps(doc))
    result = runner.invoke(app, ["learn-domain", str(good), "--prior", DOMAIN])
    assert result.exit_code == 0
    assert "1 demonstrated skill(s): open_drawer" in result.stderr
    # The demonstration's type 'inside' is the prior's predicate: no parsable domain has both.
    doc["objects"]["pinkdrawer"] = "inside"
    clash = tmp_path / "clash.json"
    clash.write_text(json.dumps(doc))
    result = runner.invoke(app, ["learn-domain", str(clash), "--prior", DOMAIN])
    assert result.exit_code == 34
    assert "clash.json: mismatch: 'inside' is a type in one and a predicate in the other" in one_line(result)
    # open/2 in the demonstration, open/1 in the prior: named by the segments file, not '<learned>'.
    arity = tmp_path / "arity.json"
    arity.write_text(json.dumps(_segments(runner, app)).replace("(open pinkdrawer)", "(open pinkdrawer table)"))
    result = runner.invoke(app, ["learn-domain", str(arity), "--prior", DOMAIN])
    assert result.exit_code == 34
    assert one_line(result).startswith(f"{arity}: mismatch: predicate open has")


def test_opposite_changes_under_one_name_are_two_skills(runner, app, tmp_path):
    import json

    # A fluent other than `open` flips one way, then back: both manipulations
    # are named Push.  Intersecting them would leave an action with no effect.
    doc = _segments(runner, app)
    pushed = next(s for s in doc["segments"] if s["added"])
    pushed["activity"] = "Push"
    doc["segments"].append(dict(pushed, index=99, before=pushed["after"], after=pushed["before"]))
    path = tmp_path / "s.json"
    path.write_text(json.dumps(doc).replace("(open ", "(at "))
    result = runner.invoke(app, ["learn-domain", str(path)])
    assert result.exit_code == 0, result.stderr
    assert "(:effect ())" not in result.stdout
    assert "(:action push_drawer\n" in result.stdout and "(:action push_drawer_2\n" in result.stdout


def test_segment_refuses_to_write_over_its_own_input(runner, app, tmp_path):
    import shutil

    demo = ROOT / "data" / "demos" / "kitchen-1" / "P1-excuse"
    for suffix in (".csv", ".state.csv"):
        shutil.copy(f"{demo}{suffix}", tmp_path / f"t{suffix}")
    before = (tmp_path / "t.state.csv").read_bytes()
    result = runner.invoke(app, ["segment", str(tmp_path / "t.csv"), "-o", str(tmp_path / "t.state.csv")])
    assert result.exit_code == 37 and "is an input of this run" in result.stderr
    assert (tmp_path / "t.state.csv").read_bytes() == before


def test_out_of_memory_is_its_own_exit_code(runner, app, monkeypatch, tmp_path):
    # A MemoryError anywhere in a command is the documented memout code, one line, no traceback,
    # and the output file is not written.
    import cli.excuse

    def exhausted(*args, **kwargs):
        raise MemoryError()

    monkeypatch.setattr(cli.excuse, "find_excuses", exhausted)
    out = tmp_path / "excuse.json"
    result = runner.invoke(app, ["excuse", str(DOMAIN), str(PROBLEM), "--json", "-o", str(out)])
    assert result.exit_code == 22
    assert one_line(result) == "out of memory: the run needed more memory than the process may use"
    assert not out.exists()


@pytest.mark.parametrize("version", ["2", "0", '"1"', "1.0", "null"])
def test_a_document_of_an_unknown_format_version_is_refused(runner, app, tmp_path, version):
    # An excuse document from another release: refused with the versions this one reads.
    doc = tmp_path / "excuse.json"
    doc.write_text('{\n  "format": "guided-lfd/excuse",\n  "format_version": ' + version + ',\n'
                   '  "excuse": {"changes": [{"op": "add", "atom": "(open pinkdrawer)"}]}\n}\n')
    human = kitchen(1, "human")[0]
    result = runner.invoke(app, ["evaluate", str(DOMAIN), str(PROBLEM), "--human", str(human), "--excuse", str(doc)])
    assert result.exit_code == 30
    line = one_line(result)
    assert f"{doc}:3: input error: " in line
    assert f"format_version {version} of guided-lfd/excuse is not one this release reads (it reads version 1)" in line


def test_a_document_of_this_format_version_still_reads():
    from guided_lfd.io import read_json_document
    from guided_lfd.errors import InputFileError

    import tempfile
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as fh:
        fh.write('{"format": "guided-lfd/excuse", "format_version": 1, "excuse": null}')
    _, doc = read_json_document(fh.name, "excuse", InputFileError, "guided-lfd excuse --json")
    assert doc["format_version"] == 1


def test_ctrl_c_is_its_own_documented_exit_code(runner, app, monkeypatch):
    import cli.excuse

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli.excuse, "find_excuses", interrupted)
    result = runner.invoke(app, ["excuse", str(DOMAIN), str(PROBLEM)])
    assert result.exit_code == 130
    assert one_line(result) == "interrupted"


def _workspace(runner, app, tmp_path):
    """Copies of a kitchen task, a plan, segments and an excuse document: every subcommand's inputs."""
    import shutil

    base = tmp_path / "in"
    base.mkdir()
    robot, problem = kitchen(1)
    shutil.copy(robot, base / "robot.pddl")
    shutil.copy(problem, base / "problem.pddl")
    shutil.copy(kitchen(1, "human")[0], base / "human.pddl")
    demo = ROOT / "data" / "demos" / "kitchen-1" / "P1-excuse"
    for suffix in (".csv", ".state.csv"):
        shutil.copy(f"{demo}{suffix}", base / f"t{suffix}")
    for name, args in (("plan.txt", ["plan", "human.pddl", "problem.pddl"]),
                       ("s.json", ["segment", "t.csv"]),
                       ("e.json", ["excuse", "robot.pddl", "problem.pddl", "--json"]),
                       ("learned.pddl", ["learn-domain", "s.json"])):
        cwd = os.getcwd()
        os.chdir(base)
        try:
            result = runner.invoke(app, [*args, "-q", "-o", name])
        finally:
            os.chdir(cwd)
        assert result.exit_code == 0, (name, result.stderr)
    return base


#: Each subcommand with the input its -o (or second output) names, by a relative path through '..'.
OWN_INPUTS = [
    (["excuse", "robot.pddl", "problem.pddl", "-o"], "robot.pddl"),
    (["excuse", "robot.pddl", "problem.pddl", "--excuse-problem"], "problem.pddl"),
    (["plan", "human.pddl", "problem.pddl", "-o"], "problem.pddl"),
    (["validate", "human.pddl", "problem.pddl", "plan.txt", "-o"], "plan.txt"),
    (["learn-domain", "s.json", "-o"], "s.json"),
    (["merge", "robot.pddl", "learned.pddl", "-o"], "learned.pddl"),
    (["evaluate", "robot.pddl", "problem.pddl", "--human", "human.pddl", "--excuse", "e.json", "-o"], "e.json"),
    (["segment", "t.csv", "-o"], "t.state.csv"),
]


@pytest.mark.parametrize("args,target", OWN_INPUTS, ids=[f"{a[0]}-{a[-1]}" for a, _ in OWN_INPUTS])
@pytest.mark.parametrize("spelling", ["relative", "symlink"])
def test_no_subcommand_writes_over_its_own_input(runner, app, tmp_path, args, target, spelling):
    """-o naming an input (through '..' or a symbolic link) is refused before any work; the input is intact."""
    base = _workspace(runner, app, tmp_path)
    before = (base / target).read_bytes()
    if spelling == "symlink":
        (tmp_path / "link").symlink_to(base / target)
        output = str(tmp_path / "link")
    else:
        output = f"../in/{target}"
    cwd = os.getcwd()
    os.chdir(base)
    try:
        result = runner.invoke(app, [*args, output])
    finally:
        os.chdir(cwd)
    assert result.exit_code == 37, result.stderr
    assert one_line(result).endswith("is an input of this run; expected another file")
    assert (base / target).read_bytes() == before


def test_two_outputs_naming_one_file_are_refused(runner, app, tmp_path):
    robot, problem = kitchen(1)
    out = tmp_path / "x.json"
    result = runner.invoke(app, ["excuse", str(robot), str(problem), "-o", str(out),
                                 "--excuse-problem", str(tmp_path / "." / "x.json")])
    assert result.exit_code == 37
    assert "is also --output" in one_line(result)
    assert not out.exists()


@pytest.mark.parametrize("name", ["a" * 300 + ".json", "a" * 300 + "/x.json"])
@pytest.mark.parametrize("command", [["excuse", "robot", "problem"], ["plan", "human", "problem"]])
def test_an_output_name_the_os_refuses_is_the_output_error(runner, app, tmp_path, name, command):
    """A 300-character name is exit 40 with the OS's reason, not an internal error."""
    files = {"robot": str(kitchen(1)[0]), "problem": str(kitchen(1)[1]), "human": str(kitchen(1, "human")[0])}
    result = runner.invoke(app, [command[0], *(files[c] for c in command[1:]), "-o", str(tmp_path / name)])
    assert result.exit_code == 40, result.stderr
    line = one_line(result)
    assert "output error" in line and ("too long" in line or "File name" in line)


#: Each subcommand with a JSON document, run with -o NAME.json and no --json.
BY_EXTENSION = [
    (["excuse", "robot.pddl", "problem.pddl"], "json", "guided-lfd/excuse"),
    (["plan", "human.pddl", "problem.pddl"], "json", "guided-lfd/plan"),
    (["validate", "human.pddl", "problem.pddl", "plan.txt"], "json", "guided-lfd/validation"),
    (["merge", "robot.pddl", "learned.pddl"], "json", "guided-lfd/merge"),
    (["learn-domain", "s.json"], "json", "guided-lfd/learned"),
    (["evaluate", "robot.pddl", "problem.pddl", "--human", "human.pddl", "--excuse", "e.json"], "json",
     "guided-lfd/evaluation"),
    (["evaluate", "robot.pddl", "problem.pddl", "--human", "human.pddl", "--excuse", "e.json"], "csv", "measure"),
    (["segment", "t.csv"], "csv", "index"),
    (["segment", "t.csv", "--json"], "json", "guided-lfd/segments"),
]


@pytest.mark.parametrize("args,suffix,marker", BY_EXTENSION, ids=[f"{a[0]}-{s}" for a, s, _ in BY_EXTENSION])
def test_the_output_extension_selects_the_format(runner, app, tmp_path, args, suffix, marker):
    """-o FILE.json writes JSON wherever there is --json (and FILE.csv writes CSV where there is --csv)."""
    import json

    base = _workspace(runner, app, tmp_path)
    cwd = os.getcwd()
    os.chdir(base)
    try:
        result = runner.invoke(app, [*args, "-q", "-o", f"result.{suffix}"])
    finally:
        os.chdir(cwd)
    assert result.exit_code == 0, result.stderr
    text = (base / f"result.{suffix}").read_text()
    if suffix == "json":
        assert json.loads(text)["format"] == marker
    else:
        assert text.splitlines()[0].split(",")[0] == marker


def test_json_and_csv_together_are_refused(runner, app, tmp_path):
    base = _workspace(runner, app, tmp_path)
    result = runner.invoke(app, ["segment", str(base / "t.csv"), "--json", "--csv"])
    assert result.exit_code == 37 and "choose one output format" in one_line(result)


def test_two_outputs_on_standard_output_are_refused(runner, app):
    result = runner.invoke(app, ["excuse", DOMAIN, PROBLEM, "-o", "-", "--excuse-problem", "-"])
    assert result.exit_code == 37 and "both name '-'" in one_line(result)


def test_memory_limit_ends_a_run_with_the_memout_code():
    """--memory-limit caps the process itself (a fresh one here): running out is exit 22, one line."""
    import subprocess

    from guided_lfd.benchmark import cli_command

    proc = subprocess.run([*cli_command(), "excuse", DOMAIN, PROBLEM, "--memory-limit", "1"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 22, proc.stderr
    assert proc.stderr.strip() == "out of memory: the run needed more memory than the process may use"
    assert proc.stdout == ""


def test_memory_limit_must_be_positive(runner, app):
    result = runner.invoke(app, ["plan", DOMAIN, PROBLEM, "--memory-limit", "0"])
    assert result.exit_code == 37 and "--memory-limit 0" in one_line(result)


def test_an_error_quoting_a_control_character_stays_one_line(runner, app, tmp_path):
    """Found by tests/test_fuzz.py: a record separator in a state file split the error in two lines."""
    import shutil

    demo = ROOT / "data" / "demos" / "kitchen-1" / "P1-excuse"
    shutil.copy(f"{demo}.csv", tmp_path / "t.csv")
    text = (demo.parent / "P1-excuse.state.csv").read_text().replace('"object(BlueDrawer', '"object\x1e0(BlueDrawer', 1)
    (tmp_path / "t.state.csv").write_text(text)
    result = runner.invoke(app, ["segment", str(tmp_path / "t.csv")])
    assert result.exit_code == 36
    assert "object\\x1e0(BlueDrawer" in one_line(result)


def _baseline_under_outside_cap(tmp_path, interrupt_after: float | None):
    """The paper's baseline on a task that needs far more memory than an outside ``ulimit -v`` allows."""
    import resource
    import signal
    import subprocess
    import time

    from guided_lfd.benchmark import BenchTask, cli_command, robot_domain_file
    from conftest import ROOT

    ipc = ROOT / "data/benchmarks/ipc/depot"
    task = BenchTask("depot-task03-load", "depot", "task03", "load", str(ipc / "domain.pddl"),
                     str(ipc / "task03.pddl"), "")
    robot = robot_domain_file(task, tmp_path)

    def cap() -> None:  # what `ulimit -v 400000` does in the shell that starts the run
        resource.setrlimit(resource.RLIMIT_AS, (400_000 * 1024, 400_000 * 1024))

    start = time.monotonic()
    proc = subprocess.Popen([*cli_command(), "excuse", str(robot), task.problem_file, "--strategy", "baseline",
                             "--change-structure", "--time-limit", "60", "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, preexec_fn=cap)
    if interrupt_after is not None:
        time.sleep(interrupt_after)
        proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    return proc.returncode, err, time.monotonic() - start


def test_an_outside_memory_cap_ends_the_baseline_promptly_with_the_memout_code(tmp_path):
    code, err, took = _baseline_under_outside_cap(tmp_path, None)
    assert code == 22, err
    assert err.strip() == "out of memory: the run needed more memory than the process may use"
    assert took < 30  # it took 200 s and a kill before, ignoring SIGINT


def test_ctrl_c_works_under_an_outside_memory_cap(tmp_path):
    code, err, took = _baseline_under_outside_cap(tmp_path, 2.0)
    assert code in (130, 22), err  # interrupted, or out of memory first on a fast machine
    assert took < 10


@pytest.mark.parametrize("args", [
    ["plan", DOMAIN, PROBLEM, "--memory-limit", "8796093022208"],
    ["excuse", DOMAIN, PROBLEM, "--memory-limit", "8796093022208"],
])
def test_a_memory_limit_too_large_for_the_system_is_an_option_error(runner, app, args):
    """#25 second round: 2**43 MiB was 'internal error: OverflowError' (the bytes overflow a C long)."""
    result = runner.invoke(app, args)
    assert result.exit_code == 37
    assert one_line(result) == ("option error: --memory-limit 8796093022208: expected a number of MiB from 1 to "
                                "1099511627776")


@pytest.mark.parametrize("args, message", [
    (["--only", ","], "--only ',': expected comma-separated parts of task ids"),
    (["--jobs", "99999999999999999999"], "--jobs 99999999999999999999: expected a number of runs at a time from 1 "
                                          "to 256"),
    (["--memory-limit", "8796093022208"], "--memory-limit 8796093022208: expected MiB from 0 (no cap) to "
                                          "1099511627776"),
])
def test_bench_refuses_an_empty_only_an_unbounded_jobs_and_a_huge_memory_limit(runner, app, tmp_path, args,
                                                                                message):
    """#25 second round: '--only ,' ran all 1,524 runs, --jobs had no bound, the memory limit overflowed."""
    result = runner.invoke(app, ["bench", "run", "--results", str(tmp_path / "r"), *args])
    assert result.exit_code == 37, result.output
    assert message in result.stderr
    assert not (tmp_path / "r").exists()
