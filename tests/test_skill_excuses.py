"""Skill excuses (guided_lfd.excuse.skills): exact against brute force on random small tasks, and as users meet them.

A random task's domain mixes learned skills (their evidence written as the comments ``learn-domain`` writes,
some preconditions confirmed by the teacher) with given ones; the brute force grounds it itself, and for every
set of droppable preconditions finds the states from which the goal is reachable by a fixpoint over all states.
"""

from __future__ import annotations

import itertools
import json

from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from cli.main import app
from guided_lfd.excuse.change import SkillChange
from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
from guided_lfd.excuse.skills import relaxable_preconditions, relaxed_domain
from guided_lfd.excuse.status import ExcuseStatus
from guided_lfd.pddl.model import Atom, Literal
from guided_lfd.pddl.reader import parse_task

OBJECTS = ("o1", "o2")
PREDICATES = {"p": 1, "q": 1, "r": 2}
ATOMS = [Atom(p, args) for p, n in sorted(PREDICATES.items()) for args in itertools.product(OBJECTS, repeat=n)]


def _atoms_over(params):
    return [Atom(p, args) for p, n in sorted(PREDICATES.items()) for args in itertools.product(params, repeat=n)]


@st.composite
def tasks(draw):
    """A random domain (2-3 actions, learned or given, some learned preconditions confirmed) and problem."""
    actions = []
    for k in range(draw(st.integers(2, 3))):
        params = ("?a", "?b")[: draw(st.integers(1, 2))]
        over = _atoms_over(params)
        pre = draw(st.lists(st.sampled_from(over), min_size=1, max_size=3, unique=True))
        add = draw(st.lists(st.sampled_from(over), min_size=1, max_size=2, unique=True))
        delete = [a for a in draw(st.lists(st.sampled_from(over), max_size=2, unique=True)) if a not in add]
        learned = draw(st.booleans())
        confirmed = {a for a in pre if learned and draw(st.integers(0, 3)) == 0}
        actions.append((f"act{k}", params, pre, add, delete, learned, confirmed))
    init = draw(st.lists(st.sampled_from(ATOMS), max_size=4, unique=True))
    goal = draw(st.lists(st.sampled_from([a for a in ATOMS if a not in init]), min_size=1, max_size=2, unique=True))
    return actions, init, goal


def _pddl(actions, init, goal) -> tuple[str, str]:
    blocks = []
    for name, params, pre, add, delete, learned, confirmed in actions:
        head = ""
        if learned:  # the evidence comment the learner writes: every precondition held in both demonstrations
            items = ", ".join(f"{a} 2/2{' confirmed' if a in confirmed else ''}" for a in pre) or "no precondition"
            head = f"  ;; evidence (held in / demonstrations): {items}\n"
        effect = " ".join([str(a) for a in add] + [f"(not {a})" for a in delete])
        blocks.append(f"{head}  (:action {name} :parameters ({' '.join(params)})\n"
                      f"    :precondition (and {' '.join(map(str, pre))}) :effect (and {effect}))")
    domain = ("(define (domain rnd) (:requirements :strips)\n  (:predicates (p ?x) (q ?x) (r ?x ?y))\n"
              + "\n".join(blocks) + ")\n")
    problem = (f"(define (problem t) (:domain rnd) (:objects {' '.join(OBJECTS)})\n"
               f"  (:init {' '.join(map(str, init))}) (:goal (and {' '.join(map(str, goal))})))\n")
    return domain, problem


def _droppable(actions) -> list[SkillChange]:
    """The spec, written out: a learned precondition not confirmed and not deleted by its own action."""
    return [SkillChange(name, Literal(a)) for name, _, pre, _, delete, learned, confirmed in actions if learned
            for a in pre if a not in confirmed and a not in delete]


def _ground(actions, dropped):
    index = {a: i for i, a in enumerate(ATOMS)}
    out = []
    for name, params, pre, add, delete, _, _ in actions:
        for objs in itertools.product(OBJECTS, repeat=len(params)):
            sub = dict(zip(params, objs))

            def mask(atoms):
                out = 0  # an OR, not a sum: (p ?a) and (p ?b) are one atom when ?a = ?b
                for a in atoms:
                    out |= 1 << index[Atom(a.predicate, tuple(sub[x] for x in a.args))]
                return out

            kept = [a for a in pre if SkillChange(name, Literal(a)) not in dropped]
            out.append((mask(kept), mask(add), mask(delete)))
    return out


def _good_states(actions, dropped, goal_mask) -> set[int]:
    """Every state from which the goal is reachable with ``dropped`` preconditions dropped (a fixpoint)."""
    ground = _ground(actions, dropped)
    good = {s for s in range(1 << len(ATOMS)) if (s & goal_mask) == goal_mask}
    changed = True
    while changed:
        changed = False
        for s in range(1 << len(ATOMS)):
            if s not in good and any((s & pre) == pre and ((s & ~dele) | add) in good for pre, add, dele in ground):
                good.add(s)
                changed = True
    return good


