"""The linear-time segmenter's building blocks against the rules written out plainly (issue #30): a quadratic
debouncing loop and a per-frame run builder are kept here as the reference, and random label sequences
(jitter, dropped frames, long gaps) must give the same runs.  (The first debouncer also joined, after its
first merge, every two runs of one label a long gap had split, which no shipped or test trace ever showed:
the segmenter, written or streamed, now keeps them apart, as "a longer gap splits a segment" says.)"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from guided_lfd.demonstration.segment import JITTER_S, MAX_GAP_S, MIN_SEGMENT_S, _debounce, _runs


def reference_runs(times, labels):
    runs = []
    for i, label in enumerate(labels):
        if runs and runs[-1][0] == label and times[i] - times[runs[-1][2]] <= MAX_GAP_S:
            runs[-1][2] = i
        else:
            runs.append([label, i, i])
    return runs


def reference_debounce(times, runs):
    frame = round(float(np.median(np.diff(times))), 6) if len(times) > 1 else 0.0

    def length(r):
        step = float(times[r[2] + 1] - times[r[2]]) if r[2] + 1 < len(times) else frame
        return float(times[r[2]] - times[r[1]]) + (min(step, 3 * frame) if step > 1.5 * frame else frame)

    def noise(k):
        n = length(runs[k])
        if n < JITTER_S:
            return True
        if k == 0 or k == len(runs) - 1:
            return n < MIN_SEGMENT_S
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
        # The absorbed run's neighbours, now touching with one label, join (runs a long gap split stay apart).
        if 0 < k < len(runs) and runs[k - 1][0] == runs[k][0]:
            runs[k - 1][2] = runs[k][2]
            del runs[k]
    return runs


@st.composite
def recordings(draw):
    """Frame times (30-120 Hz, some dropped frames, a few long gaps) and labels in short and long runs."""
    rate = draw(st.sampled_from([30.0, 60.0, 90.0, 120.0]))
    pieces = draw(st.lists(st.tuples(st.sampled_from("ABCD"), st.integers(1, 40)), min_size=1, max_size=40))
    labels = np.array([label for label, count in pieces for _ in range(count)], dtype=object)
    steps = np.full(len(labels), 1.0 / rate)
    for i in draw(st.lists(st.integers(0, max(0, len(labels) - 1)), max_size=6)):
        steps[i] = draw(st.sampled_from([2.0 / rate, 3.0 / rate, 0.2, 0.8]))  # dropped frames, long gaps
    return np.cumsum(steps), labels


@settings(max_examples=int(__import__("os").environ.get("GUIDED_LFD_FUZZ_EXAMPLES", 400)), deadline=None)
@given(recordings())
def test_runs_and_debouncing_are_the_rules_as_first_written(recording):
    times, labels = recording
    assert _runs(times, labels) == reference_runs(times, labels)
    assert _debounce(times, _runs(times, labels)) == reference_debounce(times, reference_runs(times, labels))
