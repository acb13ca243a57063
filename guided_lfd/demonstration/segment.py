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

from guided_lfd.demonstration.trace import EFFECT_DELAY_S, Demonstration, apply_changes, frame_period
from guided_lfd.pddl.model import Atom

#: Runs shorter than this are sensor jitter wherever they occur (s): a few
#: frames, as a flickering grip or the speed crossing its threshold produce.
JITTER_S = 0.06
#: Runs shorter than this between two runs of the same activity split that
#: activity and merge with it; also the shortest activity at either end of a trace (s).
MIN_SEGMENT_S = 0.15
#: Frame gaps up to this long (dropped frames) do not split a segment (s).
MAX_GAP_S = 0.5
#: A longer gap (the tracker lost the hand) up to this long does not split an activity either, when the hand
#: does the same on both sides of it: the same label, holding and targeting the same objects (s).
MAX_LOSS_S = 2.0
#: An activity interrupted this briefly on the object it works on stays one activity: a run shorter than this
#: between two runs of the same activity on the same object (holding it: a re-grasp during a carry; reaching
#: for it: an accidental grip on the way) (s).
REGRASP_S = 0.3
#: The activities that carry an object (a re-grasp between two of them, on what they carry, is still the carry).
CARRYING = frozenset({"Take", "Put", "Stack"})
#: How late the object detector may name a reach's target (s): a reach whose first frames move
#: without a target yet, after the hand was idle, is a reach from its start, not a Release.
DETECTOR_LATENCY_S = 0.15
# EFFECT_DELAY_S (from trace): fluent changes this long after a segment still belong to it (s).
#: The names a Manipulate segment takes after what it changed.
MANIPULATIONS = frozenset({"Open", "Close", "Push", "Manipulate"})
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
    # Its own changes (time, fluent, value), in time order: what ``after`` applies to ``before``.
    changes: list[tuple[float, Atom, bool]] = field(default_factory=list, compare=False, repr=False)

    @property
    def added(self) -> frozenset[Atom]:
        return self.after - self.before

    @property
    def deleted(self) -> frozenset[Atom]:
        return self.before - self.after


def frame_labels(frames, objects: dict[str, str]) -> np.ndarray:
    """The decision tree, applied to every frame (``frames`` from :func:`load_demonstration`)."""
    moving = frames["hand_move"].to_numpy(dtype=bool)
    in_hand = frames["in_hand"].to_numpy(dtype=object)
    held = in_hand != ""
    target = frames["act_on"].to_numpy(dtype=object)
    targeted = target != ""
    grip = frames["grip_closed"].to_numpy(dtype=bool)
    # Carrying toward somewhere: the hand acts on an object other than the one it holds.
    toward = targeted & (target != in_hand)
    onto_item = toward & (_types(target, objects, "") == _types(in_hand, objects, "#"))
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


def _types(names: np.ndarray, objects: dict[str, str], missing: str) -> np.ndarray:
    """Each name's object type (``missing`` for an undeclared one), looked up once per distinct name."""
    import pandas as pd

    codes, uniques = pd.factorize(names, sort=False)
    kinds = np.array([objects.get(u, missing) for u in uniques] + [missing], dtype=object)
    return kinds[codes]  # code -1 (no value) takes the last entry


def _runs(times: np.ndarray, labels: np.ndarray, held: np.ndarray | None = None,
          target: np.ndarray | None = None) -> list[list]:
    """[label, first index, last index] runs, split by label changes and long gaps: a gap longer than
    :data:`MAX_GAP_S` splits unless the hand holds and targets the same on both sides and it is no longer than
    :data:`MAX_LOSS_S` (a tracking loss inside one activity)."""
    if len(labels) == 0:
        return []
    gap = np.diff(times)
    lost = gap > MAX_GAP_S
    # Without the hand's objects no gap is known to be inside one activity; with them, only the long gaps ask.
    if held is not None and target is not None and lost.any():
        same = (held[1:] == held[:-1]) & (target[1:] == target[:-1])
        # The loss is the time without frames: the gap less the frame period, and a few dropped frames beside it.
        lost &= ~(same & (gap - 3 * frame_period(times) <= MAX_LOSS_S))
    cut = np.flatnonzero((labels[1:] != labels[:-1]) | lost) + 1
    starts = np.concatenate(([0], cut))
    ends = np.concatenate((cut - 1, [len(labels) - 1]))
    return [[labels[s], int(s), int(e)] for s, e in zip(starts, ends)]


