# SPDX-License-Identifier: EPL-2.0
"""The laser's clearance: how far the nearest thing the lidar sees is from the robot's footprint.

The monitor compares the laser with the same thresholds as the geometry's footprint-to-footprint gaps, so the
scan must be turned into a gap too. The thesis's min filter (shortest range) minus one radius can not do that
for a rectangle: a range is measured from the sensor, and the footprint's edge is nearer along a side's normal
than towards a corner. Each beam's hit point is therefore measured to the footprint rectangle itself (robot
frame, sensor at the footprint's centre), and the clearance is the smallest of those distances. It is the
geometric gap up to the spacing of the beams (1 degree at 0.3 m is 5 mm), at the corners as on the sides.
"""

from __future__ import annotations

import math

import numpy as np


class FootprintClearance:
    """Per-beam distances to a ``size_x`` x ``size_y`` footprint centred on the sensor, for one beam layout.

    The beams' directions are kept, so a scan costs a few vector operations.
    """

    __slots__ = ("_angle_increment", "_angle_min", "_beams", "_cos", "_half_x", "_half_y", "_sin")

    def __init__(self, size_x: float, size_y: float) -> None:
        if not (size_x > 0 and size_y > 0):
            raise ValueError(f"footprint must have a positive size, got {size_x} x {size_y} m")
        self._half_x, self._half_y = size_x / 2, size_y / 2
        self._angle_min = self._angle_increment = math.nan
        self._beams = -1
        self._cos = self._sin = np.empty(0)

    def __call__(self, ranges: np.ndarray, angle_min: float, angle_increment: float) -> float:
        """The clearance of one scan in metres: 0 when a hit lies on or inside the footprint, ``inf`` when no
        beam hit (``inf`` or NaN ranges are no hit)."""
        n = len(ranges)
        if (n, angle_min, angle_increment) != (self._beams, self._angle_min, self._angle_increment):
            angles = angle_min + np.arange(n) * angle_increment
            self._cos, self._sin = np.cos(angles), np.sin(angles)
            self._beams, self._angle_min, self._angle_increment = n, angle_min, angle_increment
        hit = np.isfinite(ranges)
        if not hit.any():
            return math.inf
        r = ranges[hit]
        dx = np.maximum(np.abs(r * self._cos[hit]) - self._half_x, 0.0)
        dy = np.maximum(np.abs(r * self._sin[hit]) - self._half_y, 0.0)
        return float(np.sqrt(dx * dx + dy * dy).min())
