# SPDX-License-Identifier: EPL-2.0
"""The laser's per-beam clearance equals the geometric gap, at the footprint's corners as on its sides."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rei.sim.clearance import FootprintClearance, OutlineClearance

WAFFLE = (0.281, 0.306)
BEAMS = 360
INCREMENT = 2 * math.pi / BEAMS


def wall_scan(yaw: float, distance_to_wall: float) -> np.ndarray:
    """Ranges of a centred lidar on a robot at heading ``yaw`` whose centre is ``distance_to_wall`` above an
    infinite wall y = 0 (world frame); beams that never meet the wall read inf."""
    angles = yaw + np.arange(BEAMS) * INCREMENT
    down = -np.sin(angles)  # the component of each beam towards the wall
    with np.errstate(divide="ignore"):
        return np.where(down > 1e-9, distance_to_wall / down, math.inf)


def reach(yaw: float) -> float:
    """How far below its centre the footprint reaches at heading ``yaw`` (a corner, or a side at 0 and 90 deg)."""
    hx, hy = WAFFLE[0] / 2, WAFFLE[1] / 2
    return hx * abs(math.sin(yaw)) + hy * abs(math.cos(yaw))


@pytest.mark.parametrize("yaw_deg", [0, 15, 30, 45, 47.4, 60, 90, 135, 200])
def test_clearance_is_the_gap_to_a_wall_at_any_heading(yaw_deg: float) -> None:
    yaw = math.radians(yaw_deg)
    gap = 0.20
    clearance = FootprintClearance(*WAFFLE)(wall_scan(yaw, gap + reach(yaw)), 0.0, INCREMENT)
    # a beam passes within half a degree of the lowest corner: the hit point lies that close to the true one
    assert clearance == pytest.approx(gap, abs=0.004)
    assert clearance >= gap - 1e-9  # a hit point is never nearer than the nearest point of the wall


def test_at_a_corner_the_inscribed_radius_reads_too_far_and_the_clearance_does_not() -> None:
    # the robot turned 45 degrees by a wall: its corner is 0.20 m from the wall, its sides further
    yaw = math.radians(45)
    ranges = wall_scan(yaw, 0.20 + reach(yaw))
    old = float(ranges.min()) - min(WAFFLE) / 2
    assert old > 0.25  # the former laser distance: FAR against the default 0.25 m CLOSE threshold
    assert FootprintClearance(*WAFFLE)(ranges, 0.0, INCREMENT) < 0.205  # now CLOSE, like the geometry


def test_hits_inside_the_footprint_are_zero_and_no_hit_is_inf() -> None:
    clearance = FootprintClearance(*WAFFLE)
    assert clearance(np.full(BEAMS, math.inf), 0.0, INCREMENT) == math.inf
    touching = np.full(BEAMS, math.inf)
    touching[0] = 0.12  # range_min clamps a hit under the sensor's blind zone, inside the footprint
    assert clearance(touching, 0.0, INCREMENT) == 0.0


def test_a_scan_layout_other_than_rei_lidar_is_measured_with_its_own_angles() -> None:
    # a ROS scan from -pi/2 to +pi/2: beam 0 looks right (-y), the obstacle 0.5 m there is 0.5 - 0.153 away
    ranges = np.array([0.5, math.inf, math.inf])
    assert FootprintClearance(*WAFFLE)(ranges, -math.pi / 2, math.pi / 2) == pytest.approx(0.5 - WAFFLE[1] / 2)
    with pytest.raises(ValueError, match="positive size"):
        FootprintClearance(0.0, 0.3)


def test_a_described_robots_outline_is_measured_from_its_lidar() -> None:
    rng = np.random.default_rng(41)
    ranges = rng.uniform(0.05, 2.0, 360)
    ranges[rng.uniform(size=360) < 0.2] = math.inf
    increment = 2 * math.pi / 360
    rectangle = np.array([[-0.15, -0.1], [0.15, -0.1], [0.15, 0.1], [-0.15, 0.1]])
    # a rectangle centred on the sensor measures what the rectangle footprint does
    assert OutlineClearance(rectangle)(ranges, 0.0, increment) == pytest.approx(
        FootprintClearance(0.3, 0.2)(ranges, 0.0, increment))
    # a Burger's base seen from its lidar 0.032 m behind the robot's origin (lidar frame): 0.070 to its front
    base = np.array([[-0.102, -0.07], [0.038, -0.07], [0.038, 0.07], [-0.102, 0.07]]) + [0.032, 0.0]
    ahead = np.full(360, math.inf)
    ahead[0] = 0.5
    assert OutlineClearance(base)(ahead, 0.0, increment) == pytest.approx(0.5 - 0.07)
    ahead[0] = 0.05  # a hit inside the outline
    assert OutlineClearance(base)(ahead, 0.0, increment) == 0.0
