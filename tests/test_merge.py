"""guided-lfd merge: union, duplicates up to renaming, name clashes, type refinement, errors."""

from __future__ import annotations

import contextlib
import io
import json

import pytest

from conftest import DATA
from guided_lfd.errors import EXIT_MISMATCH, MergeError
from guided_lfd.merge import merge_domains, same_up_to_renaming
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import domain_to_pddl
from guided_lfd.symbolic.portfolio import plan_task
from test_golden import check_golden

MERGE = DATA / "merge"


def load(name: str):
    return parse_domain(str(MERGE / name))


def test_same_up_to_renaming_allows_renamed_and_reordered_parameters():
    prior, learned = load("prior.pddl"), load("learned.pddl")
    assert same_up_to_renaming(prior.action("take"), learned.action("take_item"))
    assert not same_up_to_renaming(prior.action("take"), learned.action("take"))  # needs graspable
    assert not same_up_to_renaming(prior.action("take"), prior.action("put_inside"))


def test_merge_keeps_duplicates_once_and_renames_clashes():
    result = merge_domains([load("prior.pddl"), load("learned.pddl")])
    names = [a.name for a in result.domain.actions]
    assert names == ["take", "put_inside", "open_drawer", "take_2"]
    assert result.duplicates == [
        f"take_item ({MERGE / 'learned.pddl'}) equals take up to parameter renaming: kept once"]
    assert result.renamed == [
        f"take ({MERGE / 'learned.pddl'}) differs from the take already merged: renamed to take_2"]
    take = result.domain.action("take")
    assert "also from" in take.origin and "take_item" in take.origin


def test_merge_keeps_the_priors_type_hierarchy_and_refines_new_types():
    result = merge_domains([load("prior.pddl"), load("learned.pddl")])
    assert result.domain.types["drawer"] == "furniture"  # learned's "drawer - object" adds nothing
    assert result.domain.types["surface"] == "furniture"
    result = merge_domains([load("prior.pddl"), load("cabinet-flat.pddl"), load("cabinet-specific.pddl")])
    assert result.domain.types["cabinet"] == "furniture"
    assert result.refined == [f"type cabinet: parent object refined to furniture (from {MERGE / 'cabinet-specific.pddl'})"]


def test_merged_domain_solves_what_neither_part_solves():
    merged = merge_domains([load("prior.pddl"), load("learned.pddl")]).domain
    _, problem = parse_task(str(MERGE / "prior.pddl"), str(MERGE / "problem.pddl"))
    _, result = plan_task(merged, problem)
    assert [a.name for a in result.plan] == ["(open_drawer box)", "(take plate table)", "(put_inside plate box)"]
    _, alone = plan_task(load("prior.pddl"), problem)
    assert alone.plan is None


@pytest.mark.parametrize("name,message", [
    ("bad-arity.pddl", "bad-arity.pddl:4:17: mismatch: predicate open has 1 argument(s) in one domain and 2 in"),
    ("bad-types.pddl", "bad-types.pddl:4:11: mismatch: type drawer is declared under furniture by the prior and "
                       "under container in"),
    ("type-named-like-predicate.pddl", "type-named-like-predicate.pddl:3:11: mismatch: inside is a type in "),
    ("moves-prior-type.pddl", "moves-prior-type.pddl:5:50: mismatch: type drawer is declared under furniture by the "
                              "prior and under surface in"),
])
def test_incompatible_domains_are_refused_with_a_position(name, message):
    with pytest.raises(MergeError) as err:
        merge_domains([load("prior.pddl"), load(name)])
    assert message in str(err.value)
    assert err.value.exit_code == EXIT_MISMATCH


def test_a_type_cycle_across_domains_is_refused():
    with pytest.raises(MergeError) as err:
        merge_domains([load("prior.pddl"), load("cycle-a.pddl"), load("cycle-b.pddl")])
    assert "cycle-b.pddl:3:22: mismatch: type y would be its own ancestor via x" in str(err.value)


