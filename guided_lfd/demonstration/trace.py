"""The hand-trace format of a VR demonstration, and its strict reader.

A demonstration is two CSV files.

**The trace** (``demo.csv``): one row per frame and hand.

============  =========================================================
column        meaning
============  =========================================================
``time``      seconds since the start, non-decreasing for each hand
``hand``      ``left`` or ``right``
``x y z``     the hand's position in metres (world frame)
``grip``      ``open`` or ``closed`` (also ``0``/``1``)
``in_hand``   the object held by the hand, empty when none
``act_on``    the object the hand acts on or moves toward, empty when none
============  =========================================================

Extra columns are kept and ignored.  ``hand_move`` is *derived*: the hand
moves in a frame when its speed, measured as the displacement over a window
of :data:`MOVE_WINDOW_S` centred on the frame, exceeds
:data:`MOVE_THRESHOLD_M_S`.  The window makes the speed robust to tracking
noise (millimetres per frame at 90 Hz would otherwise read as 0.3 m/s).

**The environment state** (``demo.state.csv``, next to the trace): the
symbolic fluents as they change, long format, columns ``time``, ``fluent``,
``value`` (``true``/``false``); fluents with commas are quoted, as CSV
requires (``0,"inside(RedPlate,PinkDrawer)",true``).  Rows ``object(Name,type)`` declare the scene's
objects; rows at the first time list the initial state (fluents not listed
are false); later rows are changes, e.g. ``12.48,open(PinkDrawer),true``.
Fluents are written ``pred(Arg,...)``: ``inside(A,B)``, ``on_top(A,B)``,
``clear(X)``, ``open(X)``, ``graspable(X)``, ``blocking(C,F)``, ...
Predicates and types end up in a learned PDDL domain, so they are PDDL names
(an ASCII letter, then letters, digits, ``-``, ``_``; no keyword, and no type
named like a predicate).  The hand's facts come from the trace, never from
this file: ``in_hand`` and ``hand_free`` unless rows
``vocabulary(held=holding)``, ``vocabulary(free=hand-empty)`` (and, for
arms that are objects, ``vocabulary(right=rarm)``) or ``vocabulary(none)``
name the robot's own (see :mod:`guided_lfd.demonstration.vocabulary`).  A fluent has one value at a time and one arity, and
every change falls within the trace's frames (up to :data:`EFFECT_DELAY_S`
after the last one): no hand can have caused it otherwise.
"""

from __future__ import annotations

import bisect
import io
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from guided_lfd.errors import Location, TraceError
from guided_lfd.pddl.model import PDDL_NAME, PDDL_RESERVED, Atom, pddl_name_defect
from guided_lfd.io import read_text
from guided_lfd.demonstration.vocabulary import HandVocabulary, parse_vocabulary_row, vocabulary_of
from guided_lfd.demonstration import default_state_path  # noqa: F401  (re-exported: where callers look for it)

TRACE_COLUMNS = ("time", "hand", "x", "y", "z", "grip", "in_hand", "act_on")
STATE_COLUMNS = ("time", "fluent", "value")
HANDS = ("left", "right")
#: Fluents of the hand: derived from the trace's ``in_hand`` column, never part
#: of the environment state.
HAND_PREDICATES = ("in_hand", "hand_free")
#: Speed above which a hand counts as moving (m/s).
MOVE_THRESHOLD_M_S = 0.10
#: Window over which the speed is measured (s), centred on the frame.
MOVE_WINDOW_S = 0.10
#: Fluent changes this long after a hand's segment still belong to it (s); a
#: change later than this after the trace's last frame has no hand to cause it.
EFFECT_DELAY_S = 0.1
_FLUENT = re.compile(r"^\s*([A-Za-z][\w-]*)\s*\(\s*([^()]*?)\s*\)\s*$")
_TRUE = {"true", "1", "yes"}
_FALSE = {"false", "0", "no"}


@dataclass
class Demonstration:
    """A loaded demonstration: frames (with ``hand_move``) and the symbolic state."""

    frames: pd.DataFrame
    objects: dict[str, str]
    initial: frozenset[Atom]
    events: list[tuple[float, Atom, bool]] = field(default_factory=list)
    spellings: dict[str, str] = field(default_factory=dict)
    path: str = "<trace>"
    vocabulary: HandVocabulary | None = None  # declared by the state file's vocabulary rows, if any

    def state_at(self, t: float) -> frozenset[Atom]:
        """The true fluents at time ``t`` (changes at exactly ``t`` included)."""
        return apply_changes(self.initial, self.events[:bisect.bisect_right(self.events, t, key=lambda e: e[0])])


