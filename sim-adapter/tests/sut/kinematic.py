# SPDX-License-Identifier: EPL-2.0
"""A kinematic stand-in for the pybullet simulation: a unicycle robot, a ray-cast lidar, moving discs.

Controllers are tested against this fake so that their logic is checked in milliseconds and without the real
simulator; the integration test with pybullet lives elsewhere. Obstacles are the ``StaticMap`` rectangles plus
"hidden" rectangles and moving discs that the controller only sees through the laser.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import Controller, LaserScan, NavGoal, NavStatus, Observation, StaticMap

Rect = tuple[float, float, float, float, float]  # x, y, yaw, size_x, size_y
FOOTPRINT = (0.281, 0.306)
WALL = 0.1


# -- rooms ---------------------------------------------------------------------------------------------------


def room(cells: Iterable[tuple[int, int]], inner_walls: Iterable[tuple[tuple[int, int], tuple[int, int]]] = (),
         furniture: Sequence[Rect] = (), size: float = 1.0) -> StaticMap:
    """Floors of ``size`` at the given cells, walls (``WALL`` thick, centred on the edge) wherever a floor has
    no floor neighbour, plus walls between the named pairs of neighbouring cells, plus furniture."""
    floor = set(cells)
    walls: list[Rect] = []
    for i, j in sorted(floor):
        for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            if (i + di, j + dj) not in floor:
                walls.append(_edge_wall(i, j, di, dj, size))
    for (i, j), (k, m) in inner_walls:
        walls.append(_edge_wall(i, j, k - i, m - j, size))
    xs = [i for i, _ in floor]
    ys = [j for _, j in floor]
    bounds = (min(xs) * size, min(ys) * size, (max(xs) + 1) * size, (max(ys) + 1) * size)
    return StaticMap(bounds=bounds, obstacles=tuple(walls) + tuple(furniture), robot_size=FOOTPRINT)


def _edge_wall(i: int, j: int, di: int, dj: int, size: float) -> Rect:
    cx, cy = (i + 0.5) * size, (j + 0.5) * size
    if di:
        return (cx + di * 0.5 * size, cy, 0.0, WALL, size + WALL)
    return (cx, cy + dj * 0.5 * size, 0.0, size + WALL, WALL)


def rect_room(columns: int, rows: int, furniture: Sequence[Rect] = ()) -> StaticMap:
    return room([(i, j) for i in range(columns) for j in range(rows)], furniture=furniture)


# -- geometry ------------------------------------------------------------------------------------------------


def corners(rect: Rect) -> np.ndarray:
    x, y, yaw, sx, sy = rect
    c, s = math.cos(yaw), math.sin(yaw)
    local = np.array([[0.5, 0.5], [-0.5, 0.5], [-0.5, -0.5], [0.5, -0.5]]) * (sx, sy)
    return np.column_stack((x + c * local[:, 0] - s * local[:, 1], y + s * local[:, 0] + c * local[:, 1]))


def point_rect_distance(points: np.ndarray, rect: Rect) -> np.ndarray:
    x, y, yaw, sx, sy = rect
    c, s = math.cos(yaw), math.sin(yaw)
    dx, dy = points[:, 0] - x, points[:, 1] - y
    lx = np.abs(c * dx + s * dy) - 0.5 * sx
    ly = np.abs(-s * dx + c * dy) - 0.5 * sy
    return np.hypot(np.maximum(lx, 0.0), np.maximum(ly, 0.0))


def rect_distance(a: Rect, b: Rect) -> float:
    """Exact distance between two oriented rectangles (0 when they overlap)."""
    ca, cb = corners(a), corners(b)
    for yaw in (a[2], a[2] + math.pi / 2, b[2], b[2] + math.pi / 2):
        axis = np.array([math.cos(yaw), math.sin(yaw)])
        pa, pb = ca @ axis, cb @ axis
        if pa.max() < pb.min() or pb.max() < pa.min():
            break
    else:
        return 0.0
    return float(min(point_rect_distance(ca, b).min(), point_rect_distance(cb, a).min()))


# -- the fake simulation -------------------------------------------------------------------------------------


@dataclass
class Disc:
    """A moving round obstacle (a human): ``position(t)`` gives its centre."""

    radius: float
    position: Callable[[float], tuple[float, float]]


def shuttle(a: tuple[float, float], b: tuple[float, float], speed: float, t0: float = 0.0) -> Callable:
    """Back and forth between ``a`` and ``b`` at ``speed``, starting at ``a`` at time ``t0``."""
    length = math.hypot(b[0] - a[0], b[1] - a[1])

    def position(t: float) -> tuple[float, float]:
        d = max(t - t0, 0.0) * speed % (2 * length)
        f = (d if d <= length else 2 * length - d) / length
        return a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])

    return position


@dataclass
class KinematicWorld:
    """Unicycle robot, stepped one control period at a time.

    Odometry is perfect unless ``odom_turn_scale`` is not 1: then the odometry sees only that fraction of every
    turn, the heading drift of a real diff-drive whose wheels scrub when it turns (the simulated Waffle's
    odometry sees about 0.978 of a turn on the spot).
    """

    static_map: StaticMap
    pose: Pose2D
    hidden: Sequence[Rect] = ()
    discs: Sequence[Disc] = ()
    control_period: float = 0.1
    physics_dt: float = 0.025
    beams: int = 360
    range_max: float = 3.5
    max_linear: float = 0.26
    max_angular: float = 1.82
    odom_turn_scale: float = 1.0
    t: float = 0.0
    twist: Twist2D = field(default_factory=Twist2D)

    def __post_init__(self) -> None:
        self.odom = self.pose
        self.rects: list[Rect] = list(self.static_map.obstacles) + list(self.hidden)
        self.angles = -math.pi + 2 * math.pi / self.beams * np.arange(self.beams)

    def footprint(self) -> Rect:
        return (self.pose.x, self.pose.y, self.pose.yaw, *self.static_map.robot_size)

    def observation(self) -> Observation:
        scan = LaserScan(self.t, -math.pi, 2 * math.pi / self.beams, 0.12, self.range_max, self.scan())
        return Observation(self.t, self.odom, self.twist, scan)

    def apply(self, cmd: Twist2D) -> None:
        v = min(max(cmd.v, -self.max_linear), self.max_linear)
        w = min(max(cmd.w, -self.max_angular), self.max_angular)
        self.pose = _integrate(self.pose, v, w, self.control_period, self.physics_dt)
        self.odom = _integrate(self.odom, v, w * self.odom_turn_scale, self.control_period, self.physics_dt)
        self.twist = Twist2D(v, w)
        self.t = round(self.t + self.control_period, 9)

    def scan(self) -> np.ndarray:
        ox, oy, yaw = self.pose.x, self.pose.y, self.pose.yaw
        dirs = np.column_stack((np.cos(self.angles + yaw), np.sin(self.angles + yaw)))
        best = np.full(self.beams, np.inf)
        if self.rects:
            r = np.array(self.rects)
            c, s = np.cos(r[:, 2])[:, None], np.sin(r[:, 2])[:, None]
            lox = c * (ox - r[:, :1]) + s * (oy - r[:, 1:2])
            loy = -s * (ox - r[:, :1]) + c * (oy - r[:, 1:2])
            ldx = c * dirs[None, :, 0] + s * dirs[None, :, 1]
            ldy = -s * dirs[None, :, 0] + c * dirs[None, :, 1]
            ldx = np.where(np.abs(ldx) < 1e-12, 1e-12, ldx)
            ldy = np.where(np.abs(ldy) < 1e-12, 1e-12, ldy)
            hx, hy = 0.5 * r[:, 3:4], 0.5 * r[:, 4:5]
            tx1, tx2 = (-hx - lox) / ldx, (hx - lox) / ldx
            ty1, ty2 = (-hy - loy) / ldy, (hy - loy) / ldy
            tmin = np.maximum(np.minimum(tx1, tx2), np.minimum(ty1, ty2))
            tmax = np.minimum(np.maximum(tx1, tx2), np.maximum(ty1, ty2))
            hit = (tmax >= np.maximum(tmin, 0.0))
            t = np.where(hit, np.maximum(tmin, 0.0), np.inf)
            best = np.minimum(best, t.min(axis=0))
        for disc in self.discs:
            cx, cy = disc.position(self.t)
            ocx, ocy = ox - cx, oy - cy
            b = dirs[:, 0] * ocx + dirs[:, 1] * ocy
            disc_ = b * b - (ocx * ocx + ocy * ocy - disc.radius**2)
            t = -b - np.sqrt(np.maximum(disc_, 0.0))
            best = np.where((disc_ >= 0) & (t >= 0), np.minimum(best, t), best)
        best[(best < 0.12) | (best > self.range_max)] = np.inf
        return best

    def static_clearance(self) -> float:
        """Distance from the robot's footprint to the nearest rectangle (map or hidden)."""
        robot = self.footprint()
        return min(rect_distance(robot, r) for r in self.rects)

    def disc_clearance(self) -> float:
        robot = self.footprint()
        best = math.inf
        for disc in self.discs:
            cx, cy = disc.position(self.t)
            d = float(point_rect_distance(np.array([[cx, cy]]), robot)[0]) - disc.radius
            best = min(best, d)
        return best


