"""Segmentation that holds under a real tracker's noise: a tracking loss inside one activity, a re-grasp during a
carry and a brief accidental grip neither split, merge nor invent an activity (guided_lfd.demonstration.segment)."""

from __future__ import annotations

import numpy as np
import pytest

from guided_lfd.demonstration.segment import MAX_LOSS_S, REGRASP_S, _debounce, _runs

RATE = 60.0


def _frames(*parts: tuple[str, float, str, str]):
    """(label, seconds, held, target) parts at 60 Hz; a part labelled 'lost' is a gap with no frames."""
    times, labels, held, target, t = [], [], [], [], 0.0
    for label, seconds, h, g in parts:
        n = int(round(seconds * RATE))
        if label != "lost":
            times += [t + k / RATE for k in range(n)]
            labels += [label] * n
            held += [h] * n
            target += [g] * n
        t += n / RATE
    return np.array(times), np.array(labels, dtype=object), np.array(held, dtype=object), np.array(target,
                                                                                                   dtype=object)


def _segments(*parts):
    times, labels, held, target = _frames(*parts)
    return [r[0] for r in _debounce(times, _runs(times, labels, held, target), held, target)]


@pytest.mark.parametrize("loss", [0.6, 1.0, 1.5, MAX_LOSS_S - 0.05])
def test_a_tracking_loss_inside_a_carry_does_not_split_it(loss):
    assert _segments(("Put", 1.0, "cup", "shelf"), ("lost", loss, "", ""), ("Put", 0.8, "cup", "shelf"),
                     ("Release", 0.5, "", "")) == ["Put", "Release"]


def test_a_loss_longer_than_two_seconds_splits_what_is_unknown():
    assert _segments(("Put", 1.0, "cup", "shelf"), ("lost", MAX_LOSS_S + 0.5, "", ""),
                     ("Put", 0.8, "cup", "shelf")) == ["Put", "Put"]


def test_a_gap_between_two_reaches_for_different_objects_splits_them():
    assert _segments(("Reach", 1.0, "", "cup"), ("lost", 1.0, "", ""), ("Reach", 1.0, "", "plate")) == \
        ["Reach", "Reach"]


@pytest.mark.parametrize("gap", [0.18, 0.22, 0.28])
def test_a_regrasp_during_a_carry_stays_one_carry(gap):
    assert _segments(("Put", 0.6, "cup", "shelf"), ("Reach", gap, "", "cup"), ("Put", 0.6, "cup", "shelf"),
                     ("Release", 0.5, "", "")) == ["Put", "Release"]


def test_letting_go_longer_than_a_regrasp_is_its_own_activity():
    assert _segments(("Put", 0.6, "cup", "shelf"), ("Reach", REGRASP_S + 0.2, "", "cup"),
                     ("Take", 0.6, "cup", "")) == ["Put", "Reach", "Take"]


def test_a_short_pause_between_carries_of_two_objects_is_kept():
    assert _segments(("Put", 0.6, "cup", "shelf"), ("Release", 0.25, "", ""), ("Put", 0.6, "plate", "shelf")) == \
        ["Put", "Release", "Put"]


@pytest.mark.parametrize("grip", [0.1, 0.15, 0.2])
def test_a_brief_grip_during_a_reach_is_absorbed(grip):
    assert _segments(("Reach", 0.5, "", "cup"), ("Manipulate", grip, "", "cup"), ("Reach", 0.4, "", "cup"),
                     ("Take", 0.5, "cup", "")) == ["Reach", "Take"]


def test_without_the_hands_objects_a_long_gap_splits_as_it_always_did():
    times, labels, _, _ = _frames(("Put", 1.0, "cup", "shelf"), ("lost", 1.0, "", ""), ("Put", 0.8, "cup", "shelf"))
    assert [r[0] for r in _runs(times, labels)] == ["Put", "Put"]


def test_a_regrasp_as_the_transport_starts_stays_between_the_take_and_the_put():
    assert _segments(("Take", 0.5, "marker", ""), ("Reach", 0.2, "", "marker"), ("Put", 0.8, "marker", "tube"),
                     ("Release", 0.5, "", "")) == ["Take", "Put", "Release"]
