# SPDX-License-Identifier: EPL-2.0
"""The gaps of a robot whose footprint is its description's outline (a convex polygon about its origin, #41): a
rectangle given as an outline measures what the rectangle footprint measures, apart and overlapping, to boxes
and circles, still and moving; an outline off its origin is turned about the origin."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rei.geometry import footprint_gaps, outline_gaps

RNG = np.random.default_rng(41)


def rectangle(sx: float, sy: float) -> np.ndarray:
    return np.array([[-sx / 2, -sy / 2], [sx / 2, -sy / 2], [sx / 2, sy / 2], [-sx / 2, sy / 2]])


def test_a_rectangle_as_an_outline_measures_what_the_rectangle_does() -> None:
    robot = np.column_stack([RNG.uniform(-1, 1, 200), RNG.uniform(-1, 1, 200), RNG.uniform(-math.pi, math.pi, 200)])
    obstacles = np.column_stack([RNG.uniform(-1, 1, 30), RNG.uniform(-1, 1, 30), RNG.uniform(-math.pi, math.pi, 30),
                                 RNG.uniform(0.1, 0.8, 30), RNG.uniform(0.1, 0.8, 30)])
    circle = RNG.uniform(size=30) < 0.4
    obstacles[circle, 4] = obstacles[circle, 3]
    expected = footprint_gaps(robot, (0.3, 0.2), obstacles, circle)
    assert (expected < 0).any() and (expected > 0).any()  # both sides of a contact are exercised
    assert footprint_gaps(robot, rectangle(0.3, 0.2), obstacles, circle) == pytest.approx(expected, abs=1e-9)
    moving = np.broadcast_to(obstacles, (200, 30, 5)).copy()
    moving[:, :, 0] += RNG.uniform(-0.2, 0.2, (200, 30))
    assert outline_gaps(robot, rectangle(0.3, 0.2), moving, circle) == pytest.approx(
        footprint_gaps(robot, (0.3, 0.2), moving, circle), abs=1e-9)


def test_an_outline_off_its_origin_turns_about_the_origin() -> None:
    body = np.array([[-0.102, -0.07], [0.038, -0.07], [0.038, 0.07], [-0.102, 0.07]])  # a Burger without wheels
    wall = np.array([[1.0, 0.0, 0.0, 0.2, 2.0]])  # its face at x = 0.9
    post = np.array([[0.0, 1.0, 0.0, 0.2, 0.2]])
    poses = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, math.pi], [0.0, 0.0, math.pi / 2]])
    gaps = outline_gaps(poses, body, wall, np.array([False]))[:, 0]
    assert gaps[:2] == pytest.approx([0.9 - 0.038, 0.9 - 0.102])
    assert outline_gaps(poses[2:], body, post, np.array([True]))[0, 0] == pytest.approx(1.0 - 0.1 - 0.038)
    # pushed 5 cm into the wall: minus the depth
    assert outline_gaps(np.array([[0.9 - 0.038 + 0.05, 0.0, 0.0]]), body, wall, np.array([False]))[0, 0] \
        == pytest.approx(-0.05)
