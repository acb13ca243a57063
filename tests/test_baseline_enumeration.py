"""The baseline's change-set enumeration: every subset once, in order, without a frontier."""

from __future__ import annotations

import itertools
import time
from dataclasses import replace
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from guided_lfd.excuse.space import Semantics, build_space
from guided_lfd.excuse.strategies import STRATEGIES
from guided_lfd.excuse.baseline import by_weight, colex_subsets
from guided_lfd.excuse.outcome import SearchLimits
from guided_lfd.planning.grounding import ground
from guided_lfd.pddl.reader import parse_task

BLOCKS = Path(__file__).resolve().parent.parent / "data" / "benchmarks" / "ipc" / "blocks"


def _mask(atoms) -> int:
    return sum(1 << a for a in atoms)


@given(st.sets(st.integers(0, 40), max_size=9), st.integers(0, 9))
def test_colex_subsets_are_the_combinations_in_integer_order(atoms, size):
    atoms = sorted(atoms)
    expected = sorted(_mask(c) for c in itertools.combinations(atoms, size))
    assert list(colex_subsets(atoms, size)) == expected


@settings(max_examples=200)
@given(st.dictionaries(st.integers(0, 40), st.integers(1, 5), max_size=8), st.none() | st.integers(0, 8))
def test_by_weight_yields_every_subset_once_in_weight_order(weights, max_size):
    atoms = sorted(weights)
    got = list(by_weight(atoms, weights, max_size))
    expected = {_mask(c) for k in range(len(atoms) + 1) for c in itertools.combinations(atoms, k)
                if max_size is None or k <= max_size}
    masks = [m for _, m in got]
    assert len(masks) == len(set(masks)) and set(masks) == expected
    assert [w for w, _ in got] == sorted(w for w, _ in got)
    assert all(w == sum(weights[a] for a in atoms if m >> a & 1) for w, m in got)


def test_by_weight_holds_no_next_size_frontier():
    # 30 atoms of mixed weights: the heap never holds more than the subsets yielded, plus one.
    weights = {i: 1 + i % 3 for i in range(30)}
    gen = by_weight(sorted(weights), weights)
    for _ in range(5000):
        next(gen)
    frame = gen.gi_frame
    assert len(frame.f_locals["heap"]) <= 5001


def test_baseline_time_limit_is_kept_on_a_large_change_space():
    # blocks task01 without stack: the baseline does not finish in a second; abandoning it frees
    # almost nothing, so it ends at its deadline.  (How many candidates it tries by then depends on the
    # machine's speed and load: only that it tried some is checked.)
    domain, problem = parse_task(BLOCKS / "domain.pddl", BLOCKS / "task01.pddl")
    robot = replace(domain, actions=[a for a in domain.actions if a.name != "stack"])
    space = build_space(ground(robot, problem), Semantics.LITERAL)
    start = time.monotonic()
    outcome = STRATEGIES["baseline"].search(space, SearchLimits(deadline=start + 1.0))
    assert outcome.status == "timeout"
    assert time.monotonic() - start < 2.0
    assert outcome.candidates > 0