class _RunList:
    """Runs as a doubly linked list (label, first and last frame of each), for debouncing in linear time."""

    def __init__(self, times: np.ndarray, runs: list[list], held: np.ndarray | None = None,
                 target: np.ndarray | None = None) -> None:
        n = len(runs)
        self.times = times
        # What the hand works on at each frame: what it holds, else what it acts on (None: not known).
        self.on = None if held is None or target is None else np.where(held != "", held, target)
        self.frame = frame_period(times)
        self.label = [r[0] for r in runs]
        self.first = [r[1] for r in runs]
        self.last = [r[2] for r in runs]
        self.prev = list(range(-1, n - 1))
        self.nxt = [*range(1, n), -1] if n else []
        self.alive = [True] * n
        self.count = n

    def length(self, k: int) -> float:
        """How long run ``k`` lasts: until the next frame, after a few dropped frames longer than one frame
        period (clock rounding does not count: only a gap of more than one and a half periods; a longer
        dropout counts three periods at most: what happened in it is unknown)."""
        times, last, frame = self.times, self.last[k], self.frame
        step = float(times[last + 1] - times[last]) if last + 1 < len(times) else frame
        return float(times[last] - times[self.first[k]]) + (min(step, 3 * frame) if step > 1.5 * frame else frame)

    def noise(self, k: int) -> bool:
        """Whether run ``k`` is jitter to absorb (see the module docstring)."""
        size = self.length(k)
        if size < JITTER_S:
            return True
        if self.prev[k] == -1 or self.nxt[k] == -1:
            return size < MIN_SEGMENT_S  # cut off by the trace's start or end
        same = self.label[self.prev[k]] == self.label[self.nxt[k]]
        return size < MIN_SEGMENT_S and same or size < REGRASP_S and self.regrasp(k)

    def regrasp(self, k: int) -> bool:
        """Whether run ``k`` interrupts one activity on one object (the runs beside it work on the same one), or
        one carry of an object (the runs beside it carry it: a re-grasp as the transport starts or ends)."""
        if self.on is None:
            return False
        before, after = self.on[self.last[self.prev[k]]], self.on[self.first[self.nxt[k]]]
        if not before or before != after:
            return False
        labels = (self.label[self.prev[k]], self.label[self.nxt[k]])
        return labels[0] == labels[1] or set(labels) <= CARRYING

    def remove(self, k: int) -> None:
        """Unlink run ``k``."""
        p, q = self.prev[k], self.nxt[k]
        if p != -1:
            self.nxt[p] = q
        if q != -1:
            self.prev[q] = p
        self.alive[k] = False
        self.count -= 1

    def order(self) -> list[int]:
        """The live runs, first to last."""
        k = next((i for i, a in enumerate(self.alive) if a and self.prev[i] == -1), -1)
        out = []
        while k != -1:
            out.append(k)
            k = self.nxt[k]
        return out

    def keyed(self, k: int) -> tuple[float, int, int]:
        """The heap entry of run ``k``: shortest first, then the earliest (the rule's order)."""
        return self.length(k), self.first[k], k

    def absorb(self, k: int) -> list[int]:
        """Merge noise run ``k`` into a neighbour (the start's or the end's into its only one, else the longer,
        the left on a tie), join its neighbours if they now touch with one label; the runs whose key or noise
        may have changed."""
        p, q = self.prev[k], self.nxt[k]
        if p == -1:
            self.first[q] = self.first[k]
        elif q == -1 or self.length(p) >= self.length(q):
            self.last[p] = self.last[k]
        else:
            self.first[q] = self.first[k]
        self.remove(k)
        touched = [x for x in (p, q) if x != -1]
        if p != -1 and q != -1 and self.label[p] == self.label[q]:
            self.last[p] = self.last[q]
            after = self.nxt[q]
            self.remove(q)
            touched = [p] + ([after] if after != -1 else [])
        return touched


