"""Semantic segmentation of a hand trace into activities (paper, section III-D-1).

Following the semantic activity recognition the paper's LfD system uses
(Ramirez-Amaro et al. 2017; Bates et al. 2017), each frame of each hand is
labelled by a small decision tree over ``hand_move``, ``in_hand``, ``act_on``
and the grip:

* object in hand, acting on another object (carried toward it): ``Put``
  (``Stack`` onto an item of the same type); otherwise moving -> ``Put``,
  still -> ``Take``.  Like Reach, a Put is named by where the hand goes, so
  the slow start and end of the transport are not read as holding still.
* no object, grip closed on ``act_on`` (a handle, a chair): ``Manipulate``,
  named at segment level after what it changes (``Open``, ``Close``, ``Push``)
* no object, moving toward ``act_on``: ``Reach``; moving, nothing targeted: ``Release``
  (the hand withdrawing), still: ``Idle`` (still at a target: ``Reach``)

Frames are then merged into segments, for each hand on its own, with
debouncing: runs shorter than :data:`JITTER_S` (a flickering grip, the hand's
speed crossing the threshold) are absorbed by their neighbours, and so are
runs shorter than :data:`MIN_SEGMENT_S` that split one activity (the same
label on both sides); a short run between two different activities is a
short activity of its own (a brief pause between a Release and the next
Reach).  Gaps up to :data:`MAX_GAP_S` (dropped frames) do not split a segment.

Both hands may act at once.  Every change of the environment state is
attributed to the hand that caused it: to the segment, among the segments
of each hand in progress at that moment, that handles the objects the change
is about (a change and the changes at the same instant that share objects
with it go together: the chair leaves the drawer, the drawer is clear); a
change about no object goes to a hand that acts, not to one holding still.
Each segment carries the fluents just before it acts and, after it, the same
fluents with only its own changes applied.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from guided_lfd.demonstration.trace import EFFECT_DELAY_S, Demonstration
from guided_lfd.pddl.model import Atom

#: Runs shorter than this are sensor jitter wherever they occur (s): a few
#: frames, as a flickering grip or the speed crossing its threshold produce.
JITTER_S = 0.06
#: Runs shorter than this between two runs of the same activity split that
#: activity and merge with it; also the shortest activity at either end of a trace (s).
MIN_SEGMENT_S = 0.15
#: Frame gaps up to this long (dropped frames) do not split a segment (s).
MAX_GAP_S = 0.5
#: How late the object detector may name a reach's target (s): a reach whose first frames move
#: without a target yet, after the hand was idle, is a reach from its start, not a Release.
DETECTOR_LATENCY_S = 0.15
# EFFECT_DELAY_S (from trace): fluent changes this long after a segment still belong to it (s).
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
    # The environment just before the segment acts, and that state with the
    # segment's own changes applied (never the other hand's).
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
    in_hand = frames["in_hand"].to_numpy()
    # Carrying toward somewhere: the hand acts on an object other than the one it holds.
    toward = targeted & (target != in_hand)
    onto_item = toward & np.array([objects.get(t, "") == objects.get(h, "#") for t, h in zip(target, in_hand)])
    labels = np.full(len(frames), "Idle", dtype=object)
    labels[~held & ~grip & targeted] = "Reach"
    labels[~held & ~grip & ~targeted & moving] = "Release"
    labels[~held & grip & targeted] = "Manipulate"
    # The detector still naming the held object: the hand is still on the grasp (a late detector
    # at a transport's start, or tremor while holding), not carrying toward somewhere.
    on_grasp = targeted & (target == in_hand)
    labels[held & ~moving & ~toward] = "Take"
    labels[held & (moving | toward)] = "Put"
    labels[held & moving & on_grasp] = "Take"
    labels[held & (moving | toward) & onto_item] = "Stack"
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
    """Absorb jitter runs into their neighbours, shortest first (see the module docstring)."""
    frame = float(np.median(np.diff(times))) if len(times) > 1 else 0.0

    def length(r: list) -> float:
        # A run lasts until the next frame: after a few dropped frames, longer than one frame period
        # (clock rounding does not count: only a gap of more than one and a half periods; a longer
        # dropout counts three periods at most: what happened in it is unknown).
        step = float(times[r[2] + 1] - times[r[2]]) if r[2] + 1 < len(times) else frame
        return float(times[r[2]] - times[r[1]]) + (min(step, 3 * frame) if step > 1.5 * frame else frame)

    def noise(k: int) -> bool:
        n = length(runs[k])
        if n < JITTER_S:
            return True
        if k == 0 or k == len(runs) - 1:
            return n < MIN_SEGMENT_S  # cut off by the trace's start or end
        return n < MIN_SEGMENT_S and runs[k - 1][0] == runs[k + 1][0]

    while len(runs) > 1:
        candidates = [k for k in range(len(runs)) if noise(k)]
        if not candidates:
            break
        k = min(candidates, key=lambda j: (length(runs[j]), j))
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
    return runs


def _lagged_reaches(times: np.ndarray, runs: list[list]) -> list[list]:
    """A short target-less motion that starts from rest and runs into a Reach is that Reach's start
    (the detector named the target late, by up to :data:`DETECTOR_LATENCY_S`)."""
    out: list[list] = []
    for k, run in enumerate(runs):
        label, first, last = run
        after = runs[k + 1] if k + 1 < len(runs) else None
        from_rest = not out or out[-1][0] == "Idle"
        if (label == "Release" and after is not None and after[0] == "Reach" and from_rest
                and times[after[1]] - times[first] <= DETECTOR_LATENCY_S + 1e-9):
            runs[k + 1] = ["Reach", first, after[2]]  # the Reach starts here
            continue
        out.append(run)
    return out


def _late_transports(times: np.ndarray, labels: np.ndarray, onset: np.ndarray) -> np.ndarray:
    """Moving frames that end a Take and run into a Put or Stack within :data:`DETECTOR_LATENCY_S`
    are that transport's start (the detector still named the held object); longer, they are
    motion while holding (tremor, adjusting the grasp) and stay the Take's."""
    k = 0
    while k < len(labels):
        if not (onset[k] and labels[k] == "Take"):
            k += 1
            continue
        j = k
        while j < len(labels) and onset[j] and labels[j] == "Take":
            j += 1
        if j < len(labels) and labels[j] in ("Put", "Stack") and times[j] - times[k] <= DETECTOR_LATENCY_S + 1e-9:
            labels[k:j] = labels[j]
        k = j
    return labels


