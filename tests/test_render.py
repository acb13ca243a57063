"""Rendered traces: segmentation recovers the rendered activities."""

from __future__ import annotations

import pytest

from guided_lfd.demonstration.render import Noise, Scene, Step, frame_f1, render
from guided_lfd.demonstration.segment import segment
from guided_lfd.demonstration.trace import load_demonstration
from guided_lfd.pddl.model import Atom

SCENE = Scene(
    positions={"redplate": (0.5, 0.2, 0.8), "table": (0.5, 0.2, 0.75), "pinkdrawer": (-0.1, 0.45, 0.6)},
    types={"redplate": "item", "table": "surface", "pinkdrawer": "drawer"},
    spellings={"redplate": "RedPlate", "table": "Table", "pinkdrawer": "PinkDrawer"},
)
INITIAL = {Atom("graspable", ("redplate",)), Atom("on_top", ("redplate", "table")),
           Atom("clear", ("pinkdrawer",)), Atom("clear", ("table",)), Atom("hand_free")}
COMPLETE = [
    Step("Idle", duration=0.6),
    Step("Reach", "pinkdrawer", duration=1.0),
    Step("Open", "pinkdrawer", duration=0.8, changes=[(Atom("open", ("pinkdrawer",)), True)]),
    Step("Release", duration=0.6),
    Step("Reach", "redplate", duration=1.1),
    Step("Take", "redplate", duration=0.5, changes=[(Atom("on_top", ("redplate", "table")), False)]),
    Step("Put", "redplate", "pinkdrawer", duration=1.2),
    Step("Release", duration=0.6, changes=[(Atom("inside", ("redplate", "pinkdrawer")), True)]),
    Step("Idle", duration=0.8),
]


def write(tmp_path, rendering):
    (tmp_path / "demo.csv").write_text(rendering.trace_csv)
    (tmp_path / "demo.state.csv").write_text(rendering.state_csv)
    return load_demonstration(str(tmp_path / "demo.csv"))


def predicted_labels(demo, segments, labels_csv):
    import csv
    import io

    truth, predicted = [], []
    for row in csv.DictReader(io.StringIO(labels_csv)):
        t, hand = float(row["time"]), row["hand"]
        match = [s for s in segments if s.hand == hand and s.start - 1e-6 <= t <= s.end + 1e-6]
        truth.append(row["activity"])
        predicted.append(match[0].activity if match else "Idle")
    return truth, predicted


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_noisy_rendering_segments_back(tmp_path, seed):
    rendering = render(COMPLETE, SCENE, INITIAL, noise=Noise(seed=seed))
    demo = write(tmp_path, rendering)
    segments = segment(demo)
    acts = [s.activity for s in segments if s.hand == "right" and s.activity != "Idle"]
    assert acts == [s.activity for s in COMPLETE if s.activity != "Idle"]
    truth, predicted = predicted_labels(demo, segments, rendering.labels_csv)
    assert frame_f1(truth, predicted) >= 0.95
    put = next(s for s in segments if s.activity == "Put")
    assert put.object == "redplate" and put.target == "pinkdrawer"
    assert Atom("inside", ("redplate", "pinkdrawer")) in put.added


@pytest.mark.parametrize("seed", [0, 3, 5])
def test_learning_from_the_rendered_demonstration(tmp_path, seed):
    from guided_lfd.demonstration.learn import learn_domain
    from guided_lfd.demonstration.segment import segments_document
    from guided_lfd.pddl.model import Literal
    from guided_lfd.pddl.writer import domain_to_pddl

    rendering = render(COMPLETE, SCENE, INITIAL, noise=Noise(seed=seed))
    demo = write(tmp_path, rendering)
    doc = segments_document(demo, segment(demo), "demo.state.csv")
    domain = learn_domain([("demo", doc)])
    names = [a.name for a in domain.actions]
    # Reach and the Release after opening change nothing symbolic: no actions;
    # the Release that ends the Put belongs to it.
    assert names == ["open_drawer", "take_item", "put_item_drawer"]
    opening = domain.action("open_drawer")
    # nodes of interest: clear(drawer) is a precondition although it does not change
    assert Literal(Atom("clear", ("?o1",))) in opening.precondition
    assert Literal(Atom("open", ("?o1",)), False) in opening.precondition
    assert opening.add == (Atom("open", ("?o1",)),)
    put = domain.action("put_item_drawer")
    assert set(put.add) == {Atom("inside", ("?o1", "?o2")), Atom("hand_free")}
    assert put.delete == (Atom("in_hand", ("?o1",)),)
    # the PDDL parses back
    (tmp_path / "learned.pddl").write_text(domain_to_pddl(domain))
    from guided_lfd.pddl.reader import parse_domain

    assert [a.name for a in parse_domain(tmp_path / "learned.pddl").actions] == names


