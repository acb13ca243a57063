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
* a segment open longer than :data:`MAX_WINDOW_S` (a hand idle for an hour)
  does not hold its frames: the window starts at most that long before the
  newest frame, and the segment, when it closes, keeps the start, the hand's
  state and the world before it from when it was first seen.

The segments are those ``segment`` finds in the whole file (tests check that
on every shipped and test trace), written in the order they close: the
``index`` of a streamed segment is its place in that order.  The state file
may grow while it is read (its rows in time order, as a recorder writes
them): it is read again, up to its last complete line, before each window.
"""

from __future__ import annotations

import io
import select
from collections.abc import Iterator
from dataclasses import replace
from typing import IO

import numpy as np


from guided_lfd.demonstration.segment import Segment, segment
from guided_lfd.demonstration.trace import (TRACE_COLUMNS, Demonstration, _csv, _times, load_state,
                                            trace_frame)
from guided_lfd.errors import Location, TraceError

__all__ = ["stream_segments", "MARGIN_S", "HORIZON_S", "MAX_WINDOW_S", "BATCH_ROWS"]

#: How far before the earliest open segment a window starts (s).
MARGIN_S = 3.0
#: How long after a hand's next segment starts a segment counts as closed (s).
HORIZON_S = 3.0
#: The longest stretch of recording a window holds (s).
MAX_WINDOW_S = 60.0
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

    pending = b""
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
        pending += chunk
        *complete, pending = pending.split(b"\n")
        for line in complete:
            yield line + b"\n"
    if pending:
        yield pending + b"\n"


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
        self.path, self.size = path, -1

    def grew(self) -> bool:
        """Whether the file is longer than when last read (a pipe or other non-file is read once)."""
        import os

        try:
            return os.path.isfile(self.path) and os.path.getsize(self.path) != self.size
        except OSError:
            return False

    def read(self):
        """``load_state`` of the file's complete lines."""
        from guided_lfd.pddl.source import read_text

        text = read_text(self.path, "an environment state CSV (time,fluent,value)")
        self.size = len(text.encode("utf-8"))
        complete = text[: text.rfind("\n") + 1] if "\n" in text else text
        return load_state(self.path, text=complete or text)


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

    def cut(self, start: float, times: np.ndarray) -> None:
        """Drop the rows before ``start`` (a row of either hand), carrying the world's state up to it."""
        if start <= self.start:
            return
        keep = times >= start
        self.rows = [r for r, k in zip(self.rows, keep) if k]
        self.lines = [n for n, k in zip(self.lines, keep) if k]
        state = set(self.initial)
        while self.applied < len(self.events) and self.events[self.applied][0] < start:
            _, atom, value = self.events[self.applied]
            (state.add if value else state.discard)(atom)
            self.applied += 1
        self.initial, self.start = frozenset(state), start


def stream_segments(source: IO[bytes], state_path: str, path: str = "-", batch_rows: int = BATCH_ROWS,
                    flush_s: float = 0.2) -> Iterator[Segment]:
    """The segments of the trace read from ``source`` (bytes, the CSV header first), each as soon as it closes
    (see the module docstring); the state file at ``state_path`` is read first.  A bad row is a TraceError
    naming its line, raised after every segment closed before it has been yielded."""
    from pathlib import Path

    state = _GrowingState(state_path)
    objects, initial, events, spellings, vocabulary = state.read()
    lines = _lines(source, flush_s)
    header = next((x for x in lines if x is not None), b"")
    if not header.strip():
        from guided_lfd.errors import InputFileError

        # As for a file: nothing at all is an input error (30), a header alone a trace error (36).
        raise InputFileError("empty file, expected a hand trace CSV (time,hand,x,y,z,grip,in_hand,act_on)",
                             Location(path))
    window = _Window(header if header.endswith(b"\n") else header + b"\n", initial, events)
    written: dict[str, float] = {}  # the end of each hand's last written segment
    first_seen: dict[str, Segment] = {}  # each hand's earliest open segment, as seen while whole
    def close(final: bool) -> Iterator[Segment]:
        nonlocal objects, spellings, vocabulary
        if state.grew():  # the recorder wrote more of the world's changes
            objects, _, window.events, spellings, vocabulary = state.read()
        return _close(window, path, objects, spellings, vocabulary, Path(state_path).name, written, first_seen,
                      final)

    try:
        rows = 0
        for batch, numbers in _batches(lines, batch_rows):
            window.rows += batch
            window.lines += numbers
            rows += len(batch)
            yield from close(False)
        if rows == 0:
            raise TraceError("no rows after the header", Location(path, 2))
        yield from close(True)
    except TraceError as exc:
        # The recording up to the bad row is segmented and written before the error ends the stream.
        bad = exc.location.line if exc.location is not None and exc.location.line is not None else None
        if bad is None or bad not in window.lines:
            raise
        keep = window.lines.index(bad)
        window.rows, window.lines = window.rows[:keep], window.lines[:keep]
        yield from close(True)
        raise exc


def _close(window: _Window, path: str, objects, spellings, vocabulary, state_name: str,
           written: dict[str, float], first_seen: dict[str, Segment], final: bool) -> Iterator[Segment]:
    """Segment the window; yield the segments closed since the last call, in time order; move the window on.

    A hand's segments are told apart by their end (they follow each other): one that ends no later than the
    last written one was written already, whatever start a cut window gave it."""
    if not window.rows:
        return
    frame = window.frame(path, objects, state_name)
    times = frame["time"].to_numpy()
    demo = Demonstration(frame, objects, window.initial, window.events[window.applied:], spellings, path,
                         vocabulary)
    now = float(times.max())
    per_hand: dict[str, list[Segment]] = {}
    for seg in segment(demo):
        per_hand.setdefault(seg.hand, []).append(seg)
    closed: list[Segment] = []
    open_starts: list[float] = []
    for hand, segs in per_hand.items():
        for k, seg in enumerate(segs):
            if seg.end <= written.get(hand, float("-inf")) + 1e-9:
                continue
            truncated = k == 0 and window.start > float("-inf")  # its start may lie before the window
            if not (final or (k + 1 < len(segs) and segs[k + 1].start < now - HORIZON_S)):
                if not truncated:
                    first_seen[hand] = seg
                open_starts.append(first_seen[hand].start if hand in first_seen else seg.start)
                break
            earlier = first_seen.pop(hand, None)
            if truncated and earlier is not None and earlier.start < seg.start:
                # Open longer than a window holds: its start, hand and world from when it was seen whole.
                seg = replace(seg, start=earlier.start, held_before=earlier.held_before, before=earlier.before,
                              after=frozenset((earlier.before - seg.deleted) | seg.added))
            written[hand] = seg.end
            closed.append(seg)
    yield from sorted(closed, key=lambda s: (s.start, s.hand))
    if not final:
        start = min(open_starts, default=now - HORIZON_S) - MARGIN_S
        window.cut(max(start, now - MAX_WINDOW_S), times)
