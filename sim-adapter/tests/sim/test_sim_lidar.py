# SPDX-License-Identifier: EPL-2.0
"""The planar lidar measures distances to walls and humans in the robot's frame, at its own rate."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rei.geometry import Twist2D
from rei.sim.lidar import Prisms
from rei.sim.simulation import Simulation

INNER = (
    0.05,
    0.05,
    5.95,
    3.95,
)  # inner faces of the 0.1 m walls centred on the room's edges (docs/artifacts.md)


def _to_inner_walls(x: float, y: float, angle: float) -> float:
    """Distance from (x, y) along ``angle`` to the inside of the room's walls."""
    c, s = math.cos(angle), math.sin(angle)
    candidates = []
    if c > 1e-12:
        candidates.append((INNER[2] - x) / c)
    if c < -1e-12:
        candidates.append((INNER[0] - x) / c)
    if s > 1e-12:
        candidates.append((INNER[3] - y) / s)
    if s < -1e-12:
        candidates.append((INNER[1] - y) / s)
    return min(candidates)


def _to_circle(x: float, y: float, angle: float, cx: float, cy: float, r: float) -> float:
    dx, dy = math.cos(angle), math.sin(angle)
    fx, fy = x - cx, y - cy
    b = fx * dx + fy * dy
    disc = b * b - (fx * fx + fy * fy - r * r)
    if disc < 0:
        return math.inf
    t = -b - math.sqrt(disc)
    return t if t > 0 else math.inf


def test_initial_scan_reads_the_walls(sim: Simulation) -> None:
    scan = sim.observation().scan
    assert scan is not None and scan.t == 0.0
    assert scan.ranges.shape == (360,) and scan.angle_min == 0.0
    assert scan.angle_increment == pytest.approx(2 * math.pi / 360)
    assert scan.ranges[180] == pytest.approx(0.95, abs=0.01)  # left wall: 1.0 - 0.05
    assert scan.ranges[270] == pytest.approx(0.95, abs=0.01)  # bottom wall
    assert scan.ranges[90] == pytest.approx(2.95, abs=0.01)  # top wall: 3.95 - 1.0
    assert scan.ranges[0] == math.inf  # right wall at 4.95 m is beyond range_max 3.5
    assert np.all(scan.ranges[np.isfinite(scan.ranges)] > 0.3)  # the robot does not see itself
    assert sim.state().robot.laser_min == pytest.approx(0.95, abs=0.01)
    # the nearest walls face the robot's sides: its clearance is the range less the half width or length
    size_x, size_y = sim.case.world.robot.size[:2]
    assert sim.state().robot.laser_clearance == pytest.approx(0.95 - max(size_x, size_y) / 2, abs=0.01)


def test_scan_sees_the_human_cylinder(sim: Simulation) -> None:
    ranges = sim.observation().scan.ranges  # type: ignore[union-attr]
    hits = 0
    for i in range(360):
        angle = math.radians(i)
        expected = _to_circle(1.0, 1.0, angle, 1.5, 2.7, 0.25)
        if math.isfinite(expected) and expected < _to_inner_walls(1.0, 1.0, angle):
            hits += 1
            assert ranges[i] == pytest.approx(expected, abs=0.01), i
    assert hits >= 10


def test_beams_turn_with_the_robot(sim: Simulation) -> None:
    for _ in range(round(1.3 * sim.physics_rate)):
        sim.step(Twist2D(0.0, 1.2))
    for _ in range(round(0.3 * sim.physics_rate)):  # stop, and let a fresh scan be taken at rest
        sim.step(Twist2D(0.0, 0.0))
    x, y, _, yaw = sim.state().robot.pose
    assert yaw > 1.0  # really turned
    scan = sim.observation().scan
    assert scan is not None
    checked = 0
    for i in range(360):
        world_angle = yaw + i * scan.angle_increment
        if (
            math.cos(world_angle) < -0.3 or math.sin(world_angle) < -0.3
        ):  # towards the left or bottom walls only
            expected = _to_inner_walls(x, y, world_angle)
            if expected < 3.4:
                checked += 1
                assert scan.ranges[i] == pytest.approx(expected, abs=0.015), i
    assert checked > 100


def test_scan_rate(room: Path) -> None:
    with Simulation(room, lidar_rate=4.0) as sim:
        times = set()
        for _ in range(round(1.0 * sim.physics_rate)):
            sim.step(Twist2D(0.1, 0.0))
            times.add(sim.observation().scan.t)  # type: ignore[union-attr]
        assert sorted(times) == pytest.approx([0.0, 0.25, 0.5, 0.75, 1.0])


