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
        (1, "-0.5,right,0.1,0.2,0.9,open,,", "t.csv:2:1: trace error: column 'time': -0.5 is before the start; "
                                             "expected seconds since the start (>= 0)"),
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
    with pytest.raises(TraceError, match=r"t.state.csv:3:1: trace error: column 'time': -2 is before the start"):
        load_demonstration(_edit(tmp_path, state_text='time,fluent,value\n0,"object(A,item)",true\n-2,clear(A),true\n'))
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
        (True, "redplate", "redplate", True),     # moving, the detector on the held plate: the grasp's (Take)
        (False, "redplate", "blueplate", True),   # toward an item of its own type: Stack
        (False, "", "pinkdrawer", False),         # Reach, moving or not
        (True, "", "", False),                    # withdrawing: Release
        (False, "", "", False),                   # Idle
    ]), objects)
    assert list(labels) == ["Take", "Take", "Put", "Put", "Take", "Stack", "Reach", "Release", "Idle"]


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


# --- adversarial hunt on segment / learn-domain: regressions -------------------------------------------------

_STATE_HEAD = STATE.read_text()


@pytest.mark.parametrize(
    "extra,message",
    [
        # a change no hand can have caused: after the last frame (2.0 s), or before the first
        ("9.5,\"open(PinkDrawer)\",false\n", "t.state.csv:10:1: trace error: column 'time': a change at 9.5 s, outside the trace"),
        ("1.2,\"open(PinkDrawer)\",false\n", "t.state.csv:10:3: trace error: column 'value': open(PinkDrawer) is set both true and false at 1.2 s"),
        ("0,\"clear(Table)\",false\n", "t.state.csv:10:3: trace error: column 'value': clear(Table) is set both true and false at 0 s"),
        ("0,\"object(TABLE,item)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': object 'table' is declared as surface and as item"),
        ("0,\"object(Cup,tässe)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': type 'tässe' of cup: expected a PDDL name"),
        ("0,\"object(Cup,either)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': type 'either' of cup: expected a name that is not a PDDL keyword"),
        ("0,\"object(Cup,clear)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': type 'clear' is also a predicate"),
        ("1.0,\"not(PinkDrawer)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': predicate 'not': expected a name that is not a PDDL keyword"),
        ("1.0,\"klär(Table)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': predicate 'klär': expected a PDDL name"),
        ("1.0,\"in_hand(RedPlate)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': in_hand is the hand's state"),
        ("1.0,\"open(PinkDrawer,Table)\",true\n", "t.state.csv:10:2: trace error: column 'fluent': open has 2 argument(s) here and 1 before"),
    ],
)
def test_unusable_state_rows_name_file_row_and_column(tmp_path, extra, message):
    path = _edit(tmp_path, state_text=_STATE_HEAD + extra)
    with pytest.raises(TraceError) as info:
        load_demonstration(path)
    assert str(info.value).split("/")[-1].startswith(message), str(info.value)
    assert info.value.exit_code == 36


def test_change_before_the_first_frame_is_refused(tmp_path):
    lines = TRACE.read_text().splitlines()
    late = [lines[0]] + [line for line in lines[1:] if float(line.split(",")[0]) >= 1.5]
    with pytest.raises(TraceError, match=r"t.state.csv:9:1: .*a change at 1.2 s, outside the trace \(1.5 s to 2 s\)"):
        load_demonstration(_edit(tmp_path, trace_lines=late))


def test_unterminated_quote_names_its_line_and_empty_files_expect_csv(tmp_path):
    lines = TRACE.read_text().splitlines()
    lines[5] += ',"oops'
    with pytest.raises(TraceError, match=r"t.csv:6: trace error: malformed CSV"):
        load_demonstration(_edit(tmp_path, trace_lines=lines))
    (tmp_path / "t.csv").write_text("")
    with pytest.raises(Exception, match="empty file, expected a hand trace CSV"):
        load_demonstration(str(tmp_path / "t.csv"))


def test_huge_coordinates_warn_nothing(tmp_path):
    import warnings

    lines = TRACE.read_text().splitlines()
    cells = lines[5].split(",")
    cells[2] = "1e308"  # squaring it overflows
    lines[5] = ",".join(cells)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        demo = load_demonstration(_edit(tmp_path, trace_lines=lines))
    assert demo.frames["hand_move"].iloc[4]  # an infinite speed: moving


def test_a_hand_holding_something_when_the_trace_starts_did_not_pick_it_up(tmp_path):
    from conftest import ROOT
    from guided_lfd.demonstration.learn import ground_actions
    from guided_lfd.demonstration.segment import segment, segments_document

    # Kitchen I, P1's complete demonstration from 1.95 s: the right hand already
    # holds the plate and puts it into the open drawer.
    lines = (ROOT / "data/demos/kitchen-1/P1-complete.csv").read_text().splitlines()
    rows = [lines[0]] + [line for line in lines[1:] if 1.95 <= float(line.split(",")[0]) <= 3.4]
    state = ('time,fluent,value\n0,"object(RedPlate,item)",true\n0,"object(PinkDrawer,drawer)",true\n'
             '0,"object(Table,surface)",true\n1.95,"open(PinkDrawer)",true\n1.95,"clear(PinkDrawer)",true\n'
             '1.95,"graspable(RedPlate)",true\n2.401,"inside(RedPlate,PinkDrawer)",true\n')
    demo = load_demonstration(_edit(tmp_path, trace_lines=rows, state_text=state))
    put = next(s for s in segment(demo) if s.hand == "right")
    assert put.activity == "Put" and put.held_before == "redplate"
    (action,) = ground_actions(segments_document(demo, segment(demo), ""))
    assert action.name == "put_item_drawer"
    assert Atom("in_hand", ("redplate",)) in {lit.atom for lit in action.precondition if lit.positive}
    assert Atom("in_hand", ("redplate",)) in action.delete and Atom("hand_free") in action.add
