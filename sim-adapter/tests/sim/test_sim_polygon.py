# SPDX-License-Identifier: EPL-2.0
"""A POLYGON object (furniture on a concave polygon) in pybullet: the lidar sees its outline, not its bounding box,
and the robot meets it where an independent shapely computation on the same polygon says."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from polygon_desk import C_DESK_POSE
from shapely import affinity
from shapely.geometry import LineString, Point, Polygon, box

from rei.artifacts.world import Category, Shape, read_world
from rei.geometry import Twist2D
from rei.sim.simulation import Simulation


def _obstacles(case: Path) -> tuple[Polygon, list[Polygon]]:
    """The desk's polygon in the world, and every other obstacle the lidar may see (walls, a human's circle)."""
    world = read_world(case / "world.json")
    desk = Polygon(world.object("table1").outline)
    others = []
    for o in world.objects:
        if o.category in (Category.WALL, Category.HUMAN) and o.name != "table1":
            if o.shape is Shape.CYLINDER:
                others.append(Point(o.pose[:2]).buffer(o.size[0] / 2, 256))
            else:
                rect = box(-o.size[0] / 2, -o.size[1] / 2, o.size[0] / 2, o.size[1] / 2)
                others.append(affinity.translate(affinity.rotate(rect, o.pose[3], use_radians=True), *o.pose[:2]))
    return desk, others


def _first_hit(x: float, y: float, angle: float, reach: float, shape: Polygon) -> float:
    ray = LineString([(x, y), (x + reach * math.cos(angle), y + reach * math.sin(angle))])
    met = ray.intersection(shape.boundary)
    return math.inf if met.is_empty else Point(x, y).distance(met)


def test_the_lidar_sees_the_desks_outline_as_shapely_casts_it(polygon_case: Path) -> None:
    desk, others = _obstacles(polygon_case)
    with Simulation(polygon_case) as sim:
        scan = sim.observation().scan
        assert scan is not None
        pose = sim.robot_pose()
        reach = sim.case.world.robot.lidar.range_max
        on_desk = 0
        for i, measured in enumerate(scan.ranges):
            angle = pose.yaw + scan.angle_min + i * scan.angle_increment
            expected = _first_hit(pose.x, pose.y, angle, reach, desk)
            if expected < min(_first_hit(pose.x, pose.y, angle, reach, o) for o in others):
                on_desk += 1
                assert measured == pytest.approx(expected, abs=0.003), f"beam {i}"
        assert on_desk >= 30
        # straight ahead the beam enters the notch to its back, 0.6 m behind the bounding box's face
        assert scan.ranges[0] == pytest.approx(C_DESK_POSE[0] + 0.1 - pose.x, abs=0.003)


def test_the_robot_meets_the_notchs_back_where_shapely_says(polygon_case: Path) -> None:
    desk, _ = _obstacles(polygon_case)
    with Simulation(polygon_case) as sim:
        sx, sy = sim.case.world.robot.size[:2]
        start = sim.robot_pose()

        def footprint(x: float) -> Polygon:
            return box(x - sx / 2, start.y - sy / 2, x + sx / 2, start.y + sy / 2)

        # shapely: the farthest x the robot's rectangle reaches along its line before it touches the desk
        low, high = start.x, C_DESK_POSE[0] + 0.5
        while high - low > 1e-6:
            mid = (low + high) / 2
            low, high = (mid, high) if footprint(mid).distance(desk) > 0 else (low, mid)
        met = None
        for _ in range(round(20 * sim.physics_rate)):
            sim.step(Twist2D(0.2, 0.0))
            if ("tb3", "table1") in sim.state().contacts:
                met = sim.robot_pose()
                break
        assert met is not None, "the robot never touched the desk"
        # inside the notch, 0.6 m past the bounding box's face, within a step's travel and the contact margin
        assert met.x == pytest.approx(low, abs=0.005), (met.x, low)
        assert abs(met.y - start.y) < 0.01
        assert met.x > C_DESK_POSE[0] - 0.5
