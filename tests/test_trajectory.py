"""Learning operators from PDDL trajectories (issue #31): the reader, the learner core, the CLI.

Fixtures in ``tests/data/trajectories/``: ``lights`` (no hand, an operator without arguments, parameters in
an unusual order), ``paint`` (what no step rules out; an object passed twice), ``levels`` (steps that
pass one object twice and tell each other which parameter changed), ``quarry`` (a blast clears whatever is in the
next cell, a relic too, which no step shows; a static grid), ``bad`` (one file per class of bad input) and
``blocksworld`` (AMLGym's own files, for a plan checked in the true domain).
"""

from __future__ import annotations

import pytest

from conftest import DATA, ROOT
from guided_lfd.demonstration.action_model import Observation, changes, learn_operators
from guided_lfd.demonstration.trajectory import is_trajectory, learn_from_trajectories, read_trajectory
from guided_lfd.errors import EXIT_BAD_OPTION, EXIT_PDDL_SEMANTIC, EXIT_PDDL_SYNTAX, PddlSemanticError
from guided_lfd.pddl.model import Atom, Literal
from guided_lfd.pddl.reader import parse_domain, parse_problem_for

TRAJ = DATA / "trajectories"
LIGHTS = TRAJ / "lights"
PAINT = TRAJ / "paint"
BLOCKS = TRAJ / "blocksworld"
QUARRY = TRAJ / "quarry"
LEVELS = TRAJ / "levels"


def _learned(folder, prior="prior.pddl", model="safe", files=None):
    domain = parse_domain(str(folder / prior))
    paths = files or sorted(folder.glob("*.traj"))
    trajectories = [read_trajectory(str(p), p.read_text(), domain) for p in paths]
    return learn_from_trajectories(domain, trajectories, model)


def _pre(action):
    return {str(l) for l in action.precondition}


def test_an_effect_on_an_atom_without_arguments_is_learned():
    """``breaker-on`` takes no arguments and makes ``(power)`` true: a change no object binds is still its effect."""
    action = _learned(LIGHTS).action("breaker-on")
    assert action.params == ()
    assert action.add == (Atom("power"),) and action.delete == ()


def test_operator_names_and_parameter_order_are_kept():
    """The prior says ``flip-up (?r - room ?s - switch)``: the learned action keeps its name, variables and order."""
    domain = _learned(LIGHTS)
    assert [a.name for a in domain.actions] == ["breaker-on", "flip-up", "flip-down"]
    assert domain.action("flip-up").params == (("?r", "room"), ("?s", "switch"))
    assert set(domain.action("flip-up").add) == {Atom("lit", ("?r",)), Atom("up", ("?s",))}


def test_a_precondition_one_step_contradicts_is_dropped_and_one_true_in_every_step_is_kept():
    """``flip-down`` ran once with the hall lit and once with its bulb out: ``(lit ?r)`` goes, ``(up ?s)`` and
    ``(wired ?s ?r)`` (true before both steps) stay, and the delete of ``(lit ?r)`` is still learned."""
    action = _learned(LIGHTS).action("flip-down")
    assert "(lit ?r)" not in _pre(action)
    assert {"(up ?s)", "(wired ?s ?r)"} <= _pre(action)
    assert set(action.delete) == {Atom("lit", ("?r",)), Atom("up", ("?s",))}


def test_nothing_outside_the_priors_vocabulary_is_added():
    """No hand facts of the kitchens' (``in_hand``, ``hand_free``), no new types or predicates."""
    prior = parse_domain(str(LIGHTS / "prior.pddl"))
    domain = _learned(LIGHTS)
    assert domain.predicates == prior.predicates and domain.types == prior.types
    used = {l.atom.predicate for a in domain.actions for l in a.precondition} | {
        x.predicate for a in domain.actions for x in (*a.add, *a.delete)}
    assert used <= set(prior.predicates)


