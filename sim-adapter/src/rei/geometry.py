"""Planar poses and twists shared by the simulator, the controllers and the collector; footprint gaps."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class Pose2D:
    """A planar pose in the world frame: metres and radians."""

    x: float
    y: float
    yaw: float = 0.0

    def distance_to(self, other: Pose2D) -> float:
        return math.hypot(other.x - self.x, other.y - self.y)


@dataclass(frozen=True, slots=True)
class Twist2D:
    """A planar velocity command or measurement in the robot's frame: forward m/s, turn rad/s and sideways m/s
    (``vy``, towards the robot's left: only a holonomic drive makes it, a differential one limits it to 0)."""

    v: float = 0.0
    w: float = 0.0
    vy: float = 0.0


def wrap_angle(angle: float) -> float:
    """Angle wrapped to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def yaw_of_quaternion(x: float, y: float, z: float, w: float) -> float:
    """The rotation about z of the orientation ``(x, y, z, w)``: a body's planar yaw (pybullet, ROS)."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def quaternion_of_yaw(yaw: float) -> tuple[float, float, float, float]:
    """``(x, y, z, w)`` of a rotation by ``yaw`` about z."""
    return (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2))


# -- footprints ------------------------------------------------------------------------------------------------
# The monitor's footprint geometry (runtime-monitor: JTS polygons, circles as their centre less the radius;
# thesis 6.1.3.1), for NumPy arrays of poses, so that the per-run metrics (rei.evaluation.metrics) measure the
# same gaps the monitor judges. Where the monitor stops at 0 (touching or overlapping), these go below 0 by the
# penetration depth: a search that minimises clearance still has a slope inside a collision.


def footprint_gaps(robot: np.ndarray, robot_size: tuple[float, float] | np.ndarray, obstacles: np.ndarray,
                   circle: np.ndarray) -> np.ndarray:
    """Signed gaps ``(T, N)`` between the robot's rectangle footprint at ``T`` poses and ``N`` obstacles.

    ``robot``: ``(T, 3)`` of ``x, y, yaw``; ``robot_size``: the footprint's full ``size_x, size_y``, or for a
    robot read from its description its outline, an ``(M, 2)`` array (:func:`outline_gaps`).
    ``obstacles``: ``(N, 5)`` of ``x, y, yaw, size_x, size_y`` (a circle's diameter in ``size_x``), or
    ``(T, N, 5)`` for obstacles that move (their place at each robot pose; NaN gives a NaN gap), ``circle``:
    ``(N,)`` booleans. A gap is the footprints' distance when they are apart, and minus the depth
    to which they overlap otherwise (the least push along a rectangle's axis, or of a circle's centre out of the
    robot's rectangle plus its radius).
    """
    robot = np.asarray(robot, dtype=float).reshape(-1, 3)
    obstacles = np.asarray(obstacles, dtype=float)
    obstacles = obstacles.reshape(1, 5) if obstacles.ndim == 1 else obstacles
    circle = np.asarray(circle, dtype=bool).reshape(-1)
    if isinstance(robot_size, np.ndarray) and robot_size.ndim == 2:
        return outline_gaps(robot, robot_size, obstacles, circle)
    hx, hy = robot_size[0] / 2, robot_size[1] / 2
    rx, ry, ryaw = (robot[:, k, None] for k in range(3))  # (T, 1)
    ox, oy, oyaw = obstacles[..., 0], obstacles[..., 1], obstacles[..., 2]  # (N,) or (T, N)
    ohx, ohy = obstacles[..., 3] / 2, obstacles[..., 4] / 2
    rc, rs = np.cos(ryaw), np.sin(ryaw)
    # circles: the centre's signed distance to the robot's rectangle, less the radius
    u = rc * (ox - rx) + rs * (oy - ry)
    v = -rs * (ox - rx) + rc * (oy - ry)
    circles = _point_in_box(u, v, hx, hy) - ohx
    # rectangles: separating axes; apart -> least corner-to-rectangle distance both ways, else minus the overlap
    oc, os_ = np.cos(oyaw), np.sin(oyaw)
    overlap = np.full(np.broadcast_shapes(rx.shape, ox.shape), np.inf)
    for ax, ay in ((rc, rs), (-rs, rc), (oc, os_), (-os_, oc)):
        centre = np.abs((ox - rx) * ax + (oy - ry) * ay)
        reach_robot = hx * np.abs(ax * rc + ay * rs) + hy * np.abs(-ax * rs + ay * rc)
        reach_obstacle = ohx * np.abs(ax * oc + ay * os_) + ohy * np.abs(-ax * os_ + ay * oc)
        overlap = np.minimum(overlap, reach_robot + reach_obstacle - centre)
    apart = np.full(overlap.shape, np.inf)
    for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
        # a corner of the robot, in each obstacle's frame
        px, py = rx + rc * sx * hx - rs * sy * hy - ox, ry + rs * sx * hx + rc * sy * hy - oy
        apart = np.minimum(apart, _point_in_box(oc * px + os_ * py, -os_ * px + oc * py, ohx, ohy))
        # a corner of each obstacle, in the robot's frame
        qx = ox + oc * sx * ohx - os_ * sy * ohy - rx
        qy = oy + os_ * sx * ohx + oc * sy * ohy - ry
        apart = np.minimum(apart, _point_in_box(rc * qx + rs * qy, -rs * qx + rc * qy, hx, hy))
    rectangles = np.where(overlap < 0, apart, -overlap)
    return np.where(circle, circles, rectangles)


