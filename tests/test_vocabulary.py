"""The hand's facts in the robot's own words (issue #23): declared, inferred, used by the learner."""

from __future__ import annotations

import pytest

from conftest import DATA, kitchen
from guided_lfd.demonstration.learn import check_usable, document_vocabulary, ground_actions
from guided_lfd.demonstration.naming import name_after
from guided_lfd.demonstration.vocabulary import (KITCHEN, NO_HAND, HandVocabulary, bind_arms, infer_vocabulary,
                                                 parse_vocabulary_row)
from guided_lfd.errors import MismatchError, TraceError
from guided_lfd.pddl.model import ActionSchema, Atom, Literal
from guided_lfd.pddl.reader import parse_domain

BYO = DATA / "byo"


@pytest.mark.parametrize("domain, held, free", [
    (kitchen(1)[0], "in_hand", "hand_free"),
    (str(BYO / "blocksworld" / "human.pddl"), "holding", "handempty"),  # clear/handempty also toggle: refused
    (str(BYO / "fetch" / "human.pddl"), "holding", "hand-empty"),
    (str(BYO / "mobile" / "human.pddl"), "carrying", "gripper-free"),
])
def test_the_hand_facts_are_read_off_the_grasping_actions(domain, held, free):
    found = infer_vocabulary(parse_domain(domain))
    assert (found.held, found.free, found.by_arm) == (held, free, False)
    assert domain in found.origin


def test_a_domain_without_grasping_actions_shows_no_hand_facts():
    assert infer_vocabulary(parse_domain(str(DATA / "teach" / "rooms-robot.pddl"))) is None


def test_arms_are_tied_to_the_trace_hands_by_name():
    pending = HandVocabulary("grasped", "free", (), "test", by_arm=True, arm_type="arm")
    bound = bind_arms(pending, {"left-arm": "arm", "right-arm": "arm", "cup": "thing"})
    assert bound.hands == (("left", "left-arm"), ("right", "right-arm"))
    assert bound.fluents("left", "cup") == {Atom("grasped", ("left-arm", "cup"))}
    assert bound.fluents("right", "") == {Atom("free", ("right-arm",))}
    assert bind_arms(pending, {"arm1": "arm"}).hands == (("right", "arm1"),)
    with pytest.raises(ValueError, match="cannot tell which of the arms"):
        bind_arms(pending, {"a1": "arm", "a2": "arm"})


@pytest.mark.parametrize("row, parsed", [("held=holding", ("held", "holding")), ("free, hand-empty", ("free", "hand-empty")),
                                         ("none", ("none", None)), ("free=none", ("free", None)),
                                         ("right=r-arm", ("right", "r-arm"))])
def test_vocabulary_rows(row, parsed):
    assert parse_vocabulary_row(row) == parsed


@pytest.mark.parametrize("row", ["grip=holding", "held=", "held"])
def test_bad_vocabulary_rows_are_refused(row):
    with pytest.raises(ValueError):
        parse_vocabulary_row(row)


def _demo(tmp_path, rows: list[str], trace_in_hand: str = ""):
    trace = tmp_path / "demo.csv"
    trace.write_text("time,hand,x,y,z,grip,in_hand,act_on\n"
                     + "".join(f"{t / 10:.1f},right,0,0,0,open,{trace_in_hand},\n" for t in range(3)))
    (tmp_path / "demo.state.csv").write_text("time,fluent,value\n0,\"object(B1,block)\",true\n" + "".join(rows))
    return str(trace)


def test_a_state_file_declares_the_vocabulary(tmp_path):
    from guided_lfd.demonstration.trace import load_demonstration

    demo = load_demonstration(_demo(tmp_path, ["0,vocabulary(held=holding),true\n", "0,vocabulary(free=handempty),true\n",
                                               "0,clear(B1),true\n"]))
    assert (demo.vocabulary.held, demo.vocabulary.free) == ("holding", "handempty")
    assert demo.initial == {Atom("clear", ("b1",))}
    assert load_demonstration(_demo(tmp_path, ["0,vocabulary(none),true\n"])).vocabulary.predicates == frozenset()


