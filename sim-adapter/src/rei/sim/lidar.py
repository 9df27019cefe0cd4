# SPDX-License-Identifier: EPL-2.0
"""Planar 360-degree lidar: one ``rayTestBatch`` per scan, in the robot's frame.

The rays are given relative to the robot's base (``parentObjectUniqueId``), so the from/to arrays are built once
and pybullet moves them with the robot. Beam ``i`` points at ``i * 2 pi / beams`` counter-clockwise from the
robot's heading (the ``LaserScan`` convention of rei.sut.api). The robot's own links are left out through their
collision group; floors are not hit because the sensor is above them and the rays are horizontal.

Readings: the distance from the sensor to the first hit; ``inf`` when nothing is within ``range_max``; a hit
nearer than ``range_min`` reads ``range_min`` (a real sensor is blind there; clamping keeps "something touches
the robot" visible to the controller and to the monitor's laser-collision query).
"""

from __future__ import annotations

import math

import numpy as np
import pybullet as p

from rei.artifacts.world import LidarSpec
from rei.sim.robot_model import ROBOT_COLLISION_GROUP

_RAY_MASK = 0xFFFF & ~ROBOT_COLLISION_GROUP


class Lidar:
    __slots__ = ("_body", "_client", "_from", "_to", "angle_increment", "spec")

    def __init__(self, client: int, body: int, spec: LidarSpec) -> None:
        self._client = client
        self._body = body
        self.spec = spec
        self.angle_increment = 2.0 * math.pi / spec.beams
        # beam angles are the lidar's own (its link's yaw in a robot read from a description), from its place
        angles = np.arange(spec.beams) * self.angle_increment + spec.yaw
        z = spec.mount_height
        self._from = np.zeros((spec.beams, 3))
        self._from[:, 0] = spec.x
        self._from[:, 1] = spec.y
        self._from[:, 2] = z
        self._to = np.column_stack(
            [spec.x + spec.range_max * np.cos(angles), spec.y + spec.range_max * np.sin(angles),
             np.full(spec.beams, z)]
        )

    def scan(self) -> np.ndarray:
        """One scan's ranges (a new array of ``beams`` floats)."""
        results = p.rayTestBatch(
            self._from,
            self._to,
            parentObjectUniqueId=self._body,
            parentLinkIndex=-1,
            numThreads=1,
            collisionFilterMask=_RAY_MASK,
            physicsClientId=self._client,
        )
        spec = self.spec
        ranges = np.fromiter(
            (r[2] * spec.range_max if r[0] >= 0 else math.inf for r in results), dtype=float, count=spec.beams
        )
        np.maximum(ranges, spec.range_min, out=ranges)
        return ranges
