"""Streaming a trace where the window's rules are tested hardest: hands whose rows do not arrive together, a
segment open longer than a window (hands still, or gone from view), a stream cut short by a bad row, rows
and changes that come too late, a change outside the trace.  Each stream gives the whole file's segments or
refuses at the line that breaks what a stream can know."""

from __future__ import annotations

import csv
import io
from pathlib import Path

import pytest

from conftest import ROOT
from golden_segments import repeated, segment_key
from guided_lfd.demonstration.segment import segment
from guided_lfd.demonstration.stream import MAX_LAG_S, stream_segments
from guided_lfd.demonstration.trace import load_demonstration
from guided_lfd.errors import TraceError

K1 = ROOT / "data" / "demos" / "kitchen-1" / "P1-complete.csv"
K2 = ROOT / "data" / "demos" / "kitchen-2" / "P1-complete.csv"


def _whole(trace: Path, state: Path) -> list:
    return sorted(segment_key(s) for s in segment(load_demonstration(str(trace), str(state))))


def _streamed(data: bytes, state: Path, batch_rows: int, path: str = "-") -> list:
    return sorted(segment_key(s) for s in stream_segments(io.BytesIO(data), str(state), path, batch_rows=batch_rows))


def _state_of(trace: Path) -> Path:
    return trace.with_name(trace.stem + ".state.csv")


def _paused(trace: Path, at: float, seconds: float, folder: Path, hands=(), gone=False):
    """The recording paused for ``seconds`` from ``at``: each hand's last frame repeated at 60 Hz, except that
    ``hands`` have no frame at all if ``gone``; every later frame and change comes that much later."""
    header, *frames = trace.read_text().splitlines()
    rows: list[tuple[float, str]] = []
    last: dict[str, tuple[float, str]] = {}  # each hand's last frame up to ``at``
    for row in frames:
        t, rest = row.split(",", 1)
        if float(t) <= at:
            last[rest.split(",", 1)[0]] = (float(t), rest)
            rows.append((float(t), row))
        else:
            rows.append((float(t) + seconds, f"{float(t) + seconds:.4f},{rest}"))
    for hand in [h for h in last if not (gone and h in hands)]:
        start, rest = last[hand]
        rows += [(start + k / 60, f"{start + k / 60:.4f},{rest}") for k in range(1, int(seconds * 60))]
    rows.sort(key=lambda r: r[0])
    out, state = folder / "paused.csv", folder / "paused.state.csv"
    out.write_text(header + "\n" + "\n".join(r for _, r in rows) + "\n")
    table = list(csv.reader(io.StringIO(_state_of(trace).read_text())))
    shifted = [table[0]] + [[f"{float(t) + seconds:.4f}" if float(t) > at else t, f, v] for t, f, v in table[1:]]
    with state.open("w", newline="") as handle:
        csv.writer(handle, lineterminator="\n").writerows(shifted)
    return out, state


def _long(tmp_path: Path, copies: int = 8) -> tuple[Path, Path]:
    return repeated(K2.with_name("P3-complete.csv"), copies, tmp_path)


@pytest.mark.parametrize("late", [15.0, MAX_LAG_S - 1])
def test_a_hand_whose_rows_arrive_late_gives_the_whole_files_segments(late, tmp_path):
    """The format asks for time order per hand only: the right hand's rows may come that much later."""
    trace, state = _long(tmp_path)
    header, *rows = trace.read_bytes().splitlines(keepends=True)
    rows.sort(key=lambda r: float(r.split(b",")[0]) + (late if r.split(b",")[1] == b"right" else 0.0))
    assert _streamed(header + b"".join(rows), state, 97) == _whole(trace, state)


def test_a_hand_later_than_the_lag_is_refused_at_its_row(tmp_path):
    trace, state = _long(tmp_path)
    header, *rows = trace.read_bytes().splitlines(keepends=True)
    rows.sort(key=lambda r: (r.split(b",")[1] != b"left", float(r.split(b",")[0])))  # all left, then all right
    first_right = next(i for i, r in enumerate(rows) if r.split(b",")[1] == b"right")
    with pytest.raises(TraceError) as caught:
        _streamed(header + b"".join(rows), state, 1500)
    assert caught.value.location.line == first_right + 2
    assert str(caught.value).startswith(f"-:{first_right + 2}:1: trace error: column 'time': the right hand's row "
                                        "at 0 s arrives ")
    assert "expected each hand's rows within 60 s of the other's in a stream" in str(caught.value)


