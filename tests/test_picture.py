"""The excuse picture (``excuse --svg``/``--dot``, ``round-N/excuse.svg``): valid SVG, the changed facts marked.

Regenerate the golden picture after an intended change of the drawing with:
    GUIDED_LFD_REGOLD=1 python -m pytest tests/test_picture.py
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import BLOCKS, DATA, kitchen
from guided_lfd.benchmark import household
from guided_lfd.errors import EXIT_BAD_OPTION
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.picture import MAX_OBJECTS, excuse_scene
from guided_lfd.excuse.svg import SVG_NAMESPACE, scene_svg
from guided_lfd.pddl.reader import parse_task
from test_golden import check_golden

NS = {"svg": SVG_NAMESPACE}
SWITCHES = DATA / "byo" / "switches"


def _facts(root: ET.Element, mark: str, panel: int | None = None) -> list[str]:
    """The titles (facts in PDDL) of the fact groups marked ``mark``, in one panel or in all."""
    where = root if panel is None else root.find(f"svg:g[@class='panel panel-{panel}']", NS)
    assert where is not None
    return sorted(g.findtext("svg:title", namespaces=NS) for g in where.iterfind(".//svg:g", NS)
                  if g.get("class") == f"fact {mark}")


def _label(root: ET.Element, title: str) -> list[ET.Element]:
    """The ``<text>`` elements of the fact groups titled ``title``."""
    return [t for g in root.iterfind(".//svg:g", NS) if g.findtext("svg:title", namespaces=NS) == title
            for t in g.iterfind("svg:text", NS)]


def _svg(domain: str | Path, problem: str | Path, **options) -> ET.Element:
    dom, prob = parse_task(str(domain), str(problem))
    return ET.fromstring(find_excuses(dom, prob, ExcuseOptions(**options)).to_svg())


@pytest.mark.parametrize("k,change,words", [(1, "+(open pinkdrawer)", "+ open"),
                                            (2, "+(clear pinkdrawer)", "+ clear")])
def test_each_kitchen_draws_its_excuse(k, change, words, runner, app, tmp_path):
    out = tmp_path / "excuse.svg"
    result = runner.invoke(app, ["excuse", *kitchen(k), "--svg", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("Minimal excuse")  # the text still goes to stdout
    root = ET.parse(out).getroot()
    assert root.tag == f"{{{SVG_NAMESPACE}}}svg"
    # The change is marked in the excuse state only; nothing is removed; the initial state is every fact.
    assert _facts(root, "added") == _facts(root, "added", panel=2) == [change]
    assert _facts(root, "added", panel=1) == [] and _facts(root, "removed") == []
    dom, prob = parse_task(*kitchen(k))
    assert _facts(root, "same", panel=1) == sorted(str(a) for a in prob.init)
    labels = _label(root, change)
    assert [t.text for t in labels] == [words] and labels[0].get("font-weight") == "bold"
    assert root.findtext("svg:title", namespaces=NS).endswith(f"demonstrate how to reach {words[2:].title()} PinkDrawer")


def test_kitchen_2_picture_matches_golden_and_is_deterministic():
    first = find_excuses(*parse_task(*kitchen(2)), ExcuseOptions()).to_svg()
    assert first == find_excuses(*parse_task(*kitchen(2)), ExcuseOptions()).to_svg()
    assert first.isascii() and "&#8722;" in first  # the legend's minus sign, as a character reference
    check_golden("excuse-kitchen-2.svg", first)


def test_removed_facts_are_red_and_dashed_in_both_panels():
    """Blocks without unstack: C must come off B (the consistent excuse -(on c b) +(ontable c) +(clear b))."""
    root = _svg(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl")
    assert _facts(root, "removed", panel=1) == _facts(root, "removed", panel=2) == ["-(on c b)"]
    assert _facts(root, "added") == ["+(clear b)", "+(ontable c)"]
    for group in root.iterfind(".//svg:g[@class='fact removed']", NS):
        assert group.find("svg:path", NS).get("stroke-dasharray")  # a dashed arrow, labelled with a minus
        assert group.find("svg:path", NS).get("stroke") == "#cf222e"
        assert group.findtext("svg:text", namespaces=NS) == "\u2212 on"


def test_a_domain_without_a_hand_is_drawn(runner, app, tmp_path):
    out = tmp_path / "switches.svg"
    result = runner.invoke(app, ["excuse", str(SWITCHES / "robot.pddl"), str(SWITCHES / "problem.pddl"),
                                 "--svg", str(out), "--json", "--quiet"])
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["excuse"]["changes"][0]["change"] == "+(on porch-switch)"
    root = ET.parse(out).getroot()
    assert _facts(root, "added") == ["+(on porch-switch)"]
    assert [t.text for t in _label(root, "(wired porch-switch porch-lamp)")] == ["wired", "wired"]


def test_a_large_world_shows_the_changes_goal_and_neighbours_and_says_what_it_left_out():
    dom, prob = parse_task(*kitchen(1))
    report = find_excuses(dom, prob, ExcuseOptions())
    scene = excuse_scene(report, max_objects=3)
    # The change and the goal name PinkDrawer and RedPlate; the plate lies on the table.
    assert scene.objects == ["pinkdrawer", "redplate", "table"]
    assert (scene.hidden_objects, scene.hidden_facts) == (4, 3)  # clear counter, clear bluedrawer, blocking
    root = ET.fromstring(scene_svg(scene))
    assert root.findtext("svg:text[@class='caption']", namespaces=NS).startswith("Not shown: 4 objects and 3 fact(s)")
    assert "(clear counter)" not in _facts(root, "same")
    assert _facts(root, "added") == ["+(open pinkdrawer)"]
    # Kept whole, the kitchen has no caption.
    assert excuse_scene(report).caption is None


def test_a_house_is_cut_to_the_objects_near_the_changes_and_the_goal(tmp_path):
    house = household.House(8, 24, 2, 2, 2, "no-open-no-push")
    (tmp_path / "robot.pddl").write_text(household.domain_pddl(house.variant))
    (tmp_path / "house.pddl").write_text(household.problem_pddl(house))
    dom, prob = parse_task(str(tmp_path / "robot.pddl"), str(tmp_path / "house.pddl"))
    report = find_excuses(dom, prob, ExcuseOptions())
    scene = excuse_scene(report)
    named = {a for c in report.excuse.changes for a in c.atom.args} | {a for g in prob.goal for a in g.atom.args}
    after = prob.init | report.excuse.state
    near = {b for a in after if named & set(a.args) for b in a.args}  # the named objects and their neighbours
    assert len(prob.objects) == 76 > MAX_OBJECTS >= len(near) > len(named)
    assert sorted(scene.objects) == sorted(near) and scene.hidden_objects == 76 - len(near)
    hidden = [a for a in prob.init if not set(a.args) <= set(scene.objects)]
    assert scene.hidden_facts == len(hidden) > 0
    root = ET.fromstring(scene_svg(scene))
    assert _facts(root, "added") == sorted(str(c) for c in report.excuse.changes)
    assert not {str(a) for a in hidden} & set(_facts(root, "same"))


def test_without_an_excuse_the_picture_is_the_initial_state_and_why():
    dom, prob = parse_task(*kitchen(1, "human"))
    root = ET.fromstring(find_excuses(dom, prob, ExcuseOptions()).to_svg())
    assert root.findtext("svg:title", namespaces=NS) == "kitchen-1-store-plate: already solvable, no excuse needed"
    assert [p.get("class") for p in root.iterfind("svg:g", NS) if "panel" in p.get("class", "")] == ["panel panel-1"]
    assert _facts(root, "added") == _facts(root, "removed") == []


def test_dot_marks_the_changes(runner, app, tmp_path):
    out = tmp_path / "excuse.dot"
    result = runner.invoke(app, ["excuse", *kitchen(2), "--dot", str(out), "-o", str(tmp_path / "e.json"), "-q"])
    assert result.exit_code == 0, result.output
    text = out.read_text()
    assert text.startswith("digraph excuse {") and text.count("{") == text.count("}")
    assert text.count("subgraph cluster_") == 2
    added = [line for line in text.splitlines() if "#1a7f37" in line]
    assert len(added) == 1 and "<B>+ clear</B>" in added[0] and "PinkDrawer" in added[0]


def test_svg_to_stdout_only_when_the_result_goes_elsewhere(runner, app, tmp_path):
    refused = runner.invoke(app, ["excuse", *kitchen(1), "--svg", "-"])
    assert refused.exit_code == EXIT_BAD_OPTION
    assert "--output and --svg both name '-'" in refused.stderr
    result = runner.invoke(app, ["excuse", *kitchen(1), "--svg", "-", "-o", str(tmp_path / "e.txt"), "-q"])
    assert result.exit_code == 0, result.output
    assert _facts(ET.fromstring(result.stdout.split("\n", 1)[1]), "added") == ["+(open pinkdrawer)"]
    assert (tmp_path / "e.txt").read_text().startswith("Minimal excuse")


def test_teach_draws_each_round_and_reuses_its_session_folder(runner, app, tmp_path):
    robot, problem = kitchen(2)
    human = str(Path(robot).with_name("human.pddl"))
    for _ in range(2):  # the second run replaces the first session, pictures included
        result = runner.invoke(app, ["teach", robot, problem, "--simulate", human, "-o", str(tmp_path), "-q"])
        assert result.exit_code == 0, result.output
    picture = tmp_path / "round-1" / "excuse.svg"
    assert _facts(ET.parse(picture).getroot(), "added") == ["+(clear pinkdrawer)"]
    rounds = json.loads((tmp_path / "session.json").read_text())["rounds"]
    assert rounds[0]["files"]["picture"] == str(picture)
