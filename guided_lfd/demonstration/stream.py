"""Segmenting a trace while it is recorded: bounded memory, segments out as soon as they close.

A recorder pipes frames in (``guided-lfd segment - --state S --csv``); the
trace is read in batches of rows, and each batch is segmented together with
the rows it needs from before it, in a *window*:

* the window starts :data:`MARGIN_S` before the earliest segment not yet
  written, so that every rule that looks back (the speed window, debouncing
  of short runs, the hand's state at a boundary, which segment a change
  belongs to) sees what it would see in the whole trace;
* a segment is *closed*, and written, once the hand's next segment started
  more than :data:`HORIZON_S` before the newest frame: nothing recorded later
  can move its end (the rules look ahead a fraction of a second);
* "newest" is the older of the two hands' newest frames: a hand's rows may
  arrive up to :data:`MAX_LAG_S` behind the other's (the format asks for time
  order per hand only), and a row later than that is refused at its line, as
  is a row going back in time for its hand, so no segment is written before
  every row that could change it has come.  A hand not seen yet counts as
  that far behind, so a one-handed recording's segments come out a minute late;
* each hand keeps its last frames before a cut (``2 * MARGIN_S``), so what a
  hand does after a gap in its frames is read as in the file (a segment goes
  on across a gap); the world's state is carried up to the earliest frame
  kept, so a change among those frames stays the segment's that holds it;
* a segment open longer than :data:`MAX_WINDOW_S` (a hand idle for an hour)
  does not hold its frames: the window starts at most that long before the
  newest frame, and the segment is carried across the cut: its start, the
  hand's state and the world before it from when it was seen whole, and every
  change it made on either side of the cut.  The segments within
  :data:`MARGIN_S` after the cut are artefacts of the cut (the speed and
  debouncing rules lack their look-back there) and are passed over.

The segments are those ``segment`` finds in the whole file (tests check that
on every shipped and test trace), written in the order they close: the
``index`` of a streamed segment is its place in that order.  The state file
may grow while it is read (its rows in time order, as a recorder writes
them): it is read again, up to its last complete line, before each window.
A change it gains after the segments of its time were written (written more
than :data:`HORIZON_S` late) is refused at its line, and so, once the trace
ends, is a change outside the trace's span, as for a file.  A stream cut
short by a bad row is segmented as a recording that ended at the row before
it: the state file's changes after that are not its own.
"""

from __future__ import annotations

import bisect
import io
import select
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path
from typing import IO

import numpy as np

from guided_lfd.demonstration.segment import MANIPULATIONS, Segment, name_manipulation, segment
from guided_lfd.demonstration.trace import (EFFECT_DELAY_S, HANDS, TRACE_COLUMNS, Demonstration, _csv, _times,
                                            apply_changes, load_state, trace_frame)
from guided_lfd.errors import Location, TraceError

__all__ = ["stream_segments", "MARGIN_S", "HORIZON_S", "MAX_WINDOW_S", "MAX_LAG_S", "BATCH_ROWS"]

#: How far before the earliest open segment a window starts (s).
MARGIN_S = 3.0
#: How long after a hand's next segment starts a segment counts as closed (s).
HORIZON_S = 3.0
#: The longest stretch of recording a window holds (s).
MAX_WINDOW_S = 60.0
#: How far behind the other hand's newest frame a hand's rows may arrive (s).
MAX_LAG_S = 60.0
#: Seconds between two windows of a pipe that never pauses (a recorder writing frames as they happen).
FLUSH_EVERY_S = 1.0
#: Rows read before a window is segmented (fewer when the pipe pauses: see ``flush_s``).
BATCH_ROWS = 60_000


