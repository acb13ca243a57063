"""The PDDL writer: what it writes reads back to the same model."""

from __future__ import annotations

from guided_lfd.pddl.model import ActionSchema, Atom, Literal
from guided_lfd.pddl.reader import parse_task
from guided_lfd.pddl.writer import domain_to_pddl


def test_an_action_without_precondition_or_effect_reads_back(tmp_path):
    (tmp_path / "d.pddl").write_text("(define (domain d) (:predicates (p)) "
                                     "(:action a :parameters () :precondition (p) :effect (not (p))))")
    (tmp_path / "p.pddl").write_text("(define (problem q) (:domain d) (:init (p)) (:goal (not (p))))")
    domain, _ = parse_task(str(tmp_path / "d.pddl"), str(tmp_path / "p.pddl"))
    empty = ActionSchema("wait", (), (), (), ())
    domain.actions.append(empty)
    (tmp_path / "w.pddl").write_text(domain_to_pddl(domain))
    again, _ = parse_task(str(tmp_path / "w.pddl"), str(tmp_path / "p.pddl"))
    assert again.actions == [ActionSchema("a", (), (Literal(Atom("p")),), (), (Atom("p"),)), empty]