def test_what_no_step_rules_out_stays_a_condition_in_the_safe_model_only():
    """No step paints a wet board.  The safe model may not assume painting leaves ``wet`` alone or works on a
    wet board: it requires ``(not (wet ?b))`` (as SAM writes it, adding ``:negative-preconditions`` to a STRIPS
    prior's requirements).  Making ``(red ?b)`` true needs no guard unless the prior allows negative
    preconditions (the true domain may then require it false first).  The general model has no guard."""
    strips = _learned(PAINT).action("paint")
    assert Literal(Atom("wet", ("?b",)), False) in strips.precondition
    assert Literal(Atom("red", ("?b",)), False) not in strips.precondition
    assert ":negative-preconditions" in _learned(PAINT).requirements
    negative = _learned(PAINT, "prior-negative.pddl").action("paint")
    assert {Literal(Atom("wet", ("?b",)), False), Literal(Atom("red", ("?b",)), False)} <= set(negative.precondition)
    general = _learned(PAINT, model="general")
    assert general.action("paint").precondition == () and ":negative-preconditions" not in general.requirements


def test_the_safe_model_learns_from_a_step_passing_one_object_twice_where_no_change_is_ambiguous():
    """``(carry b2 yard yard)`` changes nothing, so no change can be about the wrong parameter: the safe model
    learns from it too, and it shows that carrying needs no shop at ``?to`` (the yard is none)."""
    domain = _learned(PAINT)
    carry = domain.action("carry")
    assert carry.origin == "learned from 2 observed step(s)"
    assert "(shop ?to)" not in _pre(carry) and "(at ?b ?from)" in _pre(carry)
    assert not any("passing one object twice" in w for w in domain.warnings)


def test_steps_passing_one_level_twice_tell_each_other_which_parameter_changed():
    """TPP's load: every step passes one level twice, in two different ways; each step rules out the other's
    wrong reading (the level that is not true after it), so the safe model learns the true action."""
    domain = _learned(LEVELS)
    lift, true = domain.action("lift"), parse_domain(str(LEVELS / "true.pddl")).action("lift")
    assert set(lift.precondition) == set(true.precondition)
    assert set(lift.add) == set(true.add) and set(lift.delete) == set(true.delete)
    assert not any("passing one object twice" in w for w in domain.warnings)


def test_a_step_whose_change_no_other_step_resolves_is_left_out_with_a_note():
    """Alone, ``(lift g1 l0 l1 l0 l1)`` cannot tell whether the goods' new level is ``?high`` or ``?dhigh``:
    SAM's rule, the step is left out (the general model learns from it)."""
    domain = _learned(LEVELS, files=[LEVELS / "1-swap.traj"])
    assert (domain.action("lift").add, domain.action("lift").delete) == ((), ())  # as if never observed
    assert any("1 step(s) passing one object twice (or a constant) left out: the other steps do not tell"
               in w for w in domain.warnings)
    assert _learned(LEVELS, model="general", files=[LEVELS / "1-swap.traj"]).action("lift").add


def test_moving_from_a_place_to_itself_does_not_hide_the_delete():
    """``(carry b2 yard yard)`` leaves b2 in the yard (PDDL deletes, then adds): still ``(not (at ?b ?from))``."""
    action = _learned(PAINT, model="general").action("carry")
    assert action.delete == (Atom("at", ("?b", "?from")),)
    assert action.add == (Atom("at", ("?b", "?to")),)
    assert _pre(action) == {"(at ?b ?from)"}


def test_an_operator_never_observed_requires_every_literal_so_it_never_applies():
    """SAM's most specific model: every well-typed literal over its parameters, positive and negative, and no
    effect; a note says so.  A plan naming it still reads, and no plan uses it."""
    domain = _learned(LIGHTS, files=[LIGHTS / "day-2.traj"])
    action = domain.action("breaker-on")
    assert (action.add, action.delete) == ((), ())
    positives = {l.atom for l in action.precondition if l.positive}
    assert positives and positives == {l.atom for l in action.precondition if not l.positive}
    assert any("breaker-on: never observed" in w and "never applies" in w for w in domain.warnings)


