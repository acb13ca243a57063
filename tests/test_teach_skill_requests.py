"""teach over a second task: a learned skill shown once more where a skill excuse asks, or the teacher's "cannot".

The blocks world's robot lacks unstack; the first task (tests/data/skills/table.pddl) teaches it from a block
standing on the table, so the learned unstack requires (ontable ?y); the reverse tower (tower.pddl) needs it
without.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from guided_lfd.pddl.reader import parse_domain

BYO = Path("tests/data/byo/blocksworld")
DATA = Path("tests/data/skills")


@pytest.fixture
def taught(runner, app, tmp_path):
    """The robot after the first task, taught by the simulated human (its robot.pddl)."""
    result = runner.invoke(app, ["teach", str(BYO / "robot.pddl"), str(DATA / "table.pddl"), "--simulate",
                                 str(BYO / "human.pddl"), "-o", str(tmp_path / "first"), "-q"])
    assert result.exit_code == 0, result.output
    robot = tmp_path / "first" / "robot.pddl"
    unstack = parse_domain(robot).action("unstack")
    assert "(ontable ?y)" in {str(l) for l in unstack.precondition}
    return robot


def _session(folder: Path) -> dict:
    return json.loads((folder / "session.json").read_text())


def test_a_second_task_asks_for_the_skill_once_more_and_the_skill_generalises(runner, app, tmp_path, taught):
    result = runner.invoke(app, ["teach", str(taught), str(DATA / "tower.pddl"), "--simulate",
                                 str(BYO / "human.pddl"), "-o", str(tmp_path / "second")])
    assert result.exit_code == 0, result.output
    session = _session(tmp_path / "second")
    (rnd,) = session["rounds"]
    assert rnd["skill_request"] == {"step": "(unstack c b)", "dropped": ["-(ontable ?y) in unstack"],
                                    "robot_first": []}
    assert rnd["outcome"] == "accepted" and rnd["answer"] is None
    assert session["status"] == "solved" and session["plans_original_task"] is True
    learned = parse_domain(tmp_path / "second" / "robot.pddl")
    human = parse_domain(BYO / "human.pddl").action("unstack")
    assert set(learned.action("unstack").precondition) == set(human.precondition)  # no unstack_2 beside it
    assert [a.name for a in learned.actions].count("unstack") == 1 and set(learned.action("unstack").add) == set(human.add)
    assert "Show unstack c b here (Unstack where Ontable ?y is false)" in result.stderr


def test_the_learned_skill_records_that_its_precondition_varied(runner, app, tmp_path, taught):
    runner.invoke(app, ["teach", str(taught), str(DATA / "tower.pddl"), "--simulate", str(BYO / "human.pddl"),
                        "-o", str(tmp_path / "second"), "-q"])
    unstack = parse_domain(tmp_path / "second" / "robot.pddl").action("unstack")
    required, varied = unstack.learned_evidence()
    assert {str(e) for e in required} == {"(clear ?x) 2/2", "(handempty) 2/2", "(on ?x ?y) 2/2"}
    assert [str(e) for e in varied] == ["(ontable ?y) 1/2"]


def test_a_teacher_who_cannot_do_the_skill_there_confirms_the_precondition(runner, app, tmp_path, taught):
    result = runner.invoke(app, ["teach", str(taught), str(DATA / "tower.pddl"), "--simulate",
                                 str(DATA / "table-only-human.pddl"), "-o", str(tmp_path / "second"),
                                 "--max-rounds", "2"])
    session = _session(tmp_path / "second")
    first = session["rounds"][0]
    assert first["answer"] == "unstack c b cannot be done here: it needs (ontable b)"
    assert first["demonstration_length"] is None and first["outcome"] is None
    unstack = parse_domain(tmp_path / "second" / "robot.pddl").action("unstack")
    assert [str(e) for e in unstack.evidence if e.confirmed] == ["(ontable ?y) 1/1 confirmed"]
    second = session["rounds"][1]  # the search went on without that skill change: state changes now
    assert second["skill_request"] is None and "+(clear b)" in second["request"]
    assert "the teacher answered: unstack c b cannot be done here" in (tmp_path / "second" / "session.md").read_text()
    assert "round 1: the teacher answered: unstack c b cannot be done here" in result.stderr


def test_a_recorded_answer_cannot_stands_for_the_teachers_no(runner, app, tmp_path, taught):
    result = runner.invoke(app, ["teach", str(taught), str(DATA / "tower.pddl"), "--demo", "cannot",
                                 "-o", str(tmp_path / "second"), "--max-rounds", "2"])
    session = _session(tmp_path / "second")
    assert session["rounds"][0]["answer"] == "unstack c b cannot be done there (the teacher's answer, --demo cannot)"
    assert session["status"] == "no-demonstration" and result.exit_code == 14
    unstack = parse_domain(tmp_path / "second" / "robot.pddl").action("unstack")
    assert any(e.confirmed for e in unstack.evidence)


def test_one_teach_over_both_tasks_grows_one_library(runner, app, tmp_path):
    result = runner.invoke(app, ["teach", str(BYO / "robot.pddl"), str(DATA / "table.pddl"), str(DATA / "tower.pddl"),
                                 "--simulate", str(BYO / "human.pddl"), "-o", str(tmp_path / "seq"), "--json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert (doc["format"], doc["format_version"], doc["solved"]) == ("guided-lfd/teach-library", 1, True)
    first, second = doc["tasks"]
    assert (first["demonstrations"], first["skill_requests"], first["learned_actions"]) == (1, [], ["unstack"])
    assert (second["demonstrations"], second["skill_requests"]) == (1, ["(unstack c b)"])
    assert second["plans_original_task"] is True
    library = parse_domain(tmp_path / "seq" / "robot.pddl")
    assert set(library.action("unstack").precondition) == set(parse_domain(BYO / "human.pddl").action("unstack")
                                                               .precondition)
    assert json.loads((tmp_path / "seq" / "task-2" / "session.json").read_text())["status"] == "solved"
    assert "2. `tests/data/skills/tower.pddl`: **solved**" in (tmp_path / "seq" / "library.md").read_text()


def test_a_folder_of_tasks_is_taught_in_name_order(runner, app, tmp_path):
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    (tasks / "1-table.pddl").write_text((DATA / "table.pddl").read_text())
    (tasks / "2-tower.pddl").write_text((DATA / "tower.pddl").read_text())
    (tasks / "notes.pddl").write_text(";; not a problem\n(define (domain other) (:requirements :strips))\n")
    result = runner.invoke(app, ["teach", str(BYO / "robot.pddl"), str(tasks), "--simulate", str(BYO / "human.pddl"),
                                 "-o", str(tmp_path / "seq"), "--json"])
    assert result.exit_code == 0, result.output
    assert [t["problem"] for t in json.loads(result.stdout)["tasks"]] == [str(tasks / "1-table.pddl"),
                                                                         str(tasks / "2-tower.pddl")]


def test_the_library_api_teaches_a_sequence(tmp_path):
    from guided_lfd.pddl.reader import parse_task
    from guided_lfd.teach import SimulatedHuman, teach_tasks

    robot, table = parse_task(BYO / "robot.pddl", DATA / "table.pddl")
    _, tower = parse_task(BYO / "robot.pddl", DATA / "tower.pddl")
    library = teach_tasks(robot, [table, tower], SimulatedHuman(parse_domain(BYO / "human.pddl")), tmp_path / "seq")
    assert library.solved and [s.status for s in library.sessions] == ["solved", "solved"]
    assert library.sessions[1].rounds[0].skill is not None


def test_a_folder_without_problem_files_is_refused_in_one_line(runner, app, tmp_path):
    (tmp_path / "empty").mkdir()
    result = runner.invoke(app, ["teach", str(BYO / "robot.pddl"), str(tmp_path / "empty"), "-o",
                                 str(tmp_path / "seq")])
    assert result.exit_code == 30 and "holds no problem file" in result.stderr


def test_a_door_that_leads_nowhere_drops_the_static_relations_and_their_parameter(runner, app, tmp_path):
    """mobile: open-door learned at the kitchen door keeps (door-connects ?d ?r ?o3) both ways; the study door
    needs no demonstration (the robot rebinds ?o3), a cupboard door is shown once more, and the skill becomes
    the human's: two parameters, no door-connects."""
    mobile = Path("tests/data/byo/mobile")
    result = runner.invoke(app, ["teach", str(mobile / "robot.pddl"), str(mobile / "problem.pddl"),
                                 str(mobile / "problem-2.pddl"), "--simulate", str(mobile / "human.pddl"), "-o",
                                 str(tmp_path / "seq"), "--json", "-q"])
    assert result.exit_code == 0, result.output
    second = json.loads(result.stdout)["tasks"][1]
    assert second["demonstrations"] == 1 and len(second["skill_requests"]) == 1
    assert second["skill_requests"][0].split()[1] in {"pantry-door", "linen-door", "broom-door"}
    opened = parse_domain(tmp_path / "seq" / "robot.pddl").action("open-door")
    human = parse_domain(mobile / "human.pddl").action("open-door")
    assert (opened.params, set(opened.precondition), opened.add) == (human.params, set(human.precondition), human.add)