def test_segment_learn_domain_pipeline_and_prior(runner, app, tmp_path):
    from conftest import kitchen

    rendering = render(COMPLETE, SCENE, INITIAL, noise=Noise(seed=1))
    write(tmp_path, rendering)
    segmented = runner.invoke(app, ["segment", str(tmp_path / "demo.csv")])
    assert segmented.exit_code == 0, segmented.stderr
    learned = runner.invoke(app, ["learn-domain", "-"], input=segmented.stdout)
    assert learned.exit_code == 0, learned.stderr
    assert "(:action open_drawer" in learned.stdout and "(:action put_item_drawer" in learned.stdout
    (tmp_path / "segments.json").write_text(segmented.stdout)
    merged = runner.invoke(app, ["learn-domain", str(tmp_path / "segments.json"), "--prior", kitchen(1)[0],
                                 "-o", str(tmp_path / "merged.pddl")])
    assert merged.exit_code == 0, merged.stderr
    # The robot with the demonstrated skills solves the original Kitchen I task.
    plan = runner.invoke(app, ["plan", str(tmp_path / "merged.pddl"), kitchen(1)[1]])
    assert plan.exit_code == 0, plan.stderr
    assert "(open_drawer pinkdrawer)" in plan.stdout


def test_learn_domain_rejects_non_segment_input(runner, app, tmp_path):
    bad = tmp_path / "x.json"
    bad.write_text("{not json")
    result = runner.invoke(app, ["learn-domain", str(bad)])
    assert result.exit_code == 36
    assert "x.json:1:2: trace error: not JSON" in result.stderr


@pytest.mark.parametrize("kitchen_n", [1, 2])
def test_excuse_demonstration_of_a_human_plan_teaches_the_robot(tmp_path, runner, app, kitchen_n):
    """Render the human's plan to the excuse state, learn from it, merge: the robot solves the task."""
    from conftest import kitchen
    from guided_lfd.demonstration.learn import learn_domain
    from guided_lfd.demonstration.render import script_for_plan
    from guided_lfd.demonstration.segment import segments_document
    from guided_lfd.pddl.reader import parse_task
    from guided_lfd.pddl.writer import domain_to_pddl

    human, problem = parse_task(*kitchen(kitchen_n, "human"))
    robot, _ = parse_task(*kitchen(kitchen_n))
    # The human's plans to reach the minimal excuse of each kitchen.
    plan = {1: [("open_drawer", ("pinkdrawer",))],
            2: [("move_chair", ("chair", "pinkdrawer", "corner"))]}[kitchen_n]
    scene = Scene(
        positions={"redplate": (0.5, 0.2, 0.8), "table": (0.5, 0.2, 0.75), "counter": (0.9, 0.2, 0.9),
                   "pinkdrawer": (-0.1, 0.45, 0.6), "bluedrawer": (-0.4, 0.45, 0.6), "corner": (-1.0, -0.5, 0.5),
                   "chair": (-0.1, 0.1, 0.5)},
        types={**problem.objects}, spellings=problem.spellings)
    steps = script_for_plan(plan, human, set(problem.init))
    rendering = render(steps, scene, set(problem.init), noise=Noise(seed=kitchen_n))
    demo = write(tmp_path, rendering)
    doc = segments_document(demo, segment(demo), "demo.state.csv")
    merged = learn_domain([("demo", doc)], prior=robot)
    (tmp_path / "merged.pddl").write_text(domain_to_pddl(merged))
    result = runner.invoke(app, ["plan", str(tmp_path / "merged.pddl"), kitchen(kitchen_n)[1]])
    assert result.exit_code == 0, result.stderr


