"""The segments document (``guided-lfd/segments``): reading it and checking that it is one.

What :mod:`guided_lfd.demonstration.learn` learns from; a document that is
not usable is a one-line error naming the JSON path, its line and column.
"""

from __future__ import annotations

import re

from guided_lfd.demonstration.trace import HAND_PREDICATES
from guided_lfd.errors import Location, TraceError
from guided_lfd.pddl.model import pddl_name_defect

__all__ = ["document_defect", "load_segments"]


def load_segments(path: str, text: str | None = None) -> dict:
    """Read a ``guided-lfd/segments`` JSON document (``-`` = stdin; ``text``: its text, already read);
    TraceError if it is not one."""
    from guided_lfd.io import read_json_document

    text, doc = read_json_document(path, "segments", TraceError, "`guided-lfd segment`", text)
    problem = document_defect(doc)
    if problem is not None:
        keys, message = problem
        where = _json_position(text, keys)
        name = "".join(f"[{k}]" if isinstance(k, int) else f".{k}" for k in keys).lstrip(".")
        raise TraceError(f"{name}: {message}", Location(path, *where) if where else Location(path))
    return doc


#: A fluent as the segments document writes it: ``(pred arg ...)``.
_ATOM_TEXT = re.compile(r"\(\s*(\S+?)((?:\s+[^\s()]+)*)\s*\)")
#: An object name in a segment: no blanks or parentheses, not a variable.
_OBJECT = re.compile(r"[^\s()?][^\s()]*")


def document_defect(doc: dict) -> tuple[tuple, str] | None:
    """The first thing that keeps ``doc`` from being a usable segments document: (JSON path, what was expected)."""
    arity: dict[str, int] = {}  # predicate -> number of arguments, from the first fluent naming it
    objects = doc.get("objects", {})
    found = _objects_defect(objects)
    if found:
        return found
    if "initial" in doc:
        found = _fluents_defect(("initial",), doc["initial"], arity)
        if found:
            return found
    segments = doc.get("segments", [])
    if not isinstance(segments, list):
        return ("segments",), f"expected a list of segments, got {_show(segments)}"
    for i, seg in enumerate(segments):
        found = _segment_defect(("segments", i), seg, arity)
        if found:
            return found
    found, hand = _vocabulary_defect(doc.get("vocabulary"), objects)
    if found:
        return found
    clash = sorted(set(objects.values()) & (set(arity) | hand))
    if clash:
        return ("objects",), f"type '{clash[0]}' is also a predicate; expected distinct names"
    return None


def _vocabulary_defect(value, objects: dict) -> tuple[tuple[tuple, str] | None, set[str]]:
    """(the first defect of a ``vocabulary`` binding, or None; the hand predicates it binds)."""
    if value is None:
        return None, set(HAND_PREDICATES)
    if not isinstance(value, dict):
        return (("vocabulary",), f"expected an object with held, free and hands, got {_show(value)}"), set()
    for key in ("held", "free"):
        name = value.get(key)
        why = None if name is None else "a string" if not isinstance(name, str) else pddl_name_defect(name)
        if why:
            return (("vocabulary", key), f"expected a predicate name or null, {why}, got {_show(name)}"), set()
    hands = value.get("hands", {})
    if hands is None:
        hands = {}
    if not isinstance(hands, dict) or any(h not in ("left", "right") or not isinstance(a, str) or a not in objects
                                          for h, a in hands.items()):
        return (("vocabulary", "hands"), "expected {\"left\"|\"right\": an object of the document}, got "
                f"{_show(hands)}"), set()
    from guided_lfd.demonstration.vocabulary import vocabulary_defect

    rows = [(k, value[k].lower() if isinstance(value.get(k), str) else None) for k in ("held", "free") if k in value]
    why = vocabulary_defect([*rows, *hands.items()])
    if why:
        return (("vocabulary",), why), set()
    return None, {p.lower() for p in (value.get("held"), value.get("free")) if p}


def _show(value) -> str:
    """``value`` as JSON for a message, cut to 60 characters."""
    import json

    text = json.dumps(value, ensure_ascii=False)
    return text if len(text) <= 60 else text[:57] + "..."