def test_teach_with_skill_changes_off_asks_for_state_changes_instead(runner, app, tmp_path, taught):
    runner.invoke(app, ["teach", str(taught), str(DATA / "tower.pddl"), "--simulate", str(BYO / "human.pddl"),
                        "-o", str(tmp_path / "second"), "-q", "--skill-changes", "off"])
    first = _session(tmp_path / "second")["rounds"][0]
    assert first["skill_request"] is None and "+(clear b)" in first["excuse"]


def _sequence(runner, app, out, *tasks):
    return runner.invoke(app, ["teach", str(BYO / "robot.pddl"), *map(str, tasks), "--simulate",
                               str(BYO / "human.pddl"), "-o", str(out), "-q"])


def test_a_sequence_never_writes_through_a_link_in_its_folder(runner, app, tmp_path):
    (tmp_path / "mine.txt").write_text("mine")
    (tmp_path / "seq").mkdir()
    (tmp_path / "seq" / "robot.pddl").symlink_to(tmp_path / "mine.txt")
    result = _sequence(runner, app, tmp_path / "seq", DATA / "table.pddl", DATA / "tower.pddl")
    assert result.exit_code == 40 and "holds robot.pddl as a link" in result.stderr
    assert (tmp_path / "mine.txt").read_text() == "mine" and sorted(p.name for p in (tmp_path / "seq").iterdir()) == \
        ["robot.pddl"]