def _lines(source: IO[bytes], flush_s: float) -> Iterator[bytes | None]:
    """The lines of ``source`` as they arrive, and None whenever the source pauses for ``flush_s`` seconds
    with lines read (a live recorder's latest frames are segmented without waiting for more).  A pipe or
    terminal is read through its descriptor, so nothing waits in a buffer the pause check cannot see."""
    import os

    try:
        fd = source.fileno()
        os.fstat(fd)
    except (AttributeError, OSError, ValueError, io.UnsupportedOperation):
        fd = None
    if fd is None or not _is_stream(fd):
        yield from iter(source.readline, b"")
        return
    import time

    pending: list[bytes] = []  # the part of a line read so far (joined once its end comes: a long line stays linear)
    flushed = time.monotonic()
    while True:
        ready, _, _ = select.select([fd], [], [], flush_s)
        if not ready:
            yield None  # a pause: what came so far is worth segmenting now
            flushed = time.monotonic()
            ready, _, _ = select.select([fd], [], [])
        elif time.monotonic() - flushed > FLUSH_EVERY_S:
            yield None  # a recorder that never pauses: segment what came at least this often
            flushed = time.monotonic()
        chunk = os.read(fd, 1 << 16)
        if not chunk:
            break
        if b"\n" not in chunk:
            pending.append(chunk)
            continue
        *complete, rest = b"".join(pending + [chunk]).split(b"\n")
        pending = [rest] if rest else []
        for line in complete:
            yield line + b"\n"
    if pending:
        yield b"".join(pending) + b"\n"


def _is_stream(fd: int) -> bool:
    """Whether ``fd`` is a pipe, socket or terminal (a regular file never pauses)."""
    import os
    import stat

    mode = os.fstat(fd).st_mode
    return stat.S_ISFIFO(mode) or stat.S_ISSOCK(mode) or stat.S_ISCHR(mode)


def _batches(lines: Iterator[bytes | None], batch_rows: int, first: int = 2) -> Iterator[tuple[list[bytes], list[int]]]:
    """Lists of at most ``batch_rows`` non-blank lines with their line numbers (the first line read is line
    ``first``; blank lines count, as in the file), cut early where the source paused."""
    batch: list[bytes] = []
    numbers: list[int] = []
    number = first - 1
    for line in lines:
        if line is None:
            if batch:
                yield batch, numbers
                batch, numbers = [], []
            continue
        number += 1
        if line.strip():
            batch.append(line)
            numbers.append(number)
        if len(batch) >= batch_rows:
            yield batch, numbers
            batch, numbers = [], []
    if batch:
        yield batch, numbers


class _GrowingState:
    """A state file a recorder may still be writing: read up to its last complete line, again when it grew."""

    def __init__(self, path: str) -> None:
        self.path, self.size, self.text = path, -1, ""

    def grew(self) -> bool:
        """Whether the file is longer than when last read (a pipe or other non-file is read once)."""
        import os

        try:
            return os.path.isfile(self.path) and os.path.getsize(self.path) != self.size
        except OSError:
            return False

    def read(self, settled: float = float("-inf")):
        """``load_state`` of the file's complete lines; a TraceError at the first line added since the last
        read whose change is at or before ``settled`` (the segments of its time are written already)."""
        from guided_lfd.io import read_text

        text = read_text(self.path, "an environment state CSV (time,fluent,value)")
        self.size = len(text.encode("utf-8"))
        complete = text[: text.rfind("\n") + 1] if "\n" in text else text
        before, self.text = self.text, complete or text
        if before and self.text.startswith(before):
            self._check_added(before, settled)
        return load_state(self.path, text=self.text)

    def _check_added(self, before: str, settled: float) -> None:
        """Refuse a change added after the segments of its time were written (the recorder wrote it late)."""
        import csv

        first = before.count("\n") + 1
        for offset, row in enumerate(csv.reader(io.StringIO(self.text[len(before):]))):
            try:
                when = float(row[0]) if row else float("nan")
            except ValueError:
                continue  # load_state names a malformed row itself
            if when <= settled:
                raise TraceError(f"column 'time': a change at {when:g} s reached the state file after the "
                                 f"segments up to {settled:g} s were written; expected each change within "
                                 f"{HORIZON_S:g} s of its frame", Location(self.path, first + offset, 1))

    def check_span(self, span: tuple[float, float]) -> None:
        """As for a file: a change outside the trace's span (up to the effect delay after it) is a TraceError."""
        load_state(self.path, span, text=self.text)


