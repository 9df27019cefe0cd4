# SPDX-License-Identifier: EPL-2.0
"""Catmull-Rom (cubic Hermite) trajectories through timed control points, exactly as thesis 4.2.1 defines them.

Kept out of rei.sim (no pybullet) so the mathematics can be tested against hand-computed values, and so the
view and the metrics evaluate a schedule as the simulator walks it.

Per segment ``i`` (``h = t[i+1] - t[i]``, ``s = t - t[i]``) and per axis, Table 1 of the thesis::

    a = (v[i+1] + v[i]) / h**2 - 2 (p[i+1] - p[i]) / h**3      c = v[i]
    b = 3 (p[i+1] - p[i]) / h**2 - (v[i+1] + 2 v[i]) / h       d = p[i]
    r(t) = a s**3 + b s**2 + c s + d

and the knot velocities ``v[i] = 1/2 ((p[i] - p[i-1]) / (t[i] - t[i-1]) + (p[i+1] - p[i]) / (t[i+1] - t[i]))``.

End points:

* ``loop=True``: the trajectory is closed by a segment from the last point back to the first. That closing
  segment lasts as long as the first one (``t[1] - t[0]``), so the period is ``t[n] - t[0] + t[1] - t[0]``, and the
  knot velocities wrap around (the first point's predecessor is the last point, reached ``t[1] - t[0]`` earlier).
  When the last point already equals the first (the author closed the loop), no segment is added and the period
  is ``t[n] - t[0]``. Before ``t[0]`` and after a period the motion repeats.
* ``loop=False``: end velocities are one-sided differences; before ``t[0]`` the object waits at the first point
  and after ``t[n]`` it stays at the last one.
"""

from __future__ import annotations

import bisect
import itertools
import math
from collections.abc import Sequence

_CLOSED_EPS = 1e-9


class Trajectory:
    """A planar Catmull-Rom trajectory; ``position(t)`` and ``velocity(t)`` for any time."""

    __slots__ = ("_coeffs", "_knots", "_last", "end", "loop", "period", "start")

    def __init__(self, times: Sequence[float], points: Sequence[tuple[float, float]], loop: bool) -> None:
        if len(times) != len(points) or not times:
            raise ValueError("a trajectory needs as many times as points, and at least one")
        if any(b <= a for a, b in itertools.pairwise(times)):
            raise ValueError(f"control-point times must be strictly increasing, got {list(times)}")
        knots = [float(t) for t in times]
        pts = [(float(x), float(y)) for x, y in points]
        self.loop = loop and len(pts) > 1
        if self.loop:
            closed = math.dist(pts[0], pts[-1]) < _CLOSED_EPS
            if closed and len(pts) == 2:
                pts, knots = pts[:1], knots[:1]
                self.loop = False
            elif not closed:
                knots.append(knots[-1] + knots[1] - knots[0])
                pts.append(pts[0])
        self.start = knots[0]
        self.end = knots[-1]
        self.period = self.end - self.start
        self._knots = knots
        velocities = _knot_velocities(knots, pts, self.loop)
        self._coeffs = [
            _segment(knots[i + 1] - knots[i], pts[i], pts[i + 1], velocities[i], velocities[i + 1])
            for i in range(len(pts) - 1)
        ]
        if not self._coeffs:  # a single point: stand still
            self._coeffs = [((0.0, 0.0, 0.0, pts[0][0]), (0.0, 0.0, 0.0, pts[0][1]))]
        self._last = 0

    def _locate(self, t: float) -> tuple[int, float]:
        """Segment index and the time into it, after mapping ``t`` into the trajectory's time span."""
        if self.loop:
            t = self.start + (t - self.start) % self.period
        elif t <= self.start or len(self._knots) == 1:
            return 0, 0.0
        elif t >= self.end:
            i = len(self._coeffs) - 1
            return i, self._knots[i + 1] - self._knots[i]
        i = self._last  # animation queries advance monotonically: try the previous segment first
        knots = self._knots
        if not (knots[i] <= t < knots[i + 1]):
            i = min(max(bisect.bisect_right(knots, t) - 1, 0), len(self._coeffs) - 1)
            self._last = i
        return i, t - knots[i]

    def position(self, t: float) -> tuple[float, float]:
        i, s = self._locate(t)
        (ax, bx, cx, dx), (ay, by, cy, dy) = self._coeffs[i]
        return ((ax * s + bx) * s + cx) * s + dx, ((ay * s + by) * s + cy) * s + dy

    def velocity(self, t: float) -> tuple[float, float]:
        """The spline's derivative; zero where a once trajectory waits or has finished."""
        if not self.loop and (t < self.start or t > self.end or len(self._knots) == 1):
            return 0.0, 0.0
        i, s = self._locate(t)
        (ax, bx, cx, _), (ay, by, cy, _) = self._coeffs[i]
        return (3.0 * ax * s + 2.0 * bx) * s + cx, (3.0 * ay * s + 2.0 * by) * s + cy


Point = tuple[float, float]
Coeffs = tuple[float, float, float, float]


def _knot_velocities(knots: list[float], pts: list[Point], loop: bool) -> list[Point]:
    n = len(pts)
    if n == 1:
        return [(0.0, 0.0)]

    def slope(i: int, j: int, dt: float) -> Point:
        return ((pts[j][0] - pts[i][0]) / dt, (pts[j][1] - pts[i][1]) / dt)

    slopes = [slope(i, i + 1, knots[i + 1] - knots[i]) for i in range(n - 1)]
    velocities = [(0.0, 0.0)] * n
    for i in range(1, n - 1):
        velocities[i] = _mean(slopes[i - 1], slopes[i])
    if loop:  # pts[-1] is pts[0] again: both ends share the velocity across the seam
        seam = _mean(slopes[-1], slopes[0])
        velocities[0] = velocities[-1] = seam
    else:
        velocities[0] = slopes[0]
        velocities[-1] = slopes[-1]
    return velocities


def _mean(a: Point, b: Point) -> Point:
    return (0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]))


def _segment(h: float, p0: Point, p1: Point, v0: Point, v1: Point) -> tuple[Coeffs, Coeffs]:
    return _axis(h, p0[0], p1[0], v0[0], v1[0]), _axis(h, p0[1], p1[1], v0[1], v1[1])


def _axis(h: float, p0: float, p1: float, v0: float, v1: float) -> Coeffs:
    """Table 1 of the thesis for one axis of one segment."""
    a = (v1 + v0) / h**2 - 2.0 * (p1 - p0) / h**3
    b = 3.0 * (p1 - p0) / h**2 - (v1 + 2.0 * v0) / h
    return a, b, v0, p0