def apply_changes(state: frozenset[Atom], changes: list[tuple[float, Atom, bool]]) -> frozenset[Atom]:
    """``state`` with ``changes`` (time, fluent, value) applied in their order."""
    if not changes:
        return frozenset(state)
    out = set(state)
    for _, atom, value in changes:
        (out.add if value else out.discard)(atom)
    return frozenset(out)


def _csv(text: str, path: str, columns: tuple[str, ...], numeric: tuple[str, ...] = ()) -> pd.DataFrame:
    """The CSV ``text`` as strings, ``numeric`` columns as floats where pandas' own parser reads them all as
    plain finite numbers (the fast path); otherwise every column as strings, for the checks to say where and
    what is wrong, as they always have."""
    if numeric:
        frame = _fast_frame(text, columns, numeric)
        if frame is not None:
            frame.attrs["blank_lines"] = blank_lines(text)
            return frame
    try:
        frame = pd.read_csv(io.StringIO(text), dtype=str, keep_default_na=False, skipinitialspace=True)
    except pd.errors.ParserError as exc:
        match = re.search(r"line (\d+)", str(exc))
        row = re.search(r"starting at row (\d+)", str(exc))  # 0-based, the header is row 0
        line = int(match.group(1)) if match else int(row.group(1)) + 1 if row else None
        raise TraceError(f"malformed CSV ({' '.join(str(exc).split())}; quote fields that contain commas, "
                         f"e.g. \"inside(A,B)\")", Location(path, line)) from None
    except pd.errors.EmptyDataError:
        raise TraceError("empty file, expected a CSV header and rows", Location(path, 1)) from None
    frame.columns = [c.strip() for c in frame.columns]
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise TraceError(
            f"missing column {', '.join(repr(c) for c in missing)} (expected columns: {', '.join(columns)})",
            Location(path, 1),
        )
    if frame.empty:
        raise TraceError("no rows after the header", Location(path, 2))
    frame.attrs["blank_lines"] = blank_lines(text)
    return frame


def _fast_frame(text: str, columns: tuple[str, ...], numeric: tuple[str, ...]) -> pd.DataFrame | None:
    """The trace read by pandas' C parser, numbers as floats; None where the string path must decide (a '+'
    sign, which the string path reads one unit in the last place off; words such as true; anything odd)."""
    import csv
    import warnings

    if "+" in text:
        return None
    header = next(csv.reader([text.split("\n", 1)[0]]), [])
    text_columns = {name: str for name in header if name.strip() not in numeric}  # header names as written
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a mixed column warns; it is then not numbers and falls back
            frame = pd.read_csv(io.BytesIO(text.encode("utf-8")), dtype=text_columns, keep_default_na=False,
                                skipinitialspace=True, compression=None)
    except (ValueError, TypeError, pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeError):
        return None
    if not _all_parsed(frame, columns, numeric):
        return None
    for column in numeric:
        frame[column] = frame[column].to_numpy(dtype=float) + 0.0  # -0 is 0, as the string path reads it
    return frame


def _all_parsed(frame: pd.DataFrame, columns: tuple[str, ...], numeric: tuple[str, ...]) -> bool:
    """Whether the fast read of a trace needs no check to say where it is wrong: every column there, rows,
    every number finite, no time negative (the string path's checks quote such values as written)."""
    frame.columns = [c.strip() for c in frame.columns]
    if frame.empty or any(c not in frame.columns for c in columns):
        return False
    if any(frame[c].dtype.kind not in "fi" or not np.isfinite(frame[c].to_numpy(dtype=float)).all()
           for c in numeric):
        return False
    return "time" not in numeric or not (frame["time"].to_numpy() < 0).any()


def _where(path: str, frame: pd.DataFrame, row: int, column: str) -> Location:
    # CSV line = data row + 2 (header is line 1), past the blank lines pandas skipped; column is 1-based.
    line = row + 2
    for blank in frame.attrs.get("blank_lines", ()):
        if blank > line:
            break
        line += 1
    return Location(path, line, list(frame.columns).index(column) + 1)


#: A line with nothing but blanks, which pandas' reader skips.
_BLANK_LINE = re.compile(r"^[ \t\r\f\v]*$", re.M)