def _brute_force(actions, init, goal):
    """(least total changes, least skill changes among the excuses of that total), or None."""
    index = {a: i for i, a in enumerate(ATOMS)}
    init_mask, goal_mask = sum(1 << index[a] for a in init), sum(1 << index[a] for a in goal)  # unique atoms
    if (init_mask & goal_mask) == goal_mask:
        return 0, 0
    droppable, best = _droppable(actions), None
    for k in range(len(droppable) + 1):
        for chosen in itertools.combinations(droppable, k):
            # An excuse state never satisfies the goal itself (that is no excuse, the robot would do nothing).
            good = [s for s in _good_states(actions, set(chosen), goal_mask) if (s & goal_mask) != goal_mask]
            if good:
                total = k + min((s ^ init_mask).bit_count() for s in good)
                best = min(best or (total, k), (total, k))
    return best


def _valid(plan, state, actions, dropped, goal) -> bool:
    by_name = {a[0]: a for a in actions}
    state = set(state)
    for step in plan:
        name, params, pre, add, delete, _, _ = by_name[step.action]
        sub = dict(zip(params, step.args))
        ground = lambda a: Atom(a.predicate, tuple(sub[x] for x in a.args))  # noqa: E731
        if not all(ground(a) in state for a in pre if SkillChange(name, Literal(a)) not in dropped):
            return False
        state = (state - {ground(a) for a in delete}) | {ground(a) for a in add}
    return set(goal) <= state


@settings(max_examples=200, deadline=None)
@given(tasks())
def test_the_minimal_excuse_over_state_and_skill_changes_equals_brute_force(tmp_path_factory, task):
    actions, init, goal = task
    folder = tmp_path_factory.mktemp("rnd")
    domain_text, problem_text = _pddl(actions, init, goal)
    (folder / "domain.pddl").write_text(domain_text)
    (folder / "problem.pddl").write_text(problem_text)
    domain, problem = parse_task(folder / "domain.pddl", folder / "problem.pddl")
    assert set(relaxable_preconditions(domain)) == set(_droppable(actions))
    report = find_excuses(domain, problem, ExcuseOptions(semantics="literal", change_structure=True))
    expected = _brute_force(actions, init, goal)
    if expected is None:
        assert report.excuse is None and report.status is ExcuseStatus.NONE
        return
    if expected[0] == 0:
        assert report.status is ExcuseStatus.ALREADY_SOLVABLE
        return
    excuse = report.excuse
    assert excuse is not None and (excuse.cost, len(excuse.skill_changes)) == expected
    assert _valid(excuse.plan, excuse.state, actions, set(excuse.skill_changes), goal)


def _taught_blocks(tmp_path):
    """The blocks world robot after one lesson: unstack learned from one block taken off a block on the table."""
    robot = open("tests/data/byo/blocksworld/robot.pddl").read().rstrip()[:-1]
    skill = """
  ;; evidence (held in / demonstrations): (clear ?x) 1/1, (handempty) 1/1, (on ?x ?y) 1/1, (ontable ?y) 1/1
  (:action unstack
    :parameters (?x ?y - block)
    :precondition (and (clear ?x) (handempty) (on ?x ?y) (ontable ?y))
    :effect (and (clear ?y) (holding ?x) (not (clear ?x)) (not (handempty)) (not (on ?x ?y)))))
"""
    (tmp_path / "robot.pddl").write_text(robot + skill)
    (tmp_path / "tower.pddl").write_text("""(define (problem reverse-tower) (:domain BLOCKS)
  (:objects a b c - block)
  (:init (handempty) (ontable a) (on b a) (on c b) (clear c))
  (:goal (and (on a b) (on b c))))
""")
    return tmp_path / "robot.pddl", tmp_path / "tower.pddl"


def test_a_coincidental_learned_precondition_is_the_excuse_and_the_plan_needs_it_dropped(tmp_path):
    robot, tower = _taught_blocks(tmp_path)
    result = CliRunner().invoke(app, ["excuse", str(robot), str(tower), "--json"])
    assert result.exit_code == 0, result.output
    excuse = json.loads(result.stdout)["excuse"]
    assert excuse["changes"] == [] and excuse["size"] == 1 and excuse["cost"] == 1
    assert excuse["skill_changes"] == [{"change": "-(ontable ?y) in unstack", "action": "unstack",
                                        "precondition": "(ontable ?y)", "text": "Unstack where Ontable ?y is false"}]
    assert excuse["plan"][0] == "(unstack c b)"  # b stands on a: the precondition dropped is used at once


def test_skill_changes_off_asks_for_state_changes_alone(tmp_path):
    robot, tower = _taught_blocks(tmp_path)
    result = CliRunner().invoke(app, ["excuse", str(robot), str(tower), "--json", "--skill-changes", "off"])
    excuse = json.loads(result.stdout)["excuse"]
    assert excuse["skill_changes"] == [] and excuse["size"] == 3


