"""The trace reader's fast path (pandas' C parser) reads every file as the string path does; each case is one
the two paths could read differently (tests/data/regressions/odd-traces/)."""

from __future__ import annotations

import pytest

from conftest import DATA
from guided_lfd.demonstration.segment import segment, segments_csv
from guided_lfd.demonstration.trace import load_demonstration
from guided_lfd.errors import TraceError

CASES = DATA / "regressions" / "odd-traces"


@pytest.mark.parametrize("trace, message", [
    # '+18.68...' after '18.68...': the string path reads the '+' number one unit in the last place lower.
    ("plus-backwards/trace.csv", r"trace.csv:4:1: .*time goes backwards"),
    ("allbool-column/trace.csv", r"trace.csv:2:5: .*column 'z': expected a finite number, got 'false'"),
    ("header-trailing-space/grip-trace.csv", r"column 'grip': expected open or closed, got '1.50'"),
])
def test_bad_values_are_reported_as_the_string_path_reports_them(trace, message):
    with pytest.raises(TraceError, match=message):
        load_demonstration(str(CASES / trace))


def test_a_plain_trace_named_like_an_archive_is_read_as_text():
    assert segment(load_demonstration(str(CASES / "compress-ext" / "trace.gz"),
                                      str(CASES / "compress-ext" / "trace.state.csv")))


def test_a_time_of_minus_zero_is_zero():
    text = segments_csv(segment(load_demonstration(str(CASES / "negzero-int" / "trace.csv"))))
    assert "-0.0000" not in text and ",0.0000," in text


def test_header_names_with_trailing_spaces_keep_object_names_as_text():
    segs = segment(load_demonstration(str(CASES / "header-trailing-space" / "trace.csv")))
    assert segs and all(isinstance(s.object, str) for s in segs)
