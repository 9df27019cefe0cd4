# SPDX-License-Identifier: EPL-2.0
"""The pieces the drawings rest on: world-to-pixel transform, footprints, ticks, decimation, tracks."""

from __future__ import annotations

import itertools
import math

import pytest

from rei.report.decimate import decimate, decimate_indices
from rei.report.svg import MapTransform, box_corners, nice_ticks, num
from rei.report.tracks import collect_tracks

from .runs import state


def test_map_transform_flips_y_and_keeps_one_scale() -> None:
    tf = MapTransform.fit((0.0, 0.0, 6.0, 4.0), width_px=620, pad=10)
    assert tf.scale == pytest.approx(100.0)
    assert (tf.width, tf.height) == pytest.approx((620.0, 420.0))
    assert tf.point(0.0, 4.0) == pytest.approx((10.0, 10.0))  # top left of the room: top left of the picture
    assert tf.point(6.0, 0.0) == pytest.approx((610.0, 410.0))
    assert tf.point(1.0, 1.0) == pytest.approx((110.0, 310.0))  # y up in the world is up on the screen
    assert tf.length(0.25) == pytest.approx(25.0)


def test_map_transform_respects_the_height_limit_and_rejects_empty_bounds() -> None:
    tall = MapTransform.fit((0.0, 0.0, 2.0, 20.0), width_px=420, pad=10, max_height_px=220)
    assert tall.scale == pytest.approx(10.0) and tall.height == pytest.approx(220.0)
    with pytest.raises(ValueError, match="bounds"):
        MapTransform.fit((1.0, 0.0, 1.0, 4.0), width_px=100)
    with pytest.raises(ValueError, match="bounds"):
        MapTransform.fit((0.0, 0.0, math.inf, 4.0), width_px=100)


def test_box_corners_turn_with_yaw() -> None:
    flat = [c for corner in box_corners(1.0, 1.0, 2.0, 1.0, 0.0) for c in corner]
    assert flat == pytest.approx([0.0, 0.5, 2.0, 0.5, 2.0, 1.5, 0.0, 1.5])
    turned = box_corners(0.0, 0.0, 2.0, 1.0, math.pi / 2)  # the long side now along y
    xs, ys = zip(*turned, strict=True)
    assert (max(xs) - min(xs), max(ys) - min(ys)) == pytest.approx((1.0, 2.0))


def test_nice_ticks_and_number_format() -> None:
    assert nice_ticks(0.0, 33.2, 8) == [0, 5, 10, 15, 20, 25, 30]
    ticks = nice_ticks(-213.0, 43.0, 5)
    assert ticks[0] >= -213.0 and ticks[-1] <= 43.0 and 0 in ticks
    assert num(-0.001) == "0" and num(12.5) == "12.5" and num(3.0) == "3"


def test_decimation_keeps_ends_and_spreads_evenly() -> None:
    assert decimate_indices(5, 10) == [0, 1, 2, 3, 4]
    picked = decimate_indices(100_001, 1001)
    assert len(picked) == 1001 and picked[0] == 0 and picked[-1] == 100_000
    gaps = {b - a for a, b in itertools.pairwise(picked)}
    assert gaps == {100}
    assert decimate(list("abcdefghij"), 4) == ["a", "d", "g", "j"]
    with pytest.raises(ValueError):
        decimate_indices(10, 1)


def test_tracks_keep_moving_bodies_and_the_belief() -> None:
    tracks = collect_tracks(state(i, i / 10) for i in range(11))
    assert len(tracks.robot) == len(tracks.believed) == 11
    assert set(tracks.others) == {"h1"}  # the static table of the full frame is not a track
    assert tracks.robot.at(0.55) == pytest.approx((0.55, 0.5, 0.0))  # the sample at t = 0.5, not 0.6
    assert tracks.robot.at(-1.0) == pytest.approx((0.5, 0.5, 0.0))
    assert tracks.others["h1"].at(1.0)[1] == pytest.approx(2.9)
    worst, when = tracks.odometry_error()
    assert worst == pytest.approx(0.01) and when == pytest.approx(1.0)


def test_tracks_skip_malformed_messages() -> None:
    good = state(0, 0.0)
    broken = [{"seq": 1}, {"seq": 2, "t": 0.1, "robot": {"pose": [1.0, "x", 0.0, 0.0]}}, {"seq": 3, "t": math.nan}]
    tracks = collect_tracks([good, *broken])
    assert len(tracks.robot) == 1 and tracks.states == 2
