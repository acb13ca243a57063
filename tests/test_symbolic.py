"""The symbolic engine: diagram libraries, encoding, reachability, nearest members, unsolvability proofs.

The excuse strategy itself is covered with every other registered strategy
against brute force (tests/test_excuse_engine.py)."""

from __future__ import annotations

import importlib.util
import itertools
import random
import subprocess
import time
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings

from conftest import BLOCKS, kitchen
from test_excuse_engine import _parse_random, small_tasks
from guided_lfd.planning.grounding import ground
from guided_lfd.planning.task import bits
from guided_lfd.planning.search import astar, planning_actions
from guided_lfd.pddl.reader import parse_task
from guided_lfd.symbolic.diagrams import open_diagrams
from guided_lfd.symbolic.encoding import SymbolicTask, variable_order
from guided_lfd.symbolic.nearest import nearest
from guided_lfd.symbolic.reach import backward_layers, plan_from, prove_unsolvable
from guided_lfd.symbolic.unsolvable import decide, symbolic_task

LIBRARIES = ["cudd"] + (["oxidd"] if importlib.util.find_spec("oxidd") else [])
ROOT = Path(__file__).resolve().parent.parent


def _random_function(dd, rng: random.Random, n: int):
    f = dd.false
    for _ in range(4):
        cube = dd.cube({v: rng.random() < 0.5 for v in rng.sample(range(n), 3)})
        f = f | cube if rng.random() < 0.7 else f & ~cube
    return f


def _member(dd, f, state: int) -> bool:
    return (f & dd.cube({v: bool(state >> v & 1) for v in range(6)})) != dd.false


@pytest.mark.parametrize("library", LIBRARIES)
def test_walking_a_diagram_from_its_root_agrees_with_the_library(library):
    """top() gives the cofactors of complemented roots too (dd.cudd hands out the regular node's children)."""
    dd = open_diagrams(6, library)
    rng = random.Random(1)
    for _ in range(100):
        f = _random_function(dd, rng, 6)
        for state in range(64):
            g, node = f, dd.top(f)
            while node is not None:
                level, high, low = node
                g = high if state >> level & 1 else low
                node = dd.top(g)
            assert (g == dd.true) == _member(dd, f, state)


@pytest.mark.parametrize("library", LIBRARIES)
def test_nearest_members_come_by_weighted_distance_and_skip_supersets(library):
    dd = open_diagrams(6, library)
    rng = random.Random(2)
    atoms = list(range(6))
    for _ in range(60):
        f = _random_function(dd, rng, 6)
        origin = rng.randrange(64)
        weights = {i: rng.randint(1, 4) for i in atoms}
        got = list(nearest(dd, f, atoms, weights, origin))
        members = [s for s in range(64) if _member(dd, f, s)]
        distance = {s ^ origin: sum(weights[i] for i in bits(s ^ origin)) for s in members}
        if not members:
            assert got == []
            continue
        assert [w for w, _ in got] == sorted(w for w, _ in got)
        assert got[0][0] == min(distance.values())
        assert all(distance[c] == w for w, c in got)
        # Every member is one yielded or one with changes added to one yielded.
        yielded = {c for _, c in got}
        assert all(any(c & y == y for y in yielded) for c in distance)


def test_at_most_one_and_exactly_one():
    domain, problem = parse_task(*kitchen(1))
    task = ground(domain, problem)
    sym = SymbolicTask(task, range(4), [])
    mask = 0b1111
    for exactly in (False, True):
        f = sym.at_most_one(mask, exactly)
        for state in range(16):
            ones = state.bit_count()
            assert sym.contains(f, state) == (ones == 1 if exactly else ones <= 1)