def test_the_text_says_which_skill_to_show_again_and_where(tmp_path):
    robot, tower = _taught_blocks(tmp_path)
    result = CliRunner().invoke(app, ["excuse", str(robot), str(tower)])
    assert "show a skill once more" in result.stdout
    assert "Unstack where Ontable ?y is false   -(ontable ?y) in unstack" in result.stdout
    assert "with the precondition(s) dropped" in result.stdout


def test_a_precondition_the_skill_consumes_or_the_teacher_confirmed_is_never_dropped(tmp_path):
    robot, _ = _taught_blocks(tmp_path)
    text = robot.read_text().replace("(ontable ?y) 1/1", "(ontable ?y) 1/1 confirmed")
    robot.write_text(text)
    domain, _ = parse_task(robot, tmp_path / "tower.pddl")
    assert relaxable_preconditions(domain) == []  # clear, handempty and on are consumed; ontable confirmed


def test_given_skills_are_dropped_only_with_relax_prior(tmp_path):
    domain, _ = parse_task("tests/data/byo/blocksworld/human.pddl", "tests/data/byo/blocksworld/problem.pddl")
    assert relaxable_preconditions(domain) == []
    assert SkillChange("stack", Literal(Atom("clear", ("?y",)))) not in relaxable_preconditions(domain, True)
    unstack = relaxed_domain(domain, [SkillChange("unstack", Literal(Atom("clear", ("?x",))))]).action("unstack")
    assert Literal(Atom("clear", ("?x",))) not in unstack.precondition


def test_skill_changes_off_with_relax_prior_is_refused(tmp_path):
    robot, tower = _taught_blocks(tmp_path)
    result = CliRunner().invoke(app, ["excuse", str(robot), str(tower), "--skill-changes", "off", "--relax-prior"])
    assert result.exit_code == 37 and "--relax-prior: needs skill changes" in result.stderr


def test_between_a_state_change_and_a_skill_change_of_equal_cost_the_state_change_is_asked(tmp_path):
    learned = [("fill", ("?a",), [Atom("p", ("?a",))], [Atom("q", ("?a",))], [], True, set())]
    domain_text, problem_text = _pddl(learned, [], [Atom("q", ("o1",))])
    (tmp_path / "d.pddl").write_text(domain_text)
    (tmp_path / "p.pddl").write_text(problem_text)
    domain, problem = parse_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    excuse = find_excuses(domain, problem, ExcuseOptions(semantics="literal")).excuse
    assert [str(c) for c in excuse.changes] == ["+(p o1)"] and excuse.skill_changes == []
    # Two goals that each need the precondition: one skill change (it holds for every object) beats two states.
    (tmp_path / "p.pddl").write_text(_pddl(learned, [], [Atom("q", ("o1",)), Atom("q", ("o2",))])[1])
    domain, problem = parse_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    excuse = find_excuses(domain, problem, ExcuseOptions(semantics="literal")).excuse
    assert excuse.changes == [] and [str(c) for c in excuse.skill_changes] == ["-(p ?a) in fill"]


def test_an_empty_literal_in_an_evidence_comment_is_ignored(tmp_path):
    robot, tower = _taught_blocks(tmp_path)
    robot.write_text(robot.read_text().replace("(clear ?x) 1/1,", "() 1/1, (not ()) 1/1, (clear ?x) 1/1,"))
    domain, _ = parse_task(robot, tower)
    assert [str(e) for e in domain.action("unstack").evidence][:1] == ["(clear ?x) 1/1"]


def test_max_size_counts_the_skill_changes_with_costs_too(tmp_path):
    learned = [("fill", ("?a",), [Atom("p", ("?a",)), Atom("q", ("?a",))], [Atom("r", ("?a", "?a"))], [], True,
                set())]
    domain_text, problem_text = _pddl(learned, [], [Atom("r", ("o1", "o1")), Atom("r", ("o2", "o2"))])
    (tmp_path / "d.pddl").write_text(domain_text)
    (tmp_path / "p.pddl").write_text(problem_text)
    domain, problem = parse_task(tmp_path / "d.pddl", tmp_path / "p.pddl")
    for cap in (1, 2, 3):
        report = find_excuses(domain, problem, ExcuseOptions(semantics="literal", max_size=cap, costs=["q=5"]))
        assert report.excuse is None or report.excuse.size <= cap, (cap, report.excuse)


def test_the_excuse_problem_of_a_skill_excuse_says_the_robot_needs_the_precondition_dropped(tmp_path):
    robot, tower = _taught_blocks(tmp_path)
    out = tmp_path / "excused.pddl"
    result = CliRunner().invoke(app, ["excuse", str(robot), str(tower), "--excuse-problem", str(out)])
    assert result.exit_code == 0
    assert ";;   -(ontable ?y) in unstack" in out.read_text()
    assert "the robot plans from it only with -(ontable ?y) in unstack (the skill changes)" in result.stderr