def _point_in_box(u: np.ndarray, v: np.ndarray, hx: float | np.ndarray, hy: float | np.ndarray) -> np.ndarray:
    """Signed distance of points ``(u, v)`` (box frame) to a box of half extents ``hx, hy``: < 0 inside."""
    du, dv = np.abs(u) - hx, np.abs(v) - hy
    outside = np.hypot(np.maximum(du, 0.0), np.maximum(dv, 0.0))
    return np.where((du > 0) | (dv > 0), outside, np.maximum(du, dv))


def outline_gaps(robot: np.ndarray, outline: np.ndarray, obstacles: np.ndarray, circle: np.ndarray) -> np.ndarray:
    """:func:`footprint_gaps` for a robot whose footprint is a convex polygon ``outline`` ``(M, 2)`` in its own
    frame, counter-clockwise (world.json's footprint of a robot read from its description; a round robot's circle
    as a polygon around it), placed and turned about the robot's origin as the monitor places it."""
    outline = np.asarray(outline, dtype=float)
    rx, ry, ryaw = (robot[:, k, None, None] for k in range(3))  # (T, 1, 1)
    rc, rs = np.cos(ryaw), np.sin(ryaw)
    vx = rx + rc * outline[:, 0] - rs * outline[:, 1]  # (T, 1, M): the outline in the world
    vy = ry + rs * outline[:, 0] + rc * outline[:, 1]
    ex, ey = np.roll(vx, -1, axis=-1) - vx, np.roll(vy, -1, axis=-1) - vy  # edges i -> i + 1
    length = np.hypot(ex, ey)
    nx, ny = ey / length, -ex / length  # outward normals of a counter-clockwise polygon
    ox, oy, oyaw = (obstacles[..., k, None] for k in range(3))  # (N, 1) or (T, N, 1)
    ohx, ohy = obstacles[..., 3, None] / 2, obstacles[..., 4, None] / 2

    def to_outline(px: np.ndarray, py: np.ndarray) -> np.ndarray:
        """Signed distance of points ``(..., K)`` to the outline ``(..., K)`` -> ``(...)``: < 0 inside."""
        px, py = px[..., None], py[..., None]  # (..., K, 1) against the edges (..., 1, M)
        a_x, a_y, e_x, e_y = vx[..., None, :], vy[..., None, :], ex[..., None, :], ey[..., None, :]
        side = ((px - a_x) * nx[..., None, :] + (py - a_y) * ny[..., None, :]).max(axis=-1)
        t = np.clip(((px - a_x) * e_x + (py - a_y) * e_y) / (e_x * e_x + e_y * e_y), 0.0, 1.0)
        edge = np.hypot(px - a_x - t * e_x, py - a_y - t * e_y).min(axis=-1)
        return np.where(side > 0, edge, side)

    circles = to_outline(ox, oy)[..., 0] - ohx[..., 0]
    oc, os_ = np.cos(oyaw), np.sin(oyaw)
    # separating axes: the outline's edge normals and the obstacle's two axes; apart on one -> the least
    # vertex-to-shape distance either way, else minus the least overlap
    overlap = np.full(np.broadcast_shapes(rx.shape, ox.shape)[:-1], np.inf)
    axes = [(nx[..., m], ny[..., m]) for m in range(outline.shape[0])] + [(oc[..., 0], os_[..., 0]),
                                                                          (-os_[..., 0], oc[..., 0])]
    for ax, ay in axes:
        ax, ay = ax[..., None], ay[..., None]
        robot_side = vx * ax + vy * ay
        centre = ox * ax + oy * ay
        reach = ohx * np.abs(ax * oc + ay * os_) + ohy * np.abs(-ax * os_ + ay * oc)
        # the least push that separates them along this axis (negative: apart along it)
        push = np.minimum(robot_side.max(axis=-1, keepdims=True) - (centre - reach),
                          centre + reach - robot_side.min(axis=-1, keepdims=True))
        overlap = np.minimum(overlap, push[..., 0])
    px, py = vx - ox, vy - oy  # the outline's vertices in each obstacle's frame
    apart = _point_in_box(oc * px + os_ * py, -os_ * px + oc * py, ohx, ohy).min(axis=-1)
    corners = [(ox + oc * sx * ohx - os_ * sy * ohy, oy + os_ * sx * ohx + oc * sy * ohy)
               for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
    cx = np.concatenate(np.broadcast_arrays(*[c[0] for c in corners]), axis=-1)
    cy = np.concatenate(np.broadcast_arrays(*[c[1] for c in corners]), axis=-1)
    apart = np.minimum(apart, to_outline(cx, cy).min(axis=-1))
    rectangles = np.where(overlap < 0, apart, -overlap)
    return np.where(circle, circles, rectangles)


def triangulate(points: np.ndarray | list[tuple[float, float]] | tuple[tuple[float, float], ...]
                ) -> list[tuple[int, int, int]]:
    """Ear clipping of a simple polygon (convex or not) of ``n`` counter-clockwise vertices: ``n - 2`` triangles
    of vertex indices, each counter-clockwise (a POLYGON object's prism in the simulator, its pieces in the
    metrics). A vertex is an ear when its corner turns left and no other vertex lies in its triangle."""
    pts = [(float(x), float(y)) for x, y in points]
    if len(pts) < 3:
        raise ValueError(f"a polygon has at least 3 vertices, got {len(pts)}")
    if sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(len(pts))) < 0:
        raise ValueError("the polygon's vertices must go counter-clockwise")

    def cross(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    left = list(range(len(pts)))
    out: list[tuple[int, int, int]] = []
    while len(left) > 3:
        n = len(left)
        for k in range(n):
            i, j, m = left[k - 1], left[k], left[(k + 1) % n]
            a, b, c = pts[i], pts[j], pts[m]
            if cross(a, b, c) <= 1e-15:
                continue  # a reflex (or straight) corner is no ear
            if any(q not in (i, j, m) and cross(a, b, pts[q]) >= 0 and cross(b, c, pts[q]) >= 0
                   and cross(c, a, pts[q]) >= 0 for q in left):
                continue
            out.append((i, j, m))
            del left[k]
            break
        else:  # only straight corners are left (collinear vertices): cut the flat remainder as it comes
            out.append((left[-1], left[0], left[1]))
            del left[0]
    out.append((left[0], left[1], left[2]))
    return out


def polygon_gaps(robot: np.ndarray, robot_shape: tuple[float, float] | np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Signed gaps ``(T,)`` between the robot's footprint at ``T`` poses (``robot_shape`` as
    :func:`footprint_gaps` takes it: a rectangle's size or a convex outline) and a fixed polygon, convex or not,
    ``(K, 2)`` counter-clockwise in the world (a POLYGON object's outline placed). Apart: their distance, exactly
    (the least over the polygon's triangles, which cover it); overlapping: minus the deepest overlap with one of
    its triangles (the least push along a separating axis), as :func:`footprint_gaps` goes below 0."""
    robot = np.asarray(robot, dtype=float).reshape(-1, 3)
    polygon = np.asarray(polygon, dtype=float).reshape(-1, 2)
    if isinstance(robot_shape, np.ndarray) and robot_shape.ndim == 2:
        outline = np.asarray(robot_shape, dtype=float)
    else:
        hx, hy = robot_shape[0] / 2, robot_shape[1] / 2
        outline = np.array([(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)])
    rx, ry, ryaw = (robot[:, k, None] for k in range(3))  # (T, 1)
    rc, rs = np.cos(ryaw), np.sin(ryaw)
    vx = rx + rc * outline[:, 0] - rs * outline[:, 1]  # (T, M)
    vy = ry + rs * outline[:, 0] + rc * outline[:, 1]
    best = np.full(len(robot), np.inf)
    for triangle in triangulate(polygon):
        piece = polygon[list(triangle)]
        best = np.minimum(best, _convex_gap(vx, vy, piece))
    return best


def _convex_gap(vx: np.ndarray, vy: np.ndarray, piece: np.ndarray) -> np.ndarray:
    """Signed gap ``(T,)`` between convex polygons: ``(T, M)`` vertices ``vx, vy`` (counter-clockwise) and one fixed
    ``(K, 2)`` counter-clockwise."""
    px, py = piece[:, 0], piece[:, 1]
    axes = []
    for x, y in ((vx, vy), (px[None, :], py[None, :])):
        ex, ey = np.roll(x, -1, axis=-1) - x, np.roll(y, -1, axis=-1) - y
        length = np.hypot(ex, ey)
        axes += [(ey[..., m] / length[..., m], -ex[..., m] / length[..., m]) for m in range(x.shape[-1])]
    overlap = np.full(vx.shape[0], np.inf)
    for ax, ay in axes:
        ax, ay = np.broadcast_to(np.asarray(ax), (vx.shape[0],))[:, None], np.broadcast_to(np.asarray(ay),
                                                                                            (vx.shape[0],))[:, None]
        mine = vx * ax + vy * ay  # (T, M)
        theirs = px[None, :] * ax + py[None, :] * ay  # (T, K)
        push = np.minimum(mine.max(axis=1) - theirs.min(axis=1), theirs.max(axis=1) - mine.min(axis=1))
        overlap = np.minimum(overlap, push)

    def to_edges(qx: np.ndarray, qy: np.ndarray, ax_: np.ndarray, ay_: np.ndarray) -> np.ndarray:
        """Least distance from points ``(T, A)`` to the closed chain of ``(T, B)`` vertices -> ``(T,)``."""
        bx, by = np.roll(ax_, -1, axis=-1) - ax_, np.roll(ay_, -1, axis=-1) - ay_
        dx, dy = qx[:, :, None] - ax_[:, None, :], qy[:, :, None] - ay_[:, None, :]
        t = np.clip((dx * bx[:, None, :] + dy * by[:, None, :]) / (bx * bx + by * by)[:, None, :], 0.0, 1.0)
        return np.hypot(dx - t * bx[:, None, :], dy - t * by[:, None, :]).min(axis=(1, 2))

    fx, fy = np.broadcast_to(px, (vx.shape[0], len(px))), np.broadcast_to(py, (vx.shape[0], len(py)))
    apart = np.minimum(to_edges(vx, vy, fx, fy), to_edges(fx, fy, vx, vy))
    return np.where(overlap < 0, apart, -overlap)


def polygon_distance(px: np.ndarray, py: np.ndarray, polygon: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For points ``(px, py)`` (any shape) and a polygon ``(K, 2)``, convex or not: each point's distance to the
    polygon's outline, and whether it lies inside (even-odd crossings of a ray towards +x)."""
    px, py = np.asarray(px, dtype=float), np.asarray(py, dtype=float)
    edge = np.full(px.shape, np.inf)
    inside = np.zeros(px.shape, dtype=bool)
    for (ax, ay), (bx, by) in zip(polygon, np.roll(polygon, -1, axis=0), strict=True):
        ex, ey = bx - ax, by - ay
        t = np.clip(((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey), 0.0, 1.0)
        edge = np.minimum(edge, np.hypot(px - ax - t * ex, py - ay - t * ey))
        crosses = (ay > py) != (by > py)
        with np.errstate(divide="ignore", invalid="ignore"):
            inside ^= crosses & (px < ax + (py - ay) * ex / np.where(crosses, ey, 1.0))
    return edge, inside