def _hand_segments(demo: Demonstration, labels: np.ndarray, hand: str) -> list[Segment]:
    """One hand's segments, without fluents yet."""
    frames = demo.frames
    idx = np.flatnonzero((frames["hand"] == hand).to_numpy())
    if idx.size == 0:
        return []
    times = frames["time"].to_numpy()[idx]
    onset = (frames["hand_move"].to_numpy(dtype=bool) & (frames["in_hand"] != "").to_numpy()
             & (frames["act_on"] == frames["in_hand"]).to_numpy())[idx]
    hand_labels = _late_transports(times, labels[idx].copy(), onset)
    runs = _debounce(times, _lagged_reaches(times, _runs(times, hand_labels)))
    held = frames["in_hand"].to_numpy()[idx]
    target = frames["act_on"].to_numpy()[idx]
    out = []
    for label, first, last in runs:
        obj, tgt = _roles(label, held[first:last + 1], target[first:last + 1])
        # Boundaries move by a few frames with jitter and debouncing: read
        # the hand's state over a few frames, not one.
        # At the trace's start: what the hand holds in its first frame.
        held_before = _hand_state(held[max(0, first - BOUNDARY_FRAMES):first][::-1]) if first > 0 else str(held[0])
        held_after = _hand_state(held[max(first, last - BOUNDARY_FRAMES + 1):last + 1][::-1])
        out.append(Segment(0, hand, label, float(times[first]), float(times[last]), obj, tgt,
                           held_before=held_before, held_after=held_after))
    return out


def _handled(seg: Segment) -> set[str]:
    return {o for o in (seg.object, seg.target, seg.held_before, seg.held_after) if o}


