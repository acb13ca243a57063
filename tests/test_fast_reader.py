"""The reader's fast path (Fast Downward's translator parser) reads what tarski reads, the same way.

The fast path only ever accepts: whatever it does not take goes through
tarski, for its model or its error.  So on every input the outcome must be
the one the tarski path alone gives, model and error message alike.
"""

from __future__ import annotations

import pytest

from conftest import ROOT, damaged_tasks
from guided_lfd.errors import GuidedLfdError
from guided_lfd.pddl import fast_reader, reader


def _outcome(domain: str, problem: str):
    try:
        dom, prob = reader.parse_task(domain, problem)
    except GuidedLfdError as exc:
        return ("error", type(exc).__name__, str(exc))
    return ("ok", dom.name, dom.requirements, repr(dom.actions), repr(dom.predicates), repr(dom.types),
            repr(dom.constants), dom.implicit_constants, dom.warnings, dom.spellings, prob.name, prob.domain_name,
            repr(sorted(prob.init)), repr(prob.goal), repr(prob.objects), prob.spellings,
            repr(dom.functions), repr(sorted(prob.function_values.items())), prob.metric)


def _tarski_only(monkeypatch, domain: str, problem: str):
    monkeypatch.setattr(fast_reader, "read_domain", lambda *args: None)
    try:
        return _outcome(domain, problem)
    finally:
        monkeypatch.undo()


def _large_ipc_task(path) -> bool:
    """IPC tasks 11 and up: seconds each on tarski's path (zenotravel's first ten: ~0.05 s each)."""
    import re

    if "benchmarks/ipc" not in path.as_posix():
        return False
    number = re.fullmatch(r"task(\d+)\.pddl", path.name)
    return number is not None and int(number.group(1)) > 10


def _pairs() -> list[tuple[str, str]]:
    pairs = []
    for folder in ("data", "tests/data"):
        for path in sorted((ROOT / folder).rglob("*.pddl")):
            for name in ("domain.pddl", "robot.pddl", "human.pddl"):
                domain = path.parent / name
                if domain.exists() and path.name not in ("domain.pddl", "robot.pddl", "human.pddl"):
                    if _large_ipc_task(path):
                        continue  # the whole collection is benchmarks/plan_bench.py --tasks all's job
                    pairs.append((str(domain), str(path)))
    return pairs


def test_every_pair_of_the_corpus_reads_the_same_both_ways(monkeypatch):
    pairs = _pairs()
    assert len(pairs) > 100
    fast_taken = valid = 0
    for domain, problem in pairs:
        both = _outcome(domain, problem)
        assert both == _tarski_only(monkeypatch, domain, problem), problem
        if both[0] == "ok" and not _adl(domain, problem):
            valid += 1
            fast_taken += _fast_reads(domain, problem)
    # The fast path is the path: nearly every valid STRIPS pair of the corpus takes it (ADL has its own).
    assert valid > 100 and fast_taken >= 0.9 * valid


def _adl(domain: str, problem: str) -> bool:
    from guided_lfd.pddl import adl_reader

    return any(adl_reader.needs_adl(reader._source_map(path, kind))
               for path, kind in ((domain, "domain"), (problem, "problem")))


def _fast_reads(domain: str, problem: str) -> bool:
    dsrc = reader._source_map(domain, "domain")
    psrc = reader._source_map(problem, "problem")
    dom = fast_reader.read_domain(dsrc, domain)
    return dom is not None and fast_reader.read_problem(psrc, problem, dom) is not None


def test_damaged_files_give_the_same_model_or_error_both_ways(tmp_path, monkeypatch):
    """Seeded damage to the kitchen files: fast path or not, the same model or the same message."""
    domain_text = (ROOT / "data/domains/kitchen-2/robot.pddl").read_text()
    problem_text = (ROOT / "data/domains/kitchen-2/problem.pddl").read_text()
    pieces = ["(", ")", " ", "?x", "- ", "and ", "not ", ":effect ", "; note\n", "\n", "foo ", ":", "AND ", "Not ",
              "(= ?a ?b)", "- object ", "(not (= ?x ?y)) ", ":precondition ", "either "]
    outcomes = set()
    for domain, problem in damaged_tasks(tmp_path, domain_text, problem_text, pieces, seed=11, count=300):
        result = _outcome(domain, problem)
        assert result == _tarski_only(monkeypatch, domain, problem)
        outcomes.add(result[0] if result[0] == "ok" else result[1])
    assert {"ok", "PddlSyntaxError", "PddlSemanticError"} <= outcomes