def _integrate(pose: Pose2D, v: float, w: float, period: float, physics_dt: float) -> Pose2D:
    x, y, yaw = pose.x, pose.y, pose.yaw
    steps = max(1, round(period / physics_dt))
    dt = period / steps
    for _ in range(steps):
        if abs(w) < 1e-9:
            x, y = x + v * dt * math.cos(yaw), y + v * dt * math.sin(yaw)
        else:
            x += v / w * (math.sin(yaw + w * dt) - math.sin(yaw))
            y -= v / w * (math.cos(yaw + w * dt) - math.cos(yaw))
            yaw += w * dt
    return Pose2D(x, y, math.atan2(math.sin(yaw), math.cos(yaw)))


@dataclass
class Run:
    status: NavStatus
    t: float
    poses: list[Pose2D]
    min_static_clearance: float
    min_disc_clearance: float
    text: str


def drive(controller: Controller, world: KinematicWorld, goal: Pose2D | None, max_time: float = 120.0,
          tolerance: float = 0.25) -> Run:
    """Reset the controller, give it the goal and step until it leaves ACTIVE (or ``max_time``)."""
    controller.reset(world.static_map, world.pose)
    if goal is not None:
        controller.set_goal(NavGoal(0, goal, tolerance))
    poses = [world.pose]
    min_static, min_disc = world.static_clearance(), world.disc_clearance()
    while world.t < max_time:
        cmd = controller.step(world.observation())
        if controller.status is not NavStatus.ACTIVE:
            break
        world.apply(cmd)
        poses.append(world.pose)
        min_static = min(min_static, world.static_clearance())
        min_disc = min(min_disc, world.disc_clearance())
    return Run(controller.status, world.t, poses, min_static, min_disc, controller.status_text)