def test_cli_merge_matches_golden_and_reports_on_stderr(runner, app, monkeypatch):
    monkeypatch.chdir(MERGE)
    result = runner.invoke(app, ["merge", "prior.pddl", "learned.pddl"])
    assert result.exit_code == 0, result.stderr
    check_golden("merge-prior-learned.pddl", result.stdout)
    assert "renamed to take_2" in result.stderr
    doc = json.loads(runner.invoke(app, ["merge", "prior.pddl", "learned.pddl", "--json", "-q"]).stdout)
    assert doc["format"] == "guided-lfd/merge" and doc["format_version"] == 1
    assert doc["actions"] == ["take", "put_inside", "open_drawer", "take_2"]


def test_cli_merge_error_is_one_line_with_exit_34(runner, app, monkeypatch, tmp_path):
    monkeypatch.chdir(MERGE)
    out = tmp_path / "merged.pddl"
    out.write_text("keep me")
    result = runner.invoke(app, ["merge", "prior.pddl", "bad-arity.pddl", "-o", str(out)])
    assert result.exit_code == 34
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
    assert out.read_text() == "keep me"


def test_merged_domain_parses_in_fast_downward_translator(tmp_path):
    from fast_downward.translate.pddl_parser import lisp_parser, parsing_functions

    merged = merge_domains([load("prior.pddl"), load("learned.pddl")]).domain
    text = domain_to_pddl(merged)
    problem = (MERGE / "problem.pddl").read_text()
    with contextlib.redirect_stdout(io.StringIO()):
        task = parsing_functions.parse_task(lisp_parser.parse_nested_list(text.splitlines(keepends=True)),
                                            lisp_parser.parse_nested_list(problem.splitlines(keepends=True)))
    assert sorted(a.name for a in task.actions) == ["open_drawer", "put_inside", "take", "take_2"]


def test_positive_compilation_parses_and_plans_in_pyperplan(runner, app, tmp_path):
    from pyperplan import grounding
    from pyperplan.heuristics.lm_cut import LmCutHeuristic
    from pyperplan.pddl.parser import Parser
    from pyperplan.search import astar_search

    domain, problem = tmp_path / "merged.pddl", tmp_path / "problem.pddl"
    result = runner.invoke(app, ["merge", str(MERGE / "prior.pddl"), str(MERGE / "learned.pddl"), "-q",
                                 "--positive-for", str(MERGE / "problem.pddl"), "--problem-output", str(problem),
                                 "-o", str(domain)])
    assert result.exit_code == 0, result.stderr
    assert "(not_open ?o1)" in domain.read_text() and "(not_open box)" in problem.read_text()
    parser = Parser(str(domain), str(problem))
    task = grounding.ground(parser.parse_problem(parser.parse_domain()))
    plan = astar_search(task, LmCutHeuristic(task))
    assert [op.name for op in plan] == ["(open_drawer box)", "(take plate table)", "(put_inside plate box)"]


def test_positive_compilation_keeps_plans(tmp_path):
    from guided_lfd.pddl.compile import compile_negative_preconditions

    merged = merge_domains([load("prior.pddl"), load("learned.pddl")]).domain
    _, problem = parse_task(str(MERGE / "prior.pddl"), str(MERGE / "problem.pddl"))
    domain2, problem2 = compile_negative_preconditions(merged, problem)
    assert not any(not l.positive for a in domain2.actions for l in a.precondition)
    _, before = plan_task(merged, problem)
    _, after = plan_task(domain2, problem2)
    assert [a.name for a in before.plan] == [a.name for a in after.plan]


@pytest.mark.parametrize("extra,message", [
    (["--positive-for", str(MERGE / "problem.pddl")], "--positive-for and --problem-output go together"),
    (["--positive-for", str(MERGE / "problem.pddl"), "--problem-output", "x.pddl", "-o", "x.pddl"],
     "--problem-output must differ from --output"),
])
def test_positive_compilation_options(runner, app, extra, message):
    result = runner.invoke(app, ["merge", str(MERGE / "prior.pddl"), str(MERGE / "learned.pddl"), *extra])
    assert result.exit_code == 37 and message in result.stderr


def test_positive_compilation_refuses_actions_whose_add_may_undo_their_delete(runner, app, tmp_path):
    result = runner.invoke(app, ["merge", str(MERGE / "codesignation.pddl"), str(MERGE / "prior.pddl"),
                                 "--positive-for", str(MERGE / "codesignation-problem.pddl"),
                                 "--problem-output", str(tmp_path / "p.pddl"), "-o", str(tmp_path / "d.pddl")])
    assert result.exit_code == 33
    assert "codesignation.pddl:6:3: unsupported: action mv deletes (p ?x) and adds (p ?y)" in result.stderr
    assert not (tmp_path / "d.pddl").exists() and not (tmp_path / "p.pddl").exists()


