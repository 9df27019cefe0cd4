# SPDX-License-Identifier: EPL-2.0
"""Turns a (v, w) command into wheel speeds of the differential drive, within the robot's limits."""

from __future__ import annotations

import pybullet as p

from rei.artifacts.world import DriveSpec
from rei.geometry import Twist2D


def clamp(value: float, limit: float) -> float:
    return max(-limit, min(limit, value))


class DiffDrive:
    """Velocity-controlled wheels; a command is clamped to the maximum linear and angular velocity.

    The motors are only told when the command changes: a controller runs slower than the physics, and each
    ``setJointMotorControlArray`` costs as much as a fifth of a physics step.
    """

    __slots__ = ("_body", "_client", "_joints", "_last", "_spec", "_torques")

    def __init__(self, client: int, body: int, left: int, right: int, spec: DriveSpec, torque: float) -> None:
        self._client = client
        self._body = body
        self._joints = [left, right]
        self._spec = spec
        self._torques = [torque, torque]
        self._last: tuple[float, float] | None = None
        self.command(Twist2D())

    @property
    def applied(self) -> Twist2D:
        """The command in force, after clamping."""
        v, w = self._last if self._last is not None else (0.0, 0.0)
        return Twist2D(v, w)

    def command(self, cmd: Twist2D) -> None:
        """Apply ``cmd`` clamped to the drive's limits."""
        v = clamp(cmd.v, self._spec.max_linear_velocity)
        w = clamp(cmd.w, self._spec.max_angular_velocity)
        if (v, w) != self._last:
            half = 0.5 * self._spec.wheel_separation
            r = self._spec.wheel_radius
            p.setJointMotorControlArray(
                self._body,
                self._joints,
                p.VELOCITY_CONTROL,
                targetVelocities=[(v - w * half) / r, (v + w * half) / r],
                forces=self._torques,
                physicsClientId=self._client,
            )
            self._last = (v, w)
