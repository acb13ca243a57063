"""Bring your own robot (issue #23): the whole loop on six domains whose vocabularies are not the kitchens'.

Each domain of ``tests/data/byo/`` has a robot missing one or two skills, the
human model with all of them, a task and a larger task.  ``teach --simulate``
must end solved in at most two rounds with a robot that plans the task from
its initial state, and plans the larger task using the learned skills more
than once; the learned skills must be the human model's actions (precision
and recall 1.00, but for the static relations a skill keeps, see ``PRECISION``); the committed demonstrations must give the same skills
through ``segment | learn-domain --prior | merge``.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import DATA, load_script
from guided_lfd.demonstration.quality import skill_quality
from guided_lfd.pddl.reader import parse_domain

BYO = DATA / "byo"
DOMAINS = sorted(p.name for p in BYO.iterdir() if (p / "robot.pddl").is_file())
#: Precondition precision below 1.00: a skill keeps the static relations among its objects that held in its
#: demonstrations (issue #51); mobile's open-door keeps (door-connects ?d ?r ?o3) both ways, which the human's
#: open-door (door-in ?d ?r) does not ask for.  shelves' and lab's first tasks are over-specific by design (their
#: problem-2.pddl asks for the skill once more): take-down keeps (low ?s), the only reachable boxes being on a low
#: shelf (3 of 4 preconditions the human's); write-label keeps (capped ?t), every tube being capped (2 of 3).
PRECISION = {"mobile": 0.667, "shelves": 0.75, "lab": 0.667}
#: What the kitchens' learner used to put in every skill: none of these domains declares it.
KITCHEN_HAND = ("in_hand", "hand_free")


def test_the_corpus_has_eight_domains_and_none_speaks_the_kitchens_hand():
    assert len(DOMAINS) >= 8
    for name in DOMAINS:
        human = parse_domain(str(BYO / name / "human.pddl"))
        assert not set(KITCHEN_HAND) & set(human.predicates), name


def _skills(domain_path: Path, robot_path: Path) -> dict[str, tuple]:
    """The actions of ``domain_path`` that ``robot_path`` lacks (or has otherwise), by name."""
    domain, robot = parse_domain(str(domain_path)), parse_domain(str(robot_path))
    had = {a.name: (a.params, a.precondition, a.add, a.delete) for a in robot.actions}
    return {a.name: (a.params, a.precondition, a.add, a.delete) for a in domain.actions
            if had.get(a.name) != (a.params, a.precondition, a.add, a.delete)}


@pytest.fixture(scope="module")
def taught(tmp_path_factory) -> dict[str, tuple[dict, Path]]:
    """Every domain taught once through the command line: (session.json, session folder)."""
    from typer.testing import CliRunner

    from cli.main import app

    out = {}
    for name in DOMAINS:
        folder, session = BYO / name, tmp_path_factory.mktemp(name) / "session"
        result = CliRunner().invoke(app, ["teach", str(folder / "robot.pddl"), str(folder / "problem.pddl"),
                                          "--simulate", str(folder / "human.pddl"), "-o", str(session), "--json",
                                          "--quiet"])
        assert result.exit_code == 0, (name, result.output)
        out[name] = (json.loads(result.stdout), session)
    return out


@pytest.mark.parametrize("name", DOMAINS)
def test_teach_ends_solved_and_the_taught_robot_plans_the_task_itself(name, taught):
    doc, session = taught[name]
    assert doc["status"] == "solved" and doc["plans_original_task"] is True and 1 <= len(doc["rounds"]) <= 2
    text = (session / "robot.pddl").read_text()
    assert not any(f"({p}" in text for p in KITCHEN_HAND), "a learned skill speaks the kitchens' hand"


@pytest.mark.parametrize("name", DOMAINS)
def test_the_taught_robot_plans_a_larger_task_using_the_learned_skills_more_than_once(name, taught, runner, app):
    doc, session = taught[name]
    learned = _skills(session / "robot.pddl", BYO / name / "robot.pddl")
    result = runner.invoke(app, ["plan", str(session / "robot.pddl"), str(BYO / name / "problem-large.pddl"),
                                 "--json", "--quiet"])
    assert result.exit_code == 0, result.output
    steps = [s.strip("()").split()[0] for s in json.loads(result.stdout)["plan"]]
    assert sum(s in learned for s in steps) >= 2, steps


@pytest.mark.parametrize("name", DOMAINS)
def test_the_learned_skills_are_the_human_models_actions(name, taught):
    _, session = taught[name]
    robot, taught_robot = parse_domain(str(BYO / name / "robot.pddl")), parse_domain(str(session / "robot.pddl"))
    human = parse_domain(str(BYO / name / "human.pddl"))
    learned = [a for a in taught_robot.actions if a.name not in {b.name for b in robot.actions}]
    assert {a.name for a in learned} == {a.name for a in human.actions} - {a.name for a in robot.actions}
    assert skill_quality(learned, human) == {"pre_precision": PRECISION.get(name, 1.0), "pre_recall": 1.0,
                                             "eff_precision": 1.0, "eff_recall": 1.0}


@pytest.mark.parametrize("name", DOMAINS)
def test_the_committed_demonstrations_give_the_same_skills_through_the_pipeline(name, taught, runner, app, tmp_path):
    """segment | learn-domain --prior ROBOT --human HUMAN | merge ROBOT -: the skills teach learned."""
    folder = BYO / name
    _, session = taught[name]
    traces = sorted(folder.glob("demo-round-*.csv"))
    traces = [t for t in traces if not t.name.endswith(".state.csv")]
    assert traces, "render them with tests/data/byo/render.py"
    segments = []
    for trace in traces:
        segmented = runner.invoke(app, ["segment", str(trace)])
        assert segmented.exit_code == 0, segmented.output
        path = tmp_path / f"{trace.stem}.segments.json"
        path.write_text(segmented.stdout)
        segments.append(str(path))
    learned = runner.invoke(app, ["learn-domain", *segments, "--prior", str(folder / "robot.pddl"), "--human",
                                  str(folder / "human.pddl")])
    assert learned.exit_code == 0, learned.output
    merged = runner.invoke(app, ["merge", str(folder / "robot.pddl"), "-"], input=learned.stdout)
    assert merged.exit_code == 0, merged.output
    (tmp_path / "merged.pddl").write_text(merged.stdout)
    assert _skills(tmp_path / "merged.pddl", folder / "robot.pddl") == _skills(session / "robot.pddl",
                                                                               folder / "robot.pddl")


def test_rendering_the_demonstrations_again_gives_the_committed_files(tmp_path):
    module = load_script(BYO / "render.py", "byo_render")
    for trace in module.render_domain(BYO / "twoarm", tmp_path):
        committed = BYO / "twoarm" / trace.name
        assert trace.read_bytes() == committed.read_bytes()
        state = trace.with_name(trace.stem + ".state.csv")
        assert state.read_bytes() == committed.with_name(state.name).read_bytes()


def test_a_fact_a_skill_changes_is_no_static_relation_though_the_demonstration_never_changes_it(runner, app, tmp_path):
    """The breaker feeding the switch is up throughout the demonstration; the human model resets breakers, so
    whether it is up is a condition of turning the switch on (it used to be taken for the world's structure)."""
    folder = BYO / "switches"
    result = runner.invoke(app, ["teach", str(folder / "robot.pddl"), str(folder / "problem-breaker-up.pddl"),
                                 "--simulate", str(folder / "human.pddl"), "-o", str(tmp_path), "--quiet"])
    assert result.exit_code == 0, result.output
    taught = parse_domain(str(tmp_path / "robot.pddl"))
    human = parse_domain(str(folder / "human.pddl"))
    assert set(taught.action("turn-on").precondition) == set(human.action("turn-on").precondition)