@pytest.mark.parametrize("trace, at", [(K1, 1.2), (K1, 3.61), (K1, 6.02), (K2, 13.12), (K2, 4.0)])
@pytest.mark.parametrize("gone", [False, True])
def test_a_segment_open_longer_than_a_window_keeps_its_start_and_changes(trace, at, gone, tmp_path):
    """Hands still (or out of view) for 75 s: the window is cut through their open segments, which carry
    their start, the world before them and their changes across the cut."""
    paused, state = _paused(trace, at, 75.0, tmp_path, hands=("right",), gone=gone)
    whole = _whole(paused, state)
    assert any(s[3] - s[2] > 60 for s in whole)  # a segment open longer than the window
    for batch in (30, 500):
        assert _streamed(paused.read_bytes(), state, batch) == whole


@pytest.mark.parametrize("source, batch", [("P1-complete.csv", 30), ("P1-complete.csv", 1500), ("P2-complete.csv", 300)])
def test_a_hand_idle_for_longer_than_a_window_has_the_changes_of_the_whole_file(source, batch, tmp_path):
    """Kitchen II repeated five times, the left hand idle throughout (75-180 s): the world's resets between
    copies are its changes in the file (no other hand acts then), from the first of them on."""
    trace, state = repeated(K2.with_name(source), 5, tmp_path)
    whole = _whole(trace, state)
    assert any(s[0] == "left" and s[3] - s[2] > 60 and s[8] for s in whole)
    assert _streamed(trace.read_bytes(), state, batch) == whole


def test_a_stream_cut_short_by_a_bad_row_is_the_recording_up_to_it(tmp_path):
    """Its segments are those of a file that ends at the row before, without the changes after that frame."""
    trace, state = _long(tmp_path, copies=3)
    lines = trace.read_text().splitlines(keepends=True)
    for at in (900, 2500):
        broken = "".join(lines[:at]) + "12.5,left,oops,0,0,open,,\n" + "".join(lines[at:])
        last = max(float(line.split(",", 1)[0]) for line in lines[1:at])
        (tmp_path / "ref.csv").write_text("".join(lines[:at]))
        kept = [r for r in state.read_text().splitlines(keepends=True)[1:] if float(r.split(",", 1)[0]) <= last + 0.1]
        (tmp_path / "ref.state.csv").write_text("time,fluent,value\n" + "".join(kept))
        got = []
        with pytest.raises(TraceError, match=f"-:{at + 1}:3: trace error: column 'x'"):
            for seg in stream_segments(io.BytesIO(broken.encode()), str(state), "-", batch_rows=97):
                got.append(segment_key(seg))
        assert sorted(got) == _whole(tmp_path / "ref.csv", tmp_path / "ref.state.csv")


def test_time_going_back_across_a_cut_is_refused_as_in_a_file(tmp_path):
    trace, state = _long(tmp_path, copies=3)
    lines = trace.read_text().splitlines(keepends=True)
    at = len(lines) - 100
    back = next(i for i in range(at, len(lines)) if lines[i].split(",")[1] == "left")
    lines.insert(back + 1, "2.0" + lines[back][lines[back].index(","):])
    with pytest.raises(TraceError, match=f"-:{back + 2}:1: trace error: column 'time': time goes backwards for the "
                                         "left hand"):
        _streamed("".join(lines).encode(), state, 97)


def test_a_change_after_the_trace_is_refused_once_the_stream_ends(tmp_path):
    """As for a file; the segments come first (a stream cannot know the trace's end before it comes)."""
    trace = K1
    state = tmp_path / "late.state.csv"
    state.write_text(_state_of(K1).read_text() + '60,"open(BlueDrawer)",true\n')
    got = []
    with pytest.raises(TraceError, match=r"late.state.csv:\d+:1: trace error: column 'time': a change at 60 s, "
                                         "outside the trace"):
        for seg in stream_segments(io.BytesIO(trace.read_bytes()), str(state), "-", batch_rows=97):
            got.append(segment_key(seg))
    assert sorted(got) == _whole(trace, _state_of(K1))


