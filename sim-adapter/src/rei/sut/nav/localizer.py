# SPDX-License-Identifier: EPL-2.0
"""Localization: wheel odometry corrected by matching each scan against the static map (AMCL's role).

Wheel odometry drifts: a diff-drive robot turning on the spot scrubs its wheels, so its heading error grows with
every turn (about 2 % of the turned angle for the simulated Waffle), and after a few turns the position is off by
decimetres. A controller navigating on raw odometry then stops beside its goal, sees the walls where its map has
none and takes them for obstacles.

The localizer keeps the correction ``map <- odom`` as a rigid transform. On every new scan it refines the pose
with a few Gauss-Newton steps that pull the laser points onto the map's outlines (the grid's signed ``surface``
field), with robust weights so that people and unmapped objects barely count, and with an odometry prior so that
directions the scan does not constrain (along a bare corridor) keep the odometry's estimate.
"""

from __future__ import annotations

import math

import numpy as np

from rei.geometry import Pose2D, wrap_angle
from rei.sut.nav.grid import CostGrid

_ITERATIONS = 3
_SOFT = 0.05  # metres: Cauchy scale of the residuals
# Odometry prior, as stiff as this many points of unit gradient: it only decides what the scan leaves open.
_PRIOR = np.diag((20.0, 20.0, 20.0))
_MAX_STEP_XY = 0.05  # per scan: a correction is small, a jump means a wrong match
_MAX_STEP_YAW = 0.05
_MIN_POINTS = 20


class Localizer:
    """Pose in the map frame from odometry and scans; the correction persists across goals."""

    def __init__(self, grid: CostGrid, gate: float) -> None:
        self.grid = grid
        self.gate = gate
        self._correction = (0.0, 0.0, 0.0)  # map <- odom: translation and rotation
        self.matched = 0

    def reset(self) -> None:
        """Odometry and map frames coincide (the controller was reset at the odometry's origin pose)."""
        self._correction = (0.0, 0.0, 0.0)
        self.matched = 0

    def pose(self, odom: Pose2D) -> Pose2D:
        """The odometry pose in the map frame."""
        tx, ty, ta = self._correction
        c, s = math.cos(ta), math.sin(ta)
        return Pose2D(tx + c * odom.x - s * odom.y, ty + s * odom.x + c * odom.y, wrap_angle(odom.yaw + ta))

    def update(self, odom: Pose2D, local: np.ndarray) -> Pose2D:
        """Refine the pose with a scan's points ``(N, 2)`` in the robot frame; returns the map-frame pose."""
        guess = self.pose(odom)
        x, y, yaw = guess.x, guess.y, guess.yaw
        lx, ly = local[:, 0], local[:, 1]
        self.matched = 0
        for iteration in range(_ITERATIONS):
            c, s = math.cos(yaw), math.sin(yaw)
            ox, oy = c * lx - s * ly, s * lx + c * ly  # map-frame offsets of the points from the robot
            r, gx, gy = self.grid.surface_at(x + ox, y + oy)
            use = np.abs(r) < self.gate  # nan (off the grid) compares false
            if int(np.count_nonzero(use)) < _MIN_POINTS:
                break
            r, gx, gy, ox, oy = r[use], gx[use], gy[use], ox[use], oy[use]
            if iteration == 0:  # later iterations move by millimetres: the matched points stay the same
                lx, ly = lx[use], ly[use]
            jt = gy * ox - gx * oy  # d r / d yaw
            w = 1.0 / (1.0 + (r * (1.0 / _SOFT)) ** 2)
            j = np.stack((gx, gy, jt))
            jw = j * w
            h = jw @ j.T + _PRIOR
            # The prior pulls towards the odometry-propagated guess, not towards the last iterate.
            offset = np.array((x - guess.x, y - guess.y, wrap_angle(yaw - guess.yaw)))
            step = -np.linalg.solve(h, jw @ r + _PRIOR @ offset)
            dx = min(max(float(step[0]), -_MAX_STEP_XY), _MAX_STEP_XY)
            dy = min(max(float(step[1]), -_MAX_STEP_XY), _MAX_STEP_XY)
            da = min(max(float(step[2]), -_MAX_STEP_YAW), _MAX_STEP_YAW)
            x, y, yaw = x + dx, y + dy, yaw + da
            self.matched = len(r)
            if abs(dx) + abs(dy) < 2e-4 and abs(da) < 2e-4:
                break
        # New correction: the map pose composed with the inverse of the odometry pose.
        ta = wrap_angle(yaw - odom.yaw)
        c, s = math.cos(ta), math.sin(ta)
        self._correction = (x - (c * odom.x - s * odom.y), y - (s * odom.x + c * odom.y), ta)
        return Pose2D(x, y, wrap_angle(yaw))