def test_without_humans_the_beam_reaches_the_wall(room: Path) -> None:
    with Simulation(room, humans=False) as sim:
        ranges = sim.observation().scan.ranges  # type: ignore[union-attr]
        assert ranges[74] == pytest.approx(_to_inner_walls(1.0, 1.0, math.radians(74)), abs=0.01)
        assert sim.state().objects == ()


def _through_box(origin: tuple[float, ...], ray: tuple[float, ...], centre: tuple[float, float],
                 half: tuple[float, float], yaw: float, z: tuple[float, float]) -> float:
    """The least t in [0, 1] at which ``origin + t ray`` is inside the upright box, one slab at a time (inf: never)."""
    c, s = math.cos(yaw), math.sin(yaw)
    ox, oy = origin[0] - centre[0], origin[1] - centre[1]
    low, high = 0.0, 1.0
    for u0, du, lo, hi in ((c * ox + s * oy, c * ray[0] + s * ray[1], -half[0], half[0]),
                           (-s * ox + c * oy, -s * ray[0] + c * ray[1], -half[1], half[1]),
                           (origin[2], ray[2], z[0], z[1])):
        if du == 0:
            if not lo <= u0 <= hi:
                return math.inf
            continue
        t0, t1 = sorted(((lo - u0) / du, (hi - u0) / du))
        low, high = max(low, t0), min(high, t1)
    return low if low <= high else math.inf


def test_prisms_meet_rays_at_their_exact_shape() -> None:
    # a cylinder (r 0.25, 0 to 1.7 m) and a box turned by 30 degrees (1.0 x 0.4, 0 to 0.8 m)
    prisms = Prisms(xy=[(2.0, 0.5), (-1.0, 1.5)], z=[(0.0, 1.7), (0.0, 0.8)], radius=[0.25, 0.0],
                    half=[(0.25, 0.25), (0.5, 0.2)], yaw=[0.0, math.radians(30)])
    origin = np.array([0.0, 0.0, 0.2])
    angles = np.radians(np.arange(0.0, 360.0, 0.25))
    rays = np.column_stack([3.5 * np.cos(angles), 3.5 * np.sin(angles), np.zeros_like(angles)])
    got = prisms.hits(origin, rays)
    for k, ray in enumerate(rays):
        circle = _to_circle(0.0, 0.0, angles[k], 2.0, 0.5, 0.25) / 3.5
        box = _through_box(tuple(origin), tuple(ray), (-1.0, 1.5), (0.5, 0.2), math.radians(30), (0.0, 0.8))
        expected = min(circle if circle <= 1.0 else math.inf, box)
        assert got[k] == pytest.approx(expected, abs=1e-12), k
    assert np.isfinite(got).sum() > 40  # both bodies were hit
    # a level ray over the box's top misses it; one going down meets it where it passes into its height
    above = prisms.hits(np.array([0.0, 0.0, 0.9]), np.array([[-1.0, 1.5, 0.0], [-1.0, 1.5, -0.5]]))
    assert above[0] == math.inf
    assert 0.0 < above[1] < 1.0
    assert above[1] == pytest.approx(_through_box((0.0, 0.0, 0.9), (-1.0, 1.5, -0.5), (-1.0, 1.5), (0.5, 0.2),
                                                  math.radians(30), (0.0, 0.8)), abs=1e-12)
    # a ray that starts inside a body meets it at once; one that ends short of it does not
    assert prisms.hits(np.array([2.1, 0.5, 1.0]), np.array([[1.0, 0.0, 0.0]]))[0] == 0.0
    assert prisms.hits(origin, np.array([[1.5, 0.375, 0.0]]))[0] == math.inf
    # cylinders alone (people), the rays level: the same hits
    people = Prisms(xy=[(2.0, 0.5), (0.0, -1.0)], z=[(0.0, 1.7), (0.0, 1.7)], radius=[0.25, 0.3],
                    half=[(0.25, 0.25), (0.3, 0.3)], yaw=[0.0, 0.0])
    got = people.hits(origin, rays)
    for k in range(len(rays)):
        expected = min(_to_circle(0.0, 0.0, angles[k], 2.0, 0.5, 0.25), _to_circle(0.0, 0.0, angles[k], 0.0, -1.0, 0.3))
        assert got[k] == pytest.approx(expected / 3.5 if expected <= 3.5 else math.inf, abs=1e-12), k
