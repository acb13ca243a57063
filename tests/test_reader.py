"""Parsing: supported PDDL reads correctly; bad input gives pinned one-line errors."""

from __future__ import annotations

import pytest

from conftest import BLOCKS, DATA, kitchen
from guided_lfd import errors
from guided_lfd.pddl.model import Atom, Literal
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import domain_to_pddl, problem_to_pddl

BAD = DATA / "bad"
GOOD_DOMAIN = str(BLOCKS / "domain.pddl")
GOOD_PROBLEM = str(BLOCKS / "task03.pddl")


def test_blocks_task_reads_objects_init_and_goal():
    domain, problem = parse_task(GOOD_DOMAIN, GOOD_PROBLEM)
    assert domain.name == "blocks"
    assert [a.name for a in domain.actions] == ["pick-up", "put-down", "stack", "unstack"]
    assert problem.objects == {"a": "block", "b": "block", "c": "block", "d": "block"}
    assert Atom("on", ("c", "b")) in problem.init
    assert problem.goal == (
        Literal(Atom("on", ("a", "b"))), Literal(Atom("on", ("b", "c"))), Literal(Atom("on", ("c", "d"))),
    )


def test_negative_preconditions_constants_and_spellings_are_kept():
    domain, problem = parse_task(*kitchen(2))
    open_drawer = domain.action("open_drawer")
    assert Literal(Atom("open", ("?d",)), positive=False) in open_drawer.precondition
    assert problem.spellings["pinkdrawer"] == "PinkDrawer"


@pytest.mark.parametrize("n", [1, 2])
@pytest.mark.parametrize("who", ["robot", "human"])
def test_writer_round_trips_through_the_parser(tmp_path, n, who):
    domain, problem = parse_task(*kitchen(n, who))
    (tmp_path / "d.pddl").write_text(domain_to_pddl(domain))
    (tmp_path / "p.pddl").write_text(problem_to_pddl(problem))
    domain2, problem2 = parse_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    assert domain2.actions == domain.actions
    assert domain2.types == domain.types
    assert (problem2.init, problem2.goal, problem2.objects) == (problem.init, problem.goal, problem.objects)


# (file, which side is bad, exception, exit code, message start incl. file:line:col)
BAD_INPUTS = [
    ("unknown-object.pddl", "problem", errors.PddlSemanticError, 32, "unknown-object.pddl:5:8: semantic error: unknown object 'z'"),
    ("unknown-predicate.pddl", "problem", errors.PddlSemanticError, 32, "unknown-predicate.pddl:5:3: semantic error: unknown predicate 'onn'"),
    ("wrong-arity.pddl", "problem", errors.PddlSemanticError, 32, "wrong-arity.pddl:5:2: semantic error: wrong number of arguments for 'on' (expected 2)"),
    ("syntax-goal.pddl", "problem", errors.PddlSyntaxError, 31, "syntax-goal.pddl:6:9: syntax error: no viable alternative"),
    ("unclosed.pddl", "problem", errors.PddlSyntaxError, 31, "unclosed.pddl:1:1: syntax error: '(' is never closed"),
    ("wrong-domain.pddl", "problem", errors.MismatchError, 34, "wrong-domain.pddl:2:10: mismatch: problem is for domain 'KITCHEN'"),
    ("requirement.pddl", "domain", errors.UnsupportedFeatureError, 33, "requirement.pddl:6:34: unsupported: unsupported requirement :durative-actions"),
    ("durative.pddl", "domain", errors.UnsupportedFeatureError, 33, "durative.pddl:5:4: unsupported: ':durative-action' needs :durative-actions"),
    ("numeric.pddl", "domain", errors.UnsupportedFeatureError, 33, "numeric.pddl:22:20: unsupported: 'increase' of a fluent other than total-cost: guided-lfd supports numbers only as :action-costs"),
    ("empty.pddl", "problem", errors.InputFileError, 30, "empty.pddl: input error: empty file"),
    ("blank.pddl", "domain", errors.PddlSyntaxError, 31, "blank.pddl:1:1: syntax error: no PDDL definition found"),
    ("missing.pddl", "problem", errors.InputFileError, 30, "missing.pddl: input error: file not found"),
]


@pytest.mark.parametrize("name,side,exc,code,message", BAD_INPUTS, ids=[b[0] for b in BAD_INPUTS])
def test_bad_input_is_one_pinned_line(name, side, exc, code, message):
    bad = str(BAD / name)
    args = (bad, GOOD_PROBLEM) if side == "domain" else (GOOD_DOMAIN, bad)
    with pytest.raises(exc) as info:
        parse_task(*args)
    text = str(info.value)
    assert "\n" not in text
    assert text.split("/")[-1].startswith(message)
    assert info.value.exit_code == code


def test_problem_given_as_domain_is_rejected():
    with pytest.raises(errors.PddlSyntaxError, match=r"task03.pddl:1:9: syntax error: this is a problem file, expected a domain file"):
        parse_domain(GOOD_PROBLEM)


def test_exit_codes_are_distinct_and_documented():
    classes = [errors.InputFileError, errors.PddlSyntaxError, errors.PddlSemanticError, errors.UnsupportedFeatureError,
               errors.MismatchError, errors.PlanFileError, errors.TraceError, errors.OptionError, errors.OutputError,
               errors.SearchTimeout]
    codes = [c.exit_code for c in classes]
    assert len(set(codes)) == len(codes)
    assert all(code in errors.EXIT_CODES for code in codes)


