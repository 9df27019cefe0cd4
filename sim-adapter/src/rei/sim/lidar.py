# SPDX-License-Identifier: EPL-2.0
"""Planar 360-degree lidar: one ``rayTestBatch`` per scan, in the robot's frame.

The rays are given relative to the robot's base (``parentObjectUniqueId``), so the from/to arrays are built once
and pybullet moves them with the robot. Beam ``i`` points at ``i * 2 pi / beams`` counter-clockwise from the
robot's heading (the ``LaserScan`` convention of rei.sut.api). The robot's own links are left out through their
collision group; floors are not hit because the sensor is above them and the rays are horizontal.

Readings: the distance from the sensor to the first hit; ``inf`` when nothing is within ``range_max``; a hit
nearer than ``range_min`` reads ``range_min`` (a real sensor is blind there; clamping keeps "something touches
the robot" visible to the controller and to the monitor's laser-collision query).

The reactive people are :class:`Prisms`: the rays meet them by their exact shape (an upright cylinder or box of
their size), worked out here for all beams at once, and pybullet's ray test does not see their bodies. pybullet
casts a ray against a convex body by GJK, tens of microseconds a ray and body (a cylinder is a hull of 32 sides
there), which made a scan among a crowd cost milliseconds; its hits also fall short of the exact shape by about a
millimetre (its collision margin), and by up to 2 cm at a grazing angle.
"""

from __future__ import annotations

import math

import numpy as np
import pybullet as p

from rei.artifacts.world import LidarSpec
from rei.sim.robot_model import ROBOT_COLLISION_GROUP

_RAY_MASK = 0xFFFF & ~ROBOT_COLLISION_GROUP


