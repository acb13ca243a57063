"""Semantic segmentation of a hand trace into activities (paper, section III-D-1).

Following the semantic activity recognition the paper's LfD system uses
(Ramirez-Amaro et al. 2017; Bates et al. 2017), each frame of each hand is
labelled by a small decision tree over ``hand_move``, ``in_hand``, ``act_on``
and the grip:

* object in hand:            moving -> ``Put`` (``Stack`` onto an item), still -> ``Take``
* no object, grip closed on ``act_on`` (a handle, a chair): ``Manipulate``,
  named at segment level after what it changes (``Open``, ``Close``, ``Push``)
* no object, moving toward ``act_on``: ``Reach``; moving, nothing targeted: ``Release``
  (the hand withdrawing), still: ``Idle`` (still at a target: ``Reach``)

Frames are then merged into segments per hand, with debouncing: runs shorter
than :data:`MIN_SEGMENT_S` (sensor jitter, a flickering grip) are absorbed by
their neighbours, and gaps up to :data:`MAX_GAP_S` (dropped frames) do not
split a segment.  Each segment carries the fluents before and after it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from guided_lfd.demonstration.trace import Demonstration
from guided_lfd.pddl.model import Atom

ACTIVITIES = ("Idle", "Reach", "Take", "Put", "Stack", "Release", "Open", "Close", "Push", "Manipulate")
#: Runs shorter than this are jitter and merge into their neighbours (s).
MIN_SEGMENT_S = 0.15
#: Frame gaps up to this long (dropped frames) do not split a segment (s).
MAX_GAP_S = 0.5
#: Fluent changes this long after a segment still belong to it (s).
EFFECT_DELAY_S = 0.1
#: Frames read at a segment boundary for what the hand holds or targets.
BOUNDARY_FRAMES = 4


@dataclass
class Segment:
    """One hand activity: when, which hand, on what, and what it changed."""

    index: int
    hand: str
    activity: str
    start: float
    end: float
    object: str
    target: str
    before: frozenset[Atom] = field(default_factory=frozenset)
    after: frozenset[Atom] = field(default_factory=frozenset)
    held_before: str = ""  # what the hand held just before the segment
    held_after: str = ""  # ... and at its end

    @property
    def added(self) -> frozenset[Atom]:
        return self.after - self.before

    @property
    def deleted(self) -> frozenset[Atom]:
        return self.before - self.after


def frame_labels(frames, objects: dict[str, str]) -> np.ndarray:
    """The decision tree, applied to every frame (``frames`` from :func:`load_demonstration`)."""
    moving = frames["hand_move"].to_numpy(dtype=bool)
    held = (frames["in_hand"] != "").to_numpy()
    target = frames["act_on"].to_numpy()
    targeted = target != ""
    grip = frames["grip_closed"].to_numpy(dtype=bool)
    onto_item = np.array([objects.get(t, "") == objects.get(h, "#") and t != "" for t, h in
                          zip(target, frames["in_hand"].to_numpy())])
    labels = np.full(len(frames), "Idle", dtype=object)
    labels[~held & ~grip & targeted] = "Reach"
    labels[~held & ~grip & ~targeted & moving] = "Release"
    labels[~held & grip & targeted] = "Manipulate"
    labels[held & ~moving] = "Take"
    labels[held & moving] = "Put"
    labels[held & moving & onto_item] = "Stack"
    return labels


def _runs(times: np.ndarray, labels: np.ndarray) -> list[list]:
    """[label, first index, last index] runs, split by label changes and long gaps."""
    runs: list[list] = []
    for i, label in enumerate(labels):
        if runs and runs[-1][0] == label and times[i] - times[runs[-1][2]] <= MAX_GAP_S:
            runs[-1][2] = i
        else:
            runs.append([label, i, i])
    return runs


def _debounce(times: np.ndarray, runs: list[list]) -> list[list]:
    """Absorb runs shorter than :data:`MIN_SEGMENT_S` into a neighbour, shortest first."""
    def length(r):
        return times[r[2]] - times[r[1]] + (times[1] - times[0] if len(times) > 1 else 0)

    changed = True
    while changed and len(runs) > 1:
        changed = False
        k = min(range(len(runs)), key=lambda j: length(runs[j]))
        if length(runs[k]) >= MIN_SEGMENT_S:
            break
        if k == 0:
            runs[1][1] = runs[0][1]
            del runs[0]
        elif k == len(runs) - 1 or length(runs[k - 1]) >= length(runs[k + 1]):
            runs[k - 1][2] = runs[k][2]
            del runs[k]
        else:
            runs[k + 1][1] = runs[k][1]
            del runs[k]
        # Neighbours with the same label now touch: join them.
        merged: list[list] = []
        for r in runs:
            if merged and merged[-1][0] == r[0]:
                merged[-1][2] = r[2]
            else:
                merged.append(r)
        runs = merged
        changed = True
    return runs


def segment(demo: Demonstration) -> list[Segment]:
    """Segments of both hands, in time order, Idle included."""
    frames = demo.frames
    labels = frame_labels(frames, demo.objects)
    out: list[Segment] = []
    for hand in ("left", "right"):
        idx = np.flatnonzero((frames["hand"] == hand).to_numpy())
        if idx.size == 0:
            continue
        times = frames["time"].to_numpy()[idx]
        runs = _debounce(times, _runs(times, labels[idx]))
        held = frames["in_hand"].to_numpy()[idx]
        target = frames["act_on"].to_numpy()[idx]
        for label, first, last in runs:
            start, end = float(times[first]), float(times[last])
            obj, tgt = _roles(label, held[first:last + 1], target[first:last + 1])
            # Effect windows (start + delay, end + delay] tile the timeline, so
            # every change belongs to exactly one segment of the hand.
            before = demo.state_at(start + EFFECT_DELAY_S)
            after = demo.state_at(end + EFFECT_DELAY_S)
            if label == "Manipulate":
                label = _name_manipulation(obj, before, after)
            # Boundaries move by a few frames with jitter and debouncing: read
            # the hand's state over a few frames, not one.
            held_before = _most_common(held[max(0, first - BOUNDARY_FRAMES):first]) if first > 0 else ""
            held_after = _most_common(held[max(first, last - BOUNDARY_FRAMES + 1):last + 1])
            out.append(Segment(0, hand, label, start, end, obj, tgt, before, after, held_before, held_after))
    out.sort(key=lambda s: (s.start, s.hand))
    for i, seg in enumerate(out):
        seg.index = i
    return out


def _most_common(values) -> str:
    vals = [v for v in values if v]
    if not vals:
        return ""
    names, counts = np.unique(np.array(vals, dtype=object).astype(str), return_counts=True)
    return str(names[int(np.argmax(counts))])


def _roles(label: str, held, target) -> tuple[str, str]:
    """(object, target) of a segment: what the hand holds or handles, and where it goes."""
    if label in ("Take", "Put", "Stack"):
        tail = target[max(0, len(target) - 3 * BOUNDARY_FRAMES):]
        return _most_common(held), (_most_common(tail) if label != "Take" else "")
    return _most_common(target), ""


def _name_manipulation(obj: str, before: frozenset[Atom], after: frozenset[Atom]) -> str:
    """Open/Close for a drawer's ``open`` fluent, Push when the object moved otherwise."""
    if Atom("open", (obj,)) in after - before:
        return "Open"
    if Atom("open", (obj,)) in before - after:
        return "Close"
    if any(obj in a.args for a in after ^ before):
        return "Push"
    return "Manipulate"