def test_readme_documents_every_exit_code():
    from conftest import ROOT

    readme = (ROOT / "docs" / "exit-codes.md").read_text()
    for code in errors.EXIT_CODES:
        assert f"\n| {code} |" in readme, f"exit code {code} missing from docs/exit-codes.md"
        row = readme.split(f"\n| {code} |", 1)[1].split("\n", 1)[0]
        # meaning here, and what Fast Downward's driver means by the same number
        assert [c.strip() != "" for c in row.split("|")] == [True, True, False], row


def _keywords_in_capitals(text: str) -> str:
    import re

    text = re.sub(r"\((define|domain|problem|and|not)\b", lambda m: "(" + m.group(1).upper(), text)
    return re.sub(r"(?<![;\w]):[a-z-]+", lambda m: m.group(0).upper(), text)


@pytest.mark.parametrize("path", ["fast", "tarski"])
def test_keywords_read_in_any_case(tmp_path, monkeypatch, path):
    """DOMAIN, :REQUIREMENTS, :PARAMETERS, AND ... read as in lower case, on both reading paths."""
    from guided_lfd.pddl import fast_reader

    domain, problem = kitchen(1)
    expected = parse_task(domain, problem)
    (tmp_path / "d.pddl").write_text(_keywords_in_capitals(open(domain).read()))
    (tmp_path / "p.pddl").write_text(_keywords_in_capitals(open(problem).read()))
    assert ":REQUIREMENTS :STRIPS" in (tmp_path / "d.pddl").read_text()
    if path == "tarski":
        monkeypatch.setattr(fast_reader, "read_domain", lambda *a: None)
    import dataclasses

    for got, want in zip(parse_task(tmp_path / "d.pddl", tmp_path / "p.pddl"), expected):
        for field in dataclasses.fields(want):
            if field.name not in ("path", "source", "spellings"):  # where it was read, and how it was spelt
                assert getattr(got, field.name) == getattr(want, field.name), field.name


def test_an_action_without_precondition_reads(tmp_path):
    """:precondition is optional in PDDL: the action has an empty one."""
    domain = tmp_path / "d.pddl"
    domain.write_text("(define (domain d) (:predicates (p ?x))\n  (:action a :parameters (?x) :effect (p ?x)))\n")
    parsed = parse_domain(domain)
    assert list(parsed.actions[0].precondition) == []
    assert [str(a) for a in parsed.actions[0].add] == ["(p ?x)"]


@pytest.mark.parametrize("line", [
    "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) :effect (p ?x)) "
    "(:action b :parameters (?x) :effect (p ?x) (p ?x)))",
    # two insertions before the error, on the same line
    "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) :effect (p ?x)) "
    "(:action b :parameters (?x) :effect (p ?x)) (:action c :parameters (?x) :effect (p ?x) (p ?x)))",
], ids=["one insertion", "two insertions"])
def test_an_error_after_actions_without_precondition_is_located_as_written(tmp_path, line):
    """tarski is given ':precondition (and)'; the columns it reports are mapped back to the file."""
    (tmp_path / "d.pddl").write_text(line + "\n")
    with pytest.raises(errors.PddlSyntaxError) as caught:
        parse_domain(tmp_path / "d.pddl")
    assert caught.value.location.line == 1
    assert caught.value.location.col == line.rindex("(p ?x)") + 1


def test_an_action_without_precondition_reads_in_a_typed_one_line_domain(tmp_path):
    """The insertion goes before :effect as written, whatever tarski is given for :types."""
    (tmp_path / "d.pddl").write_text("(define (domain d) (:requirements :typing) (:types t) (:predicates (p ?x - t)) "
                                     "(:action a :parameters (?x - t) :effect (p ?x)))\n")
    parsed = parse_domain(tmp_path / "d.pddl")
    assert list(parsed.actions[0].precondition) == [] and parsed.actions[0].params == (("?x", "t"),)


def test_a_name_spelt_like_a_keyword_keeps_reading(tmp_path):
    """Only keywords where a keyword goes are lowered: an object 'Max' stays a name."""
    (tmp_path / "d.pddl").write_text("(define (domain d) (:requirements :typing) (:types t) (:predicates (p ?x - t)) "
                                     "(:action a :parameters (?x - t) :precondition (not (p ?x)) :effect (p ?x)))\n")
    (tmp_path / "p.pddl").write_text("(define (problem q) (:domain d) (:objects Max Anna - t) (:init) (:goal (p Max)))\n")
    _, problem = parse_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    assert set(problem.objects) == {"max", "anna"} and problem.spellings["max"] == "Max"


def test_a_large_file_with_an_unclosed_list_is_read_once(tmp_path, monkeypatch):
    """Beyond SECOND_OPINION_MAX_CHARS the open list is reported from the one pass (no tarski re-parse)."""
    from guided_lfd.pddl import reader

    def second_parse(*args):
        raise AssertionError("parsed twice")

    monkeypatch.setattr(reader, "_tarski_syntax_error", second_parse)
    lines = "".join(f"  (p{k} ?x)\n" for k in range(reader.SECOND_OPINION_MAX_CHARS // 10))
    (tmp_path / "d.pddl").write_text(f"(define (domain d)\n (:predicates\n{lines}")
    with pytest.raises(errors.PddlSyntaxError) as caught:
        parse_domain(tmp_path / "d.pddl")
    assert "never closed" in caught.value.message and caught.value.location.line in (1, 2)