def test_variable_order_keeps_groups_together_and_starts_at_the_goal():
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task03.pddl")
    task = ground(domain, problem)
    goal = list(bits(task.goal_pos))
    group = sum(1 << i for i in range(len(task.atoms)) if task.atoms[i].predicate == "holding")
    order = variable_order(range(len(task.atoms)), task.actions, first=goal, groups=[group])
    assert sorted(order) == list(range(len(task.atoms)))
    assert order[0] == goal[0]
    places = sorted(order.index(i) for i in bits(group))
    assert places == list(range(places[0], places[0] + len(places)))


def _decide_and_search(domain, problem):
    task = ground(domain, problem, fixed=domain.predicates)
    actions = planning_actions(task, task.init)
    proof = decide(task, actions)
    plan = astar(actions, task.init, task.goal_pos, task.goal_neg)
    return task, actions, proof, plan


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(pddl=small_tasks())
def test_symbolic_decision_agrees_with_astar(tmp_path_factory, pddl):
    domain, problem = _parse_random(tmp_path_factory, "sym", pddl)
    task, actions, proof, plan = _decide_and_search(domain, problem)
    assert proof.solvable == (plan is not None)
    sym = symbolic_task(task, actions, [])
    layers = backward_layers(sym)
    steps = plan_from(sym, layers, task.init)
    assert (steps is None) == (plan is None)
    if steps is not None:  # a shortest plan in steps, and a plan
        state = task.init
        for act in steps:
            assert act.applicable(state)
            state = act.apply(state)
        assert task.satisfies_goal(state)
        assert len(steps) == len(plan) or any(a.cost != 1 for a in actions)


@pytest.mark.parametrize("name", ["bottleneck/prob01.pddl", "chessboard-pebbling/prob03.pddl", "pegsol/prob05.pddl"])
def test_ipc_unsolvability_tasks_are_proven_unsolvable(name):
    track = ROOT / "data" / "benchmarks" / "unsolvability-ipc2016"
    problem = track / name
    domain = problem.parent / "domain.pddl"
    task = ground(*parse_task(domain, problem), fixed=parse_task(domain, problem)[0].predicates)
    proof = decide(task, planning_actions(task, task.init))
    assert not proof.solvable


def test_blocks_are_solvable_both_ways():
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task03.pddl")
    _, _, proof, plan = _decide_and_search(domain, problem)
    assert proof.solvable and plan is not None