@pytest.mark.parametrize("rows, message", [
    (["0,vocabulary(held=holding),true\n", "0,holding(B1),true\n"], r"demo.state.csv:4:2: .*holding is the hand's state"),
    (["0,vocabulary(grip=holding),true\n"], r"demo.state.csv:3:2: .*expected vocabulary\(held=PREDICATE\)"),
    (["0,vocabulary(held=grasped),true\n", "0,vocabulary(free=free),true\n", "0,vocabulary(right=arm9),true\n"],
     r"demo.state.csv:5:2: .*object 'arm9' is never declared"),
    (["0,vocabulary(held=holding),true\n", "0,vocabulary(held=grabbed),true\n"],
     r"demo.state.csv:4:2: .*held is bound twice \(holding, then grabbed\)"),
    (["0,vocabulary(held=holding),true\n", "0,vocabulary(none),true\n"], r"demo.state.csv:4:2: .*vocabulary\(none\) beside"),
    (["0,vocabulary(held=handempty),true\n", "0,vocabulary(free=handempty),true\n"],
     r"demo.state.csv:4:2: .*held and free are both handempty"),
    (["0,vocabulary(right=b1),true\n"], r"demo.state.csv:3:2: .*arms bound without held or free"),
    (["0,vocabulary(held=holding),maybe\n"], r"demo.state.csv:3:3: .*a vocabulary row is a declaration; expected true"),
    (["0,clear(B1),true\n", "0.1,vocabulary(none),true\n"], r"demo.state.csv:4:1: .*a vocabulary row at 0.1 s"),
    (["0,in_hand(B1),true\n"], r"in_hand is the hand's state"),  # undeclared: the kitchens' hand facts
])
def test_the_hand_facts_are_never_environment_fluents(tmp_path, rows, message):
    from guided_lfd.demonstration.trace import load_demonstration

    with pytest.raises(TraceError, match=message):
        load_demonstration(_demo(tmp_path, rows))


def _document(vocabulary: dict | None = None) -> dict:
    """Taking block b1 from the table, as a segments document."""
    doc = {"objects": {"b1": "block"}, "initial": ["(clear b1)", "(ontable b1)"],
           "segments": [{"index": 0, "hand": "right", "activity": "Take", "start": 0.0, "end": 1.0, "object": "b1",
                         "target": "", "held_before": "", "held_after": "b1",
                         "before": ["(clear b1)", "(ontable b1)"], "after": ["(clear b1)"]}]}
    if vocabulary is not None:
        doc["vocabulary"] = vocabulary
    return doc


def test_the_learner_writes_the_robots_own_hand_facts():
    blocks = parse_domain(str(BYO / "blocksworld" / "robot.pddl"))
    (default,) = ground_actions(_document())
    assert Atom("in_hand", ("b1",)) in default.add and Literal(Atom("hand_free")) in default.precondition
    (declared,) = ground_actions(_document({"held": "holding", "free": "handempty", "hands": {}}))
    assert declared.add == {Atom("holding", ("b1",))} and declared.delete == {Atom("ontable", ("b1",)),
                                                                              Atom("handempty")}
    inferred = document_vocabulary(_document(), blocks)
    assert (inferred.held, inferred.free) == ("holding", "handempty")
    (none,) = ground_actions(_document(), vocabulary=NO_HAND)
    assert none.add == frozenset() and none.delete == {Atom("ontable", ("b1",))}
    assert document_vocabulary(_document()) == KITCHEN


def test_skills_are_named_after_the_human_action_with_its_parameter_order():
    human = parse_domain(str(BYO / "blocksworld" / "human.pddl"))
    take = ActionSchema("take_block", (("?o1", "block"), ("?o2", "block")),
                        (Literal(Atom("clear", ("?o1",))), Literal(Atom("handempty")), Literal(Atom("on", ("?o1", "?o2")))),
                        (Atom("clear", ("?o2",)), Atom("holding", ("?o1",))),
                        (Atom("clear", ("?o1",)), Atom("handempty"), Atom("on", ("?o1", "?o2"))))
    (named,) = name_after([take], human)
    unstack = human.action("unstack")
    assert named.name == "unstack" and [v for v, _ in named.params] == [v for v, _ in unstack.params]
    assert set(named.precondition) == set(unstack.precondition) and set(named.add) == set(unstack.add)
    odd = ActionSchema("push_block", (("?o1", "block"),), (), (Atom("ontable", ("?o1",)),), ())
    assert name_after([odd], human) == [odd]  # no human action has these effects: the activity's name stays


def test_a_skill_that_could_never_run_is_refused_naming_it_and_the_predicate():
    from dataclasses import replace

    robot = parse_domain(str(BYO / "fetch" / "robot.pddl"))
    push = ActionSchema("push_cabinet", (("?o1", "cabinet"),), (Literal(Atom("hand_free")),),
                        (Atom("cabinet-open", ("?o1",)),), ())
    merged = replace(robot, actions=[*robot.actions, push])
    with pytest.raises(MismatchError, match=r"learned skill push_cabinet needs \(hand_free \.\.\.\), a predicate "
                                            r".*robot.pddl never makes true"):
        check_usable(merged, robot, {"push_cabinet"}, "demo.csv")
    fine = replace(push, precondition=(Literal(Atom("hand-empty")),))
    check_usable(replace(robot, actions=[*robot.actions, fine]), robot, {"push_cabinet"}, "demo.csv")
    alien = replace(push, params=(("?o1", "obstacle"),))
    with pytest.raises(MismatchError, match="acts on objects of type obstacle, a type .* does not have"):
        check_usable(replace(robot, actions=[*robot.actions, alien]), robot, {"push_cabinet"}, "demo.csv")