def test_generalise_aligns_repeats_and_keeps_names_unique():
    from guided_lfd.demonstration.learn import generalise
    from guided_lfd.pddl.model import ActionSchema, Literal

    # The same push demonstrated twice with the extra objects in swapped order.
    a = ActionSchema("push", (("?o1", "obstacle"), ("?o2", "furniture"), ("?o3", "drawer")),
                     (Literal(Atom("blocking", ("?o1", "?o3"))),), (Atom("blocking", ("?o1", "?o2")),),
                     (Atom("blocking", ("?o1", "?o3")),))
    b = ActionSchema("push", (("?o1", "obstacle"), ("?o2", "furniture"), ("?o3", "surface")),
                     (Literal(Atom("blocking", ("?o1", "?o2"))),), (Atom("blocking", ("?o1", "?o3")),),
                     (Atom("blocking", ("?o1", "?o2")),))
    c = ActionSchema("push", (("?o1", "obstacle"),), (), (Atom("clear", ("?o1",)),), ())
    parents = {"furniture": "object", "drawer": "furniture", "surface": "furniture", "obstacle": "object"}
    out = generalise([a, b, c], parents)
    # Two skills (different effects): named by their parameters' types.
    assert [x.name for x in out] == ["push_obstacle_furniture_furniture", "push_obstacle"]
    merged = out[0]
    assert merged.add == (Atom("blocking", ("?o1", "?o2")),) and merged.delete == (Atom("blocking", ("?o1", "?o3")),)
    assert dict(merged.params)["?o3"] == "furniture"  # drawer and surface generalise to furniture


# Both hands at once: the left hand fetches the plate while the right hand
# opens the drawer, then puts the plate in once the drawer is open.
TWO_HANDED = [
    Step("Idle", duration=0.4),
    Step("Reach", "redplate", duration=1.0, hand="left", parallel=True),
    Step("Take", "redplate", duration=0.5, hand="left", parallel=True,
         changes=[(Atom("on_top", ("redplate", "table")), False)]),
    Step("Reach", "pinkdrawer", duration=1.0, parallel=True),
    Step("Open", "pinkdrawer", duration=0.8, parallel=True, changes=[(Atom("open", ("pinkdrawer",)), True)]),
    Step("Release", duration=0.6, parallel=True),
    Step("Put", "redplate", "pinkdrawer", duration=1.2, hand="left"),
    Step("Release", duration=0.6, hand="left", changes=[(Atom("inside", ("redplate", "pinkdrawer")), True)]),
    Step("Idle", duration=0.5),
]


def test_schedule_runs_parallel_steps_alongside_the_other_hand():
    from guided_lfd.demonstration.render import schedule

    times = schedule(TWO_HANDED)
    assert times[1] == (0.0, 1.0)  # the left hand starts at once
    assert times[3] == (0.4, 1.4)  # the right hand after its pause, meanwhile
    put = times[6]
    assert put[0] == pytest.approx(2.8)  # waits until the right hand is done (the drawer is open)
    assert schedule(COMPLETE)[-1][1] == pytest.approx(sum(s.duration for s in COMPLETE))  # sequential


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_two_handed_demonstration_segments_per_hand(tmp_path, seed):
    import csv
    import io

    rendering = render(TWO_HANDED, SCENE, INITIAL, noise=Noise(seed=seed))
    demo = write(tmp_path, rendering)
    # The waiting left hand holds the plate: grip closed, labelled Take (the activity model's holding still).
    labels = {(r["time"], r["hand"]): r["activity"] for r in csv.DictReader(io.StringIO(rendering.labels_csv))}
    assert labels[("2.0000", "left")] == "Take"
    waiting = demo.frames[(demo.frames["hand"] == "left") & demo.frames["time"].between(1.6, 2.7)]
    assert (waiting["in_hand"] == "redplate").all() and waiting["grip_closed"].mean() > 0.9
    segments = segment(demo)
    acts = {h: [s.activity for s in segments if s.hand == h and s.activity != "Idle"] for h in ("left", "right")}
    assert acts == {"left": ["Reach", "Take", "Put", "Release"], "right": ["Reach", "Open", "Release"]}
    truth, predicted = predicted_labels(demo, segments, rendering.labels_csv)
    assert frame_f1(truth, predicted) >= 0.95
    # Each change belongs to the hand that caused it, although the left hand's
    # Take is in progress while the right hand opens the drawer.
    changes = {(s.hand, s.activity): (s.added, s.deleted) for s in segments if s.added or s.deleted}
    assert changes == {
        ("left", "Take"): (frozenset(), {Atom("on_top", ("redplate", "table"))}),
        ("right", "Open"): ({Atom("open", ("pinkdrawer",))}, frozenset()),
        ("left", "Put"): ({Atom("inside", ("redplate", "pinkdrawer"))}, frozenset()),
    }
    put = next(s for s in segments if s.activity == "Put")
    assert Atom("open", ("pinkdrawer",)) in put.before  # the world as the left hand found it


