"""The delete-relaxation core (guided_lfd.planning.relaxation) against brute force, and the successor index."""

from __future__ import annotations

import heapq

from hypothesis import given, settings
from hypothesis import strategies as st

from guided_lfd.planning.relaxation import INF, RelaxedTask, close, hmax, index_facts
from guided_lfd.planning.successors import SuccessorIndex
from guided_lfd.planning.task import GroundAction


@st.composite
def tables(draw):
    """A relaxed table: facts 0..n-1, actions with non-empty preconditions, adds and costs, and seeded facts."""
    n = draw(st.integers(1, 8))
    facts = st.integers(0, n - 1)
    pre = draw(st.lists(st.lists(facts, min_size=1, max_size=3, unique=True), max_size=10))
    add = [draw(st.lists(facts, max_size=3, unique=True)) for _ in pre]
    cost = [draw(st.integers(0, 3)) for _ in pre]
    seeds = draw(st.lists(st.tuples(st.integers(0, 4), facts), min_size=1, max_size=5))
    return n, pre, add, cost, seeds


def naive_hmax(n, pre, add, cost, seeds):
    """h^max by iterating to the fixpoint (Bellman-Ford style)."""
    h = [INF] * n
    for value, f in seeds:
        h[f] = min(h[f], value)
    changed = True
    while changed:
        changed = False
        for p, a, c in zip(pre, add, cost):
            reach = max(h[f] for f in p) + c
            for q in a:
                if reach < h[q]:
                    h[q], changed = reach, True
    return h


@settings(max_examples=400, deadline=None)
@given(tables(), st.booleans())
def test_hmax_is_the_fixpoint_and_each_choice_a_maximal_precondition(table, ordered):
    n, pre, add, cost, seeds = table
    h, pcf = hmax(seeds, n, index_facts(n, pre, add)[0], add, [len(p) for p in pre], cost, ordered=ordered)
    assert h == naive_hmax(n, pre, add, cost, seeds)
    for ai, p in enumerate(pre):
        if max(h[f] for f in p) == INF:
            assert pcf[ai] == -1
        else:
            assert pcf[ai] in p and h[pcf[ai]] == max(h[f] for f in p)


@settings(max_examples=400, deadline=None)
@given(tables(), st.data())
def test_the_closure_reaches_what_zero_cost_hmax_reaches_and_stops_at_the_goal(table, data):
    n, pre, add, _, seeds = table
    start = sorted({f for _, f in seeds})
    everything = naive_hmax(n, pre, add, [0] * len(pre), [(0, f) for f in start])
    reached = bytearray(n)
    order, _ = close(start, reached, [len(p) for p in pre], index_facts(n, pre, add)[0], add)
    assert {f for f in range(n) if reached[f]} == {f for f in range(n) if everything[f] == 0} == set(order)
    goal = set(data.draw(st.lists(st.integers(0, n - 1), min_size=1, max_size=3, unique=True)))
    _, left = close(start, bytearray(n), [len(p) for p in pre], index_facts(n, pre, add)[0], add, goal, len(goal))
    assert (left == 0) == all(everything[g] == 0 for g in goal)


@st.composite
def ground_tasks(draw):
    """A small ground task over at most 6 atoms: (actions, initial state, goal atoms)."""
    n = draw(st.integers(1, 6))
    masks = st.integers(0, (1 << n) - 1)
    actions = []
    for k in range(draw(st.integers(1, 8))):
        pre_pos, pre_neg = draw(masks), draw(masks)
        actions.append(GroundAction(f"a{k}", "a", (), pre_pos, pre_neg & ~pre_pos, draw(masks), draw(masks),
                                    draw(st.integers(0, 3))))
    return actions, draw(masks), draw(masks)


def optimal_cost(actions, init, goal):
    """The cost of a cheapest plan (Dijkstra over every state; INF: none)."""
    best, queue = {init: 0}, [(0, init)]
    while queue:
        g, s = heapq.heappop(queue)
        if g > best[s]:
            continue
        if s & goal == goal:
            return g
        for act in actions:
            if act.applicable(s):
                t, ng = act.apply(s), g + act.cost
                if ng < best.get(t, INF):
                    best[t] = ng
                    heapq.heappush(queue, (ng, t))
    return INF


@settings(max_examples=400, deadline=None)
@given(ground_tasks())
def test_lmcut_is_admissible_and_infinite_only_without_a_plan(task):
    actions, init, goal = task
    relaxed = RelaxedTask(actions, goal, 0)
    cuts: list[list[int]] = []
    bound, optimum = relaxed.lmcut(init, cuts), optimal_cost(actions, init, goal)
    assert bound <= optimum
    if bound == INF:
        assert optimum == INF
    for cut in cuts:  # each cut is a landmark: no plan avoids all of its actions
        assert optimal_cost([a for k, a in enumerate(actions) if k not in cut], init, goal) == INF


@settings(max_examples=300, deadline=None)
@given(ground_tasks(), st.integers(0, 63))
def test_the_successor_index_offers_every_applicable_action(task, state):
    actions, _, _ = task
    index = SuccessorIndex((min(a.pre_pos_ids) if a.pre_pos_ids else None, k) for k, a in enumerate(actions))
    offered = [k for bucket in index.candidates(state) for k in bucket]
    assert len(offered) == len(set(offered))
    assert {k for k, a in enumerate(actions) if a.applicable(state)} <= set(offered)
