"""The hand-trace format: a valid demonstration loads; bad input is one pinned error."""

from __future__ import annotations

import pytest

from conftest import DATA
from guided_lfd.demonstration.trace import load_demonstration, parse_fluent
from guided_lfd.errors import TraceError
from guided_lfd.pddl.model import Atom

DEMO = DATA / "demo"
TRACE = DEMO / "open-drawer.csv"
STATE = DEMO / "open-drawer.state.csv"


def test_valid_trace_loads_with_state_and_hand_move():
    demo = load_demonstration(str(TRACE))
    assert demo.objects == {"redplate": "item", "table": "surface", "pinkdrawer": "drawer"}
    assert Atom("on_top", ("redplate", "table")) in demo.initial
    assert Atom("open", ("pinkdrawer",)) not in demo.initial
    assert Atom("open", ("pinkdrawer",)) in demo.state_at(1.5)
    right = demo.frames[demo.frames["hand"] == "right"]
    # moving while reaching (0.6 m/s) and pulling, still afterwards; the left hand never moves
    assert right[(right["time"] > 0.1) & (right["time"] < 0.7)]["hand_move"].all()
    assert not right[right["time"] > 1.5]["hand_move"].any()
    assert not demo.frames[demo.frames["hand"] == "left"]["hand_move"].any()
    assert demo.spellings["pinkdrawer"] == "PinkDrawer"


def test_parse_fluent():
    assert parse_fluent("inside(RedPlate, PinkDrawer)") == Atom("inside", ("redplate", "pinkdrawer"))
    with pytest.raises(ValueError):
        parse_fluent("inside RedPlate")


def _edit(tmp_path, trace_lines=None, state_text=None, line=None, new=None):
    lines = TRACE.read_text().splitlines()
    if line is not None:
        lines[line] = new
    if trace_lines is not None:
        lines = trace_lines
    (tmp_path / "t.csv").write_text("\n".join(lines) + "\n")
    (tmp_path / "t.state.csv").write_text(STATE.read_text() if state_text is None else state_text)
    return str(tmp_path / "t.csv")


@pytest.mark.parametrize(
    "line,new,message",
    [
        (0, "time,hand,x,y,z,in_hand,act_on", "t.csv:1: trace error: missing column 'grip'"),
        (5, "0.0333,right,nan,0.2,0.9,open,,PinkDrawer", "t.csv:6:3: trace error: column 'x': expected a finite number, got 'nan'"),
        (5, "0.0333,middle,0.1,0.2,0.9,open,,PinkDrawer", "t.csv:6:2: trace error: column 'hand': expected left or right"),
        (5, "0.0333,right,0.1,0.2,0.9,half,,PinkDrawer", "t.csv:6:6: trace error: column 'grip': expected open or closed"),
        (5, "0.0333,right,0.1,0.2,0.9,open,,Sofa", "t.csv:6:8: trace error: column 'act_on': object 'Sofa' is never declared"),
        (5, "5.0,right,0.1,0.2,0.9,open,,PinkDrawer", "t.csv:8:1: trace error: column 'time': time goes backwards for the right hand"),
    ],
)
def test_bad_trace_rows_name_file_row_and_column(tmp_path, line, new, message):
    path = _edit(tmp_path, line=line, new=new)
    with pytest.raises(TraceError) as info:
        load_demonstration(path)
    assert str(info.value).split("/")[-1].startswith(message)
    assert info.value.exit_code == 36


def test_empty_trace_and_state_errors(tmp_path):
    with pytest.raises(TraceError, match="t.csv: input error|empty"):
        load_demonstration(_edit(tmp_path, trace_lines=["time,hand,x,y,z,grip,in_hand,act_on"]))
    with pytest.raises(TraceError, match=r"t.state.csv:4:2: trace error: column 'fluent': object 'sofa' is never declared"):
        load_demonstration(_edit(tmp_path, state_text='time,fluent,value\n0,"object(A,item)",true\n0,clear(A),true\n0,clear(Sofa),true\n'))
    with pytest.raises(TraceError, match=r"column 'fluent': expected pred\(Arg,...\), got 'clear A'"):
        load_demonstration(_edit(tmp_path, state_text='time,fluent,value\n0,"object(A,item)",true\n0,clear A,true\n'))