def segments_document(demo: Demonstration, segments: list[Segment], state_path: str) -> dict:
    """The ``guided-lfd/segments`` JSON body (see README)."""
    def atoms(xs):
        return [str(a) for a in sorted(xs)]

    return {
        "trace": demo.path,
        "state": state_path,
        "objects": dict(sorted(demo.objects.items())),
        "spellings": dict(sorted(demo.spellings.items())),
        "initial": atoms(demo.initial),
        "segments": [
            {"index": s.index, "hand": s.hand, "activity": s.activity, "start": round(s.start, 4),
             "end": round(s.end, 4), "object": s.object, "target": s.target,
             "held_before": s.held_before, "held_after": s.held_after,
             "added": atoms(s.added), "deleted": atoms(s.deleted),
             "before": atoms(s.before), "after": atoms(s.after)}
            for s in segments
        ],
    }


def segments_csv(segments: list[Segment]) -> str:
    """Segments as CSV (fluent lists joined with ``;``)."""
    import csv
    import io

    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["index", "hand", "activity", "start", "end", "object", "target", "added", "deleted"])
    for s in segments:
        writer.writerow([s.index, s.hand, s.activity, f"{s.start:.4f}", f"{s.end:.4f}", s.object, s.target,
                         ";".join(str(a) for a in sorted(s.added)), ";".join(str(a) for a in sorted(s.deleted))])
    return buf.getvalue()