def _debounce(times: np.ndarray, runs: list[list], held: np.ndarray | None = None,
              target: np.ndarray | None = None) -> list[list]:
    """Absorb jitter runs into their neighbours, shortest first (see the module docstring).

    The noise runs wait in a heap keyed by (length, first frame), the rule's order; a merge changes only the
    runs beside it, which are keyed again: linear in the runs up to the heap's logarithm."""
    import heapq

    rl = _RunList(times, runs, held, target)
    heap = [rl.keyed(k) for k in range(len(runs)) if rl.noise(k)]
    heapq.heapify(heap)
    while rl.count > 1 and heap:
        size, start, k = heapq.heappop(heap)
        if not rl.alive[k] or rl.first[k] != start or rl.length(k) != size or not rl.noise(k):
            continue  # stale: the run changed since (a fresh entry is in the heap if it is noise now)
        touched = rl.absorb(k)
        for x in touched:
            if rl.alive[x] and rl.noise(x):
                heapq.heappush(heap, rl.keyed(x))
    return [[rl.label[k], rl.first[k], rl.last[k]] for k in rl.order()]


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
    moving_take = onset & (labels == "Take")
    # Each run of such frames: where it starts (the frame before is not one) and the first frame after it.
    starts = np.flatnonzero(moving_take & ~np.concatenate(([False], moving_take[:-1])))
    ends = np.flatnonzero(moving_take & ~np.concatenate((moving_take[1:], [False]))) + 1
    for k, j in zip(starts, ends):
        if j < len(labels) and labels[j] in ("Put", "Stack") and times[j] - times[k] <= DETECTOR_LATENCY_S + 1e-9:
            labels[k:j] = labels[j]
    return labels


def _hand_segments(demo: Demonstration, labels: np.ndarray, hand: str) -> list[Segment]:
    """One hand's segments, without fluents yet."""
    frames = demo.frames
    idx = np.flatnonzero(frames["hand"].to_numpy(dtype=object) == hand)
    if idx.size == 0:
        return []
    times = frames["time"].to_numpy()[idx]
    all_held, all_target = frames["in_hand"].to_numpy(dtype=object)[idx], frames["act_on"].to_numpy(dtype=object)[idx]
    onset = frames["hand_move"].to_numpy(dtype=bool)[idx] & (all_held != "") & (all_target == all_held)
    hand_labels = _late_transports(times, labels[idx].copy(), onset)
    runs = _debounce(times, _lagged_reaches(times, _runs(times, hand_labels, all_held, all_target)), all_held,
                     all_target)
    held, target = all_held, all_target
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


def _states_at(demo: Demonstration, queries: list[tuple[float, bool, int]]) -> dict[int, frozenset[Atom]]:
    """The true fluents for each query (time, strictly before it?, key): the changes before the time, and
    at it unless strictly before; by key.  One sweep over the changes in time order."""
    state = set(demo.initial)
    out: dict[int, frozenset[Atom]] = {}
    events, i = demo.events, 0
    for t, strict, key in sorted(queries, key=lambda q: (q[0], not q[1])):
        while i < len(events) and (events[i][0] < t or (not strict and events[i][0] == t)):
            _, atom, value = events[i]
            (state.add if value else state.discard)(atom)
            i += 1
        out[key] = frozenset(state)
    return out


