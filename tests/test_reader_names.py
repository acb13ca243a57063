"""Valid PDDL that goes beyond tarski's reading: either types, shared type/object names, implicit constants.

Fixtures in tests/data/grammar/; the parity of both reading paths on them is
tests/test_fast_reader.py's (corpus, CASES, a domain alone).
"""

from __future__ import annotations

import json

import pytest

from conftest import DATA, ROOT
from guided_lfd import errors
from guided_lfd.excuse.document import read_excuse
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.task import ground_atoms
from guided_lfd.merge import merge_domains
from guided_lfd.pddl.model import Atom, common_supertype, objects_by_type, type_members
from guided_lfd.pddl.reader import parse_domain, parse_task
from guided_lfd.pddl.writer import domain_to_pddl, problem_to_pddl

GRAMMAR = DATA / "grammar"
EITHER = (str(GRAMMAR / "either/domain.pddl"), str(GRAMMAR / "either/problem.pddl"))
SHARED = (str(GRAMMAR / "shared-name/domain.pddl"), str(GRAMMAR / "shared-name/problem.pddl"))
IMPLICIT = (str(GRAMMAR / "implicit-constant/domain.pddl"), str(GRAMMAR / "implicit-constant/problem.pddl"))
ZENO = ROOT / "data/benchmarks/ipc/zenotravel"
WRENCH_WARNING = ("implicit-constant/domain.pddl:10:28: warning: 'wrench' in action 'fetch' is not a declared "
                  "constant; it is read as one, its type taken from the problem's objects")


def _write(tmp_path, domain: str, problem: str) -> tuple[str, str]:
    (tmp_path / "d.pddl").write_text(domain)
    (tmp_path / "p.pddl").write_text(problem)
    return str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl")


def _error(*paths) -> str:
    with pytest.raises(errors.GuidedLfdError) as info:
        parse_task(*paths) if len(paths) == 2 else parse_domain(*paths)
    text = str(info.value)
    assert "\n" not in text
    return text.split("/")[-1]


def _round_trip(tmp_path, domain, problem):
    (tmp_path / "written-d.pddl").write_text(domain_to_pddl(domain))
    (tmp_path / "written-p.pddl").write_text(problem_to_pddl(problem))
    return parse_task(tmp_path / "written-d.pddl", tmp_path / "written-p.pddl")


def _same_model(a, b) -> None:
    (d1, p1), (d2, p2) = a, b
    assert (d2.types, d2.constants, d2.predicates, d2.actions, d2.implicit_constants) == (
        d1.types, d1.constants, d1.predicates, d1.actions, d1.implicit_constants)
    assert (p2.objects, p2.init, p2.goal) == (p1.objects, p1.init, p1.goal)


# -- either types -------------------------------------------------------------------------------------------------

def test_an_either_type_is_kept_and_covers_its_members_subtypes():
    domain, problem = parse_task(*EITHER)
    either = "(either person vehicle)"
    assert domain.predicates["at"].params == (("?x0", either), ("?x1", "city"))
    assert type_members(either) == ("person", "vehicle") and type_members("city") == ("city",)
    assert domain.subtypes()[either] == {"person", "vehicle", "aircraft"}
    assert objects_by_type(domain, problem)[either] == ["ann", "bob", "plane"]
    atoms = ground_atoms(domain, problem)
    assert Atom("at", ("plane", "home")) in atoms and Atom("at", ("ann", "away")) in atoms
    assert Atom("at", ("home", "away")) not in atoms


