"""Regressions found by reviewing #14's learner and segmenter: each failed before its fix."""

from __future__ import annotations

import numpy as np
from conftest import ROOT

from guided_lfd.demonstration.generalise import aligned, generalise
from guided_lfd.demonstration.learn import ground_actions, learn_domain
from guided_lfd.pddl.model import ActionSchema, Atom, Literal


def _seg(i, activity, obj, target, before, after, held_before, held_after, hand="right"):
    return {"index": i, "hand": hand, "activity": activity, "object": obj, "target": target,
            "held_before": held_before, "held_after": held_after, "start": float(i), "end": i + 0.5,
            "before": before, "after": after}


def test_a_put_whose_target_was_never_named_joins_the_named_skill_and_names_stay_unique():
    doc = {"objects": {"r": "block", "g": "block", "table": "surface"},
           "initial": ["(on_top r table)", "(clear r)", "(clear g)"], "segments": [
               _seg(0, "Put", "r", "table", ["(clear r)", "(clear g)"], ["(clear r)", "(clear g)", "(on_top r table)"],
                    "r", ""),
               _seg(1, "Put", "r", "", ["(clear r)", "(clear g)"], ["(clear r)", "(clear g)", "(on_top r table)"],
                    "r", ""),
               _seg(2, "Put", "r", "", ["(clear r)", "(clear g)"], ["(clear r)", "(on r g)"], "r", "")]}
    names = [a.name for a in learn_domain([("doc", doc)]).actions]
    assert len(names) == len(set(names)), names
    assert names == ["put_block_surface", "put_block"]  # the target-less Put onto the table joined the named one


def test_names_from_different_activities_never_clash():
    def act(name, pred):
        return ActionSchema(name, (("?o1", "block"),), (), (Atom(pred, ("?o1",)),), (), name)

    # "open" splits into open_object (two skills), beside a skill literally named open_object.
    out = generalise([act("open_object", "open"), act("open", "lit"), act("open", "shut")])
    assert len({a.name for a in out}) == 3, [a.name for a in out]


def test_unstacking_is_not_reconciled_with_taking_from_the_table():
    objects = {"r": "block", "g": "block", "table": "surface"}
    from_table = [_seg(i, "Take", "r", "", ["(on r table)", "(clear r)", "(clear g)"], ["(clear r)", "(clear g)"],
                       "", "r") for i in range(2)]
    from_block = [_seg(10, "Take", "r", "", ["(on r g)", "(clear r)"], ["(clear r)", "(clear g)"], "", "r")]
    for segments in (from_table + from_block, from_table[:1] + from_block):
        domain = learn_domain([("doc", {"objects": objects, "initial": [], "segments": segments})])
        assert any(Atom("clear", ("?o2",)) in a.add for a in domain.actions), domain.actions
        assert domain.warnings == ()


def test_alignment_finds_a_support_renamed_among_many_bystanders_quickly():
    import time

    def take(origin, support):
        blocks = [f"?o{i}" for i in range(2, 10)]
        sup = f"?o{support}"
        pre = [Literal(Atom("hand_free")), Literal(Atom("clear", ("?o1",))), Literal(Atom("on", ("?o1", sup)))]
        pre += [Literal(Atom("near", ("?o1", b))) for b in blocks]
        pre += [Literal(Atom("clear", (b,))) for b in blocks if b != sup]
        return ActionSchema("take_block", (("?o1", "block"),) + tuple((b, "block") for b in blocks),
                            tuple(sorted(pre)), (Atom("clear", (sup,)), Atom("in_hand", ("?o1",))),
                            (Atom("hand_free"), Atom("on", ("?o1", sup))), origin)

    start = time.monotonic()
    assert aligned(take("a", 2), take("b", 9))["?o9"] == "?o2"
    assert len(generalise([take("a", 2), take("b", 9)])) == 1
    assert time.monotonic() - start < 1.0


def test_a_skill_on_something_never_held_keeps_its_static_facts():
    objects = {"chair": "obstacle", "plate": "item", "table": "surface", "drawer": "drawer", "corner": "furniture"}
    scene = ["(movable chair)", "(movable plate)", "(graspable plate)"]
    doc = {"objects": objects, "initial": scene + ["(blocking chair drawer)", "(on_top plate table)", "(clear corner)"],
           "segments": [
               _seg(0, "Push", "chair", "", scene + ["(blocking chair drawer)", "(clear corner)"],
                    scene + ["(blocking chair corner)", "(clear drawer)"], "", ""),
               _seg(1, "Take", "plate", "", scene + ["(on_top plate table)", "(clear drawer)"],
                    scene + ["(clear drawer)"], "", "plate")]}
    push = next(a for a in learn_domain([("doc", doc)]).actions if a.name.startswith("push"))
    assert Literal(Atom("movable", ("?o1",))) in push.precondition


