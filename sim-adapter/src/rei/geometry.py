"""Planar poses and twists shared by the simulator, the controllers and the collector."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Pose2D:
    """A planar pose in the world frame: metres and radians."""

    x: float
    y: float
    yaw: float = 0.0

    def distance_to(self, other: Pose2D) -> float:
        return math.hypot(other.x - self.x, other.y - self.y)


@dataclass(frozen=True, slots=True)
class Twist2D:
    """A planar velocity command or measurement: forward m/s and turn rad/s (robot frame)."""

    v: float = 0.0
    w: float = 0.0


def wrap_angle(angle: float) -> float:
    """Angle wrapped to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def yaw_of_quaternion(x: float, y: float, z: float, w: float) -> float:
    """The rotation about z of the orientation ``(x, y, z, w)``: a body's planar yaw (pybullet, ROS)."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def quaternion_of_yaw(yaw: float) -> tuple[float, float, float, float]:
    """``(x, y, z, w)`` of a rotation by ``yaw`` about z."""
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))