def test_changes_bind_atoms_without_arguments_and_only_the_actions_objects():
    before = frozenset({Atom("power"), Atom("at", ("b", "x"))})
    after = frozenset({Atom("at", ("b", "y")), Atom("lit", ("z",))})
    added, deleted = changes(before, after, {"b", "y", "x"})
    assert added == {Atom("at", ("b", "y"))} and deleted == {Atom("power"), Atom("at", ("b", "x"))}


def test_the_safe_model_only_plans_what_the_true_domain_accepts():
    """AMLGym's blocksworld, 3 trajectories: the learned safe model's plan for a larger problem (8 blocks)
    is valid in the true domain."""
    from guided_lfd.api import plan, validate

    learned = _learned(BLOCKS, files=sorted(BLOCKS.glob("*.traj")))
    true = parse_domain(str(BLOCKS / "true.pddl"))
    report = plan(learned, parse_problem_for(learned, BLOCKS / "problem.pddl"), search="gbfs-hff")
    assert report.plan, "the learned model should solve the problem"
    steps = [f"({s.action} {' '.join(s.args)})" for s in report.plan]
    assert validate(true, parse_problem_for(true, BLOCKS / "problem.pddl"), steps).valid


def test_a_trajectory_is_told_from_a_segments_document_by_content():
    assert is_trajectory("; comment\n\n(:trajectory (:state))")
    assert not is_trajectory('{"format": "guided-lfd/segments"}')


def test_object_types_come_from_the_problem_where_given():
    prior = parse_domain(str(LIGHTS / "prior.pddl"))
    path = LIGHTS / "day-1.traj"
    objects = parse_problem_for(prior, LIGHTS / "problem.pddl").objects
    with pytest.raises(PddlSemanticError, match="object 's1' is not declared in the problem"):
        read_trajectory(str(path), path.read_text(), prior, objects)


def test_observations_of_unknown_operators_are_ignored_by_the_core():
    prior = parse_domain(str(LIGHTS / "prior.pddl"))
    step = Observation("dance", (), frozenset(), frozenset({Atom("power")}))
    domain, notes = learn_operators(prior, [step], {}, "safe")
    assert "dance" not in [a.name for a in domain.actions] and len(notes) == 3
    assert all(not a.add and not a.delete for a in domain.actions)  # the prior's operators, none observed


BAD = [
    ("unbalanced.traj", EXIT_PDDL_SYNTAX, ":1:1: syntax error: '(' is never closed"),
    ("arity.traj", EXIT_PDDL_SEMANTIC, ":3:13: semantic error: 'flip-up' takes 2 argument(s)"),
    ("undeclared.traj", EXIT_PDDL_SEMANTIC, ":4:44: semantic error: predicate 'bright' is not declared"),
    ("ends-with-action.traj", EXIT_PDDL_SYNTAX, ":3:13: syntax error: the trajectory ends with an action"),
    ("nested.traj", EXIT_PDDL_SYNTAX, ":4:18: syntax error: nested list in an atom"),
    ("two-states.traj", EXIT_PDDL_SYNTAX, ":5:3: syntax error: two states without an action between them"),
    ("negated.traj", EXIT_PDDL_SYNTAX, ":4:12: syntax error: 'not' in a state, expected only the atoms that are true"),
    ("type-clash.traj", EXIT_PDDL_SEMANTIC, ":4:39: semantic error: object 'hall' is used as a room and here as a"),
]


@pytest.mark.parametrize("name, code, message", BAD, ids=[b[0] for b in BAD])
def test_bad_trajectories_get_a_one_line_error_at_their_place(runner, app, name, code, message):
    path = TRAJ / "bad" / name
    result = runner.invoke(app, ["learn-domain", "--prior", str(LIGHTS / "prior.pddl"), str(path)])
    assert result.exit_code == code, result.output
    assert f"{path}{message}" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 and "Traceback" not in result.stderr


