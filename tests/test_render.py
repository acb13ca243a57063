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
