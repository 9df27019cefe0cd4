# SPDX-License-Identifier: EPL-2.0
"""The simulator's true state at one instant: what the data collector publishes and the monitor judges.

Unlike :class:`rei.sut.api.Observation` (what the robot knows), this holds ground truth: true poses and twists of
the robot and of every moving object, and the physical contacts. Poses are ``(x, y, z, yaw)`` and twists
``(vx, vy, wz)`` in the world frame, as on the wire (docs/protocol.md, ``rei.run.<run_id>.state``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rei.geometry import Pose2D

Pose4 = tuple[float, float, float, float]
Twist3 = tuple[float, float, float]


@dataclass(frozen=True, slots=True, eq=False)
class RobotState:
    """``odom`` is the robot's own estimate; ``laser_min``/``laser_ranges`` are the last scan as the sensor
    reported it (faults included), ``inf`` / ``None`` before any hit / scan. The array is read-only.
    ``laser_clearance`` is that scan's distance to the footprint (rei.sim.clearance), ``inf`` likewise.

    Equality compares the ranges element-wise (a dataclass's generated ``==`` would fail on an array).
    """

    name: str
    pose: Pose4
    twist: Twist3
    odom: Pose2D
    laser_min: float
    laser_ranges: np.ndarray | None
    laser_clearance: float = math.inf

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, RobotState):
            return NotImplemented
        mine, theirs = self.laser_ranges, other.laser_ranges
        same_ranges = (mine is None and theirs is None) or (
            mine is not None and theirs is not None and np.array_equal(mine, theirs)
        )
        mine_fields = (self.name, self.pose, self.twist, self.odom, self.laser_min, self.laser_clearance)
        return same_ranges and mine_fields == (
            other.name,
            other.pose,
            other.twist,
            other.odom,
            other.laser_min,
            other.laser_clearance,
        )

    __hash__ = None  # type: ignore[assignment]


@dataclass(frozen=True, slots=True)
class ObjectState:
    """A moving object (HUMAN or DYNAMIC); ``category`` is the world.json category name."""

    name: str
    category: str
    pose: Pose4
    twist: Twist3


@dataclass(frozen=True, slots=True)
class SimState:
    """``contacts``: ``(robot_name, object_name)`` for every non-floor body the robot touched since the previous
    snapshot."""

    t: float
    robot: RobotState
    objects: tuple[ObjectState, ...]
    contacts: tuple[tuple[str, str], ...]
