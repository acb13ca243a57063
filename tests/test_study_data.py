"""The shipped demonstrations: reproducible, Table II sizes, and they teach the robot."""

from __future__ import annotations

import re

import pytest

from conftest import ROOT
from guided_lfd.demonstration.learn import ground_actions, learn_domain
from guided_lfd.demonstration.segment import segment, segments_document
from guided_lfd.demonstration.study_data import DEMONSTRATORS, TABLE_I, TABLE_II_OBSERVED, render_study
from guided_lfd.demonstration.trace import load_demonstration
from guided_lfd.planning.grounding import ground
from guided_lfd.pddl.reader import parse_task
from guided_lfd.planning import find_plan

DEMOS = ROOT / "data" / "demos"
CASES = [(k, who, kind) for k in ("kitchen-1", "kitchen-2") for kind in ("excuse", "complete")
         for who in DEMONSTRATORS]


def test_shipped_demonstrations_are_exactly_what_the_generator_renders(tmp_path):
    render_study(ROOT / "data" / "domains", tmp_path)
    for kitchen, who, kind in CASES:
        for suffix in (".csv", ".state.csv", ".labels.csv"):
            name = f"{who}-{kind}{suffix}"
            assert (tmp_path / kitchen / name).read_text() == (DEMOS / kitchen / name).read_text(), name


@pytest.mark.parametrize("kitchen,who,kind", CASES, ids=[f"{k}-{w}-{c}" for k, w, c in CASES])
def test_demonstration_matches_the_papers_tables(kitchen, who, kind):
    demo = load_demonstration(str(DEMOS / kitchen / f"{who}-{kind}.csv"))
    k = DEMONSTRATORS.index(who)
    assert abs(demo.frames["time"].max() - TABLE_I[kitchen][kind][k]) < 0.2
    observed = TABLE_II_OBSERVED[kitchen][kind][k]
    doc = segments_document(demo, segment(demo), "state")
    if observed is not None:
        assert len(ground_actions(doc)) == observed
    if kind == "excuse":
        robot, problem = parse_task(ROOT / "data" / "domains" / kitchen / "robot.pddl",
                                    ROOT / "data" / "domains" / kitchen / "problem.pddl")
        merged = learn_domain([("demo", doc)], prior=robot)
        assert find_plan(ground(merged, problem, fixed=merged.predicates)).plan is not None


def test_padding_that_is_not_applicable_is_refused():
    """Regression: Kitchen II's padding pushed the chair from the corner while it stood before BlueDrawer."""
    from guided_lfd.demonstration.study_data import check_executable

    human, problem = parse_task(ROOT / "data" / "domains" / "kitchen-2" / "human.pddl",
                                ROOT / "data" / "domains" / "kitchen-2" / "problem.pddl")
    good = [("move_chair", ("chair", "pinkdrawer", "corner")), ("move_chair", ("chair", "corner", "counter"))]
    check_executable(good, human, set(problem.init))
    bad = [("move_chair", ("chair", "pinkdrawer", "bluedrawer")), ("move_chair", ("chair", "corner", "counter"))]
    with pytest.raises(ValueError, match=r"step 2 \(move_chair chair corner counter\) is not applicable: "
                                         r"\(blocking chair corner\) does not hold"):
        check_executable(bad, human, set(problem.init))


@pytest.mark.parametrize("kitchen,skills", [
    ("kitchen-1", [("right", "open_drawer"), ("left", "take_item"), ("left", "put_item_drawer")]),
    ("kitchen-2", [("right", "push_obstacle"), ("right", "open_drawer"), ("left", "take_item"),
                   ("left", "put_item_drawer")]),
])
def test_two_handed_complete_demonstration_yields_the_plan_per_hand(kitchen, skills):
    """P3's complete demonstrations (both hands at once, not processable for the paper's tool)."""
    demo = load_demonstration(str(DEMOS / kitchen / "P3-complete.csv"))
    doc = segments_document(demo, segment(demo), "state")
    actions = ground_actions(doc)
    hands = {s["index"]: s["hand"] for s in doc["segments"]}
    found = [(hands[int(re.search(r"segment (\d+)", a.source).group(1))], a.name) for a in actions]
    assert sorted(found) == sorted(skills)
    # The left hand's Take lasts while the right hand works; only the plate's change is its own.
    take = next(a for a in actions if a.name == "take_item")
    assert {str(x) for x in take.add | take.delete} == {"(in_hand redplate)", "(hand_free)", "(on_top redplate table)"}