def test_two_handed_demonstration_teaches_the_same_skills(tmp_path):
    from guided_lfd.demonstration.learn import learn_domain
    from guided_lfd.demonstration.segment import segments_document
    from guided_lfd.pddl.model import Literal

    sequential = write(tmp_path, render(COMPLETE, SCENE, INITIAL, noise=Noise(seed=4)))
    one = learn_domain([("one", segments_document(sequential, segment(sequential), ""))])
    (tmp_path / "two").mkdir()
    parallel = write(tmp_path / "two", render(TWO_HANDED, SCENE, INITIAL, noise=Noise(seed=4)))
    two = learn_domain([("two", segments_document(parallel, segment(parallel), ""))])
    def skills(domain):
        return {a.name: (a.params, a.precondition, a.add, a.delete) for a in domain.actions}

    assert skills(two) == skills(one)
    # taking the plate with the left hand needs that hand free, whatever the right hand holds
    assert Literal(Atom("hand_free")) in two.action("take_item").precondition


@pytest.mark.parametrize("plan, odd", [
    ([("open_drawer", ("pinkdrawer",))], set()),  # changes open: Reach + Open + Release
    ([("move_chair", ("chair", "pinkdrawer", "corner"))], set()),  # pushes its first object
])
def test_undrawable_actions_accepts_hand_manipulation(plan, odd):
    from conftest import kitchen
    from guided_lfd.demonstration.render import undrawable_actions
    from guided_lfd.pddl.reader import parse_task

    human, _ = parse_task(*kitchen(2, "human"))
    assert undrawable_actions(plan, human) == odd


def test_every_action_with_objects_is_drawable_walking_and_keys_too():
    """Walking through a door or turning a key is drawn as the hand working on the action's objects (issue #23);
    only an action without objects leaves the hand nothing to act on."""
    from guided_lfd.demonstration.render import script_for_plan, undrawable_actions
    from guided_lfd.pddl.reader import parse_domain

    human = parse_domain("tests/data/teach/rooms-human.pddl")
    assert undrawable_actions([("walk", ("d1", "hall", "kitchen")), ("unlock", ("k1", "d1", "hall", "kitchen")),
                               ("pick", ("k1", "hall"))], human) == set()
    assert undrawable_actions([("wait", ())], human) == {"wait"}
    state = {Atom("at", ("hall",)), Atom("connects", ("d1", "hall", "kitchen")), Atom("unlocked", ("d1",))}
    steps = script_for_plan([("walk", ("d1", "hall", "kitchen"))], human, state)
    acting = [s for s in steps if s.activity != "Idle"]
    # The walker leaves the hall: the hand works on the first object the changes are about (not the door).
    assert [(s.activity, s.obj) for s in acting] == [("Reach", "hall"), ("Push", "hall"), ("Release", "")]
    assert acting[1].changes == [(Atom("at", ("kitchen",)), True), (Atom("at", ("hall",)), False)]