class Prisms:
    """Upright bodies the rays meet by their exact shape: each a vertical cylinder (``radius`` > 0) or a box
    (``half`` extents along its own axes, turned by ``yaw``) from height ``z[i, 0]`` to ``z[i, 1]``, standing at
    ``xy[i]``, which its owner moves."""

    __slots__ = ("_cos_sin", "_reach", "half", "radius", "xy", "z")

    def __init__(self, xy: object, z: object, radius: object, half: object, yaw: object) -> None:
        self.xy = np.array(xy, dtype=float).reshape(-1, 2)
        self.z = np.array(z, dtype=float).reshape(-1, 2)
        self.radius = np.array(radius, dtype=float).reshape(-1)
        self.half = np.array(half, dtype=float).reshape(-1, 2)
        yaw = np.array(yaw, dtype=float).reshape(-1)
        self._cos_sin = np.column_stack([np.cos(yaw), np.sin(yaw)])
        # the radius of the disc around each footprint
        self._reach = np.where(self.radius > 0, self.radius, np.hypot(self.half[:, 0], self.half[:, 1]))

    def hits(self, origin: np.ndarray, rays: np.ndarray) -> np.ndarray:
        """For each ray ``origin + t * rays[k]`` (0 <= t <= 1, with a horizontal extent), the least ``t`` at which it
        meets a body (0 when it starts inside one), ``inf`` where it meets none."""
        # the bodies whose footprint's disc a ray's horizontal extent reaches; then every ray against each of them
        # at once, bodies in rows (a scan's arrays are small: a numpy call costs more than its elements)
        wx, wy = origin[0] - self.xy[:, 0], origin[1] - self.xy[:, 1]
        dx, dy, dz = rays[None, :, 0], rays[None, :, 1], rays[None, :, 2]
        a = dx * dx + dy * dy
        reach = math.sqrt(float(a.max(initial=0.0))) + self._reach
        near = np.flatnonzero(wx * wx + wy * wy <= reach * reach)
        if not len(near):
            return np.full(len(rays), np.inf)
        wx, wy = wx[near, None], wy[near, None]
        z0, z1 = self.z[near, 0:1], self.z[near, 1:2]
        low, high = origin[2] + min(float(dz.min()), 0.0), origin[2] + max(float(dz.max()), 0.0)
        level = low >= z0.max() and high <= z1.min()  # every ray stays within every body's height
        with np.errstate(divide="ignore", invalid="ignore"):
            if (self.radius[near] > 0).all():  # vertical cylinders: where the line is within their radius
                half_b = wx * dx + wy * dy
                c = wx * wx + wy * wy - self.radius[near, None] ** 2  # < 0: the rays start inside
                root = np.sqrt(half_b * half_b - a * c)  # nan: the line misses the circle
                if level and c.min() > 0:  # the usual scan: both crossings ahead of the sensor or both behind
                    enter = (-half_b - root) / a
                    return np.where((enter >= 0.0) & (enter <= 1.0), enter, np.inf).min(axis=0)  # nan: False
                enter, leave = (-half_b - root) / a, (-half_b + root) / a
            else:
                enter, leave = self._through(near, wx, wy, dx, dy, a)
            if not level:  # some ray leaves some body's height: clip to it
                _clip(enter, leave, np.full_like(z0, origin[2]), np.broadcast_to(dz, enter.shape), z0, z1)
            met = (leave >= 0.0) & (enter <= leave) & (enter <= 1.0)  # nan (missed) compares false
        return np.where(met, np.maximum(enter, 0.0), np.inf).min(axis=0)

    def _through(self, near: np.ndarray, wx: np.ndarray, wy: np.ndarray, dx: np.ndarray, dy: np.ndarray,
                 a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Where each ray (columns) enters and leaves each body (rows), unbounded in t and z: a box by the slabs of
        its two horizontal axes, a cylinder by its circle."""
        shape = (len(near), dx.shape[1])
        enter, leave = np.full(shape, -np.inf), np.full(shape, np.inf)
        box = self.radius[near] <= 0
        c, s = self._cos_sin[near][box, 0:1], self._cos_sin[near][box, 1:2]
        bx, by = wx[box], wy[box]
        lo, hi = enter[box], leave[box]
        for u0, du, half in ((c * bx + s * by, c * dx + s * dy, self.half[near][box, 0:1]),
                             (-s * bx + c * by, -s * dx + c * dy, self.half[near][box, 1:2])):
            _clip(lo, hi, u0, du, -half, half)
        enter[box], leave[box] = lo, hi
        round_ = ~box
        if round_.any():
            cx, cy = wx[round_], wy[round_]
            half_b = cx * dx + cy * dy
            root = np.sqrt(half_b * half_b - a * (cx * cx + cy * cy - self.radius[near][round_, None] ** 2))
            enter[round_], leave[round_] = (-half_b - root) / a, (-half_b + root) / a
        return enter, leave


def _clip(enter: np.ndarray, leave: np.ndarray, u0: np.ndarray, du: np.ndarray, low: np.ndarray,
          high: np.ndarray) -> None:
    """Narrow ``[enter, leave]`` (in place) to the t where ``u0 + t du`` lies in ``[low, high]`` (in numpy's
    errstate that ignores division by zero)."""
    t0, t1 = (low - u0) / du, (high - u0) / du
    still = du == 0
    outside = (u0 < low) | (u0 > high)
    np.maximum(enter, np.where(still, np.where(outside, np.inf, -np.inf), np.minimum(t0, t1)), out=enter)
    np.minimum(leave, np.where(still, np.where(outside, -np.inf, np.inf), np.maximum(t0, t1)), out=leave)


class Lidar:
    __slots__ = ("_body", "_client", "_from", "_prisms", "_rays", "_to", "angle_increment", "spec")

    def __init__(self, client: int, body: int, spec: LidarSpec, prisms: Prisms | None = None) -> None:
        """``prisms``: bodies pybullet's ray test does not see, met by their exact shape (module docstring)."""
        self._client = client
        self._body = body
        self._prisms = prisms
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
        self._rays = self._to - self._from

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
        fractions = np.fromiter((r[2] if r[0] >= 0 else math.inf for r in results), dtype=float, count=spec.beams)
        if self._prisms is not None and len(self._prisms.xy):
            # the rays in the world, as pybullet casts them: from the robot's base frame
            position, (qx, qy, qz, qw) = p.getBasePositionAndOrientation(self._body, physicsClientId=self._client)
            rotation = np.array([
                [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]])
            origin = np.asarray(position) + rotation @ self._from[0]
            np.minimum(fractions, self._prisms.hits(origin, self._rays @ rotation.T), out=fractions)
        ranges = fractions * spec.range_max
        np.maximum(ranges, spec.range_min, out=ranges)
        return ranges