def test_a_sequence_refuses_a_folder_with_other_files_or_of_other_tasks(runner, app, tmp_path):
    (tmp_path / "busy").mkdir()
    (tmp_path / "busy" / "notes.txt").write_text("notes")
    result = _sequence(runner, app, tmp_path / "busy", DATA / "table.pddl", DATA / "tower.pddl")
    assert result.exit_code == 40 and "holds notes.txt" in result.stderr
    assert _sequence(runner, app, tmp_path / "seq", DATA / "table.pddl", DATA / "tower.pddl").exit_code == 0
    result = _sequence(runner, app, tmp_path / "seq", DATA / "tower.pddl", DATA / "table.pddl")
    assert result.exit_code == 40 and "holds a teaching of other tasks (bw-t1, bw-t2)" in result.stderr


def test_a_sequence_of_the_same_tasks_replaces_the_previous_one_whole(runner, app, tmp_path):
    assert _sequence(runner, app, tmp_path / "seq", DATA / "table.pddl", DATA / "tower.pddl").exit_code == 0
    assert _sequence(runner, app, tmp_path / "seq", DATA / "table.pddl", DATA / "tower.pddl").exit_code == 0
    assert sorted(p.name for p in (tmp_path / "seq").iterdir()) == ["library.json", "library.md", "robot.pddl",
                                                                     "task-1", "task-2"]


def test_a_negative_seed_is_refused_in_one_line(runner, app, tmp_path):
    result = runner.invoke(app, ["teach", str(BYO / "robot.pddl"), str(DATA / "table.pddl"), "--simulate",
                                 str(BYO / "human.pddl"), "--seed", "-1", "-o", str(tmp_path / "s")])
    assert result.exit_code == 37 and "--seed -1: expected a whole number >= 0" in result.stderr


def test_cannot_where_a_demonstration_was_asked_for_says_so(runner, app, tmp_path):
    result = runner.invoke(app, ["teach", str(BYO / "robot.pddl"), str(DATA / "table.pddl"), "--demo", "cannot",
                                 "-o", str(tmp_path / "s")])
    assert result.exit_code == 14
    assert "the next --demo was 'cannot', which answers only a round that asks for a skill once more" in result.stderr