class _Window:
    """The rows a window holds, their file lines and the world's state where the window starts."""

    def __init__(self, header: bytes, initial: frozenset, events: list) -> None:
        self.header = header
        self.rows: list[bytes] = []
        self.lines: list[int] = []  # each row's line in the file (the header is line 1)
        self.initial = initial
        self.events = events  # every change of the state file, in time order
        self.applied = 0  # changes before the window's start, applied to ``initial``
        self.start = float("-inf")
        self.hand_start: dict[str, float] = {hand: self.start for hand in HANDS}  # a hand's rows from here

    def frame(self, path: str, objects: dict[str, str], state_name: str):
        """The window's rows as a checked trace frame (a bad cell named at its line in the whole file)."""
        text = (self.header + b"".join(self.rows)).decode("utf-8-sig", errors="replace")
        try:
            frame = _csv(text, "-", TRACE_COLUMNS, numeric=("time", "x", "y", "z"))
            times = _times(frame, path)
            return trace_frame(frame, times, path, objects, state_name)
        except TraceError as exc:
            loc = exc.location
            if loc is not None and loc.line is not None and loc.line >= 2 and loc.line - 2 < len(self.lines):
                raise TraceError(exc.message, Location(path, self.lines[loc.line - 2], loc.col)) from None
            raise TraceError(exc.message, Location(path, loc.line if loc else None, loc.col if loc else None)) from None

    def cut(self, start: float, times: np.ndarray, hands: np.ndarray, tails: dict[str, float]) -> None:
        """Drop the rows before ``start`` (a row of either hand) but a hand's rows from its ``tails`` time on,
        carrying the world's state up to ``start``."""
        for hand in HANDS:
            self.hand_start[hand] = min(start, tails.get(hand, start))
        if start <= self.start:
            return
        keep = times >= start
        for hand, tail in tails.items():
            keep |= (hands == hand) & (times >= tail)
        self.rows = [r for r, k in zip(self.rows, keep) if k]
        self.lines = [n for n, k in zip(self.lines, keep) if k]
        # The world is carried up to the earliest frame kept, not to ``start``: a change among a hand's kept
        # frames may still be an open segment's (one a hand's frames hold whole is not carried).
        done = bisect.bisect_left(self.events, self.world_start, lo=self.applied, key=lambda e: e[0])
        self.initial = apply_changes(self.initial, self.events[self.applied:done])
        self.applied, self.start = done, start

    @property
    def world_start(self) -> float:
        """The time of the earliest frame the window may hold: where its initial state stands."""
        return min(self.hand_start.values())


def _carried(carry: Segment, seg: Segment) -> Segment:
    """``seg``, the part after a cut of a segment open longer than a window, joined to ``carry``, what came
    before the cut: its start, the hand and the world before it, and its changes on both sides (a
    manipulation named by all of them)."""
    if carry.after != carry.before:
        before, after = carry.before, frozenset((carry.after - seg.deleted) | seg.added)
    elif seg.after != seg.before:  # its first change comes after the cut: the world just before it is the part's
        before, after = seg.before, seg.after
    else:
        before, after = carry.before, carry.after
    activity = seg.activity
    if activity in MANIPULATIONS:
        activity = name_manipulation(seg.object, before, after)
    return replace(seg, activity=activity, start=carry.start, held_before=carry.held_before, before=before,
                   after=after)