def segment(demo: Demonstration) -> list[Segment]:
    """Segments of both hands, in time order, Idle included."""
    labels = frame_labels(demo.frames, demo.objects)
    per_hand = {hand: _hand_segments(demo, labels, hand) for hand in ("left", "right")}
    caused = _attribute(demo, per_hand)
    # The world just before each segment acts: at its first own change, or where its effect window opens
    # (the other hand's changes until then included); one sweep over the changes answers every segment.
    queries: list[tuple[float, bool, int]] = []
    for segs in per_hand.values():
        for k, seg in enumerate(segs):
            own = caused[id(seg)]
            if own:
                queries.append((min(c[0] for c in own), True, id(seg)))
            elif k:
                queries.append((seg.start + EFFECT_DELAY_S, False, id(seg)))
    states = _states_at(demo, queries)
    out: list[Segment] = []
    for segs in per_hand.values():
        for k, seg in enumerate(segs):
            seg.changes = sorted(caused[id(seg)], key=lambda c: c[0])
            before = states.get(id(seg), demo.initial)
            seg.before, seg.after = frozenset(before), apply_changes(before, seg.changes)
            if seg.activity == "Manipulate":
                seg.activity = name_manipulation(seg.object, seg.before, seg.after)
            out.append(seg)
    out.sort(key=lambda s: (s.start, s.hand))
    for i, seg in enumerate(out):
        seg.index = i
    return out


def _most_common(values) -> str:
    from collections import Counter

    counts = Counter(str(v) for v in values if v)
    # The most frequent name, the first in name order among equals.
    return min(counts.items(), key=lambda kv: (-kv[1], kv[0]))[0] if counts else ""


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


def name_manipulation(obj: str, before: frozenset[Atom], after: frozenset[Atom]) -> str:
    """Open/Close for a drawer's ``open`` fluent, Push when the object moved otherwise."""
    if Atom("open", (obj,)) in after - before:
        return "Open"
    if Atom("open", (obj,)) in before - after:
        return "Close"
    if any(obj in a.args for a in after ^ before):
        return "Push"
    return "Manipulate"


def segments_document(demo: Demonstration, segments: list[Segment], state_path: str) -> dict:
    """The ``guided-lfd/segments`` JSON body (see docs/formats.md)."""
    def atoms(xs):
        return [str(a) for a in sorted(xs)]

    doc = {
        "trace": demo.path,
        "state": state_path,
        "objects": dict(sorted(demo.objects.items())),
        "spellings": dict(sorted(demo.spellings.items())),
        "initial": atoms(demo.initial),
        "segments": [segment_json(s) for s in segments],
    }
    if demo.vocabulary is not None:  # only where the state file declared it: older documents stay as they were
        doc["vocabulary"] = demo.vocabulary.to_dict()
    return doc


#: The columns of the segments CSV.
CSV_COLUMNS = ("index", "hand", "activity", "start", "end", "object", "target", "added", "deleted")


def segments_csv(segments: list[Segment], header: bool = True) -> str:
    """Segments as CSV (fluent lists joined with ``;``), with the header row unless told otherwise."""
    import csv
    import io

    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    if header:
        writer.writerow(CSV_COLUMNS)
    for s in segments:
        writer.writerow([s.index, s.hand, s.activity, f"{s.start:.4f}", f"{s.end:.4f}", s.object, s.target,
                         ";".join(str(a) for a in sorted(s.added)), ";".join(str(a) for a in sorted(s.deleted))])
    return buf.getvalue()


def segment_json(s: Segment) -> dict:
    """One segment as the segments document (and a JSON Lines stream) writes it."""
    def atoms(xs):
        return [str(a) for a in sorted(xs)]

    return {"index": s.index, "hand": s.hand, "activity": s.activity, "start": round(s.start, 4),
            "end": round(s.end, 4), "object": s.object, "target": s.target,
            "held_before": s.held_before, "held_after": s.held_after,
            "added": atoms(s.added), "deleted": atoms(s.deleted),
            "before": atoms(s.before), "after": atoms(s.after)}