def blank_lines(text: str) -> tuple[int, ...]:
    """The numbers of ``text``'s blank lines (1-based), for positions in a CSV read by pandas."""
    if not re.search(r"\n[ \t\r\f\v]*\n", text) and text[:1] not in ("\n", "\r", " ", "\t"):
        return ()  # the common case, one scan
    out: list[int] = []
    counted, line = 0, 1
    for match in _BLANK_LINE.finditer(text):
        if match.start() == len(text):
            break  # after the final line break: no line
        line += text.count("\n", counted, match.start())
        counted = match.start()
        out.append(line)
    return tuple(out)


def _numbers(frame: pd.DataFrame, path: str, column: str) -> np.ndarray:
    if frame[column].dtype.kind == "f":  # parsed already, every value finite (see _csv)
        return frame[column].to_numpy(dtype=float)
    values = pd.to_numeric(frame[column].str.strip(), errors="coerce").to_numpy(dtype=float)
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        row = int(bad[0])
        raise TraceError(
            f"column '{column}': expected a finite number, got '{frame[column].iloc[row]}'",
            _where(path, frame, row, column),
        )
    return values


def _times(frame: pd.DataFrame, path: str) -> np.ndarray:
    """The ``time`` column: finite seconds since the start, so never negative."""
    values = _numbers(frame, path, "time")
    bad = np.flatnonzero(values < 0)
    if bad.size:
        row = int(bad[0])
        raise TraceError(f"column 'time': {frame['time'].iloc[row].strip()} is before the start; "
                         "expected seconds since the start (>= 0)", _where(path, frame, row, "time"))
    return values


def parse_fluent(text: str) -> Atom:
    """``inside(RedPlate,PinkDrawer)`` -> ``(inside redplate pinkdrawer)``."""
    match = _FLUENT.match(text)
    if not match:
        raise ValueError(text)
    args = tuple(a.strip().lower() for a in match.group(2).split(",")) if match.group(2).strip() else ()
    if any(not a or not re.fullmatch(r"[\w-]+", a) for a in args):
        raise ValueError(text)
    return Atom(match.group(1).lower(), args)


def load_state(path: str, span: tuple[float, float] | None = None, text: str | None = None) -> tuple[
        dict[str, str], frozenset[Atom], list[tuple[float, Atom, bool]], dict[str, str], HandVocabulary | None]:
    """Objects, initial fluents, later changes, spellings and the declared hand vocabulary from a state CSV
    (``text``: its content, already read).

    With ``span`` (the trace's first and last frame times), a change must fall
    within it (up to :data:`EFFECT_DELAY_S` after the last frame): no hand can
    have caused it otherwise.
    """
    if text is None:
        text = read_text(path, "an environment state CSV (time,fluent,value)")
    frame = _csv(text, path, STATE_COLUMNS)
    times = _times(frame, path)
    objects, spellings, type_row, rows, declared = _state_rows(frame, times, path)
    if not objects:
        raise TraceError("no object(Name,type) rows: the scene's objects must be declared", Location(path, 1))
    vocabulary = _declared_vocabulary(frame, path, declared)
    hand = vocabulary.predicates if vocabulary is not None else frozenset(HAND_PREDICATES)
    for i, _, atom, _ in rows:
        if atom.predicate in hand:
            raise TraceError(f"column 'fluent': {atom.predicate} is the hand's state, read from the trace's "
                             "in_hand column; expected an environment fluent", _where(path, frame, i, "fluent"))
    for i, (key, value) in declared:
        if value is not None and key in ("held", "free") and pddl_name_defect(value):
            raise TraceError(f"column 'fluent': vocabulary {key}={value}: expected {pddl_name_defect(value)}",
                             _where(path, frame, i, "fluent"))
        if value is not None and key in ("left", "right") and value not in objects:
            raise TraceError(f"column 'fluent': vocabulary {key}={value}: object '{value}' is never declared "
                             f"(add an object({value},type) row)", _where(path, frame, i, "fluent"))
    arity = _check_fluents(frame, path, objects, rows)
    clash = sorted(set(objects.values()) & (set(arity) | set(hand)))
    if clash:
        raise TraceError(f"column 'fluent': type '{clash[0]}' is also a predicate; expected distinct names",
                         _where(path, frame, type_row[clash[0]], "fluent"))
    # Vocabulary rows stand at the start too: a world whose only initial facts are the hand's has no fluent row.
    start = min([t for _, t, _, _ in rows] + [float(times[i]) for i, _ in declared], default=0.0)
    late = [i for i, _ in declared if float(times[i]) > start]
    if late:
        raise TraceError(f"column 'time': a vocabulary row at {float(times[late[0]]):g} s; expected it with the "
                         f"initial state, at {start:g} s", _where(path, frame, late[0], "time"))
    if span is not None:
        _check_span(frame, path, rows, start, span)
    initial = frozenset(a for _, t, a, v in rows if t == start and v)
    events = sorted(((t, a, v) for _, t, a, v in rows if t > start), key=lambda e: e[0])
    return objects, initial, events, spellings, vocabulary