class _Stream:
    """What the stream knows between windows: the hands' newest frames, the segments written and carried."""

    def __init__(self, header: bytes, state: _GrowingState, path: str) -> None:
        self.state, self.path = state, path
        self.world = state.read()
        self.window = _Window(header, self.world[1], self.world[2])
        self.newest: dict[str, float] = {}  # each hand's newest frame
        self.latest = float("-inf")  # the newest frame of either hand
        self.first = float("inf")  # the earliest frame
        self.checked = 0  # the window's rows already checked for their arrival
        self.settled = float("-inf")  # the segments before this time are written
        self.written: dict[str, float] = {}  # the end of each hand's last written segment
        self.carry: dict[str, Segment] = {}  # each hand's open segment a cut went through, up to the cut

    def now(self) -> float:
        """The time up to which both hands' rows have come (a hand more than the lag behind does not hold it)."""
        both = min(self.newest.get(hand, float("-inf")) for hand in HANDS)
        return max(both, self.latest - MAX_LAG_S)

    def arrived(self, times: np.ndarray, hands: np.ndarray) -> None:
        """Check the rows not yet checked: none goes back in time for its hand, none comes later than the lag;
        then take their times in."""
        n = len(times)
        if self.checked >= n:
            return
        new, who = times[self.checked:], hands[self.checked:]
        ahead = np.maximum.accumulate(np.concatenate(([self.latest], new)))[:-1]
        wrong: list[tuple[int, str]] = []  # (row, what is wrong with it): the first one is reported
        late = np.flatnonzero(new < ahead - MAX_LAG_S)
        if late.size:
            i = int(late[0])
            wrong.append((i, f"the {who[i]} hand's row at {new[i]:g} s arrives {ahead[i] - new[i]:g} s behind a "
                             f"frame at {ahead[i]:g} s already read; expected each hand's rows within "
                             f"{MAX_LAG_S:g} s of the other's in a stream (give the file's path to segment it whole)"))
        for hand in HANDS:  # within the window trace_frame checks it; this is across a cut
            mine = np.flatnonzero(who == hand)
            if mine.size and new[mine[0]] < self.newest.get(hand, float("-inf")):
                i = int(mine[0])
                wrong.append((i, f"time goes backwards for the {hand} hand ({self.newest[hand]:g} s, then "
                                 f"{new[i]:g} s)"))
        if wrong:
            i, why = min(wrong)
            raise TraceError(f"column 'time': {why}", Location(self.path, self.window.lines[self.checked + i], 1))
        for hand in HANDS:
            mine = new[who == hand]
            if mine.size:
                self.newest[hand] = max(self.newest.get(hand, float("-inf")), float(mine.max()))
        self.latest = max(self.latest, float(new.max()))
        self.first = min(self.first, float(new.min()))
        self.checked = n

    def close(self, final: bool) -> list[Segment]:
        """Segment the window; the segments closed since the last call, in time order; move the window on."""
        window, state = self.window, self.state
        if state.grew():  # the recorder wrote more of the world's changes
            self.world = state.read(self.settled)
            window.events = self.world[2]
        if not window.rows:
            return []
        objects, _, _, spellings, vocabulary = self.world
        frame = window.frame(self.path, objects, Path(state.path).name)
        times, hands = frame["time"].to_numpy(), frame["hand"].to_numpy()
        self.arrived(times, hands)
        # Changes after the newest frame are not yet anyone's (an open segment would claim them all), and a
        # stream cut short by a bad row ends there.  After a cut through an open segment, the changes within
        # the margin after the cut are the carried part's (the segments there are the cut's artefacts).
        edge = window.start + MARGIN_S if self.carry else window.world_start
        first = bisect.bisect_left(window.events, edge, lo=window.applied, key=lambda e: e[0])
        until = bisect.bisect_right(window.events, self.latest + EFFECT_DELAY_S, lo=first, key=lambda e: e[0])
        demo = Demonstration(frame, objects, apply_changes(window.initial, window.events[window.applied:first]),
                             window.events[first:until], spellings, self.path, vocabulary)
        per_hand: dict[str, list[Segment]] = {}
        for seg in segment(demo):
            per_hand.setdefault(seg.hand, []).append(seg)
        now = self.now()
        closed: list[Segment] = []
        opened: dict[str, Segment] = {}  # each hand's earliest open segment, as this window has it
        for hand, segs in per_hand.items():
            seg = self._hand(hand, segs, now, final, closed)
            if seg is not None:
                opened[hand] = seg
        if not final:
            self.settled = max(self.settled, now - HORIZON_S)
            starts = [self.carry[h].start if h in self.carry else s.start for h, s in opened.items()]
            start = max(min(starts, default=now - HORIZON_S) - MARGIN_S, now - MAX_WINDOW_S)
            # Each hand keeps its last frames before the cut, for the rules that look back (across a gap in
            # its frames too: a segment goes on across one).
            tails = {}
            for hand in HANDS:
                before = times[(hands == hand) & (times < start)]
                if before.size:
                    tails[hand] = float(before.max()) - 2 * MARGIN_S
            window.cut(start, times, hands, tails)
            self.carry = self._carried_over(opened)
            self.checked = len(window.rows)
        return sorted(closed, key=lambda s: (s.start, s.hand))

    def _carried_over(self, opened: dict[str, Segment]) -> dict[str, Segment]:
        """The open segments the window's last cut went through (or through the margin before them), each as
        far as the cut: its start, the hand and world before it, and its own changes up to the margin after
        the cut (the next window's segments there are the cut's artefacts)."""
        cut = self.window.start + MARGIN_S
        carry = {}
        for hand, seg in opened.items():
            if self.window.hand_start[hand] <= (self.carry[hand].start if hand in self.carry else seg.start) - MARGIN_S:
                continue  # the cut is before it and its margin
            early = [c for c in seg.changes if c[0] < cut]
            # A part without a change of its own keeps after == before: the world before its first change is
            # then the later part's (see _carried).
            part = seg if len(early) == len(seg.changes) else replace(seg, after=apply_changes(seg.before, early))
            carry[hand] = _carried(self.carry[hand], part) if hand in self.carry else part
        return carry

    def _hand(self, hand: str, segs: list[Segment], now: float, final: bool,
              closed: list[Segment]) -> Segment | None:
        """Add the hand's segments that closed to ``closed``; its earliest open one, if any, as in the window.

        A hand's segments are told apart by their end (they follow each other): one that ends no later than
        the last written one was written already, whatever start a cut window gave it."""
        carry = self.carry.get(hand)
        edge = self.window.hand_start[hand] + MARGIN_S  # segments ending before this are a cut's artefacts
        for k, seg in enumerate(segs):
            if seg.end <= self.written.get(hand, float("-inf")) + 1e-9:
                continue
            if carry is not None and seg.end <= edge:
                continue
            if not (final or (k + 1 < len(segs) and segs[k + 1].start < now - HORIZON_S)):
                return seg
            if carry is not None:
                seg, carry = _carried(carry, seg), None
                self.carry.pop(hand)
            self.written[hand] = seg.end
            closed.append(seg)
        return None


