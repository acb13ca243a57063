"""Segmenting a trace while it is recorded (issue #30): the streamed segments are the whole file's, a pipe's
segments come out before the recorder has finished, and a bad row late in a stream keeps what came before."""

from __future__ import annotations

import json
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from conftest import ROOT
from golden_segments import GOLDEN, repeated, segment_key
from guided_lfd.demonstration.stream import stream_segments
from guided_lfd.demonstration.trace import default_state_path

RECORDED = {d["trace"]: d["segments"] for d in map(json.loads, GOLDEN.read_text().splitlines())}
K1 = ROOT / "data" / "demos" / "kitchen-1" / "P1-complete.csv"


def _streamed(trace: Path, state: Path, batch_rows: int) -> list[list]:
    with trace.open("rb") as source:
        return sorted(segment_key(s) for s in stream_segments(source, str(state), str(trace), batch_rows=batch_rows))


@pytest.mark.parametrize("name", sorted(RECORDED))
def test_a_streamed_trace_gives_the_whole_files_segments(name):
    trace = ROOT / name
    assert _streamed(trace, Path(default_state_path(str(trace))), batch_rows=97) == sorted(RECORDED[name])


@pytest.mark.parametrize("source", ["data/demos/kitchen-2/P3-complete.csv", "tests/data/traces/cupboard/field-20hz/D2.csv",
                                    "tests/data/traces/stacking/drops-dups/D1.csv"])
def test_a_long_recording_streamed_in_windows_gives_the_whole_files_segments(source, tmp_path):
    """Eight copies end to end (two to three minutes): windows are cut behind the segments already written
    and a hand idle throughout outlasts the longest window."""
    from guided_lfd.demonstration.segment import segment
    from guided_lfd.demonstration.trace import load_demonstration

    trace, state = repeated(ROOT / source, 8, tmp_path)
    whole = sorted(segment_key(s) for s in segment(load_demonstration(str(trace))))
    assert _streamed(trace, state, batch_rows=1500) == whole


def _pipe(state: Path, *flags: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-c", "from cli.main import run; run()", "segment", "-", "--state",
                             str(state), *flags], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, cwd=ROOT)


def test_a_piped_recording_gives_its_first_segments_before_it_ends(tmp_path):
    """The recorder writes half its frames and waits: segments must come out then (a tool that waited for the
    end would never answer, and the test would fail on its timeout, not on the machine's speed)."""
    trace, state = repeated(K1, 6, tmp_path)
    lines = trace.read_bytes().splitlines(keepends=True)
    half = len(lines) // 2
    # The recorder writes the state file as it goes too: so far only what happened in the first half.
    half_time = float(lines[half].split(b",")[0])
    state_rows = state.read_bytes().splitlines(keepends=True)
    later = [r for r in state_rows[1:] if not r.startswith(b"0,") and float(r.split(b",")[0]) >= half_time]
    growing = tmp_path / "growing.state.csv"
    growing.write_bytes(b"".join(r for r in state_rows if r not in later))
    proc = _pipe(growing, "--csv")
    proc.stdin.write(b"".join(lines[:half]))
    proc.stdin.flush()
    got: list[bytes] = []
    reader = threading.Thread(target=lambda: got.extend(proc.stdout.readline() for _ in range(2)))
    reader.start()
    reader.join(timeout=120)  # the header, then the first segment, while the recorder still holds the rest
    assert not reader.is_alive(), "no segment before the recording ended"
    assert got[0].startswith(b"index,hand,activity") and got[1].count(b",") >= 8
    with growing.open("ab") as more:
        more.write(b"".join(later))
    proc.stdin.write(b"".join(lines[half:]))
    proc.stdin.close()
    with proc.stdout, proc.stderr:
        rest, err = proc.stdout.read(), proc.stderr.read()
    assert proc.wait(timeout=120) == 0, err
    whole = subprocess.run([sys.executable, "-c", "from cli.main import run; run()", "segment", str(trace), "--csv"],
                           capture_output=True, cwd=ROOT, check=True).stdout

    def rows(text: bytes) -> list[bytes]:  # a segment without its index (the stream counts in closing order)
        return sorted(line.split(b",", 1)[1] for line in text.splitlines()[1:] if line)

    # Every segment of the file, with the changes the recorder wrote after the stream started.
    assert rows(b"".join(got) + rest) == rows(whole)


def test_a_bad_row_late_in_a_stream_keeps_the_segments_before_it(tmp_path):
    trace, state = repeated(K1, 6, tmp_path)
    lines = trace.read_bytes().splitlines(keepends=True)
    bad = len(lines) - 40
    lines[bad] = b"12x,right,0.1,0.2,0.9,open,,\n"
    proc = _pipe(state, "--jsonl")
    out, err = proc.communicate(b"".join(lines), timeout=120)
    assert proc.returncode == 36
    assert f"-:{bad + 1}:1: trace error: column 'time': expected a finite number, got '12x'" in err.decode()
    assert len(out.splitlines()) > 10 and all(json.loads(line)["hand"] for line in out.splitlines())


@pytest.mark.parametrize("given, code, message", [
    (b"", 30, "-: input error: empty file, expected a hand trace CSV"),
    (b"time,hand,x,y,z,grip,in_hand,act_on\n", 36, "-:2: trace error: no rows after the header"),
])
def test_an_empty_stream_is_refused_as_an_empty_file_is(given, code, message):
    proc = _pipe(ROOT / "data" / "demos" / "kitchen-1" / "P1-complete.state.csv", "--csv")
    out, err = proc.communicate(given, timeout=120)
    assert proc.returncode == code and message in err.decode() and b"Traceback" not in err


def test_two_formats_for_a_pipe_are_refused_as_for_a_file():
    proc = _pipe(ROOT / "data" / "demos" / "kitchen-1" / "P1-complete.state.csv", "--csv", "--json")
    out, err = proc.communicate(K1.read_bytes(), timeout=120)
    assert proc.returncode == 37 and "--csv and --json: choose one output format" in err.decode() and not out


def test_a_bad_row_after_blank_lines_is_named_at_its_line_in_a_file_and_in_a_pipe(runner, app):
    """Blank lines count as lines (pandas skips them; the numbers used to fall two short, lines 4 for 6)."""
    trace = ROOT / "tests" / "data" / "regressions" / "odd-traces" / "blank-lines.csv"
    state = default_state_path(str(trace))
    message = "6:3: trace error: column 'x': expected a finite number, got 'zz'"
    result = runner.invoke(app, ["segment", str(trace)])
    assert result.exit_code == 36 and f"{trace}:{message}" in result.stderr
    proc = _pipe(Path(state), "--csv")
    _, err = proc.communicate(trace.read_bytes(), timeout=120)
    assert proc.returncode == 36 and f"-:{message}" in err.decode()
