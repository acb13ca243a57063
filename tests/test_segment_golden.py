"""Segments checked two ways.

* Read by hand: a few demonstrations' segments written out here from their
  CSV rows (which columns change at which frame, when the hand starts and
  stops moving, which state change falls in which segment), with the rules
  of the segmenter's docstring (the paper's section III-D-1), not by
  running the segmenter.  These fail when the segmenter is wrong.
* Recorded: every shipped and test trace segments exactly as recorded in
  tests/data/golden/segments.jsonl (written by ``python tests/golden_segments.py``
  from the segmenter itself): a record of today's segments that fails when
  any of them changes, whatever the segmenter's algorithm.
"""

from __future__ import annotations

import json

import pytest

from golden_segments import GOLDEN, ROOT, segments_of, traces

RECORDED = {d["trace"]: d["segments"] for d in map(json.loads, GOLDEN.read_text().splitlines())}

# Each segment as [hand, activity, start, end, object, target, held before, held after, added, deleted].
# Labels per frame: no object held and the grip closed on a target: Manipulate (named Open/Close after the
# `open` fluent it changes); no object, open grip, a target: Reach; no target, moving: Release, still:
# Idle; an object held, still on the grasp: Take; carried toward another target: Put (Stack onto an object
# of its own type).  Runs shorter than 0.06 s join their longer neighbour.  A state change belongs to the
# hand's segment in progress 0.1 s before it (the effect delay); the hand's facts are not state changes.
BY_HAND = {
    # A scripted trace at 60 Hz.  Right: rows 0-47 open grip toward PinkDrawer, moving 1.25 cm a frame (Reach);
    # rows 48-77 (0.8-1.2833 s) grip closed on PinkDrawer (open(PinkDrawer) at 1.2 s: Open); rows 78-80
    # (1.3-1.3333 s) open grip, no target, the window still sees the pull's motion: three frames (0.05 s) of
    # Release, jitter, joining the longer Idle after it (rows 81-120, 0.65 s against the Open's 0.5 s).  Left:
    # still, open, no target throughout.
    "tests/data/demo/open-drawer.csv": [
        ["left", "Idle", 0.0, 2.0, "", "", "", "", [], []],
        ["right", "Reach", 0.0, 0.7833, "pinkdrawer", "", "", "", [], []],
        ["right", "Open", 0.8, 1.2833, "pinkdrawer", "", "", "", ["(open pinkdrawer)"], []],
        ["right", "Idle", 1.3, 2.0, "", "", "", "", [], []],
    ],
    # The independent generator's stacking D1 at 60 Hz (tests/data/traces), right hand only.  Rows: 0-28 still;
    # 29 (0.4833 s) names RedBlock, moving from row 30 to 93; 94 (1.5667 s) grip closed holding RedBlock;
    # 122 (2.0333 s) the target turns to GreenBlock (a block: Stack) until 178; 179 (2.9833 s) open, no target,
    # moving until 208, still from 209 (3.4833 s); 230 (3.8333 s) names BlueBlock; 278 (4.6333 s) holds it;
    # 312 (5.2 s) toward RedBlock until 374; 375 (6.25 s) open, moving until 402, still from 403 (6.7167 s);
    # 428 (7.1333 s) names BlueBlock; 487 (8.1167 s) holds it; 520 (8.6667 s) toward Table (a surface: Put)
    # until 589; 590 (9.8333 s) open, moving until 623, still from 624 (10.4 s) to the end (11.0667 s).
    # Changes: 1.8367 RedBlock leaves the table (Take, 1.5667 s + 0.1 on); 3.0030 RedBlock on GreenBlock, which
    # is no longer clear (Stack, until the Release's 2.9833 + 0.1); 4.8986 BlueBlock leaves the table (Take);
    # 6.2812 BlueBlock on RedBlock (Stack, until 6.35); 8.3305 BlueBlock off RedBlock, RedBlock clear (Take,
    # from 8.2167); 9.8564 BlueBlock on the table (Put, until 9.9333).
    "tests/data/traces/stacking/base/D1.csv": [
        ["right", "Idle", 0.0, 0.4667, "", "", "", "", [], []],
        ["right", "Reach", 0.4833, 1.55, "redblock", "", "", "", [], []],
        ["right", "Take", 1.5667, 2.0167, "redblock", "", "", "redblock", [], ["(on_top redblock table)"]],
        ["right", "Stack", 2.0333, 2.9667, "redblock", "greenblock", "redblock", "redblock",
         ["(on redblock greenblock)"], ["(clear greenblock)"]],
        ["right", "Release", 2.9833, 3.4667, "", "", "redblock", "", [], []],
        ["right", "Idle", 3.4833, 3.8167, "", "", "", "", [], []],
        ["right", "Reach", 3.8333, 4.6167, "blueblock", "", "", "", [], []],
        ["right", "Take", 4.6333, 5.1833, "blueblock", "", "", "blueblock", [], ["(on_top blueblock table)"]],
        ["right", "Stack", 5.2, 6.2333, "blueblock", "redblock", "blueblock", "blueblock",
         ["(on blueblock redblock)"], ["(clear redblock)"]],
        ["right", "Release", 6.25, 6.7, "", "", "blueblock", "", [], []],
        ["right", "Idle", 6.7167, 7.1167, "", "", "", "", [], []],
        ["right", "Reach", 7.1333, 8.1, "blueblock", "", "", "", [], []],
        ["right", "Take", 8.1167, 8.65, "blueblock", "", "", "blueblock", ["(clear redblock)"],
         ["(on blueblock redblock)"]],
        ["right", "Put", 8.6667, 9.8167, "blueblock", "table", "blueblock", "blueblock", ["(on_top blueblock table)"],
         []],
        ["right", "Release", 9.8333, 10.3833, "", "", "blueblock", "", [], []],
        ["right", "Idle", 10.4, 11.0667, "", "", "", "", [], []],
    ],
    # The independent generator's cupboard D1 at 60 Hz, right hand only.  Rows: 0-28 still; 29 (0.4833 s) names
    # RightDoor; 85 (1.4167 s) grip closed on it until 139 (open(RightDoor) at 2.1626: Open); 140 (2.3333 s)
    # open, no target, still: one frame, jitter, joining the longer Open (0.92 s against the Release's 0.48 s);
    # 141-169 moving, 170 (2.8333 s) still; 194 (3.2333 s) names Mug; 256 (4.2667 s) holds it; 285 (4.75 s)
    # toward Cupboard until 355; 356 (5.9333 s) open, moving until 385, still from 386 (6.4333 s); 413
    # (6.8833 s) names RightDoor; 477 (7.95 s) grip closed on it until 530 (open(RightDoor) false at 8.6239:
    # Close); 531 (8.85 s) open, moving until 565, still from 566 (9.4333 s) to the end.  The Mug leaves the
    # table at 4.4940 (Take) and is inside the cupboard at 5.9674 (Put, until 5.9333 + 0.1).
    "tests/data/traces/cupboard/base/D1.csv": [
        ["right", "Idle", 0.0, 0.4667, "", "", "", "", [], []],
        ["right", "Reach", 0.4833, 1.4, "rightdoor", "", "", "", [], []],
        ["right", "Open", 1.4167, 2.3333, "rightdoor", "", "", "", ["(open rightdoor)"], []],
        ["right", "Release", 2.35, 2.8167, "", "", "", "", [], []],
        ["right", "Idle", 2.8333, 3.2167, "", "", "", "", [], []],
        ["right", "Reach", 3.2333, 4.25, "mug", "", "", "", [], []],
        ["right", "Take", 4.2667, 4.7333, "mug", "", "", "mug", [], ["(on_top mug table)"]],
        ["right", "Put", 4.75, 5.9167, "mug", "cupboard", "mug", "mug", ["(inside mug cupboard)"], []],
        ["right", "Release", 5.9333, 6.4167, "", "", "mug", "", [], []],
        ["right", "Idle", 6.4333, 6.8667, "", "", "", "", [], []],
        ["right", "Reach", 6.8833, 7.9333, "rightdoor", "", "", "", [], []],
        ["right", "Close", 7.95, 8.8333, "rightdoor", "", "", "", [], ["(open rightdoor)"]],
        ["right", "Release", 8.85, 9.4167, "", "", "", "", [], []],
        ["right", "Idle", 9.4333, 10.1667, "", "", "", "", [], []],
    ],
}


@pytest.mark.parametrize("name", sorted(BY_HAND))
def test_a_trace_segments_as_read_by_hand(name):
    assert sorted(segments_of(ROOT / name)) == sorted(BY_HAND[name])


def test_the_golden_file_covers_every_trace():
    assert {str(t.relative_to(ROOT)) for t in traces()} <= set(RECORDED)
    assert len(RECORDED) >= 100


@pytest.mark.parametrize("name", sorted(RECORDED))
def test_a_trace_segments_as_recorded(name):
    assert segments_of(ROOT / name) == RECORDED[name]