def test_zenotravel_plans_optimally(runner, app):
    result = runner.invoke(app, ["plan", str(ZENO / "domain.pddl"), str(ZENO / "task01.pddl"), "--json"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert (doc["status"], doc["plan"], doc["optimal"], doc["validated"]) == (
        "solved", ["(fly plane1 city0 city1 fl1 fl0)"], True, True)


T = "(:types a b c)"
PRED = "(:predicates (p ?x - (either a b)) (q ?x))"
OK_ACTION = "(:action m :parameters (?x - a) :precondition (p ?x) :effect (not (p ?x)))"


@pytest.mark.parametrize("domain,problem,message", [
    (f"(define (domain d) {T} (:predicates (p ?x - a))\n (:action m :parameters (?x - (either a b)) "
     ":precondition (p ?x) :effect (not (p ?x))))", "(:objects o - a)",
     "d.pddl:2:32: unsupported: 'either' types are supported in predicate declarations only "
     "(expected a single type name)"),
    (f"(define (domain d) {T}\n (:constants k - (either a b)) {PRED} {OK_ACTION})", "(:objects o - a)",
     "d.pddl:2:19: unsupported: 'either' types are supported in predicate declarations only"),
    (f"(define (domain d) {T} {PRED} {OK_ACTION})", "(:objects\n o - (either a b))",
     "p.pddl:2:7: unsupported: 'either' types are supported in predicate declarations only"),
    (f"(define (domain d) (:types a b\n - (either object c) c) {PRED} {OK_ACTION})", "(:objects o - a)",
     "d.pddl:2:5: unsupported: 'either' types are supported in predicate declarations only"),
    (f"(define (domain d) {T} {PRED} {OK_ACTION})", "(:objects o - a k - c) (:init (p o)\n (p k))",
     "p.pddl:2:5: semantic error: 'k' is a c, expected either a or b"),
    (f"(define (domain d) {T} {PRED} {OK_ACTION})", "(:objects o - a k - c) (:init (p o)) (:goal\n (not (p k)))",
     "p.pddl:2:10: semantic error: 'k' is a c, expected either a or b"),
    (f"(define (domain d) {T} {PRED}\n (:action m :parameters (?x - c) :precondition (q ?x) :effect (p ?x)))",
     "(:objects o - c)", "d.pddl:2:66: semantic error: '?x' is a c, expected either a or b"),
    (f"(define (domain d) {T} (:predicates\n (p ?x - (either a zz))) {OK_ACTION})", "(:objects o - a)",
     "d.pddl:2:20: semantic error: unknown type 'zz' (expected a type declared in :types)"),
    (f"(define (domain d) {T} (:predicates\n (p ?x - (either))) {OK_ACTION})", "(:objects o - a)",
     "d.pddl:2:10: syntax error: expected '(either TYPE ...)' with one or more type names"),
], ids=["action parameter", "constant", "object", "parent type", "init argument", "goal argument",
        "action argument", "unknown member", "no member"])
def test_either_errors_are_one_pinned_line(tmp_path, domain, problem, message):
    if ":init" not in problem:
        problem += " (:init (p o))"
    if ":goal" not in problem:
        problem += " (:goal (not (p o)))"
    paths = _write(tmp_path, domain, f"(define (problem q) (:domain d) {problem})")
    assert _error(*paths).startswith(message)


def test_a_domain_with_either_types_round_trips_through_the_writer(tmp_path):
    for task in (EITHER, (ZENO / "domain.pddl", ZENO / "task03.pddl")):
        read = parse_task(*task)
        _same_model(read, _round_trip(tmp_path, *read))
        assert "(either person aircraft)" in domain_to_pddl(read[0]) or "(either person vehicle)" in domain_to_pddl(read[0])


def test_excuse_changes_and_merges_type_check_against_either_types(tmp_path):
    domain, problem = parse_task(*EITHER)
    doc = {"format": "guided-lfd/excuse", "format_version": 1,
           "excuse": {"changes": [{"op": "add", "atom": "(at plane away)"}]}}
    (tmp_path / "e.json").write_text(json.dumps(doc))
    assert [str(c) for c in read_excuse(str(tmp_path / "e.json"), domain, problem)] == ["+(at plane away)"]
    doc["excuse"]["changes"] = [{"op": "add", "atom": "(at home away)"}]
    (tmp_path / "e.json").write_text(json.dumps(doc))
    with pytest.raises(errors.InputFileError, match=r"home is a city, at expects a \(either person vehicle\)"):
        read_excuse(str(tmp_path / "e.json"), domain, problem)
    either = "(either person vehicle)"
    assert common_supertype(domain.types, either, "aircraft") == either
    assert common_supertype(domain.types, "person", either) == either
    assert common_supertype(domain.types, either, "city") == "object"
    merged = merge_domains([domain, parse_domain(EITHER[0])]).domain
    assert merged.predicates["at"] == domain.predicates["at"]


# -- a type and an object of the same name ------------------------------------------------------------------------

def test_a_type_and_an_object_or_constant_may_share_a_name(runner, app, tmp_path):
    domain, problem = parse_task(*SHARED)
    assert {"cart", "gripper"} <= set(domain.types)
    assert domain.constants == {"gripper": "gripper"} and problem.objects["cart"] == "cart"
    assert domain.predicates["holding"].params == (("?x0", "gripper"), ("?x1", "cart"))
    assert domain.predicates["at"].params[0][1] == "(either cart item)"
    _same_model((domain, problem), _round_trip(tmp_path, domain, problem))
    result = runner.invoke(app, ["plan", *SHARED])
    assert result.exit_code == 0 and "(push cart kitchen hall)" in result.stdout


def test_a_type_named_like_an_object_reads_in_messages_as_written(tmp_path):
    """Tarski is given the type under another name: none of it shows in an error."""
    domain = "(define (domain d) (:types cart place) (:predicates (at ?c - cart ?p - place)) (:action m " \
             ":parameters (?c - cart ?p - place) :precondition (at ?c ?p) :effect (not (at ?c ?p))))"
    paths = _write(tmp_path, domain, "(define (problem q) (:domain d) (:objects cart - cart hall - place)\n"
                                     " (:init (at hall cart)) (:goal (not (at cart hall))))")
    assert _error(*paths) == "p.pddl:2:13: semantic error: 'hall' is a place, expected a cart"


@pytest.mark.parametrize("domain,problem,where", [
    ("(:types t) (:predicates (p ?x))", "(:objects o - t o - t)", "p.pddl:1:49"),
    ("(:types t) (:predicates (p ?x) (p ?y))", "(:objects o)", None),
    ("(:types t) (:constants o - t) (:predicates (p ?x))", "(:objects o - t)", "p.pddl:1:43"),
    ("(:types t) (:predicates (t ?x) (p ?x))", "(:objects t - t)", "d.pddl:1:45"),
], ids=["two objects", "two predicates", "an object and a constant", "a type and a predicate"])
def test_a_name_declared_twice_in_one_namespace_is_still_refused(tmp_path, domain, problem, where):
    act = "(:action a :parameters (?x) :precondition (p ?x) :effect (not (p ?x)))"
    paths = _write(tmp_path, f"(define (domain d) {domain} {act})",
                   f"(define (problem q) (:domain d) {problem} (:init (p o)) (:goal (not (p o))))")
    message = _error(*paths)
    assert "declared twice" in message
    if where is not None:
        assert message.startswith(where + ": semantic error:")


TWICE = GRAMMAR / "declared-twice"


def test_a_type_declared_again_is_one_type_below_the_lower_parent_with_a_warning(runner, app):
    """``area`` among the plain types and again below ``place``: Fast Downward reads it, guided-lfd refused it
    ("type 'area' is declared twice in :types")."""
    domain = parse_domain(TWICE / "domain.pddl")
    assert domain.types["area"] == "place"
    warning = (f"{TWICE / 'domain.pddl'}:7:11: warning: type 'area' is declared again (first at 6:23); read as one "
               "type below 'place', as Fast Downward reads it")
    assert domain.warnings == (warning,)
    for command in ("plan", "excuse"):
        result = runner.invoke(app, [command, str(TWICE / "domain.pddl"), str(TWICE / "problem.pddl")])
        assert result.exit_code == 0, result.output
        assert [line for line in result.stderr.splitlines() if "warning" in line] == [warning]


def test_a_predicate_and_an_object_may_share_a_name(runner, app):
    """The predicate ``home`` and the object ``home``: separate namespaces for Fast Downward, one for tarski
    ("'home' is declared twice")."""
    domain, problem = parse_task(TWICE / "domain.pddl", TWICE / "problem.pddl")
    assert "home" in domain.predicates and problem.objects["home"] == "area"
    assert Atom("home", ("home",)) in problem.init
    result = runner.invoke(app, ["plan", str(TWICE / "domain.pddl"), str(TWICE / "problem.pddl")])
    assert result.exit_code == 0 and result.stdout.endswith("(drop-home r1 box home)\n; cost = 4 (unit cost)\n")


@pytest.mark.parametrize("domain, problem, where", [
    (TWICE / "domain.pddl", TWICE / "problem-object-twice.pddl", "problem-object-twice.pddl:4:13"),
    (DATA / "adl" / "household" / "domain.pddl", TWICE / "household-plate-twice.pddl",
     "household-plate-twice.pddl:9:13"),
])
def test_an_object_declared_twice_is_refused_at_its_second_declaration_on_every_path(domain, problem, where):
    """As Fast Downward's translator refuses it ("duplicate objects"); the ADL path read it without a word."""
    message = _error(domain, problem)  # from the file's name on
    assert message.startswith(f"{where}: semantic error: '") and "is declared twice" in message


def test_an_action_declared_twice_is_still_refused(tmp_path):
    act = "(:action a :parameters (?x) :precondition (p ?x) :effect (not (p ?x)))"
    paths = _write(tmp_path, f"(define (domain d) (:predicates (p ?x)) {act}\n {act})",
                   "(define (problem q) (:domain d) (:objects o) (:init (p o)) (:goal (not (p o))))")
    assert _error(*paths).startswith("d.pddl:2:11: semantic error: 'a' is declared twice")


# -- implicit constants -------------------------------------------------------------------------------------------

def test_an_implicit_constant_reads_with_the_domain_alone():
    domain = parse_domain(IMPLICIT[0])
    assert domain.implicit_constants == ("wrench",) and domain.constants == {}
    assert [w.split("/grammar/")[-1] for w in domain.warnings] == [WRENCH_WARNING]
    assert Atom("have", ("wrench",)) in domain.action("fetch").add


def test_an_implicit_constant_takes_the_problems_type():
    domain, problem = parse_task(*IMPLICIT)
    assert domain.implicit_constants == ("wrench",) and domain.constants == {}
    assert problem.objects == {"w1": "wheel", "w2": "wheel", "wrench": "tool"}
    task = ground(domain, problem)
    assert "(fetch)" in {a.name for a in task.actions}


def test_an_implicit_constant_the_problem_does_not_declare_is_refused():
    with pytest.raises(errors.PddlSemanticError) as info:
        parse_task(IMPLICIT[0], str(GRAMMAR / "implicit-constant/undeclared.pddl"))
    assert str(info.value) == (
        f"{IMPLICIT[0]}:10:28: semantic error: unknown object 'wrench' in action 'fetch' (expected a domain "
        "constant, or an object declared in the problem's :objects)")
    assert info.value.exit_code == 32


def test_an_implicit_constant_of_a_type_its_uses_do_not_take_is_refused(tmp_path):
    text = (GRAMMAR / "implicit-constant/problem.pddl").read_text().replace("wrench - tool", "wrench - wheel")
    (tmp_path / "p.pddl").write_text(text)
    message = _error(IMPLICIT[0], str(tmp_path / "p.pddl"))
    assert message == "domain.pddl:10:28: semantic error: 'wrench' is a wheel, expected a tool"


def test_the_writer_writes_an_implicit_constant_as_written(tmp_path):
    domain, problem = parse_task(*IMPLICIT)
    text = domain_to_pddl(domain)
    assert ":constants" not in text and "(have wrench)" in text
    _same_model((domain, problem), _round_trip(tmp_path, domain, problem))
    merged = merge_domains([domain, parse_domain(IMPLICIT[0])]).domain
    assert merged.implicit_constants == ("wrench",) and merged.constants == {}


def test_the_cli_warns_once_about_an_implicit_constant(runner, app, tmp_path):
    result = runner.invoke(app, ["plan", *IMPLICIT])
    assert result.exit_code == 0, result.stderr
    lines = result.stderr.strip().splitlines()
    assert [l for l in lines if "warning" in l] == [str(GRAMMAR / WRENCH_WARNING)]
    assert result.stdout.startswith("(fetch)\n")
    quiet = runner.invoke(app, ["plan", *IMPLICIT, "--quiet"])
    assert quiet.exit_code == 0 and quiet.stderr == ""
    # consistent semantics: the invariant synthesis (Fast Downward's translator) reads it too
    excuse = runner.invoke(app, ["excuse", *IMPLICIT, "--invariants-from", IMPLICIT[0]])
    assert excuse.exit_code == 0, excuse.stderr
    assert sum("warning" in l for l in excuse.stderr.splitlines()) == 1
    merged = runner.invoke(app, ["merge", IMPLICIT[0], IMPLICIT[0], "-o", str(tmp_path / "m.pddl")])
    assert merged.exit_code == 0, merged.stderr
    assert ":constants" not in (tmp_path / "m.pddl").read_text()


# -- names outside ASCII ------------------------------------------------------------------------------------------

NON_ASCII = GRAMMAR / "non-ascii"
LIGHTS = DATA / "trajectories" / "lights"


@pytest.mark.parametrize("args, where, char", [
    (["plan", "domain.pddl", "problem-objects.pddl"], "problem-objects.pddl:3:14", "'ü' (U+00FC)"),
    (["excuse", "domain.pddl", "problem-objects.pddl"], "problem-objects.pddl:3:14", "'ü' (U+00FC)"),
    (["validate", "domain.pddl", "problem-objects.pddl", "PLAN"], "problem-objects.pddl:3:14", "'ü' (U+00FC)"),
    (["excuse", "domain-type.pddl", "problem.pddl"], "domain-type.pddl:4:17", "'ü' (U+00FC)"),
    (["plan", "domain-predicate.pddl", "problem.pddl"], "domain-predicate.pddl:5:19", "'ö' (U+00F6)"),
    (["validate", "domain-name.pddl", "problem.pddl", "PLAN"], "domain-name.pddl:2:18", "'ü' (U+00FC)"),
    (["excuse", "domain-override.pddl", "problem.pddl"], "domain-override.pddl:6:17", "'\\u202e' (U+202E)"),
    (["merge", "domain.pddl", "domain-type.pddl"], "domain-type.pddl:4:17", "'ü' (U+00FC)"),
    (["learn-domain", "--prior", "LIGHTS", "lights-kueche.traj"], "lights-kueche.traj:3:30", "'ü' (U+00FC)"),
])
def test_a_name_outside_ascii_is_one_syntax_error_in_every_command(runner, app, tmp_path, args, where, char):
    """As Fast Downward's translator reads PDDL ("Non-ASCII character outside comment"); it was read by tarski
    and then refused by the translator inside excuse ("mismatch: cannot synthesise invariants", 34)."""
    (tmp_path / "plan.txt").write_text("(open-door front)\n")
    names = {"PLAN": str(tmp_path / "plan.txt"), "LIGHTS": str(LIGHTS / "prior.pddl")}
    argv = [args[0], *(names.get(a) or (str(NON_ASCII / a) if a.endswith((".pddl", ".traj")) else a) for a in args[1:])]
    result = runner.invoke(app, argv)
    assert result.exit_code == errors.EXIT_PDDL_SYNTAX, result.output
    assert result.stderr == (f"{NON_ASCII}/{where}: syntax error: non-ASCII character {char} outside a comment, "
                             "expected ASCII (Fast Downward's translator reads no other; comments may hold any "
                             "character)\n")


def test_characters_outside_ascii_in_comments_are_read(runner, app):
    assert not (NON_ASCII / "domain.pddl").read_text().isascii()
    result = runner.invoke(app, ["plan", str(NON_ASCII / "domain.pddl"), str(NON_ASCII / "problem.pddl")])
    assert result.exit_code == 0 and result.stdout.startswith("(open-door front)\n")