def _attribute(demo: Demonstration, per_hand: dict[str, list[Segment]]) -> dict[int, list[tuple[float, Atom, bool]]]:
    """The environment changes each segment caused, keyed by ``id(segment)``.

    Each hand's effect windows (start + :data:`EFFECT_DELAY_S`, next start +
    :data:`EFFECT_DELAY_S`] tile the timeline, so at any moment exactly one
    segment of each hand is in progress.  Changes at the same instant that
    share objects are one event; it goes to the segment that handles most of
    its objects, else to a segment that is not Idle, else (no way to tell)
    to all of them.
    """
    windows = {}
    for hand, segs in per_hand.items():
        windows[hand] = np.array([s.start + EFFECT_DELAY_S for s in segs[1:]])
    caused: dict[int, list[tuple[float, Atom, bool]]] = {id(s): [] for segs in per_hand.values() for s in segs}
    by_time: dict[float, list[tuple[Atom, bool]]] = {}
    for when, atom, value in demo.events:
        by_time.setdefault(when, []).append((atom, value))
    for when, changes in by_time.items():
        positions = [(segs, int(np.searchsorted(windows[hand], when, side="left")))
                     for hand, segs in per_hand.items() if segs]
        for event in _linked(changes):
            candidates = [_by_contact(segs, k, event) for segs, k in positions]
            objects = {a for atom, _ in event for a in atom.args}
            # A change about no object at all (the light is on) is not the doing of a hand holding still.
            scored = [(len(objects & _handled(s)), s.activity != "Idle", bool(objects) or s.activity != "Take")
                      for s in candidates]
            best = max(scored)
            for seg, score in zip(candidates, scored):
                if score == best:
                    caused[id(seg)] += [(when, atom, value) for atom, value in event]
    return caused


def _by_contact(segs: list[Segment], k: int, event: list[tuple[Atom, bool]]) -> Segment:
    """The segment of one hand an event belongs to: the one in progress, except that the carried object
    leaving its place (a fact about it ends, none about it begins: its support becomes clear with it)
    belongs to the Take that grasped it, however far into the transport the contact ended (the plate
    leaves the table once lifted)."""
    seg = segs[k]
    carried = seg.object
    leaves = any(not value and carried in atom.args for atom, value in event)
    arrives = any(value and carried in atom.args for atom, value in event)
    if (seg.activity in ("Put", "Stack") and k > 0 and carried and segs[k - 1].activity == "Take"
            and segs[k - 1].object == carried and leaves and not arrives):
        return segs[k - 1]
    return seg


def _linked(changes: list[tuple[Atom, bool]]) -> list[list[tuple[Atom, bool]]]:
    """Changes grouped into connected components by shared arguments."""
    groups: list[list[tuple[Atom, bool]]] = []
    for change in changes:
        args = set(change[0].args)
        joined = [g for g in groups if any(args & set(a.args) for a, _ in g)]
        merged = [change] + [c for g in joined for c in g]
        groups = [g for g in groups if g not in joined] + [merged]
    return groups


def _state_before(demo: Demonstration, t: float) -> set[Atom]:
    """The true fluents just before ``t`` (changes at ``t`` excluded)."""
    state = set(demo.initial)
    for when, atom, value in demo.events:
        if when >= t:
            break
        (state.add if value else state.discard)(atom)
    return state


def segment(demo: Demonstration) -> list[Segment]:
    """Segments of both hands, in time order, Idle included."""
    labels = frame_labels(demo.frames, demo.objects)
    per_hand = {hand: _hand_segments(demo, labels, hand) for hand in ("left", "right")}
    caused = _attribute(demo, per_hand)
    out: list[Segment] = []
    for segs in per_hand.values():
        for k, seg in enumerate(segs):
            own = sorted(caused[id(seg)], key=lambda c: c[0])
            # The world just before the segment acts: at its first own change,
            # or where its effect window opens (the other hand's changes until
            # then included).
            when = own[0][0] if own else (seg.start + EFFECT_DELAY_S if k else float("-inf"))
            before = _state_before(demo, when) if own else demo.state_at(when) if k else set(demo.initial)
            after = set(before)
            for _, atom, value in own:
                (after.add if value else after.discard)(atom)
            seg.before, seg.after = frozenset(before), frozenset(after)
            if seg.activity == "Manipulate":
                seg.activity = _name_manipulation(seg.object, seg.before, seg.after)
            out.append(seg)
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


def _hand_state(values) -> str:
    """What the hand holds over a few boundary frames, nearest first: the majority, an empty hand
    counted too (one frame of the next grasp at a Reach's end is not holding), ties to the nearest."""
    vals = [str(v) if v else "" for v in values]
    return max(dict.fromkeys(vals), key=vals.count) if vals else ""


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

    doc = {
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
    if demo.vocabulary is not None:  # only where the state file declared it: older documents stay as they were
        doc["vocabulary"] = demo.vocabulary.to_dict()
    return doc


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