def stream_segments(source: IO[bytes], state_path: str, path: str = "-", batch_rows: int = BATCH_ROWS,
                    flush_s: float = 0.2) -> Iterator[Segment]:
    """The segments of the trace read from ``source`` (bytes, the CSV header first), each as soon as it closes
    (see the module docstring); the state file at ``state_path`` is read first.  A bad row is a TraceError
    naming its line, raised after every segment closed before it has been yielded."""
    lines = _lines(source, flush_s)
    header = next((x for x in lines if x is not None), b"")
    if not header.strip():
        from guided_lfd.errors import InputFileError

        # As for a file: nothing at all is an input error (30), a header alone a trace error (36).
        raise InputFileError("empty file, expected a hand trace CSV (time,hand,x,y,z,grip,in_hand,act_on)",
                             Location(path))
    stream = _Stream(header if header.endswith(b"\n") else header + b"\n", _GrowingState(state_path), path)
    window = stream.window
    try:
        rows = 0
        for batch, numbers in _batches(lines, batch_rows):
            window.rows += batch
            window.lines += numbers
            rows += len(batch)
            yield from stream.close(False)
        if rows == 0:
            raise TraceError("no rows after the header", Location(path, 2))
        yield from stream.close(True)
    except TraceError as exc:
        # The recording up to the bad row is segmented and written before the error ends the stream.
        loc = exc.location
        if loc is None or loc.path != path or loc.line is None or loc.line not in window.lines:
            raise
        keep = window.lines.index(loc.line)
        window.rows, window.lines = window.rows[:keep], window.lines[:keep]
        yield from stream.close(True)
        raise exc
    stream.state.check_span((stream.first, stream.latest))