@pytest.mark.parametrize("fixture", ["either", "shared-name", "implicit-constant"])
def test_damaged_grammar_fixtures_give_the_same_model_or_error_both_ways(tmp_path, monkeypatch, fixture):
    """Seeded damage to either types, a type named like an object, an implicit constant."""
    folder = ROOT / "tests/data/grammar" / fixture
    pieces = ["(", ")", " ", "?x", "- ", "either ", "(either a b) ", "cart ", "wrench ", "tool ", "- tool ",
              "- cart ", "; c\n", "\n", "object ", "(and) ", "not "]
    outcomes = set()
    for domain, problem in damaged_tasks(tmp_path, (folder / "domain.pddl").read_text(),
                                         (folder / "problem.pddl").read_text(), pieces, seed=7, count=80):
        result = _outcome(domain, problem)
        assert result == _tarski_only(monkeypatch, domain, problem)
        outcomes.add(result[0] if result[0] == "ok" else result[1])
    assert {"ok", "PddlSyntaxError", "PddlSemanticError"} <= outcomes


P = "(define (problem q) (:domain d) (:objects o) (:init (p o)) (:goal (not (p o))))"
ACT = "(:action a :parameters (?x) :precondition (p ?x) :effect (not (p ?x)))"
CASES = {
    # taken by the fast path: the same model as tarski's
    "plain": (True, f"(define (domain d) (:predicates (p ?x)) {ACT})", P),
    "equality, negation, constants": (True, "(define (domain d) (:requirements :strips :equality :negative-preconditions) "
        "(:constants k) (:predicates (p ?x) (q ?x ?y)) (:action a :parameters (?x ?y) :precondition (and (p ?x) "
        "(not (= ?x ?y)) (not (q ?x k))) :effect (and (q ?x ?y) (not (p ?x)))))", P),
    "parentless type before its child": (True, "(define (domain d) (:types truck - vehicle vehicle place) "
        "(:predicates (p ?x - vehicle)) (:action a :parameters (?x - truck) :precondition (p ?x) :effect (not (p ?x))))",
        "(define (problem q) (:domain d) (:objects o - truck l - place) (:init (p o)) (:goal (not (p o))))"),
    "capitalised names": (True, f"(define (domain d) (:predicates (p ?x)) {ACT})",
        "(define (problem q) (:domain d) (:objects PinkDrawer) (:init (p PinkDrawer)) (:goal (not (p pinkdrawer))))"),
    "a comment ends the file, no line break": (True, f"(define (domain d) (:predicates (p ?x)) {ACT})\n; end", P + " ; end"),
    "capitalised keyword": (True, f"(define (DOMAIN d) (:predicates (p ?x)) {ACT})", P),
    "keywords in capitals": (True, "(DEFINE (DOMAIN d) (:REQUIREMENTS :STRIPS :TYPING :NEGATIVE-PRECONDITIONS) "
        "(:TYPES t - OBJECT) (:PREDICATES (p ?x - t)) (:ACTION a :PARAMETERS (?x - t) :PRECONDITION (AND (p ?x)) "
        ":EFFECT (AND (NOT (p ?x)))))", "(DEFINE (PROBLEM q) (:DOMAIN d) (:OBJECTS o - t) (:INIT (p o)) "
        "(:GOAL (AND (NOT (p o)))))"),
    "keywords in capitals, either": (True, "(define (domain d) (:types a b) (:predicates (p ?x - (EITHER a b))) "
        "(:action m :parameters (?x - a) :precondition (p ?x) :effect (not (p ?x))))",
        "(define (problem q) (:domain d) (:objects o - a) (:init (p o)) (:goal (not (p o))))"),
    "no parameters": (False, "(define (domain d) (:predicates (p)) (:action a :precondition (p) :effect (not (p))))",
        "(define (problem q) (:domain d) (:init (p)) (:goal (not (p))))"),
    "no precondition": (False, "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) :effect (p ?x)))", P),
    "nested and in an effect": (False, "(define (domain d) (:predicates (p ?x) (q ?x)) (:action a :parameters (?x) "
        ":precondition (p ?x) :effect (and (not (p ?x)) (and (q ?x)))))", P),
    "reserved word as a name": (False, f"(define (domain d) (:predicates (p ?x)) {ACT})",
        "(define (problem q) (:domain d) (:objects min) (:init (p min)) (:goal (not (p min))))"),
    "double negation": (False, "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) "
        ":precondition (not (not (p ?x))) :effect (not (p ?x))))", P),
    "type cycle": (False, "(define (domain d) (:types a - b b - a) (:predicates (p ?x - b)) (:action m :parameters "
        "(?x - b) :precondition (p ?x) :effect (not (p ?x))))", "(define (problem q) (:domain d) (:objects o - b) "
        "(:init (p o)) (:goal (not (p o))))"),
    "untyped after typed": (False, "(define (domain d) (:types t) (:predicates (p ?x)) " + ACT + ")",
        "(define (problem q) (:domain d) (:objects a - t b) (:init (p a) (p b)) (:goal (not (p a))))"),
    "sections out of order": (False, "(define (domain d) (:predicates (p ?x)) (:types t) " + ACT + ")", P),
    "sections out of order, again": (False, "(define (domain d) (:predicates (p ?x)) (:types t) " + ACT + ")", P),
    "type name as a predicate": (False, "(define (domain d) (:types t) (:predicates (t ?x)) (:action a :parameters "
        "(?x) :precondition (t ?x) :effect (not (t ?x))))", "(define (problem q) (:domain d) (:objects o - t) "
        "(:init (t o)) (:goal (not (t o))))"),
    "action without effects": (False, "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) "
        ":precondition (p ?x) :effect (and)))", P),
    "repeated initial fact": (False, f"(define (domain d) (:predicates (p ?x)) {ACT})",
        "(define (problem q) (:domain d) (:objects o) (:init (p o) (p o)) (:goal (not (p o))))"),
    # (either ...) types of predicate parameters, as Fast Downward reads them
    "either, a subtype's object": (True, "(define (domain d) (:types v p - object a - v) (:predicates "
        "(at ?x - (either p v) ?y - v)) (:action m :parameters (?x - a ?y - p) :precondition (at ?y ?x) "
        ":effect (not (at ?y ?x))))", "(define (problem q) (:domain d) (:objects o - a k - p) (:init (at k o) "
        "(at o o)) (:goal (not (at k o))))"),
    "either, an argument of no member type": (False, "(define (domain d) (:types a b c) (:predicates "
        "(p ?x - (either a b))) (:action m :parameters (?x - a) :precondition (p ?x) :effect (not (p ?x))))",
        "(define (problem q) (:domain d) (:objects o - a k - c) (:init (p o) (p k)) (:goal (not (p o))))"),
    "either, a parameter of no member type": (False, "(define (domain d) (:types a b c) (:predicates "
        "(p ?x - (either a b)) (q ?x)) (:action m :parameters (?x - c) :precondition (q ?x) :effect (p ?x)))",
        "(define (problem q) (:domain d) (:objects o - c) (:init (q o)) (:goal (p o)))"),
    "either on an action parameter": (False, "(define (domain d) (:types a b) (:predicates (p ?x - a)) (:action m "
        ":parameters (?x - (either a b)) :precondition (p ?x) :effect (not (p ?x))))",
        "(define (problem q) (:domain d) (:objects o - a) (:init (p o)) (:goal (not (p o))))"),
    "either of an unknown type": (False, "(define (domain d) (:types a) (:predicates (p ?x - (either a zz))) "
        "(:action m :parameters (?x - a) :precondition (p ?x) :effect (not (p ?x))))",
        "(define (problem q) (:domain d) (:objects o - a) (:init (p o)) (:goal (not (p o))))"),
    # types and objects are separate namespaces (IPC tidybot: type cart, object cart)
    "a type named like an object": (True, "(define (domain d) (:types cart) (:predicates (p ?x - cart)) (:action m "
        ":parameters (?x - cart) :precondition (p ?x) :effect (not (p ?x))))", "(define (problem q) (:domain d) "
        "(:objects cart - cart) (:init (p cart)) (:goal (not (p cart))))"),
    "a type named like a constant, in either": (True, "(define (domain d) (:types k t) (:constants k - k) "
        "(:predicates (p ?x - (either k t))) (:action m :parameters (?x - t) :precondition (p k) :effect (p ?x)))",
        "(define (problem q) (:domain d) (:objects o - t) (:init (p k)) (:goal (p o)))"),
    "a type named like an object and a predicate": (False, "(define (domain d) (:types t) (:predicates (t ?x)) "
        "(:action a :parameters (?x) :precondition (t ?x) :effect (not (t ?x))))", "(define (problem q) "
        "(:domain d) (:objects t - t) (:init (t t)) (:goal (not (t t))))"),
    "an object declared twice": (False, f"(define (domain d) (:predicates (p ?x)) {ACT})",
        "(define (problem q) (:domain d) (:objects o o) (:init (p o)) (:goal (not (p o))))"),
    # an object the actions use, declared by the problem only (older IPC tyreworld's wrench)
    "an implicit constant": (True, "(define (domain d) (:types tool) (:predicates (have ?t - tool) (p ?x)) "
        f"(:action f :parameters (?x) :precondition (p ?x) :effect (have wrench)))",
        "(define (problem q) (:domain d) (:objects o - object wrench - tool) (:init (p o)) (:goal (have wrench)))"),
    "an implicit constant, also a type": (True, "(define (domain d) (:types tool) (:constants k - tool) "
        "(:predicates (have ?t - tool)) (:action f :parameters () :precondition (have k) :effect (have tool)))",
        "(define (problem q) (:domain d) (:objects tool - tool) (:init (have k)) (:goal (have tool)))"),
    "an implicit constant the problem does not declare": (False, "(define (domain d) (:predicates (have ?t) (p ?x)) "
        "(:action f :parameters (?x) :precondition (p ?x) :effect (have wrench)))", P),
    "an implicit constant of the wrong type": (False, "(define (domain d) (:types tool wheel) (:predicates "
        "(have ?t - tool) (p ?x)) (:action f :parameters (?x) :precondition (p ?x) :effect (have wrench)))",
        "(define (problem q) (:domain d) (:objects wrench - wheel o) (:init (p o)) (:goal (have wrench)))"),
    "an implicit constant, a syntax error after it": (False, "(define (domain d) (:predicates (have ?t) (p ?x)) "
        "(:action f :parameters (?x) :precondition (p ?x) :effect (have wrench)) (:action g :parameters (?x) "
        ":precondition ((p ?x)) :effect (have ?x)))", "(define (problem q) (:domain d) (:objects wrench o) "
        "(:init (p o)) (:goal (have wrench)))"),
    "an implicit constant, the problem of another domain": (False, "(define (domain d) (:types tool) (:predicates "
        "(have ?t - tool)) (:action f :parameters () :precondition (have wrench) :effect (not (have wrench))))",
        "(define (problem q) (:domain e) (:objects wrench) (:init (have wrench)) (:goal (not (have wrench))))"),
    "an object named object, a type named like an object": (False, "(define (domain d) (:types cart - object) "
        "(:predicates (p ?x - cart)) (:action m :parameters (?x - cart) :precondition (p ?x) :effect (not (p ?x))))",
        "(define (problem q) (:domain e) (:objects cart - cart object) (:init (p cart)) (:goal (not (p cart))))"),
    # left to tarski (its model, or its error)
    "contradicting effects": (True, "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) "
        ":precondition (p ?x) :effect (and (p ?x) (not (p ?x)))))", P),
    "parameter of a supertype": (False, "(define (domain d) (:types a b - a) (:predicates (p ?x - b)) (:action m "
        ":parameters (?x - a) :precondition (p ?x) :effect (not (p ?x))))", "(define (problem q) (:domain d) "
        "(:objects o - b) (:init (p o)) (:goal (not (p o))))"),
}