def _declared_vocabulary(frame: pd.DataFrame, path: str,
                         declared: list[tuple[int, tuple[str, str | None]]]) -> HandVocabulary | None:
    """The hand facts the ``vocabulary`` rows declare (None without any); TraceError at the first row that
    is not true or contradicts the ones before it."""
    from guided_lfd.demonstration.vocabulary import vocabulary_defect

    for k, (i, _) in enumerate(declared):
        if frame["value"].iloc[i].strip().lower() not in _TRUE:
            raise TraceError(f"column 'value': a vocabulary row is a declaration; expected true, got "
                             f"'{frame['value'].iloc[i].strip()}'", _where(path, frame, i, "value"))
        why = vocabulary_defect([v for _, v in declared[:k + 1]], complete=k == len(declared) - 1)
        if why:
            raise TraceError(f"column 'fluent': {why}", _where(path, frame, i, "fluent"))
    return vocabulary_of([v for _, v in declared], f"the vocabulary rows of {path}") if declared else None


def _state_rows(frame: pd.DataFrame, times: np.ndarray, path: str) -> tuple[
        dict[str, str], dict[str, str], dict[str, int], list[tuple[int, float, Atom, bool]],
        list[tuple[int, tuple[str, str | None]]]]:
    """Read every row of a state CSV: the declared objects, their spellings, the first row declaring each type,
    the fluent rows as (row, time, atom, value) and the vocabulary rows as (row, (key, value)); TraceError on a
    row that is not one of those."""
    objects: dict[str, str] = {}
    spellings: dict[str, str] = {}
    type_row: dict[str, int] = {}  # the first row declaring an object of each type
    rows: list[tuple[int, float, Atom, bool]] = []
    declared: list[tuple[int, tuple[str, str | None]]] = []
    for i, (t, text, value) in enumerate(zip(times, frame["fluent"], frame["value"])):
        raw = text.strip()
        if raw.lower().startswith("vocabulary(") and raw.endswith(")"):
            try:
                declared.append((i, parse_vocabulary_row(raw[len("vocabulary("):-1])))
            except ValueError:
                raise TraceError("column 'fluent': expected vocabulary(held=PREDICATE), vocabulary(free=PREDICATE), "
                                 f"vocabulary(left=OBJECT), vocabulary(right=OBJECT) or vocabulary(none), got '{raw}'",
                                 _where(path, frame, i, "fluent")) from None
            continue
        try:
            atom = parse_fluent(raw)
        except ValueError:
            raise TraceError(f"column 'fluent': expected pred(Arg,...), got '{raw}'",
                             _where(path, frame, i, "fluent")) from None
        flag = value.strip().lower()
        if flag not in _TRUE | _FALSE:
            raise TraceError(f"column 'value': expected true or false, got '{value}'", _where(path, frame, i, "value"))
        if atom.predicate == "object":
            _declare_object(frame, path, i, raw, atom, objects, spellings, type_row)
            continue
        why = pddl_name_defect(atom.predicate)
        if why:
            raise TraceError(f"column 'fluent': predicate '{atom.predicate}': expected {why}",
                             _where(path, frame, i, "fluent"))
        rows.append((i, float(t), atom, flag in _TRUE))
    return objects, spellings, type_row, rows, declared


