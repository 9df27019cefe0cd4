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

    __slots__ = ("_body", "_client", "_joints", "_key", "_last", "_spec", "_torques")

    def __init__(self, client: int, body: int, left: int, right: int, spec: DriveSpec, torque: float) -> None:
        self._client = client
        self._body = body
        self._joints = [left, right]
        self._spec = spec
        self._torques = [torque, torque]
        self._last: tuple[float, float] | None = None
        self._key: tuple[object, ...] | None = None
        self.command(Twist2D())

    @property
    def applied(self) -> Twist2D:
        """The command in force, after clamping."""
        v, w = self._last if self._last is not None else (0.0, 0.0)
        return Twist2D(v, w)

    def command(self, cmd: Twist2D, fraction: float = 1.0, stuck: tuple[bool, bool] = (False, False)) -> None:
        """Apply ``cmd`` clamped to the drive's limits; drive faults (rei.sim.faults.motion): the wheels' speeds
        times ``fraction`` (a slip), a ``stuck`` wheel's (left, right) forced to 0."""
        v = clamp(cmd.v, self._spec.max_linear_velocity)
        w = clamp(cmd.w, self._spec.max_angular_velocity)
        key = (v, w) if fraction == 1.0 and stuck == (False, False) else (v, w, fraction, stuck)
        if key != self._key:
            half = 0.5 * self._spec.wheel_separation
            r = self._spec.wheel_radius
            left, right = fraction * (v - w * half) / r, fraction * (v + w * half) / r
            p.setJointMotorControlArray(
                self._body,
                self._joints,
                p.VELOCITY_CONTROL,
                targetVelocities=[0.0 if stuck[0] else left, 0.0 if stuck[1] else right],
                forces=self._torques,
                physicsClientId=self._client,
            )
            self._last = (v, w)
            self._key = key