def test_an_excuse_run_of_kitchen_1_never_loads_the_diagram_library():
    code = ("import sys; from guided_lfd import read_task, find_excuses; "
            f"d, p = read_task({str(kitchen(1)[0])!r}, {str(kitchen(1)[1])!r}); "
            "r = find_excuses(d, p); assert r.excuse is not None; "
            "print(sorted(m for m in sys.modules if m == 'dd' or m.startswith(('dd.', 'oxidd'))))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    assert out.stdout.strip() == "[]"


def test_a_diagram_library_out_of_memory_is_a_memout():
    from guided_lfd.symbolic.diagrams import memory_as_memout

    with pytest.raises(MemoryError):
        with memory_as_memout():
            raise ValueError("`DdNode *node` is `NULL` pointer.")
    with pytest.raises(ValueError, match="other"):
        with memory_as_memout():
            raise ValueError("other")


def test_the_symbolic_strategy_out_of_memory_ends_as_a_memout(monkeypatch):
    """A cap far below what the search needs: CUDD fails, and the run says memout (exit 22), no traceback."""
    from guided_lfd.errors import EXIT_MEMORY
    from typer.testing import CliRunner
    from cli.main import app
    from guided_lfd.symbolic import diagrams

    monkeypatch.setattr(diagrams, "_memory_cap", lambda: 1)
    monkeypatch.setattr(diagrams.CuddDiagrams, "__init__", _tiny_cudd(diagrams.CuddDiagrams.__init__))
    domain, problem = BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl"
    out = CliRunner().invoke(app, ["excuse", str(domain), str(problem), "--strategy", "symbolic"])
    assert out.exit_code == EXIT_MEMORY, out.output


def _tiny_cudd(init):
    def tiny(self, variables, memory):
        init(self, variables, memory)
        self.bdd.configure(max_memory=1)  # every new node fails

    return tiny


def _held_in_c(space, limits):
    """A symbolic search stuck in one long C call: it never looks at its deadline."""
    time.sleep(30)


def test_the_symbolic_strategy_ends_at_its_deadline_even_inside_a_long_call(monkeypatch):
    from guided_lfd.excuse import symbolic as symbolic_strategy
    from guided_lfd.excuse.prepare import prepare
    from guided_lfd.excuse.space import Semantics
    from guided_lfd.excuse.status import ExcuseStatus
    from guided_lfd.excuse.strategies import STRATEGIES
    from guided_lfd.excuse.outcome import SearchLimits

    monkeypatch.setattr(symbolic_strategy, "symbolic_outcome", _held_in_c)
    space = prepare(*parse_task(BLOCKS / "domain-no-unstack.pddl", BLOCKS / "task03.pddl"), Semantics.LITERAL).space
    began = time.monotonic()
    outcome = STRATEGIES["symbolic"].search(space, SearchLimits(deadline=time.monotonic() + 0.5))
    assert outcome.status is ExcuseStatus.TIMEOUT
    assert time.monotonic() - began < 25  # the 30 s call was not waited for


@pytest.mark.parametrize("strategy", ["symbolic", "portfolio", "landmark"])
def test_a_group_no_variable_touches_keeps_its_initial_atoms(strategy):
    """o2's place matters to no goal: its exactly-one group has no variable, and must not empty the excuse
    states (it did: 'no excuse exists' under the consistent semantics)."""
    from guided_lfd.excuse.engine import ExcuseOptions, find_excuses

    data = ROOT / "tests" / "data" / "symbolic"
    report = find_excuses(*parse_task(data / "domain.pddl", data / "problem.pddl"),
                          ExcuseOptions(semantics="consistent", strategy=strategy, all_minimal=True))
    assert [[str(c) for c in e.changes] for e in report.excuses] == [["+(road l1 l2)"]]


def test_the_excuse_variables_leave_out_atoms_no_minimal_excuse_changes(tmp_path):
    """Depot with type predicates grounds (lifting crate0 crate1) and the like: false, read by no action, in
    at-most-one groups only through a crate.  They stay out; what a group's repair may need stays in."""
    from guided_lfd.excuse.engine import ExcuseOptions
    from guided_lfd.excuse.prepare import prepare
    from guided_lfd.excuse.space import Semantics
    from guided_lfd.excuse.symbolic import excuse_atoms

    depot = ROOT / "data" / "benchmarks" / "ipc" / "depot"
    text = (depot / "domain.pddl").read_text()
    start = text.index("(:action lift")
    (tmp_path / "domain.pddl").write_text(text[:start] + text[text.index("(:action", start + 1):])
    domain, problem = parse_task(tmp_path / "domain.pddl", depot / "task01.pddl")
    full = parse_task(depot / "domain.pddl", depot / "task01.pddl")[0]
    fixed = ExcuseOptions(fixed_from=full).fixed_predicates(domain)
    space = prepare(domain, problem, Semantics.CONSISTENT, fixed).space
    atoms = excuse_atoms(space)
    assert set(bits(space.relevant_atoms)) <= atoms
    for group in space.groups:
        if any(group.mask >> i & 1 for i in atoms):
            assert set(bits(group.mask if group.exactly_one else group.mask & space.task.init)) <= atoms
    names = {str(space.task.atoms[i]) for i in atoms}
    assert "(lifting hoist0 crate0)" in names and "(available crate0)" not in names
    assert len(atoms) < space.changeable.bit_count() / 2


def _miconic_without_up(task: str):
    from dataclasses import replace

    miconic = ROOT / "data" / "benchmarks" / "ipc" / "miconic"
    full, problem = parse_task(miconic / "domain.pddl", miconic / f"{task}.pddl")
    return full, replace(full, actions=[a for a in full.actions if a.name != "up"]), problem


@pytest.mark.parametrize("budget", [50_000, 1])
def test_under_the_consistent_semantics_the_backward_search_stays_inside_the_invariants(monkeypatch, budget):
    """The groups are inductive, so R's states that keep them are reached without leaving them (miconic
    without up: no state with the lift at two floors is ever built); groups beyond the diagram budget are
    applied afterwards.  Either way the answer is the landmark search's."""
    from guided_lfd.excuse import symbolic
    from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
    from guided_lfd.excuse.prepare import prepare
    from guided_lfd.excuse.space import Semantics

    monkeypatch.setattr(symbolic, "CONSTRAINT_NODES", budget)
    full, domain, problem = _miconic_without_up("task03")
    space = prepare(domain, problem, Semantics.CONSISTENT, fixed=["above", "destin", "origin"]).space
    run = symbolic.SymbolicRun(space, None)
    states = run.excuse_states()
    dd = run.sym.dd
    inside = run.sym.invariants([(g.mask, g.exactly_one) for g in space.groups])
    assert space.groups and states != dd.false and states & ~inside == dd.false
    assert (run.layers.reached & ~inside == dd.false) == (budget > 1)
    answers = [find_excuses(domain, problem, ExcuseOptions(semantics="consistent", strategy=s, fixed_from=full))
               for s in ("symbolic", "landmark")]
    assert answers[0].excuse.cost == answers[1].excuse.cost


@pytest.mark.parametrize("model", ["model-moves", "model-static"])
def test_groups_of_another_domain_the_robot_breaks_are_no_bound_on_its_backward_search(model):
    """The robot teleports without leaving (a thing at two places on its way); the invariants come from a
    model where things move, or never move (one place).  The robot's own plan breaks them, so the backward
    search may not stay inside them: the one-change excuse +(flag), not three changes."""
    from guided_lfd.excuse.engine import ExcuseOptions, find_excuses
    from guided_lfd.pddl.reader import parse_domain

    data = ROOT / "tests" / "data" / "borrowed-invariants"
    domain, problem = parse_task(data / "robot.pddl", data / "problem.pddl")
    opts = ExcuseOptions(semantics="consistent", strategy="symbolic", invariants_from=parse_domain(data / f"{model}.pddl"))
    report = find_excuses(domain, problem, opts)
    assert report.invariant_groups
    assert [[str(c) for c in e.changes] for e in report.excuses] == [["+(flag)"]]


def test_an_action_keeps_a_group_when_its_precondition_says_which_atom_was_true():
    from guided_lfd.excuse.symbolic import keeps_group
    from guided_lfd.planning.task import GroundAction

    group = 0b111  # atoms 0, 1, 2: at most one true

    def act(pre=0, neg=0, add=0, delete=0):
        return GroundAction("a", "a", (), pre, neg, add, delete)

    assert keeps_group(act(pre=0b001, add=0b010, delete=0b001), group, True)  # move: 0 -> 1
    assert keeps_group(act(pre=0b010, add=0b010), group, False)  # adds what holds already
    assert keeps_group(act(neg=0b100, add=0b010, delete=0b001), group, False)  # every other atom ends false
    assert not keeps_group(act(pre=0b001, add=0b010), group, False)  # 0 stays true beside 1
    assert not keeps_group(act(add=0b010), group, False)  # teleport: which atom held is unknown
    assert not keeps_group(act(add=0b110), group, False)  # two at once
    assert keeps_group(act(pre=0b001, delete=0b001), group, False)  # at most one: none is fine
    assert not keeps_group(act(pre=0b001, delete=0b001), group, True)  # exactly one: not replaced
    assert keeps_group(act(pre=0b1000, add=0b1000), group, True)  # touches no atom of the group
    assert keeps_group(act(pre=0b011, add=0b110, delete=0b001), group, True)  # needs two: never applies
