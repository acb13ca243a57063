"""The independent trace source (issue #14): tests/data/traces, made by its own generator, not render.py.

* the committed files are what ``tests/data/traces/generate.py`` makes;
* every trace reads and segments, and its state changes are those of the
  scenario's ``human.pddl`` playing the trace's script;
* the quality per source, scenario and condition is pinned at what today's
  segmenter and learner achieve (regression baselines, not the issue's
  targets: a change that improves them should raise these pins).
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from conftest import ROOT, load_script

TRACES = ROOT / "tests" / "data" / "traces"

#: (scenario, condition): (lowest frame macro-F1, truth segments, found segments, demonstrations with exact
#: counts, preconditions precision, recall, effects precision, recall, near-duplicate skills), as measured
#: by `guided-lfd quality --traces tests/data/traces` after the rate-independent speed window (2026-12-02; the
#: tracking-loss, re-grasp and brief-grip conditions after the segmenter learned to hold through them, 2026-12-07;
#: P/R rounded to 2 decimals).
BASELINE = {
    ('cupboard', 'all'): (0.972, 338, 338, 26, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'base'): (0.997, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'drops-dups'): (0.991, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'field-20hz'): (0.972, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'lag'): (0.983, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'liftoff'): (0.993, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'piecewise-tremor'): (0.993, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'rate-120hz'): (0.994, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'rate-15hz'): (0.997, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'rate-20hz'): (0.996, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'rate-30hz'): (0.994, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'all'): (0.977, 273, 273, 26, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'base'): (0.994, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'drops-dups'): (0.992, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'field-20hz'): (0.977, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'lag'): (0.984, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'liftoff'): (0.996, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'piecewise-tremor'): (0.993, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'rate-120hz'): (0.994, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'rate-15hz'): (0.996, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'rate-20hz'): (0.991, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'rate-30hz'): (0.991, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'all'): (0.980, 299, 299, 26, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'base'): (0.996, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'drops-dups'): (0.986, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'field-20hz'): (0.980, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'lag'): (0.981, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'liftoff'): (0.997, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'piecewise-tremor'): (0.991, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'rate-120hz'): (0.996, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'rate-15hz'): (0.995, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'rate-20hz'): (1.000, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'rate-30hz'): (0.995, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'all'): (0.962, 312, 312, 26, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'base'): (0.997, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'drops-dups'): (0.990, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'field-20hz'): (0.962, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'lag'): (0.970, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'liftoff'): (0.995, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'piecewise-tremor'): (0.992, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'rate-120hz'): (0.995, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'rate-15hz'): (0.993, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'rate-20hz'): (0.990, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'rate-30hz'): (0.997, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'tracking-loss'): (0.984, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'regrasp'): (0.996, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('cupboard', 'brief-grip'): (0.995, 26, 26, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'tracking-loss'): (0.982, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'regrasp'): (0.996, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-1', 'brief-grip'): (0.994, 21, 21, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'tracking-loss'): (0.986, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'regrasp'): (0.994, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('kitchen-2', 'brief-grip'): (0.994, 23, 23, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'tracking-loss'): (0.976, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'regrasp'): (0.995, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
    ('stacking', 'brief-grip'): (0.994, 24, 24, 2, 1.00, 1.00, 1.00, 1.00, 0),
}
F1_TOLERANCE = 0.01
LEARNING_TOLERANCE = 0.02  # the pins are rounded to 2 decimals


def _generator():
    return load_script(TRACES / "generate.py", "independent_trace_generator")


def _manifest() -> list[dict[str, str]]:
    with open(TRACES / "manifest.csv", encoding="utf-8", newline="") as fh:
        return list(csv.DictReader(fh))


@pytest.fixture(scope="module")
def rows():
    from guided_lfd.demonstration.quality import sources_report

    return sources_report(ROOT / "data" / "demos", ROOT / "data" / "domains", [TRACES])


def test_the_committed_files_are_what_the_generator_makes(tmp_path):
    written = _generator().generate(tmp_path)
    made = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*.csv"))
    committed = sorted(p.relative_to(TRACES) for p in TRACES.rglob("*.csv"))
    assert made == committed
    assert len(written) == 104  # 4 scenarios x 13 conditions x 2 scripts
    for rel in made:
        assert (tmp_path / rel).read_bytes() == (TRACES / rel).read_bytes(), rel
    total = sum(p.stat().st_size for p in TRACES.rglob("*") if p.is_file())
    assert total < 5e6  # about 45 kB a trace with its state and labels (the slow tracking-loss ones twice): small


def test_the_generator_does_not_use_the_project_renderer():
    text = (TRACES / "generate.py").read_text()
    assert "guided_lfd" not in text.replace("guided_lfd/demonstration/render.py", "").replace(
        "guided_lfd's renderer", "")


_HUMAN_NAMES = {
    "kitchen": {"open": "open_drawer", "close": "close_drawer", "push": "move_chair", "take": "take",
                "put_on": "put_on", "put_inside": "put_inside"},
    "stacking": {"take": "take", "put_on": "put_on", "stack": "stack", "unstack": "unstack"},
    "cupboard": {"open": "open_door", "close": "close_door", "take": "take", "put_on": "put_on",
                 "put_inside": "put_inside"},
}


def _human_plan(scenario: str, actions: str) -> list[tuple[str, tuple[str, ...]]]:
    names = _HUMAN_NAMES["kitchen" if scenario.startswith("kitchen") else scenario]
    plan, open_doors = [], []
    for text in actions.strip("()").split(") ("):
        verb, *args = text.split()
        args = [a.lower() for a in args]
        if scenario == "cupboard" and verb == "open":
            open_doors.append(args[0])
        if scenario == "cupboard" and verb == "close":
            open_doors.remove(args[0])
        if scenario == "cupboard" and verb == "put_inside":
            args.append(sorted(open_doors)[0])  # through an open door
        plan.append((names[verb], tuple(args)))
    return plan


@pytest.mark.parametrize("entry", _manifest(), ids=lambda e: e["file"])
def test_every_trace_reads_segments_and_plays_its_human_plan(entry):
    from guided_lfd.demonstration.segment import segment
    from guided_lfd.demonstration.trace import HAND_PREDICATES, load_demonstration
    from guided_lfd.pddl.reader import parse_task
    from guided_lfd.planning.validation import PlanStep, validate_plan

    scenario = entry["scenario"]
    demo = load_demonstration(str(TRACES / entry["file"]))
    segments = segment(demo)
    assert [s for s in segments if s.activity != "Idle"]
    folder = TRACES / scenario if (TRACES / scenario / "human.pddl").exists() else ROOT / "data" / "domains" / scenario
    human, problem = parse_task(folder / "human.pddl", folder / "problem.pddl")
    env = {a for a in problem.init if a.predicate not in HAND_PREDICATES}
    assert set(demo.initial) == env  # the scene is the problem's
    report = validate_plan(human, frozenset(problem.init), (),
                           [PlanStep(n, a) for n, a in _human_plan(scenario, entry["actions"])])
    assert report.first_failure is None, report.first_failure
    final = {a for a in report.final_state if a.predicate not in HAND_PREDICATES}
    assert set(demo.state_at(float("inf"))) == final


def test_every_source_scenario_and_condition_is_reported(rows):
    keys = [(r.scenario, r.condition) for r in rows if r.source != str(ROOT / "data" / "demos")]
    assert sorted(keys) == sorted(BASELINE)
    demos = [r for r in rows if r.source == str(ROOT / "data" / "demos")]
    assert [(r.scenario, r.condition, len(r.segmentation)) for r in demos] == [("kitchen-1", "rendered", 10),
                                                                                ("kitchen-2", "rendered", 10)]
    # The shipped demonstrations meet every target of #14 (as test_learn pins on them).
    assert all(not r.misses() for r in demos), [(r.scenario, r.misses()) for r in demos]


@pytest.mark.parametrize("key", sorted(BASELINE), ids=lambda k: "/".join(k))
def test_quality_does_not_fall_below_todays_baseline(rows, key):
    f1, truth, found, exact, pre_p, pre_r, eff_p, eff_r, dupes = BASELINE[key]
    row = next(r for r in rows if (r.scenario, r.condition) == key and r.source == str(TRACES))
    assert row.truth_segments == truth
    assert row.min_f1 >= f1 - F1_TOLERANCE, (key, row.min_f1)
    assert abs(row.segments - row.truth_segments) <= abs(found - truth), (key, row.segments)
    assert row.exact >= exact, (key, row.exact)
    measured = [row.learning[k] for k in ("pre_precision", "pre_recall", "eff_precision", "eff_recall")]
    for name, value, pin in zip(("pre P", "pre R", "eff P", "eff R"), measured, (pre_p, pre_r, eff_p, eff_r)):
        assert value >= pin - LEARNING_TOLERANCE, (key, name, value)
    assert len(row.near_duplicates) <= dupes, (key, row.near_duplicates)


@pytest.mark.parametrize("key", sorted(BASELINE), ids=lambda k: "/".join(k))
def test_every_source_scenario_and_condition_meets_the_targets(rows, key):
    """#14's acceptance: segment counts exact at 20-120 Hz, lowest frame macro-F1 >= 0.95 (>= 0.9 at 15 Hz),
    preconditions and effects precision and recall >= 0.9 against human.pddl, no near-duplicate skills."""
    from guided_lfd.demonstration.quality import TARGET_F1, TARGET_F1_LOW_RATE, TARGET_LEARNING

    assert (TARGET_F1, TARGET_F1_LOW_RATE, TARGET_LEARNING) == (0.95, 0.9, 0.9)
    row = next(r for r in rows if (r.scenario, r.condition) == key and r.source == str(TRACES))
    assert row.misses() == [], (key, row.misses())


def test_a_held_out_draw_of_the_traces_meets_the_targets_too(tmp_path):
    """The rules were measured on the committed draw; a fresh one (every duration, speed profile, noise, drop
    and lag drawn with other seeds) must meet the same targets, so they are not fitted to those 104 files."""
    import shutil

    from guided_lfd.demonstration.quality import sources_report

    _generator().generate(tmp_path, seed_base=24_000)
    for scenario in ("stacking", "cupboard"):
        for model in ("human.pddl", "problem.pddl"):
            shutil.copy(TRACES / scenario / model, tmp_path / scenario / model)
    rows = [r for r in sources_report(ROOT / "data" / "demos", ROOT / "data" / "domains", [tmp_path])
            if r.source == str(tmp_path)]
    assert len(rows) == len(BASELINE)
    assert [(r.scenario, r.condition, r.misses()) for r in rows if r.misses()] == []


def test_quality_with_traces_prints_both_tables(runner, app):
    from guided_lfd.demonstration.quality import quality_markdown, quality_report, sources_markdown, sources_report

    demos, domains = ROOT / "data/demos", ROOT / "data/domains"
    result = runner.invoke(app, ["quality", "--demos", str(demos), "--domains", str(domains), "--traces", str(TRACES)])
    assert result.exit_code == 0, result.output
    first = quality_markdown(quality_report(demos, domains))
    assert result.stdout == first + "\n## All sources\n\n" + sources_markdown(sources_report(demos, domains, [TRACES]))
    assert "| tests/data/traces" not in first


def test_the_readme_shows_todays_table():
    """tests/data/traces/README.md carries the measured table (relative paths, as `guided-lfd quality` prints it
    from the repository root)."""
    import os

    from guided_lfd.demonstration.quality import sources_markdown, sources_report

    here = os.getcwd()
    os.chdir(ROOT)
    try:
        table = sources_markdown(sources_report(Path("data/demos"), Path("data/domains"), [Path("tests/data/traces")]))
    finally:
        os.chdir(here)
    assert table in (TRACES / "README.md").read_text()


def test_a_late_named_target_starts_the_reach_not_a_release():
    """Detector lag: a short target-less motion from rest that runs into a Reach is the Reach's start;
    a Release after a Put (not from rest), or one longer than the latency, stays."""
    import numpy as np

    from guided_lfd.demonstration.segment import _lagged_reaches

    times = np.arange(0, 2.0, 0.05)
    lagged = [["Idle", 0, 9], ["Release", 10, 12], ["Reach", 13, 25], ["Take", 26, 39]]
    assert _lagged_reaches(times, [list(r) for r in lagged]) == [["Idle", 0, 9], ["Reach", 10, 25], ["Take", 26, 39]]
    after_put = [["Put", 0, 9], ["Release", 10, 12], ["Reach", 13, 25]]
    assert _lagged_reaches(times, [list(r) for r in after_put]) == after_put
    too_long = [["Idle", 0, 5], ["Release", 6, 12], ["Reach", 13, 25]]  # 0.35 s: a real motion
    assert _lagged_reaches(times, [list(r) for r in too_long]) == too_long


def test_a_late_named_transport_starts_the_put_and_longer_motion_stays_the_take():
    """Detector lag while holding: moving frames with the detector still naming the held object that run
    into a Put/Stack within 0.15 s are its start; longer (tremor while holding), they stay the Take's."""
    import numpy as np

    from guided_lfd.demonstration.segment import _late_transports

    times = np.arange(0, 1.0, 0.05)
    labels = np.array(["Take"] * 10 + ["Stack"] * 10, dtype=object)
    lagged = np.zeros(20, dtype=bool)
    lagged[7:10] = True  # 0.10 s before the Stack
    assert list(_late_transports(times, labels.copy(), lagged)) == ["Take"] * 7 + ["Stack"] * 13
    tremor = np.zeros(20, dtype=bool)
    tremor[3:10] = True  # 0.30 s of motion while holding
    assert list(_late_transports(times, labels.copy(), tremor)) == list(labels)
    before_release = np.array(["Take"] * 10 + ["Release"] * 10, dtype=object)
    assert list(_late_transports(times, before_release.copy(), lagged)) == list(before_release)


def test_the_hand_state_at_a_boundary_counts_empty_frames_and_ties_go_to_the_nearest():
    from guided_lfd.demonstration.segment import _hand_state

    assert _hand_state(["greenblock", "", "", ""]) == ""  # one frame of the next grasp at a Reach's end
    assert _hand_state(["mug", "mug", "", ""]) == "mug"  # a tie: the frame nearest the boundary
    assert _hand_state(["", "mug", "mug", "mug"]) == "mug"
    assert _hand_state([]) == ""


def test_a_frame_followed_by_dropped_frames_is_not_jitter():
    """A run lasts until the next frame: one grasp frame then 0.15 s of dropped frames is a grasp's start,
    not a jitter run merged into the Reach before it."""
    import numpy as np

    from guided_lfd.demonstration.segment import _debounce

    times = np.array([0.0, 0.05, 0.10, 0.15, 0.20, 0.35, 0.40, 0.45, 0.50, 0.55, 0.60])
    runs = [["Reach", 0, 3], ["Take", 4, 4], ["Put", 5, 5], ["Take", 6, 10]]
    assert _debounce(times, [list(r) for r in runs]) == [["Reach", 0, 3], ["Take", 4, 10]]
