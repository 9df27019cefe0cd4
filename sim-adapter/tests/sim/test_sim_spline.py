# SPDX-License-Identifier: EPL-2.0
"""Catmull-Rom trajectories against values computed by hand from thesis Table 1."""

from __future__ import annotations

import math

import pytest

from rei.spline import Trajectory

# Once trajectory x: 0 -> 2 -> 2 at t = 0, 1, 3 (y stays 0). Knot velocities: v0 = 2 (one-sided), v1 = (2 + 0)/2
# = 1, v2 = 0. Segment 0 (h=1): a = (1+2) - 2*2 = -1, b = 3*2 - (1+2*2) = 1, c = 2, d = 0.
# Segment 1 (h=2): a = (0+1)/4 = 0.25, b = 0 - (0+2*1)/2 = -1, c = 1, d = 2.
ONCE = Trajectory([0.0, 1.0, 3.0], [(0.0, 0.0), (2.0, 0.0), (2.0, 0.0)], loop=False)


@pytest.mark.parametrize(
    ("t", "x", "vx"),
    [
        (0.5, -0.125 + 0.25 + 1.0, 3 * -1 * 0.25 + 2 * 1 * 0.5 + 2),  # 1.125, 2.25
        (2.0, 0.25 - 1.0 + 1.0 + 2.0, 3 * 0.25 - 2 + 1),  # 2.25, -0.25
        (2.5, 0.25 * 1.5**3 - 1.5**2 + 1.5 + 2.0, 3 * 0.25 * 1.5**2 - 2 * 1.5 + 1),
    ],
)
def test_once_matches_hand_computed_values(t: float, x: float, vx: float) -> None:
    px, py = ONCE.position(t)
    vxs, vys = ONCE.velocity(t)
    assert px == pytest.approx(x, abs=1e-12) and py == 0.0
    assert vxs == pytest.approx(vx, abs=1e-12) and vys == 0.0


def test_once_holds_before_and_after() -> None:
    assert ONCE.position(-5.0) == (0.0, 0.0) and ONCE.velocity(-5.0) == (0.0, 0.0)
    assert ONCE.position(3.0) == pytest.approx((2.0, 0.0))
    assert ONCE.position(100.0) == pytest.approx((2.0, 0.0)) and ONCE.velocity(100.0) == (0.0, 0.0)


FIXTURE_POINTS = [(1.5, 2.7), (3.5, 2.7), (3.5, 1.9), (1.5, 1.9)]
FIXTURE_TIMES = [0.0, 4.0, 6.0, 10.0]


@pytest.mark.parametrize("loop", [False, True])
def test_passes_through_control_points_at_their_times(loop: bool) -> None:
    trajectory = Trajectory(FIXTURE_TIMES, FIXTURE_POINTS, loop=loop)
    for t, point in zip(FIXTURE_TIMES, FIXTURE_POINTS, strict=True):
        assert trajectory.position(t) == pytest.approx(point, abs=1e-12)


@pytest.mark.parametrize("loop", [False, True])
def test_c1_continuous_at_interior_points(loop: bool) -> None:
    trajectory = Trajectory(FIXTURE_TIMES, FIXTURE_POINTS, loop=loop)
    eps = 1e-7
    for t in FIXTURE_TIMES[1:-1]:
        assert trajectory.position(t - eps) == pytest.approx(trajectory.position(t + eps), abs=1e-6)
        assert trajectory.velocity(t - eps) == pytest.approx(trajectory.velocity(t + eps), abs=1e-5)
    # interior knot velocity is the thesis's mean of the neighbouring slopes: at t=4, ((0.5, 0) + (0, -0.4)) / 2
    assert trajectory.velocity(4.0) == pytest.approx((0.25, -0.2), abs=1e-12)


def test_loop_wraps_with_closing_segment() -> None:
    trajectory = Trajectory(FIXTURE_TIMES, FIXTURE_POINTS, loop=True)
    # the closing segment lasts as long as the first one: period = 10 + 4
    assert trajectory.period == 14.0
    for t, point in zip(FIXTURE_TIMES, FIXTURE_POINTS, strict=True):
        assert trajectory.position(t + 14.0) == pytest.approx(point, abs=1e-9)
        assert trajectory.position(t + 28.0) == pytest.approx(point, abs=1e-9)
    # seam velocity: mean of closing slope (0, 0.8/4) and first slope (2/4, 0)
    assert trajectory.velocity(0.0) == pytest.approx((0.25, 0.1), abs=1e-12)
    assert trajectory.velocity(14.0 - 1e-9) == pytest.approx((0.25, 0.1), abs=1e-6)
    assert trajectory.position(12.0) != pytest.approx(FIXTURE_POINTS[-1])  # moving on the closing segment
    assert trajectory.position(-3.0) == pytest.approx(trajectory.position(11.0), abs=1e-12)


def test_two_point_loop_goes_back_and_forth() -> None:
    # knots 0, 2, 4 with x 0, 4, 0: both knot velocities are 0; segment 0: a = -2*4/8 = -1, b = 3*4/4 = 3
    trajectory = Trajectory([0.0, 2.0], [(0.0, 0.0), (4.0, 0.0)], loop=True)
    assert trajectory.period == 4.0
    assert trajectory.position(1.0) == pytest.approx((2.0, 0.0), abs=1e-12)
    assert trajectory.position(3.0) == pytest.approx((2.0, 0.0), abs=1e-12)
    assert trajectory.position(4.0) == pytest.approx((0.0, 0.0), abs=1e-12)
    assert trajectory.velocity(1.0) == pytest.approx((3.0, 0.0), abs=1e-12)  # 3a + 2b = -3 + 6
    assert trajectory.velocity(3.0) == pytest.approx((-3.0, 0.0), abs=1e-12)


def test_explicitly_closed_loop_adds_no_segment() -> None:
    trajectory = Trajectory([0.0, 1.0, 2.0], [(0.0, 0.0), (1.0, 1.0), (0.0, 0.0)], loop=True)
    assert trajectory.period == 2.0
    assert trajectory.position(2.5) == pytest.approx(trajectory.position(0.5), abs=1e-12)
    vx, vy = trajectory.velocity(0.0)
    assert math.hypot(vx, vy) == pytest.approx(0.0, abs=1e-12)  # mean of slopes (-1,-1) and (1,1)


def test_single_point_stands_still() -> None:
    trajectory = Trajectory([3.0], [(1.0, 2.0)], loop=True)
    assert trajectory.position(0.0) == (1.0, 2.0) and trajectory.position(50.0) == (1.0, 2.0)
    assert trajectory.velocity(7.0) == (0.0, 0.0)


def test_rejects_bad_input() -> None:
    with pytest.raises(ValueError, match="strictly increasing"):
        Trajectory([0.0, 0.0], [(0.0, 0.0), (1.0, 0.0)], loop=False)
    with pytest.raises(ValueError, match="as many times as points"):
        Trajectory([0.0], [(0.0, 0.0), (1.0, 0.0)], loop=False)