def _declare_object(frame: pd.DataFrame, path: str, i: int, raw: str, atom: Atom, objects: dict[str, str],
                    spellings: dict[str, str], type_row: dict[str, int]) -> None:
    """Record the ``object(Name,type)`` row ``i`` in ``objects``, ``spellings`` and ``type_row``; TraceError if
    it has no two arguments, its type is no PDDL name, or it gives a declared object another type."""
    if len(atom.args) != 2:
        raise TraceError(f"column 'fluent': expected object(Name,type), got '{raw}'",
                         _where(path, frame, i, "fluent"))
    name, kind = atom.args
    why = pddl_name_defect(kind) if kind != "object" else None  # the root type
    if why:
        raise TraceError(f"column 'fluent': type '{kind}' of {name}: expected {why}",
                         _where(path, frame, i, "fluent"))
    if objects.get(name, kind) != kind:
        raise TraceError(f"column 'fluent': object '{name}' is declared as {objects[name]} and as {kind} "
                         "(names are case-insensitive); expected one type", _where(path, frame, i, "fluent"))
    objects[name] = kind
    type_row.setdefault(kind, i)
    original = _FLUENT.match(raw).group(2).split(",")[0].strip()  # type: ignore[union-attr]
    spellings[atom.args[0]] = original


def _check_fluents(frame: pd.DataFrame, path: str, objects: dict[str, str],
                   rows: list[tuple[int, float, Atom, bool]]) -> dict[str, int]:
    """Check that fluents name declared objects, keep one arity per predicate and one value per time; the arities."""
    for i, _, atom, _ in rows:
        for arg in atom.args:
            if arg not in objects:
                raise TraceError(f"column 'fluent': object '{arg}' is never declared (add an object({arg},type) row)",
                                 _where(path, frame, i, "fluent"))
    arity: dict[str, int] = {}
    value_at: dict[tuple[float, Atom], bool] = {}
    for i, t, atom, value in rows:
        if arity.setdefault(atom.predicate, len(atom.args)) != len(atom.args):
            raise TraceError(f"column 'fluent': {atom.predicate} has {len(atom.args)} argument(s) here and "
                             f"{arity[atom.predicate]} before; expected the same number",
                             _where(path, frame, i, "fluent"))
        if value_at.setdefault((t, atom), value) != value:
            raise TraceError(f"column 'value': {frame['fluent'].iloc[i].strip()} is set both true and false "
                             f"at {t:g} s; expected one value", _where(path, frame, i, "value"))
    return arity


def _check_span(frame: pd.DataFrame, path: str, rows: list[tuple[int, float, Atom, bool]], start: float,
                span: tuple[float, float]) -> None:
    """Check that every change after ``start`` falls within the trace's ``span`` (up to :data:`EFFECT_DELAY_S`)."""
    for i, t, _, _ in rows:
        if t > start and not span[0] <= t <= span[1] + EFFECT_DELAY_S:
            raise TraceError(f"column 'time': a change at {t:g} s, outside the trace ({span[0]:g} s to "
                             f"{span[1]:g} s), that no hand can have caused; expected a time within the trace",
                             _where(path, frame, i, "time"))


def load_demonstration(trace_path: str, state_path: str | None = None) -> Demonstration:
    """Read and check a trace and its state file; adds the derived ``hand_move`` column."""
    state_path = state_path or default_state_path(trace_path)
    frame = _csv(read_text(trace_path, "a hand trace CSV (time,hand,x,y,z,grip,in_hand,act_on)"),
                 trace_path, TRACE_COLUMNS, numeric=("time", "x", "y", "z"))
    times = _times(frame, trace_path)
    objects, initial, events, spellings, vocabulary = load_state(state_path, (float(times.min()), float(times.max())))
    frame = trace_frame(frame, times, trace_path, objects, Path(state_path).name)
    return Demonstration(frame, objects, initial, events, spellings, trace_path, vocabulary)


