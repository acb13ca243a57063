"""Every shipped and test trace segments exactly as recorded in tests/data/golden/segments.jsonl (issue #30):
the same activities, boundaries, objects and fluents, whatever the segmenter's algorithm."""

from __future__ import annotations

import json

import pytest

from golden_segments import GOLDEN, ROOT, segments_of, traces

RECORDED = {d["trace"]: d["segments"] for d in map(json.loads, GOLDEN.read_text().splitlines())}


def test_the_golden_file_covers_every_trace():
    assert {str(t.relative_to(ROOT)) for t in traces()} <= set(RECORDED)
    assert len(RECORDED) >= 100


@pytest.mark.parametrize("name", sorted(RECORDED))
def test_a_trace_segments_as_recorded(name):
    assert segments_of(ROOT / name) == RECORDED[name]