def test_segmenting_the_open_drawer_trace():
    from guided_lfd.demonstration.segment import segment

    segments = [s for s in segment(load_demonstration(str(TRACE))) if s.hand == "right"]
    assert [s.activity for s in segments] == ["Reach", "Open", "Idle"]
    opened = segments[1]
    assert opened.object == "pinkdrawer"
    assert opened.added == {Atom("open", ("pinkdrawer",))}
    assert 0.7 < opened.start < 0.9 and 1.2 < opened.end < 1.4


def test_debouncing_absorbs_grip_flicker(tmp_path):
    from guided_lfd.demonstration.segment import segment

    lines = TRACE.read_text().splitlines()
    # one frame of the pull reports an open grip (flicker)
    k = next(i for i, l in enumerate(lines) if l.startswith("1.0") and ",right," in l)
    lines[k] = lines[k].replace(",closed,", ",open,")
    path = _edit(tmp_path, trace_lines=lines)
    segments = [s for s in segment(load_demonstration(path)) if s.hand == "right"]
    assert [s.activity for s in segments] == ["Reach", "Open", "Idle"]


def test_segment_cli_json_and_errors(runner, app, tmp_path):
    import json

    result = runner.invoke(app, ["segment", str(TRACE)])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["format"] == "guided-lfd/segments"
    assert [s["activity"] for s in doc["segments"] if s["hand"] == "right"] == ["Reach", "Open"]
    bad = _edit(tmp_path, line=5, new="0.0333,right,0.1,0.2,0.9,half,,PinkDrawer")
    result = runner.invoke(app, ["segment", bad])
    assert result.exit_code == 36
    assert result.stderr.strip().endswith("t.csv:6:6: trace error: column 'grip': expected open or closed, got 'half'")


def _frames(rows):
    import pandas as pd

    frame = pd.DataFrame(rows, columns=["hand_move", "in_hand", "act_on", "grip_closed"])
    return frame


def test_decision_tree_names_a_put_by_where_the_hand_goes():
    from guided_lfd.demonstration.segment import frame_labels

    objects = {"redplate": "item", "blueplate": "item", "pinkdrawer": "drawer"}
    labels = frame_labels(_frames([
        (False, "redplate", "redplate", True),    # grasping, still: Take
        (False, "redplate", "", True),            # holding still: Take
        (False, "redplate", "pinkdrawer", True),  # the transport's slow start or end: still a Put
        (True, "redplate", "pinkdrawer", True),   # carrying toward the drawer: Put
        (True, "redplate", "redplate", True),     # moving while grasping: Put, not Stack onto itself
        (False, "redplate", "blueplate", True),   # toward an item of its own type: Stack
        (False, "", "pinkdrawer", False),         # Reach, moving or not
        (True, "", "", False),                    # withdrawing: Release
        (False, "", "", False),                   # Idle
    ]), objects)
    assert list(labels) == ["Take", "Take", "Put", "Put", "Put", "Stack", "Reach", "Release", "Idle"]


def _debounced(pattern, rate=90.0):
    import numpy as np

    from guided_lfd.demonstration.segment import _debounce, _runs

    labels = np.array([label for label, n in pattern for _ in range(n)], dtype=object)
    times = np.arange(len(labels)) / rate
    return [(label, last - first + 1) for label, first, last in _debounce(times, _runs(times, labels))]


def test_debouncing_keeps_a_short_pause_between_two_activities():
    # Kitchen I, P3's excuse demonstration: a 0.13 s pause between withdrawing
    # the hand and reaching again is an activity of its own, not jitter ...
    assert _debounced([("Release", 20), ("Idle", 12), ("Reach", 30)]) == [("Release", 20), ("Idle", 12), ("Reach", 30)]
    # ... but the same run splitting one activity is absorbed ...
    assert _debounced([("Reach", 20), ("Idle", 12), ("Reach", 30)]) == [("Reach", 62)]
    # ... and a few frames are jitter anywhere (into the longer neighbour).
    assert _debounced([("Open", 40), ("Idle", 4), ("Release", 30)]) == [("Open", 44), ("Release", 30)]
    assert _debounced([("Take", 2), ("Put", 40)]) == [("Put", 42)]