class _Recorder:
    """A trace read line by line while its state file is appended to, as a recorder that writes a change
    late would: after ``after`` lines, ``row`` is added to the state file."""

    def __init__(self, data: bytes, state: Path, after: int, row: str) -> None:
        self.lines = io.BytesIO(data).readlines()
        self.state, self.after, self.row, self.read = state, after, row, 0

    def readline(self) -> bytes:
        if self.read == self.after:
            with self.state.open("a") as handle:
                handle.write(self.row)
        self.read += 1
        return self.lines[self.read - 1] if self.read <= len(self.lines) else b""


def test_a_change_written_after_its_segments_is_refused_at_its_line(tmp_path):
    state = tmp_path / "growing.state.csv"
    text = _state_of(K1).read_text()
    state.write_text(text)
    source = _Recorder(K1.read_bytes(), state, after=1200, row='1.0,"open(BlueDrawer)",true\n')
    line = text.count("\n") + 1
    with pytest.raises(TraceError, match=f"growing.state.csv:{line}:1: trace error: column 'time': a change at 1 s "
                                         "reached the state file after the segments up to"):
        list(stream_segments(source, str(state), "-", batch_rows=97))


def _held_handle(folder: Path, unlocked_at: float) -> tuple[Path, Path]:
    """A right hand that reaches PinkDrawer's handle (0-0.8 s), holds it still for a minute and more, pulls it
    (75-76 s) and lets go (76-76.5 s); the left hand idle throughout.  The drawer is unlocked at ``unlocked_at``
    and comes open at 75.5 s: one Manipulate segment, open longer than a window, with a change before the
    window is first cut through it and one after."""
    rows = []
    for k in range(int(78 * 60) + 1):
        t = k / 60
        if t < 0.8:
            right = (0.1 + 0.5 * t, "open", "PinkDrawer")
        elif t < 75:
            right = (0.5, "closed", "PinkDrawer")
        elif t < 76:
            right = (0.5 - 0.2 * (t - 75), "closed", "PinkDrawer")
        elif t < 76.5:
            right = (0.3 - 0.4 * (t - 76), "open", "")
        else:
            right = (0.1, "open", "")
        x, grip, target = right
        rows.append(f"{t:.4f},right,{x:.4f},0.2000,0.9000,{grip},,{target}")
        rows.append(f"{t:.4f},left,-0.2000,0.2000,0.9000,open,,")
    trace, state = folder / "held.csv", folder / "held.state.csv"
    trace.write_text("time,hand,x,y,z,grip,in_hand,act_on\n" + "\n".join(rows) + "\n")
    state.write_text('time,fluent,value\n0,"object(PinkDrawer,drawer)",true\n0,locked(PinkDrawer),true\n'
                     f'{unlocked_at},locked(PinkDrawer),false\n75.5,open(PinkDrawer),true\n')
    return trace, state


@pytest.mark.parametrize("batch", [120, 500, 1500])
def test_a_segment_carried_across_cuts_keeps_what_it_added_after_them(batch, tmp_path):
    """The carried part deleted (locked pinkdrawer) before the cut; the part after it adds (open pinkdrawer).
    The joined segment has both (read off the state file: this hand alone handles the drawer), and is named
    Open for it."""
    trace, state = _held_handle(tmp_path, unlocked_at=10.0)
    long = ["right", "Open", 0.8, 75.9833, "pinkdrawer", "", "", "", ["(open pinkdrawer)"],
            ["(locked pinkdrawer)"]]
    whole = _whole(trace, state)
    assert [s for s in whole if s[3] - s[2] > 60 and s[0] == "right"] == [long]
    streamed = _streamed(trace.read_bytes(), state, batch)
    assert [s for s in streamed if s[3] - s[2] > 60 and s[0] == "right"] == [long]
    assert streamed == whole


@pytest.mark.parametrize("unlocked_at", [2.0, 5.0, 8.0])
@pytest.mark.parametrize("batch", [120, 500, 1500])
def test_a_change_in_the_first_seconds_of_a_segment_longer_than_a_window_is_kept(batch, unlocked_at, tmp_path):
    """A cut at most a window before the newest frame passes the change while the hand's kept frames still
    hold the whole segment (so it is not carried): the world is carried only up to the earliest kept frame,
    and the change stays the segment's."""
    trace, state = _held_handle(tmp_path, unlocked_at=unlocked_at)
    whole = _whole(trace, state)
    assert ["right", "Open", 0.8, 75.9833, "pinkdrawer", "", "", "", ["(open pinkdrawer)"],
            ["(locked pinkdrawer)"]] in whole
    assert _streamed(trace.read_bytes(), state, batch) == whole