def trace_frame(frame: pd.DataFrame, times: np.ndarray, trace_path: str, objects: dict[str, str],
                state_name: str) -> pd.DataFrame:
    """The trace's rows checked (hands, grips, objects the state file declares, time never going back for a
    hand) and normalised, with the derived ``hand_move`` column; TraceError at the first bad cell."""
    for axis in ("x", "y", "z"):
        frame[axis] = _numbers(frame, trace_path, axis)
    frame["time"] = times
    codes, hands = _factorised(frame["hand"])
    bad = np.flatnonzero(~np.isin(codes, [i for i, h in enumerate(hands) if h in HANDS]))
    if bad.size:
        row = int(bad[0])
        raise TraceError(f"column 'hand': expected left or right, got '{frame['hand'].iloc[row]}'",
                         _where(trace_path, frame, row, "hand"))
    frame["hand"] = hands[codes]
    codes, grips = _factorised(frame["grip"])
    closed = {"open": False, "0": False, "closed": True, "1": True}
    bad = np.flatnonzero(~np.isin(codes, [i for i, g in enumerate(grips) if g in closed]))
    if bad.size:
        row = int(bad[0])
        raise TraceError(f"column 'grip': expected open or closed, got '{frame['grip'].iloc[row]}'",
                         _where(trace_path, frame, row, "grip"))
    frame["grip_closed"] = np.array([closed.get(g, False) for g in grips], dtype=bool)[codes]
    for column in ("in_hand", "act_on"):
        codes, names = _factorised(frame[column])
        unknown = np.flatnonzero(~np.isin(codes, [i for i, n in enumerate(names) if n == "" or n in objects]))
        if unknown.size:
            row = int(unknown[0])
            raise TraceError(
                f"column '{column}': object '{frame[column].iloc[row].strip()}' is never declared in {state_name}",
                _where(trace_path, frame, row, column),
            )
        frame[column] = names[codes]
    for hand in HANDS:
        idx = np.flatnonzero((frame["hand"] == hand).to_numpy())
        if idx.size > 1:
            back = np.flatnonzero(np.diff(times[idx]) < 0)
            if back.size:
                row = int(idx[back[0] + 1])
                raise TraceError(f"column 'time': time goes backwards for the {hand} hand "
                                 f"({times[idx[back[0]]]:g} s, then {times[row]:g} s)",
                                 _where(trace_path, frame, row, "time"))
    frame["hand_move"] = hand_move(frame)
    return frame


def _factorised(column: pd.Series) -> tuple[np.ndarray, np.ndarray]:
    """(codes, values): each row's value stripped and lower-cased is ``values[codes[row]]``; the string work
    is done once per distinct value, not once per frame."""
    codes, uniques = pd.factorize(column, sort=False)
    return codes, np.array([str(u).strip().lower() for u in uniques] or [""], dtype=object)


def frame_period(times: np.ndarray) -> float:
    """A hand's frame period: the median interval between its frames, to the microsecond (clocks written
    to 0.1 ms make the median of 0.05 s intervals 0.04999999999999716 on one stretch of a recording and
    0.05 on another: rules that compare durations with multiples of it must not tip over on that)."""
    return round(float(np.median(np.diff(times))), 6) if len(times) > 1 else 0.0


def hand_move(frame: pd.DataFrame) -> np.ndarray:
    """Whether each frame's hand moves (see :data:`MOVE_THRESHOLD_M_S`)."""
    out = np.zeros(len(frame), dtype=bool)
    half = MOVE_WINDOW_S / 2
    for hand in HANDS:
        idx = np.flatnonzero((frame["hand"] == hand).to_numpy())
        if idx.size < 2:
            continue
        t = frame["time"].to_numpy()[idx]
        pos = frame[["x", "y", "z"]].to_numpy()[idx]
        # At low frame rates the window must still reach one neighbouring frame on each side.
        period = frame_period(t)
        half = max(MOVE_WINDOW_S / 2, 1.01 * period) if idx.size > 1 else half
        lo = np.searchsorted(t, t - half, side="left")
        hi = np.searchsorted(t, t + half, side="right") - 1
        # A few dropped frames: still reach the nearest frame before and after (a one-sided window over
        # one interval doubles the noise on the speed); across a longer dropout, not (the hand may have
        # moved while untracked: that motion is not this frame's).
        reach = 3.01 * period
        before = np.maximum(np.searchsorted(t, t, side="left") - 1, 0)
        after = np.minimum(np.searchsorted(t, t, side="right"), len(t) - 1)
        lo = np.where(t - t[before] <= reach, np.minimum(lo, before), lo)
        hi = np.where(t[after] - t <= reach, np.maximum(hi, after), hi)
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):  # huge coordinates: infinite speed
            span = t[hi] - t[lo]
            dist = np.linalg.norm(pos[hi] - pos[lo], axis=1)
            speed = np.where(span > 0, dist / span, 0.0)
        out[idx] = speed > MOVE_THRESHOLD_M_S
    return out


__all__ = ["Demonstration", "load_demonstration", "load_state", "trace_frame", "frame_period", "parse_fluent", "hand_move", "TRACE_COLUMNS",
           "STATE_COLUMNS", "HAND_PREDICATES", "MOVE_THRESHOLD_M_S", "MOVE_WINDOW_S", "EFFECT_DELAY_S",
           "PDDL_NAME", "PDDL_RESERVED", "pddl_name_defect"]