def test_a_type_clash_between_two_trajectory_files_names_both_places(runner, app):
    """It named the second file alone, no line."""
    path = TRAJ / "bad" / "type-clash-with-day-1.traj"
    result = runner.invoke(app, ["learn-domain", "--prior", str(LIGHTS / "prior.pddl"), str(LIGHTS / "day-1.traj"),
                                 str(path)])
    assert result.exit_code == EXIT_PDDL_SEMANTIC, result.output
    assert result.stderr == (f"{path}:4:26: semantic error: object 'hall' is a switch here and a room in an earlier "
                             f"trajectory ({LIGHTS / 'day-1.traj'}:3:21); expected one type\n")


def test_cli_learns_from_trajectories_with_the_model_asked_for(runner, app, tmp_path):
    out = tmp_path / "learned.pddl"
    result = runner.invoke(app, ["learn-domain", "--prior", str(PAINT / "prior.pddl"), str(PAINT / "week.traj"),
                                 "--model", "general", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "3 operator(s) learned from 4 step(s) of 1 trajectory(ies), general model" in result.stderr
    learned = parse_domain(str(out))
    assert learned.action("paint").delete == ()


def test_a_prior_with_an_adl_action_keeps_it_and_learns_its_empty_operators(runner, app, tmp_path):
    """The translator's parser drops an action without effects (and, with no options set, fails on one): the
    ADL prior's empty operators were lost or the prior refused (31, a Fast Downward internal message)."""
    out = tmp_path / "learned.pddl"
    result = runner.invoke(app, ["learn-domain", "--prior", str(LIGHTS / "prior-adl.pddl"), str(LIGHTS / "day-1.traj"),
                                 str(LIGHTS / "day-2.traj"), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "3 operator(s) learned from 6 step(s) of 2 trajectory(ies), safe model" in result.stderr
    prior, learned = parse_domain(str(LIGHTS / "prior-adl.pddl")), parse_domain(str(out))
    assert [a.name for a in prior.actions] == ["breaker-on", "flip-up", "flip-down", "all-off"]
    assert learned.action("all-off") == prior.action("all-off")
    assert learned.action("flip-up").add == _learned(LIGHTS).action("flip-up").add


@pytest.mark.parametrize("args, message", [
    (["TRAJ"], "is a trajectory: expected --prior DOMAIN"),
    (["--prior", "PRIOR", "TRAJ", "SEGMENTS"], "holds segments and"),
    (["--prior", "PRIOR", "TRAJ", "--model", "bold"], "--model 'bold': expected one of safe, general"),
    (["--prior", "PRIOR", "TRAJ", "--human", "PRIOR"], "--human is for segments"),
    (["SEGMENTS", "--model", "general"], "--model is for trajectories"),
])
def test_options_that_do_not_fit_the_input_are_refused(runner, app, args, message):
    names = {"TRAJ": str(LIGHTS / "day-1.traj"), "PRIOR": str(LIGHTS / "prior.pddl"),
             "SEGMENTS": str(ROOT / "results" / "study" / "kitchen-1" / "P3-complete.segments.json")}
    argv = ["learn-domain", *(names.get(a, a) for a in args)]
    result = runner.invoke(app, argv)
    assert result.exit_code == EXIT_BAD_OPTION, result.output
    assert message in result.stderr


def test_the_python_example_in_the_docs_runs():
    import re

    from conftest import fresh_interpreter

    blocks = re.findall(r"```python\n(.*?)```", (ROOT / "docs" / "python.md").read_text(), re.S)
    out = fresh_interpreter(blocks[1])
    assert out.splitlines() == ["(('?r', 'room'), ('?s', 'switch'))", "3"]


DOOR = TRAJ / "door"


def test_atoms_about_the_priors_constants_are_learned_as_such():
    """``walk`` needs the main door open: ``(open main)``, a constant, not ``(open ?r)``; the step that walks
    into ``main`` (a constant passed as an argument: ``(in main)`` is ``(in ?r)`` or an atom of the constant)
    is learned from, the other step telling which.  The plan for a problem whose door is shut is no plan (the
    true domain has none either)."""
    domain = _learned(DOOR)
    walk = domain.action("walk")
    assert "(open main)" in _pre(walk) and "(open ?r)" not in _pre(walk)
    assert walk.add == (Atom("in", ("?r",)),) and walk.origin == "learned from 2 observed step(s)"
    assert domain.action("close-main").delete == (Atom("open", ("main",)),)


def test_an_action_with_only_a_cost_is_learned_and_keeps_its_cost(tmp_path):
    text = (LIGHTS / "prior.pddl").read_text().replace(":requirements :strips :typing",
                                                         ":requirements :strips :typing :action-costs")
    text = text.replace("(:action breaker-on :parameters () :precondition (and) :effect (and))",
                        "(:functions (total-cost) - number)\n  (:action breaker-on :parameters () :precondition (and)"
                        " :effect (increase (total-cost) 5))")
    (tmp_path / "prior.pddl").write_text(text)
    for p in LIGHTS.glob("*.traj"):
        (tmp_path / p.name).write_text(p.read_text())
    action = _learned(tmp_path).action("breaker-on")
    assert action.add == (Atom("power"),) and action.cost == 5


def test_a_prior_with_nothing_to_learn_says_so():
    domain = _learned(LIGHTS, prior="true.pddl")
    assert any("every action of" in w and "has a body: nothing to learn" in w for w in domain.warnings)


def test_too_many_lifted_atoms_for_an_operator_is_refused(runner, app, tmp_path):
    params = " ".join(f"?v{i}" for i in range(8))
    (tmp_path / "big.pddl").write_text(f"(define (domain big) (:requirements :strips) (:predicates (r {params}))"
                                       f" (:action go :parameters ({params}) :precondition (and) :effect (and)))")
    objs = " ".join(f"o{i}" for i in range(8))
    (tmp_path / "t.traj").write_text(f"(:trajectory (:state) (:action (go {objs})) (:state (r {objs})))")
    result = runner.invoke(app, ["learn-domain", "--prior", str(tmp_path / "big.pddl"), str(tmp_path / "t.traj")])
    assert result.exit_code == 21 and "lifted atoms over its parameters" in result.stderr


def test_declared_types_must_fit_every_use(runner, app, tmp_path):
    (tmp_path / "p.pddl").write_text("(define (problem a) (:domain lights) (:objects hall kitchen - switch "
                                     "s1 s2 - room) (:init) (:goal (power)))")
    result = runner.invoke(app, ["learn-domain", "--prior", str(LIGHTS / "prior.pddl"), "--problem",
                                 str(tmp_path / "p.pddl"), str(LIGHTS / "day-1.traj")])
    assert result.exit_code == EXIT_PDDL_SEMANTIC and "object 's1' is a room, used here as a switch" in result.stderr
    (tmp_path / "a.traj").write_text("(:trajectory (:state (power) (wired x y)) (:action (flip-up y x)) "
                                     "(:state (power) (wired x y) (up x) (lit y)))")
    (tmp_path / "b.traj").write_text("(:trajectory (:state (power) (wired y x)) (:action (flip-up x y)) "
                                     "(:state (power) (wired y x) (up y) (lit x)))")
    result = runner.invoke(app, ["learn-domain", "--prior", str(LIGHTS / "prior.pddl"), str(tmp_path / "a.traj"),
                                 str(tmp_path / "b.traj")])
    assert result.exit_code == EXIT_PDDL_SEMANTIC
    assert f"b.traj:1:37: semantic error: object 'y' is a switch here and a room in an earlier trajectory " \
           f"({tmp_path / 'a.traj'}:1:39); expected one type" in result.stderr


def test_the_learned_domain_keeps_the_priors_name_unless_named(runner, app):
    args = ["learn-domain", "--prior", str(LIGHTS / "prior.pddl"), str(LIGHTS / "day-1.traj")]
    assert "(define (domain lights)" in runner.invoke(app, args).stdout
    assert "(define (domain learned)" in runner.invoke(app, [*args, "--name", "learned"]).stdout


def test_types_inferred_in_two_trajectories_combine_to_the_narrower(tmp_path):
    """A shot is only a container in one trajectory (used where any container goes) and a shot in the next."""
    (tmp_path / "prior.pddl").write_text(
        "(define (domain bar) (:requirements :strips :typing) (:types container - object shot - container)"
        " (:predicates (clean ?c - container) (filled ?s - shot))"
        " (:action wash :parameters (?c - container) :precondition (and) :effect (and))"
        " (:action fill :parameters (?s - shot) :precondition (and) :effect (and)))")
    (tmp_path / "a.traj").write_text("(:trajectory (:state) (:action (wash s1)) (:state (clean s1)))")
    (tmp_path / "b.traj").write_text("(:trajectory (:state (clean s1)) (:action (fill s1)) (:state (clean s1) (filled s1)))")
    prior = parse_domain(str(tmp_path / "prior.pddl"))
    trajectories = [read_trajectory(str(p), p.read_text(), prior) for p in sorted(tmp_path.glob("*.traj"))]
    assert trajectories[0].objects == {"s1": "container"} and trajectories[1].objects == {"s1": "shot"}
    domain = learn_from_trajectories(prior, trajectories)
    assert domain.action("fill").add == (Atom("filled", ("?s",)),)


def _neg(action):
    return {str(l.atom) for l in action.precondition if not l.positive}


def test_the_general_model_guards_what_a_clearing_action_may_also_clear():
    """Blasting deleted rubble in one step and a boulder in another, each absent in the other step: the blast
    clears whatever is in the next cell, so the general model guards it against the facts about that cell no
    step showed there (the relic).  Flying, whose delete held before every step, gets no guard."""
    domain = _learned(QUARRY, model="general")
    assert "(relic ?to)" in _neg(domain.action("blast"))
    assert _neg(domain.action("fly")) == set() and _neg(domain.action("collect")) == set()
    assert ":negative-preconditions" in domain.requirements


@pytest.mark.parametrize("model", ["safe", "general"])
def test_a_learned_model_makes_no_false_plan_where_a_blast_would_destroy_the_relic(model):
    """Relic under rubble: unsolvable in the true domain, so the learned models find no plan (without the guard
    the general model would blast, fly and collect a relic the blast destroyed).  Relic behind rubble: the
    learned model's plan is valid in the true domain."""
    from guided_lfd.api import plan, validate

    learned = _learned(QUARRY, model=model)
    true = parse_domain(str(QUARRY / "true.pddl"))
    assert plan(learned, parse_problem_for(learned, QUARRY / "relic-under-rubble.pddl")).plan is None
    problem = QUARRY / "relic-behind-rubble.pddl"
    report = plan(learned, parse_problem_for(learned, problem))
    steps = [f"({s.action} {' '.join(s.args)})" for s in report.plan]
    assert validate(true, parse_problem_for(true, problem), steps).valid


def test_guards_on_static_facts_no_world_allows_are_left_out_with_a_note():
    """``next`` never changes, and no cell is next to itself in the trajectory's world: ``(not (next ?to ?to))``
    guards nothing and is left out of the safe model, with a note.  A hazard lies next to a cell the drone
    flies from, so ``(not (hazard ?to))`` stays: no step says what flying into a hazard does."""
    domain = _learned(QUARRY)
    fly = _neg(domain.action("fly"))
    assert not {"(next ?to ?to)", "(next ?from ?from)"} & fly
    assert "(hazard ?to)" in fly
    assert any("guard(s) on static facts left out" in w for w in domain.warnings)


def test_one_place_at_a_time_needs_no_guard_on_distinct_objects():
    """The drone is at one cell (Fast Downward's invariant, true in every observed state): blasting from
    ``?from`` into another cell ``?to`` needs no ``(not (drone-at ?to))`` in the safe model (actions on distinct
    objects), though no step blasted the drone's own cell."""
    assert "(drone-at ?to)" not in _neg(_learned(QUARRY).action("blast"))
