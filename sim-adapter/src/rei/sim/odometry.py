# SPDX-License-Identifier: EPL-2.0
"""Wheel odometry: dead reckoning from the wheels' rotation, the only pose a real robot's controller gets.

Integrated from the change of the wheel joint angles (not from the simulator's true pose), so wheel slip and
bumps show up as odometry drift, as on a real robot. Optional noise models imperfect encoders and wheel radius:
each wheel's travel gets Gaussian error with variance ``noise**2 * |travel|``, so the error after distance ``d``
has standard deviation ``noise * sqrt(d)`` per wheel, independent of the physics rate.
"""

from __future__ import annotations

import math

import numpy as np

from rei.geometry import Pose2D, Twist2D, wrap_angle


class _DeadReckoning:
    """The pose an odometry integrates, and what both kinds do with it: its noise's checks, a jump, the pose."""

    __slots__ = ("_noise", "_rng", "_x", "_y", "_yaw")

    def __init__(self, start: Pose2D, noise: float, rng: np.random.Generator | None) -> None:
        if noise < 0.0:
            raise ValueError(f"odometry noise must be >= 0, got {noise}")
        if noise > 0.0 and rng is None:
            raise ValueError("odometry noise needs a seeded generator")
        self._noise = noise
        self._rng = rng
        self._x, self._y, self._yaw = start.x, start.y, start.yaw

    def shift(self, dx: float, dy: float, dyaw: float) -> None:
        """Move the pose by an offset (an odometry jump): world axes, radians."""
        self._x += dx
        self._y += dy
        self._yaw = wrap_angle(self._yaw + dyaw)

    @property
    def pose(self) -> Pose2D:
        return Pose2D(self._x, self._y, self._yaw)


class WheelOdometry(_DeadReckoning):
    """Midpoint integration of a differential drive's wheel angles."""

    __slots__ = ("_b", "_left", "_r", "_right", "_v", "_w")

    def __init__(
        self,
        wheel_radius: float,
        wheel_separation: float,
        start: Pose2D,
        left_angle: float,
        right_angle: float,
        noise: float = 0.0,
        rng: np.random.Generator | None = None,
    ) -> None:
        super().__init__(start, noise, rng)
        self._r = wheel_radius
        self._b = wheel_separation
        self._left, self._right = left_angle, right_angle
        self._v = self._w = 0.0

    def update(self, left_angle: float, right_angle: float, left_rate: float, right_rate: float,
               scale: float = 1.0, yaw_bias: float = 0.0) -> None:
        """Advance by the wheels' rotation since the last update; rates (rad/s) give the current twist.

        Odometry faults (rei.sim.faults.motion): the wheels' travel and rates times ``scale``, ``yaw_bias``
        radians added to this update's heading change."""
        dl = self._r * wrap_angle(left_angle - self._left)
        dr = self._r * wrap_angle(right_angle - self._right)
        self._left, self._right = left_angle, right_angle
        if self._noise > 0.0 and self._rng is not None:
            e = self._rng.standard_normal(2)
            dl += self._noise * math.sqrt(abs(dl)) * float(e[0])
            dr += self._noise * math.sqrt(abs(dr)) * float(e[1])
        if scale != 1.0:
            dl, dr, left_rate, right_rate = scale * dl, scale * dr, scale * left_rate, scale * right_rate
        ds = 0.5 * (dl + dr)
        dyaw = (dr - dl) / self._b + yaw_bias
        heading = self._yaw + 0.5 * dyaw
        self._x += ds * math.cos(heading)
        self._y += ds * math.sin(heading)
        self._yaw = wrap_angle(self._yaw + dyaw)
        self._v = 0.5 * self._r * (left_rate + right_rate)
        self._w = self._r * (right_rate - left_rate) / self._b

    @property
    def twist(self) -> Twist2D:
        return Twist2D(self._v, self._w)


class BodyOdometry(_DeadReckoning):
    """A holonomic base's odometry: its wheels (mecanum or omni) measure the body's velocity in its own frame, so
    this integrates the body's velocity (forward, sideways, turn) turned into the frame of the odometry's own
    heading, at the midpoint of each step. Noise as :class:`WheelOdometry`'s, on each axis's travel; a bump or a
    push is measured as the motion it is (a holonomic base's rollers slip sideways by design, so the model has no
    wheel slip to miss)."""

    __slots__ = ("_twist",)

    def __init__(self, start: Pose2D, noise: float = 0.0, rng: np.random.Generator | None = None) -> None:
        super().__init__(start, noise, rng)
        self._twist = Twist2D()

    def update(self, v: float, vy: float, w: float, dt: float, scale: float = 1.0, yaw_bias: float = 0.0) -> None:
        """Advance by the body's velocity ``(v, vy, w)`` in its own frame over ``dt``; odometry faults as
        :meth:`WheelOdometry.update`'s."""
        dx, dy, dyaw = scale * v * dt, scale * vy * dt, scale * w * dt
        if self._noise > 0.0 and self._rng is not None:
            e = self._rng.standard_normal(2)
            dx += self._noise * math.sqrt(abs(dx)) * float(e[0])
            dy += self._noise * math.sqrt(abs(dy)) * float(e[1])
        dyaw += yaw_bias
        heading = self._yaw + 0.5 * dyaw
        c, s = math.cos(heading), math.sin(heading)
        self._x += c * dx - s * dy
        self._y += s * dx + c * dy
        self._yaw = wrap_angle(self._yaw + dyaw)
        self._twist = Twist2D(scale * v, scale * w, scale * vy)

    @property
    def twist(self) -> Twist2D:
        return Twist2D(self._twist.v, self._twist.w, self._twist.vy)