def test_positive_compilation_reads_the_problem_against_the_merged_domain(runner, app, tmp_path):
    problem = tmp_path / "problem.pddl"
    problem.write_text((MERGE / "problem.pddl").read_text().replace("(hand_free))", "(hand_free) (graspable plate))"))
    result = runner.invoke(app, ["merge", str(MERGE / "prior.pddl"), str(MERGE / "learned.pddl"), "--name", "merged",
                                 "--positive-for", str(problem), "--problem-output", str(tmp_path / "p.pddl"),
                                 "-o", str(tmp_path / "d.pddl"), "-q"])
    assert result.exit_code == 0, result.stderr
    text = (tmp_path / "p.pddl").read_text()
    assert "(:domain merged)" in text and "(graspable plate)" in text


@pytest.mark.parametrize("name", ["bad name", "", "9lives"])
def test_merge_refuses_a_name_that_is_not_pddl(runner, app, name):
    result = runner.invoke(app, ["merge", str(MERGE / "prior.pddl"), str(MERGE / "learned.pddl"), "--name", name])
    assert result.exit_code == 37 and "expected a PDDL name" in result.stderr


_SKILL = """(define (domain blocks) (:requirements :strips :typing) (:types block)
  (:predicates (on ?x ?y - block) (ontable ?x - block) (clear ?x - block) (handempty) (holding ?x - block))
  ;; evidence (held in / demonstrations): {evidence}
  (:action unstack :parameters (?x ?y - block)
    :precondition (and {pre})
    :effect (and (holding ?x) (clear ?y) (not (on ?x ?y)) (not (clear ?x)) (not (handempty)))))
"""


def _learned(tmp_path, name, evidence, pre):
    path = tmp_path / name
    path.write_text(_SKILL.format(evidence=evidence, pre=pre))
    return parse_domain(path)


def test_a_learned_skill_shown_again_is_kept_once_requiring_what_both_require(tmp_path):
    table = _learned(tmp_path, "a.pddl", "(on ?x ?y) 1/1, (clear ?x) 1/1, (ontable ?y) 1/1 confirmed",
                     "(on ?x ?y) (clear ?x) (ontable ?y)")
    tower = _learned(tmp_path, "b.pddl", "(on ?x ?y) 2/2, (clear ?x) 2/2", "(on ?x ?y) (clear ?x)")
    merged = merge_domains([table, tower])
    (unstack,) = merged.domain.actions
    assert unstack.name == "unstack" and {str(l) for l in unstack.precondition} == {"(on ?x ?y)", "(clear ?x)"}
    assert {str(e) for e in unstack.evidence} == {"(on ?x ?y) 3/3", "(clear ?x) 3/3", "(ontable ?y) 1/3 confirmed"}
    assert merged.generalised and not merged.renamed


def test_given_skills_of_one_name_are_not_generalised_but_renamed(tmp_path):
    table = _learned(tmp_path, "a.pddl", "(on ?x ?y) 1/1", "(on ?x ?y) (ontable ?y)")
    given = parse_domain(tmp_path / "a.pddl")
    text = (tmp_path / "a.pddl").read_text().replace(";; evidence (held in / demonstrations): (on ?x ?y) 1/1", "")
    (tmp_path / "c.pddl").write_text(text.replace("(ontable ?y)", ""))
    assert [a.name for a in merge_domains([given, parse_domain(tmp_path / "c.pddl")]).domain.actions] == \
        ["unstack", "unstack_2"]
    assert table.action("unstack").evidence


def test_a_learned_domain_merged_with_itself_keeps_its_evidence_once(tmp_path):
    table = _learned(tmp_path, "a.pddl", "(on ?x ?y) 1/1, (ontable ?y) 1/1", "(on ?x ?y) (ontable ?y)")
    merged = merge_domains([table, parse_domain(tmp_path / "a.pddl")])
    (unstack,) = merged.domain.actions
    assert {str(e) for e in unstack.evidence} == {"(on ?x ?y) 1/1", "(ontable ?y) 1/1"}
    assert merged.duplicates and not merged.generalised
