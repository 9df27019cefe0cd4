# SPDX-License-Identifier: EPL-2.0
"""Turns a velocity command into the robot's motion within its limits: a differential drive's wheel speeds, or a
holonomic drive's force and torque (docs/robots.md#drives)."""

from __future__ import annotations

import math

import pybullet as p

from rei.artifacts.world import DriveSpec
from rei.geometry import Twist2D, yaw_of_quaternion


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


class HolonomicDrive:
    """An omnidirectional base (mecanum or omni wheels), modelled by what it does rather than by its rollers: the
    body glides on frictionless wheels and casters, and a planar force and a torque about the vertical, applied at
    its centre of mass on every physics step, bring its velocity in its own frame to the command's (v, vy, w).
    Force and torque are those the differential drive's motors give (``max_force``: the whole robot's mass times
    their acceleration; ``max_torque``: that force at half the wheel separation), so both drives accelerate alike.

    pybullet clears external forces after each step, so :meth:`push` runs before every ``stepSimulation``.
    """

    __slots__ = ("_body", "_client", "_com", "_gain_f", "_gain_t", "_last", "_max_force", "_max_torque", "_spec",
                 "_target")

    #: The share of the velocity error corrected in one physics step: 1 would cancel it exactly on a free body,
    #: but a contact or the casters' bounce then makes it overshoot; a half converges in a few steps (~20 ms).
    GAIN = 0.5

    def __init__(self, client: int, body: int, spec: DriveSpec, max_acceleration: float, dt: float) -> None:
        self._client = client
        self._body = body
        self._spec = spec
        mass, com, izz = mass_properties(client, body)
        self._com = com
        # the force and torque that change the velocity by GAIN of the error within one step of dt
        self._gain_f = self.GAIN * mass / dt
        self._gain_t = self.GAIN * izz / dt
        self._max_force = mass * max_acceleration
        self._max_torque = self._max_force * spec.wheel_separation / 2
        self._last = Twist2D()
        self._target = (0.0, 0.0, 0.0)

    @property
    def applied(self) -> Twist2D:
        """The command in force, after clamping."""
        return self._last

    def command(self, cmd: Twist2D, fraction: float = 1.0, stuck: tuple[bool, bool] = (False, False)) -> None:
        """Take ``cmd`` clamped to the drive's limits (``vy`` to the forward speed's); a slip's ``fraction`` scales
        the motion the ground gives. A holonomic drive has no left or right wheel to stick (the language refuses
        such a fault on it)."""
        if stuck != (False, False):
            raise ValueError("a stuck wheel is a fault of a differential drive; this robot's drive is holonomic")
        spec = self._spec
        v = clamp(cmd.v, spec.max_linear_velocity)
        vy = clamp(cmd.vy, spec.max_lateral_velocity)
        w = clamp(cmd.w, spec.max_angular_velocity)
        self._last = Twist2D(v, w, vy)
        self._target = (fraction * v, fraction * vy, fraction * w)

    def push(self) -> None:
        """Apply this step's force and torque towards the target velocity."""
        client, body = self._client, self._body
        (x, y, z), orientation = p.getBasePositionAndOrientation(body, physicsClientId=client)
        (vx, vy, _), (_, _, wz) = p.getBaseVelocity(body, physicsClientId=client)
        yaw = yaw_of_quaternion(*orientation)
        c, s = math.cos(yaw), math.sin(yaw)
        v, lateral, w = self._target
        fx = self._gain_f * (c * v - s * lateral - vx)
        fy = self._gain_f * (s * v + c * lateral - vy)
        norm = math.hypot(fx, fy)
        if norm > self._max_force:
            fx, fy = fx * self._max_force / norm, fy * self._max_force / norm
        torque = clamp(self._gain_t * (w - wz), self._max_torque)
        cx, cy, cz = self._com
        at = (x + c * cx - s * cy, y + s * cx + c * cy, z + cz)
        p.applyExternalForce(body, -1, (fx, fy, 0.0), at, p.WORLD_FRAME, physicsClientId=client)
        p.applyExternalTorque(body, -1, (0.0, 0.0, torque), p.WORLD_FRAME, physicsClientId=client)


def mass_properties(client: int, body: int) -> tuple[float, tuple[float, float, float], float]:
    """The whole body's mass, its centre of mass in the base's frame (x, y, z) and its moment of inertia about the
    vertical through that centre, from pybullet's links as loaded (each link's inertia turned to the world's axes,
    moved by the parallel-axis theorem); the body must stand upright."""
    (bx, by, bz), base_orientation = p.getBasePositionAndOrientation(body, physicsClientId=client)
    parts = []  # (mass, world centre, zz of the inertia in world axes about the link's own centre)
    for link in range(-1, p.getNumJoints(body, physicsClientId=client)):
        info = p.getDynamicsInfo(body, link, physicsClientId=client)
        mass, inertia = info[0], info[2]
        if link == -1:
            centre, orientation = (bx, by, bz), base_orientation
        else:
            state = p.getLinkState(body, link, computeForwardKinematics=True, physicsClientId=client)
            centre, orientation = state[0], state[1]
        m = p.getMatrixFromQuaternion(orientation)
        zz = sum(m[6 + j] ** 2 * inertia[j] for j in range(3))
        parts.append((mass, centre, zz))
    total = sum(mass for mass, _, _ in parts)
    cx, cy, cz = (sum(mass * centre[k] for mass, centre, _ in parts) / total for k in range(3))
    izz = sum(zz + mass * ((centre[0] - cx) ** 2 + (centre[1] - cy) ** 2) for mass, centre, zz in parts)
    yaw = yaw_of_quaternion(*base_orientation)
    c, s = math.cos(yaw), math.sin(yaw)
    dx, dy = cx - bx, cy - by
    return total, (c * dx + s * dy, -s * dx + c * dy, cz - bz), izz