def _domain_outcome(domain: str):
    try:
        dom = reader.parse_domain(domain)
    except GuidedLfdError as exc:
        return ("error", type(exc).__name__, str(exc))
    return ("ok", repr(dom.actions), repr(dom.predicates), repr(dom.types), repr(dom.constants),
            dom.implicit_constants, dom.warnings)


def test_a_domain_alone_reads_the_same_both_ways(tmp_path, monkeypatch):
    """parse_domain (no problem: merge, learn-domain --prior, --fixed-from) on the corner cases and the grammar fixtures."""
    domains = [str(p) for p in sorted((ROOT / "tests/data/grammar").rglob("domain.pddl"))]
    for k, (_, domain_text, _) in enumerate(CASES.values()):
        (tmp_path / f"d{k}.pddl").write_text(domain_text)
        domains.append(str(tmp_path / f"d{k}.pddl"))
    for domain in domains:
        fast = _domain_outcome(domain)
        monkeypatch.setattr(fast_reader, "read_domain", lambda *args: None)
        assert fast == _domain_outcome(domain), domain
        monkeypatch.undo()


@pytest.mark.parametrize("case", list(CASES))
def test_corner_cases_read_the_same_both_ways(tmp_path, monkeypatch, case):
    fast, domain_text, problem_text = CASES[case]
    (tmp_path / "d.pddl").write_text(domain_text)
    (tmp_path / "p.pddl").write_text(problem_text)
    d, p = str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl")
    assert _outcome(d, p) == _tarski_only(monkeypatch, d, p)
    try:
        taken = _fast_reads(d, p)
    except GuidedLfdError:
        taken = False  # the source map itself refuses it
    assert taken is fast


def test_the_fast_path_reads_the_kitchens_and_ipc_tasks():
    for domain, problem in [("data/domains/kitchen-1/robot.pddl", "data/domains/kitchen-1/problem.pddl"),
                            ("data/benchmarks/ipc/depot/domain.pddl", "data/benchmarks/ipc/depot/task05.pddl"),
                            ("data/benchmarks/ipc/sokoban/domain.pddl", "data/benchmarks/ipc/sokoban/task03.pddl")]:
        assert _fast_reads(str(ROOT / domain), str(ROOT / problem))
