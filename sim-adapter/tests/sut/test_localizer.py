# SPDX-License-Identifier: EPL-2.0
"""Localization against the static map: the signed outline field and the scan matcher."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rei.geometry import Pose2D
from rei.sut.nav import NavConfig
from rei.sut.nav.grid import CostGrid
from rei.sut.nav.localizer import Localizer

from .kinematic import Disc, KinematicWorld, rect_room, room

CONFIG = NavConfig()


def local_points(world: KinematicWorld) -> np.ndarray:
    scan = world.observation().scan
    assert scan is not None
    angles = scan.angle_min + scan.angle_increment * np.arange(len(scan.ranges))
    ok = np.isfinite(scan.ranges)
    return np.column_stack((scan.ranges[ok] * np.cos(angles[ok]), scan.ranges[ok] * np.sin(angles[ok])))


def settle(localizer: Localizer, odom: Pose2D, points: np.ndarray, scans: int = 20) -> Pose2D:
    pose = localizer.pose(odom)
    for _ in range(scans):
        pose = localizer.update(odom, points)
    return pose


def test_surface_field_is_signed_and_zero_on_the_outlines_only():
    grid = CostGrid(rect_room(4, 4, [(2.0, 2.0, 0.0, 1.0, 0.6)]), CONFIG)
    d, gx, gy = grid.surface_at(np.array([2.0, 2.8, 2.5, 1.0, 0.05, 0.1]), np.array([1.8, 2.0, 2.0, 2.0, 2.0, 2.0]))
    assert d[0] == pytest.approx(-0.1, abs=0.01)  # inside the box, 0.1 m from its lower side
    assert d[1] == pytest.approx(0.3, abs=0.01)  # right of the box
    assert d[2] == pytest.approx(0.0, abs=0.01)  # on its outline
    assert gx[1] == pytest.approx(1.0, abs=0.05) and gy[1] == pytest.approx(0.0, abs=0.05)
    assert d[4] == pytest.approx(0.0, abs=0.01)  # the wall's inner face (walls are centred on the bounds)
    assert d[5] == pytest.approx(0.05, abs=0.01)
    assert np.isnan(grid.surface_at(np.array([-5.0]), np.array([2.0]))[0][0])  # off the grid


def test_scan_matching_removes_an_odometry_error():
    static_map = rect_room(6, 4, [(3.0, 2.0, 0.3, 1.2, 0.8)])
    world = KinematicWorld(static_map, Pose2D(1.2, 1.1, 0.4))
    localizer = Localizer(CostGrid(static_map, CONFIG), CONFIG.match_gate)
    wrong = Pose2D(1.28, 1.04, 0.4 + math.radians(4.0))  # the odometry, with the map frame = odometry frame
    pose = settle(localizer, wrong, local_points(world))
    assert pose.distance_to(world.pose) < 0.005
    assert abs(pose.yaw - world.pose.yaw) < math.radians(0.2)
    # The correction stays for later odometry poses.
    assert localizer.pose(wrong).distance_to(world.pose) < 0.005


def test_scan_matching_ignores_a_person_beside_the_robot():
    static_map = rect_room(6, 4)
    world = KinematicWorld(static_map, Pose2D(2.0, 2.0, 0.0), discs=[Disc(0.25, lambda t: (2.6, 2.3))])
    localizer = Localizer(CostGrid(static_map, CONFIG), CONFIG.match_gate)
    pose = settle(localizer, Pose2D(2.05, 1.95, 0.03), local_points(world))
    assert pose.distance_to(world.pose) < 0.01
    assert abs(pose.yaw) < math.radians(0.3)


def test_scan_matching_keeps_the_odometry_where_the_scan_says_nothing():
    # A 12 m corridor: with 3.5 m of laser range the robot in its middle sees only the two side walls.
    static_map = room([(i, 0) for i in range(12)])
    world = KinematicWorld(static_map, Pose2D(6.0, 0.5, 0.0))
    localizer = Localizer(CostGrid(static_map, CONFIG), CONFIG.match_gate)
    pose = settle(localizer, Pose2D(6.2, 0.56, 0.02), local_points(world))
    assert pose.x == pytest.approx(6.2, abs=0.01)  # along the corridor: nothing to match, odometry stands
    assert pose.y == pytest.approx(0.5, abs=0.005)
    assert pose.yaw == pytest.approx(0.0, abs=math.radians(0.2))
