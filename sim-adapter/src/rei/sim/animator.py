# SPDX-License-Identifier: EPL-2.0
"""Moves humans and dynamic objects along their Catmull-Rom trajectories (thesis 4.2.2, 6.2.2). (Reactive people are
fixed bodies the simulation puts where the crowd model puts them, rei.sim.simulation.)

At each update, at time ``t`` with the next update due at ``t + T``, a body is given the velocity that brings it
from where it really is to ``r(t + T)`` (the thesis's ``v = (r(t1) - r(t0)) / dt`` with the measured position as
``r(t0)``), so it follows the spline without drift and returns to it after being pushed. Two ways to impose it:

* ``velocity`` (default, thesis 6.2.2): set the base velocity directly;
* ``force``: apply ``F = m dv / dt`` for one physics step, so the change goes through the contact solver.

The speed is capped at ``MAX_SPEED`` so a blocked body does not build up an explosive catch-up velocity.

To make bodies track, nothing may slow them between updates: they do not collide with the floors (no friction,
and a standing cylinder's floor contact would cost the solver more than the rest of the room), and gravity is
compensated instead, by the vertical velocity that keeps them at their standing height over the next update
interval. Their angular velocity is zeroed and they are set upright again when something tilted them. They still
collide with the robot, walls, furniture and each other.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Protocol

import pybullet as p

from rei.geometry import yaw_of_quaternion

MAX_SPEED = 3.0
_TILT = 1e-3


class DriveMode(enum.StrEnum):
    VELOCITY = "velocity"
    FORCE = "force"


class Path(Protocol):
    """Where a body should be at a time: a trajectory on rails (rei.spline)."""

    def position(self, t: float) -> tuple[float, float]: ...


@dataclass(slots=True)
class AnimatedBody:
    name: str
    body: int
    mass: float
    trajectory: Path
    height: float = 0.0
    """z of the body's centre when standing; set by :meth:`Animator.place`."""


class Animator:
    __slots__ = ("_bodies", "_client", "_dt", "_gravity", "_mode", "_zero")

    def __init__(
        self,
        client: int,
        bodies: list[AnimatedBody],
        mode: DriveMode,
        physics_dt: float,
        floors: Iterable[int],
        gravity: float,
    ) -> None:
        self._client = client
        self._bodies = bodies
        self._mode = mode
        self._dt = physics_dt
        self._gravity = gravity
        self._zero = (0.0, 0.0, 0.0)
        floors = tuple(floors)
        for b in bodies:
            p.changeDynamics(b.body, -1, linearDamping=0.0, angularDamping=0.0, physicsClientId=client)
            for floor in floors:
                p.setCollisionFilterPair(b.body, floor, -1, -1, 0, physicsClientId=client)

    @property
    def bodies(self) -> tuple[AnimatedBody, ...]:
        return tuple(self._bodies)

    def place(self, t: float) -> None:
        """Put every body on its trajectory at ``t``, at rest, upright, at its current (standing) height."""
        for b in self._bodies:
            x, y = b.trajectory.position(t)
            pos, orn = p.getBasePositionAndOrientation(b.body, physicsClientId=self._client)
            b.height = pos[2]
            p.resetBasePositionAndOrientation(
                b.body,
                (x, y, pos[2]),
                p.getQuaternionFromEuler((0.0, 0.0, yaw_of_quaternion(*orn))),
                physicsClientId=self._client,
            )
            p.resetBaseVelocity(b.body, self._zero, self._zero, physicsClientId=self._client)

    def update(self, t: float, t_next: float) -> None:
        """Steer every body so that it reaches its trajectory's point of ``t_next`` (``t_next > t``)."""
        client = self._client
        horizon = t_next - t
        steps = max(1, round(horizon / self._dt))
        # semi-implicit Euler over n steps sinks by g dt^2 n(n+1)/2: start with that much extra upward speed
        lift = self._gravity * self._dt * (steps + 1) / 2.0
        for b in self._bodies:
            tx, ty = b.trajectory.position(t_next)
            pos, orn = p.getBasePositionAndOrientation(b.body, physicsClientId=client)
            vx = (tx - pos[0]) / horizon
            vy = (ty - pos[1]) / horizon
            speed = math.hypot(vx, vy)
            if speed > MAX_SPEED:
                vx *= MAX_SPEED / speed
                vy *= MAX_SPEED / speed
            vz = (b.height - pos[2]) / horizon + lift
            if abs(orn[0]) > _TILT or abs(orn[1]) > _TILT:
                p.resetBasePositionAndOrientation(
                    b.body, pos, p.getQuaternionFromEuler((0.0, 0.0, yaw_of_quaternion(*orn))), physicsClientId=client
                )
            if self._mode is DriveMode.VELOCITY:
                p.resetBaseVelocity(b.body, (vx, vy, vz), self._zero, physicsClientId=client)
            else:
                lin, _ = p.getBaseVelocity(b.body, physicsClientId=client)
                k = b.mass / self._dt
                p.resetBaseVelocity(b.body, lin, self._zero, physicsClientId=client)
                p.applyExternalForce(
                    b.body,
                    -1,
                    (k * (vx - lin[0]), k * (vy - lin[1]), k * (vz - lin[2])),
                    pos,
                    p.WORLD_FRAME,
                    physicsClientId=client,
                )