def test_learning_beside_the_robot_keeps_what_its_actions_can_break(runner, app, tmp_path):
    import json

    from guided_lfd.pddl.reader import parse_domain

    result = runner.invoke(app, ["segment", str(ROOT / "tests/data/traces/stacking/base/D1.csv")])
    doc = json.loads(result.stdout)
    robot = parse_domain(ROOT / "tests/data/learn/robot-pick-up-unclear.pddl")  # grasps a block with one on top
    alone = next(a for a in learn_domain([("D1", doc)]).actions if a.name.startswith("stack"))
    beside = next(a for a in learn_domain([("D1", doc)], context=robot).actions if a.name.startswith("stack"))
    assert Literal(Atom("clear", ("?o1",))) not in alone.precondition  # proven over the learned skills alone
    assert Literal(Atom("clear", ("?o1",))) in beside.precondition


def test_a_static_relation_through_a_changed_object_ties_nothing_in():
    scene = ["(next_to table counter)", "(graspable mug)", "(graspable cup)"]
    doc = {"objects": {"mug": "item", "cup": "item", "table": "surface", "counter": "surface"},
           "initial": [*scene, "(on_top mug table)", "(clear counter)"], "segments": [
               _seg(0, "Take", "mug", "", [*scene, "(on_top mug table)", "(clear counter)"], [*scene, "(clear counter)"],
                    "", "mug"),
               _seg(2, "Put", "cup", "counter", [*scene, "(clear counter)"], [*scene, "(on_top cup counter)"], "cup", "",
                    hand="left")]}
    take = ground_actions(doc, "d")[0]
    assert take.objects == ("mug", "table")


def test_a_glitch_frame_beside_a_tracking_dropout_is_jitter():
    from guided_lfd.demonstration.segment import _debounce, _runs

    dt = 1 / 90
    times = np.concatenate([np.arange(0, 1, dt), np.arange(1.3, 2.3, dt)])
    labels = np.array(["Put"] * len(times), dtype=object)
    labels[int(np.searchsorted(times, 1.0)) - 1] = "Take"
    assert [r[0] for r in _debounce(times, _runs(times, labels))] == ["Put"]


def test_a_still_hand_across_a_tracking_dropout_is_one_take(tmp_path):
    """Tracking lost for 0.4 s while the hand holds still (it drifts 6 cm meanwhile): one Take, then the Put."""
    from guided_lfd.demonstration.segment import segment
    from guided_lfd.demonstration.trace import load_demonstration

    rows, t, dt, drift = [], 0.0, 1 / 60, 0.06
    while t < 6.0:
        if 2.0 < t < 2.4:
            t += dt
            continue
        if t < 1.0:
            x, grip, held, on = 0.3 + 0.2 * t, 0, "", "Red"
        elif t < 3.0:
            x, grip, held, on = 0.5 + (drift if t >= 2.4 else 0.0), 1, "Red", ""
        elif t < 4.0:
            x, grip, held, on = 0.5 + drift + 0.3 * (t - 3.0), 1, "Red", "Table"
        elif t < 4.3:
            x, grip, held, on = 0.8 + drift, 0, "", ""
        elif t < 5.0:
            x, grip, held, on = 0.8 + drift - 0.3 * (t - 4.3), 0, "", ""
        else:
            x, grip, held, on = 0.8 + drift - 0.21, 0, "", ""
        rows += [f"{t:.4f},right,{x:.4f},0.000,1.000,{grip},{held},{on}", f"{t:.4f},left,-0.3000,0.000,1.000,0,,"]
        t += dt
    trace = tmp_path / "gap.csv"
    trace.write_text("time,hand,x,y,z,grip,in_hand,act_on\n" + "\n".join(rows) + "\n")
    (tmp_path / "gap.state.csv").write_text(
        'time,fluent,value\n0,"object(Red,block)",true\n0,"object(Table,surface)",true\n0,"object(Shelf,surface)",'
        'true\n0,"on_top(Red,Shelf)",true\n0,clear(Red),true\n1.2,"on_top(Red,Shelf)",false\n'
        '4.05,"on_top(Red,Table)",true\n')
    acts = [s.activity for s in segment(load_demonstration(str(trace))) if s.hand == "right" and s.activity != "Idle"]
    assert acts == ["Reach", "Take", "Put", "Release"], acts
