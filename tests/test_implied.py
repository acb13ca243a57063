"""Dropping preconditions holding implies, and grasp affordances off the grasped object (#14).

Each rule has a case where it fires and cases where it must not.
"""

from __future__ import annotations

from dataclasses import replace

from conftest import ROOT

from guided_lfd.demonstration.implied import Implication, drop_implied_preconditions, grasp_affordances, proven_implications
from guided_lfd.demonstration.mutex import proven_invariants
from guided_lfd.pddl.model import ActionSchema, Atom, Literal
from guided_lfd.pddl.reader import parse_domain

DOMAIN = ROOT / "tests" / "data" / "learn" / "stacking-nodes-of-interest.pddl"
OBJECTS = {"r": "block", "g": "block", "b": "block", "table": "surface"}


def _state(*atoms: str) -> frozenset[Atom]:
    return frozenset(Atom(a.split()[0], tuple(a.split()[1:])) for a in atoms)


BLOCKS = ("graspable r", "graspable g", "graspable b")
#: Red taken from the table and stacked on Green, as a demonstration shows it.
STATES = [
    _state(*BLOCKS, "on_top r table", "on_top g table", "on_top b table", "clear r", "clear g", "clear b", "hand_free"),
    _state(*BLOCKS, "on_top g table", "on_top b table", "clear r", "clear g", "clear b", "in_hand r"),
    _state(*BLOCKS, "on r g", "on_top g table", "on_top b table", "clear r", "clear b", "hand_free"),
]


def _simplified(domain=None, states=STATES):
    domain = domain or parse_domain(DOMAIN)
    invariants = proven_invariants(domain, OBJECTS, states)
    out = drop_implied_preconditions(domain, {a.name for a in domain.actions}, states, invariants, OBJECTS)
    return {a.name: {str(l) for l in a.precondition} for a in out.actions}


def test_holding_implies_the_held_blocks_facts_and_they_are_dropped():
    domain = parse_domain(DOMAIN)
    invariants = proven_invariants(domain, OBJECTS, STATES)
    implications = proven_implications(domain, STATES, invariants)
    assert Implication("in_hand", 1, "clear", (0,)) in implications
    assert Implication("in_hand", 1, "graspable", (0,)) in implications
    pre = _simplified(domain)
    assert pre["stack_block_block"] == {"(clear ?o2)", "(in_hand ?o1)"}
    assert pre["put_block_surface"] == {"(in_hand ?o1)"}


def test_a_take_keeps_the_graspable_of_what_it_grasps_but_not_of_the_block_below():
    assert grasp_affordances(parse_domain(DOMAIN), STATES) == {"graspable"}
    pre = _simplified()
    assert pre["take_block_surface"] == {"(clear ?o1)", "(graspable ?o1)", "(hand_free)", "(on_top ?o1 ?o2)"}
    assert pre["take_block_block"] == {"(clear ?o1)", "(graspable ?o1)", "(hand_free)", "(on ?o1 ?o2)"}


def test_an_action_that_could_unclear_a_held_block_keeps_clear():
    domain = parse_domain(DOMAIN)
    smudge = ActionSchema("smudge", (("?o1", "block"),), (Literal(Atom("clear", ("?o1",))),), (),
                          (Atom("clear", ("?o1",)),))
    domain = replace(domain, actions=[*domain.actions, smudge])
    assert Implication("in_hand", 1, "clear", (0,)) not in proven_implications(
        domain, STATES, proven_invariants(domain, OBJECTS, STATES))
    assert "(clear ?o1)" in _simplified(domain)["stack_block_block"]


def test_stacking_a_block_onto_itself_without_letting_go_would_unclear_it():
    # Stacking deletes clear of ?o2 while ?o1 is held: ?o2 is not held (one hand) unless ?o2 = ?o1, and
    # then only letting go in the same action keeps "held means clear" (the first test proves that case).
    domain = parse_domain(DOMAIN)
    stack = next(a for a in domain.actions if a.name == "stack_block_block")
    without_release = replace(stack, delete=tuple(d for d in stack.delete if d.predicate != "in_hand"),
                              add=tuple(a for a in stack.add if a.predicate != "hand_free"))
    domain = replace(domain, actions=[a if a is not stack else without_release for a in domain.actions])
    implications = proven_implications(domain, STATES, proven_invariants(domain, OBJECTS, STATES))
    assert Implication("in_hand", 1, "clear", (0,)) not in implications


def test_a_demonstrated_state_against_an_implication_keeps_the_precondition():
    held_not_clear = _state(*BLOCKS, "on_top g table", "on_top b table", "clear g", "clear b", "in_hand r")
    assert "(clear ?o1)" in _simplified(states=[*STATES, held_not_clear])["stack_block_block"]


def test_no_affordance_when_a_held_object_lacks_it_or_an_action_changes_it():
    held_ungraspable = _state("graspable g", "graspable b", "on_top g table", "on_top b table", "clear r", "clear g",
                              "clear b", "in_hand r")
    assert grasp_affordances(parse_domain(DOMAIN), [*STATES, held_ungraspable]) == set()
    domain = parse_domain(DOMAIN)
    glue = ActionSchema("glue", (("?o1", "block"),), (Literal(Atom("graspable", ("?o1",))),), (),
                        (Atom("graspable", ("?o1",)),))
    assert grasp_affordances(replace(domain, actions=[*domain.actions, glue]), STATES) == set()
    pre = _simplified(replace(domain, actions=[*domain.actions, glue]))
    assert "(graspable ?o2)" in pre["take_block_block"]