def _objects_defect(objects) -> tuple[tuple, str] | None:
    """The first defect of the ``objects`` mapping (object names to PDDL type names), or None."""
    if not isinstance(objects, dict):
        return ("objects",), f"expected an object mapping object names to types, got {_show(objects)}"
    for obj, kind in objects.items():
        if not _OBJECT.fullmatch(obj):
            return ("objects",), f"object name {_show(obj)}: expected no blanks or parentheses"
        why = "a string" if not isinstance(kind, str) else pddl_name_defect(kind) if kind != "object" else None
        if why:
            return ("objects", obj), f"type of {obj}: expected {why}, got {_show(kind)}"
    return None


def _fluents_defect(keys: tuple, value, arity: dict[str, int]) -> tuple[tuple, str] | None:
    """The first defect of the fluent list ``value`` at ``keys``, or None; records predicate arities in ``arity``
    (a predicate must keep the arity it was first seen with)."""
    if not isinstance(value, list):
        return keys, f"expected a list of fluents like \"(open pinkdrawer)\", got {_show(value)}"
    for k, text in enumerate(value):
        match = _ATOM_TEXT.fullmatch(text.strip()) if isinstance(text, str) else None
        if match is None or any(a.startswith("?") for a in match.group(2).split()):
            return keys + (k,), f"expected a fluent like \"(open pinkdrawer)\", got {_show(text)}"
        why = pddl_name_defect(match.group(1))
        if why:
            return keys + (k,), f"predicate {_show(match.group(1))}: expected {why}"
        n = len(match.group(2).split())
        if arity.setdefault(match.group(1), n) != n:
            return keys + (k,), (f"{match.group(1)} has {n} argument(s) here and {arity[match.group(1)]} "
                                 "elsewhere; expected the same number")
    return None


def _segment_defect(here: tuple, seg, arity: dict[str, int]) -> tuple[tuple, str] | None:
    """The first defect of the segment ``seg`` at ``here`` (keys, their types, object names, its fluents), or None."""
    if not isinstance(seg, dict):
        return here, f"expected a segment (an object with index, hand, activity, before, after), got {_show(seg)}"
    for key in ("index", "hand", "activity", "before", "after"):
        if key not in seg:
            return here, f"missing key '{key}' (expected index, hand, activity, before, after)"
    if not isinstance(seg["index"], int) or isinstance(seg["index"], bool):
        return here + ("index",), f"expected a whole number, got {_show(seg['index'])}"
    if not isinstance(seg["hand"], str):
        return here + ("hand",), f"expected left or right, got {_show(seg['hand'])}"
    activity = seg["activity"]
    why = "a string" if not isinstance(activity, str) else pddl_name_defect(activity.lower())
    if why:
        return here + ("activity",), f"expected an activity name, {why}, got {_show(activity)}"
    for key in ("object", "target", "held_before", "held_after"):
        value = seg.get(key)
        if value is not None and not (isinstance(value, str) and (value == "" or _OBJECT.fullmatch(value))):
            return here + (key,), f"expected an object name or \"\", got {_show(value)}"
    for key in ("before", "after"):
        found = _fluents_defect(here + (key,), seg[key], arity)
        if found:
            return found
    return None


def _json_position(text: str, keys: tuple) -> tuple[int, int] | None:
    """1-based line and column of the innermost object or list on ``keys`` in JSON ``text``."""
    import json
    import json.decoder
    import json.scanner

    where: dict[int, int] = {}
    decoder = json.JSONDecoder()

    def parse_object(s_and_end, *args):
        value, end = json.decoder.JSONObject(s_and_end, *args)
        where[id(value)] = s_and_end[1] - 1
        return value, end

    def parse_array(s_and_end, scan_once):
        value, end = json.decoder.JSONArray(s_and_end, scan_once)
        where[id(value)] = s_and_end[1] - 1
        return value, end

    decoder.parse_object, decoder.parse_array = parse_object, parse_array  # type: ignore[assignment]
    try:
        value, _ = json.scanner.py_make_scanner(decoder)(text, json.decoder.WHITESPACE.match(text, 0).end())
    except (ValueError, StopIteration, RecursionError):
        return None
    offset = where.get(id(value))
    for key in keys:
        try:
            value = value[key]
        except (KeyError, IndexError, TypeError):
            break
        offset = where.get(id(value), offset)
    if offset is None:
        return None
    return text.count("\n", 0, offset) + 1, offset - text.rfind("\n", 0, offset)
