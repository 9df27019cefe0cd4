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

from rei.artifacts.world import CircleFootprint, RobotSpec, footprint_polygon


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
        hits = self._hits(ranges, angle_min, angle_increment)
        if hits is None:
            return math.inf
        r, cos, sin = hits
        dx = np.maximum(np.abs(r * cos) - self._half_x, 0.0)
        dy = np.maximum(np.abs(r * sin) - self._half_y, 0.0)
        return float(np.sqrt(dx * dx + dy * dy).min())

    def _hits(self, ranges: np.ndarray, angle_min: float,
              angle_increment: float) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """The finite ranges and their beams' cosines and sines (cached per scan geometry), None when none hit."""
        n = len(ranges)
        if (n, angle_min, angle_increment) != (self._beams, self._angle_min, self._angle_increment):
            angles = angle_min + np.arange(n) * angle_increment
            self._cos, self._sin = np.cos(angles), np.sin(angles)
            self._beams, self._angle_min, self._angle_increment = n, angle_min, angle_increment
        hit = np.isfinite(ranges)
        if not hit.any():
            return None
        return ranges[hit], self._cos[hit], self._sin[hit]


class OutlineClearance(FootprintClearance):
    """Per-beam distances to a robot's outline (world.json's footprint of a robot read from its description): the
    hit points are measured to the convex polygon itself, given in the lidar's frame (the lidar need not be at its
    centre), or to a circle (``radius`` > 0, ``points`` its centre alone)."""

    __slots__ = ("_edges", "_normals", "_points", "_radius", "_reach", "_within")

    def __init__(self, points: np.ndarray, radius: float = 0.0) -> None:
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        self._radius = float(radius)
        if radius > 0:
            (cx, cy), = points
            super().__init__(2 * radius, 2 * radius)
            self._reach = math.hypot(cx, cy) + radius
            self._within = max(math.hypot(cx, cy) - radius, 0.0)
            self._points = points
            return
        xmin, ymin = points.min(axis=0)
        xmax, ymax = points.max(axis=0)
        super().__init__(xmax - xmin, ymax - ymin)
        self._points = points
        self._edges = np.roll(points, -1, axis=0) - points
        length = np.hypot(self._edges[:, 0], self._edges[:, 1])
        self._normals = np.column_stack([self._edges[:, 1], -self._edges[:, 0]]) / length[:, None]  # outward, CCW
        # the outline's farthest point from the lidar, and the lidar's distance from the outline (0: inside it)
        self._reach = float(np.hypot(points[:, 0], points[:, 1]).max())
        self._within = float(self._distances(np.zeros((1, 1)), np.zeros((1, 1)))[0])

    def _distances(self, px: np.ndarray, py: np.ndarray) -> np.ndarray:
        """Each point's distance to the polygon, 0 inside it (points in rows, (K, 1), against the edges)."""
        ax, ay = self._points[:, 0], self._points[:, 1]
        inside = ((px - ax) * self._normals[:, 0] + (py - ay) * self._normals[:, 1]).max(axis=1) <= 0
        ex, ey = self._edges[:, 0], self._edges[:, 1]
        t = np.clip(((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
        edge = np.hypot(px - ax - t * ex, py - ay - t * ey).min(axis=1)
        return np.where(inside, 0.0, edge)

    def __call__(self, ranges: np.ndarray, angle_min: float, angle_increment: float) -> float:
        hits = self._hits(ranges, angle_min, angle_increment)
        if hits is None:
            return math.inf
        r, cos, sin = hits
        # only the beams that can hold the least distance: a hit at range r is at least r - reach from the outline
        # and at most r + within, so one whose r - reach exceeds the shortest hit's r + within cannot (every hit
        # measured cost a scan of a 64-gon's outline 2 ms, where a few beams are near)
        near = r - self._reach <= r.min() + self._within
        r = r[near]
        px, py = r * cos[near], r * sin[near]
        if self._radius > 0:
            (cx, cy), = self._points
            return float(np.maximum(np.hypot(px - cx, py - cy) - self._radius, 0.0).min())
        return float(self._distances(px[:, None], py[:, None]).min())


def clearance_for(spec: RobotSpec) -> FootprintClearance:
    """The laser's clearance for the robot: a box robot's rectangle centred on its sensor, as always; a described
    robot's outline seen from its lidar's place and yaw."""
    if spec.footprint is None:
        return FootprintClearance(spec.size[0], spec.size[1])
    c, s = math.cos(spec.lidar.yaw), math.sin(spec.lidar.yaw)
    turn = np.array([[c, -s], [s, c]])  # into the lidar's frame: turned by -yaw
    if isinstance(spec.footprint, CircleFootprint):  # the circle itself, as the monitor and the body have it
        centre = np.array([[spec.footprint.x - spec.lidar.x, spec.footprint.y - spec.lidar.y]])
        return OutlineClearance(centre @ turn, spec.footprint.radius)
    points = np.array(footprint_polygon(spec.footprint)) - [spec.lidar.x, spec.lidar.y]
    return OutlineClearance(points @ turn)
