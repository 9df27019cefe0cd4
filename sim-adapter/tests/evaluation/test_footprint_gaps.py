# SPDX-License-Identifier: EPL-2.0
"""rei.geometry.footprint_gaps against an independent oracle (the kinematic fake's exact rectangle distance)."""

from __future__ import annotations

import math

import numpy as np
from sut.kinematic import rect_distance

from rei.geometry import footprint_gaps

ROBOT = (0.281, 0.306)


def test_gaps_equal_the_oracle_where_apart_and_are_negative_where_overlapping() -> None:
    rng = np.random.default_rng(7)
    poses = np.column_stack((rng.uniform(-2, 2, 300), rng.uniform(-2, 2, 300), rng.uniform(-math.pi, math.pi, 300)))
    boxes = np.column_stack((rng.uniform(-2, 2, 40), rng.uniform(-2, 2, 40), rng.uniform(-math.pi, math.pi, 40),
                             rng.uniform(0.1, 1.5, 40), rng.uniform(0.1, 1.5, 40)))
    gaps = footprint_gaps(poses, ROBOT, boxes, np.zeros(40, dtype=bool))
    oracle = np.array([[rect_distance((*p, *ROBOT), tuple(b)) for b in boxes] for p in poses])
    apart = oracle > 0
    assert apart.sum() > 1000 and (~apart).sum() > 100  # both cases are exercised
    np.testing.assert_allclose(gaps[apart], oracle[apart], atol=1e-9)
    assert (gaps[~apart] <= 1e-12).all()


def test_penetration_depth_and_circles() -> None:
    robot = np.array([[0.0, 0.0, 0.0]])
    # a box overlapping the robot's front edge by 0.1 m: the least push is 0.1 m along x
    inside = footprint_gaps(robot, (0.2, 0.4), np.array([0.5, 0.0, 0.0, 1.0, 0.2]), np.array([False]))[0, 0]
    assert abs(inside + 0.1) < 1e-12
    # a human (circle of 0.5 m) 1 m ahead: 1 - 0.1 (half the robot) - 0.25 (radius)
    ahead = footprint_gaps(robot, (0.2, 0.4), np.array([1.0, 0.0, 0.0, 0.5, 0.5]), np.array([True]))[0, 0]
    assert abs(ahead - 0.65) < 1e-12
    # diagonally off a corner: the distance to the corner less the radius
    corner = footprint_gaps(robot, (0.2, 0.4), np.array([0.4, 0.5, 0.0, 0.2, 0.2]), np.array([True]))[0, 0]
    assert abs(corner - (math.hypot(0.3, 0.3) - 0.1)) < 1e-12
    # moving obstacles: one place per robot pose, NaN where unknown
    places = np.array([[[1.0, 0.0, 0.0, 0.5, 0.5]], [[math.nan, math.nan, math.nan, 0.5, 0.5]]])
    pair = footprint_gaps(np.array([[0.0, 0.0, 0.0], [5.0, 5.0, 0.0]]), (0.2, 0.4), places, np.array([True]))
    assert abs(pair[0, 0] - 0.65) < 1e-12 and math.isnan(pair[1, 0])
