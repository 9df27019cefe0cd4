# SPDX-License-Identifier: EPL-2.0
"""The reference navigation controller (``nav``): a small ``move_base`` in numpy.

It plays the role of the thesis's navigation stack (2.1.1: path planning plus path execution): A* on the static
map when a goal arrives, a DWA local planner that avoids what the laser sees (humans included), replanning with
the sensed obstacles when blocked, a back-up recovery, and cancellation when the robot only oscillates (7.4.4).
Everything works in the map frame: the wheel odometry is corrected by matching each scan to the static map
(``localizer``), since odometry alone drifts decimetres in a room-sized mission.
It is meant as a meaningful baseline for the monitor, not as the last word in navigation.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import Controller, LaserScan, NavGoal, NavStatus, Observation, StaticMap
from rei.sut.nav.config import NavConfig
from rei.sut.nav.global_planner import Path, PlanningError, plan
from rei.sut.nav.grid import CostGrid
from rei.sut.nav.local_planner import DynamicWindow
from rei.sut.nav.localizer import Localizer
from rei.sut.nav.progress import ProgressMonitor
from rei.sut.nav.tracker import DynamicTracker

_FOLLOW, _ROTATE, _BACKUP = "follow", "rotate", "backup"


class NavController(Controller):
    """Navigation to one goal at a time; heading-free (the goal's yaw is ignored).

    ``max_linear``, ``max_angular`` and ``footprint`` describe the robot (TurtleBot3 Waffle by default) and
    override the same fields of ``config``, which holds the planners' tuning; ``footprint=None``: the robot's own,
    the static map's ``robot_size``, taken at each :meth:`reset`.
    """

    def __init__(
        self,
        max_linear: float = 0.26,
        max_angular: float = 1.82,
        footprint: tuple[float, float] | None = (0.281, 0.306),
        config: NavConfig | None = None,
    ) -> None:
        config = config or NavConfig()
        self._robots_footprint = footprint is None
        if footprint is None:
            footprint = (config.footprint_x, config.footprint_y)
        self.config = dataclasses.replace(
            config, max_linear=max_linear, max_angular=max_angular,
            footprint_x=footprint[0], footprint_y=footprint[1],
        )
        self._grid: CostGrid | None = None
        self._localizer: Localizer | None = None
        self._scan_t: float | None = None
        self._dwa = DynamicWindow(self.config, None)
        self._monitor = ProgressMonitor(self.config)
        self._status = NavStatus.IDLE
        self._text = ""
        self._goal: NavGoal | None = None
        self._path: Path | None = None
        self._idx = 0
        self._mode = _FOLLOW
        self._blocked_since: float | None = None
        self._replanned_in_block = False
        self._backup_from: tuple[float, float] | None = None
        self._last_cmd = Twist2D()
        self._last_t: float | None = None
        self._scan_world = np.zeros((0, 2))
        self._tracker = DynamicTracker()
        self._trig: tuple[tuple[int, float, float], np.ndarray, np.ndarray] | None = None
        self._lidar = (0.0, 0.0, 0.0)
        self._pose: Pose2D | None = None
        self.replans = 0
        self.recoveries = 0

    # -- Controller interface ------------------------------------------------------------------------------

    @property
    def status(self) -> NavStatus:
        return self._status

    @property
    def status_text(self) -> str:
        return self._text

    @property
    def pose(self) -> Pose2D | None:
        """Where the controller believes the robot is (odometry corrected by localization), after a step."""
        return self._pose

    @property
    def path(self) -> np.ndarray | None:
        """The current global plan as ``(N, 2)`` world points (for visualisation and tests)."""
        return None if self._path is None else self._path.points

    def reset(self, static_map: StaticMap, start: Pose2D) -> None:
        self._lidar, self._trig = static_map.lidar, None
        if self._robots_footprint:
            self.config = dataclasses.replace(self.config, footprint_x=static_map.robot_size[0],
                                              footprint_y=static_map.robot_size[1])
            if static_map.outline is not None:  # a described robot: its outline's radii, not its bounding box's
                far, near = static_map.robot_radii
                self.config = dataclasses.replace(self.config, outline_circumscribed=far, outline_inscribed=near)
        if static_map.holonomic:
            self.config = dataclasses.replace(self.config, holonomic=True)
        self._grid = CostGrid(static_map, self.config)
        self._localizer = Localizer(self._grid, self.config.match_gate) if self.config.localize else None
        self._scan_t, self._pose = None, None
        self._dwa = DynamicWindow(self.config, self._grid)
        self._status, self._text = NavStatus.IDLE, ""
        self._goal, self._path = None, None
        self._last_cmd, self._last_t = Twist2D(), None
        self._scan_world = np.zeros((0, 2))
        self._tracker = DynamicTracker()

    def set_goal(self, goal: NavGoal) -> None:
        self._goal = goal
        self._path = None
        self._status, self._text = NavStatus.ACTIVE, ""
        self._mode = _FOLLOW
        self._blocked_since, self._replanned_in_block = None, False
        self._monitor = ProgressMonitor(self.config)

    def cancel(self) -> None:
        if self._status is NavStatus.ACTIVE:
            self._status, self._text = NavStatus.CANCELLED, "cancelled by the client"
        self._path = None

    def step(self, observation: Observation) -> Twist2D:
        t = observation.t
        dt = 0.1 if self._last_t is None else min(max(t - self._last_t, 0.02), 0.5)
        self._last_t = t
        pose = observation.odom if self._localizer is None else self._localizer.pose(observation.odom)
        scan = observation.scan
        if scan is not None and scan.t != self._scan_t:
            self._scan_t = scan.t
            local = self._scan_local(scan)
            if self._localizer is not None:
                pose = self._localizer.update(observation.odom, local)
            self._scan_world = self._to_world(pose, local)
            if self._grid is not None and len(self._scan_world):
                pts = self._scan_world
                unexplained = self._grid.distance_at(pts[:, 0], pts[:, 1]) > 2.0 * self._grid.resolution
                self._tracker.update(scan.t, pts[unexplained])
        self._pose = pose
        if self._status is not NavStatus.ACTIVE or self._goal is None:
            return self._send(0.0, 0.0)
        if self._grid is None:
            return self._abort("reset() was not called: no static map")
        if self.config.stop_when_blind and scan is not None and not np.isfinite(scan.ranges).any():
            return self._send(0.0, 0.0)
        return self._navigate(t, dt, pose)

    # -- navigation ----------------------------------------------------------------------------------------

    def _navigate(self, t: float, dt: float, pose: Pose2D) -> Twist2D:
        assert self._goal is not None
        if self._path is None:
            try:
                self._plan(pose, sensed=False)
            except PlanningError as exc:
                return self._abort(f"planning failed: {exc}")
            self._monitor.start(t, pose.x, pose.y, self._remaining(pose))
        path = self._path
        assert path is not None
        reach = min(self.config.xy_goal_tolerance, 0.3 * self._goal.tolerance)
        end = path.end
        to_end = math.hypot(end[0] - pose.x, end[1] - pose.y)
        if to_end <= reach or pose.distance_to(self._goal.pose) <= reach:
            self._status, self._text = NavStatus.SUCCEEDED, f"reached the goal ({to_end:.3f} m from its target)"
            return self._send(0.0, 0.0)
        self._track(pose)
        reason = self._monitor.update(t, pose.x, pose.y, self._remaining(pose))
        if reason is not None:
            return self._abort(reason)

        points = self._robot_points(pose)
        xyyaw = (pose.x, pose.y, pose.yaw)
        if self._mode == _BACKUP:
            cmd = self._backup(pose, dt, points)
            if cmd is not None:
                return cmd
        if math.hypot(*(path.points[self._idx] - (pose.x, pose.y))) > self.config.max_path_deviation:
            self._try_replan(pose, sensed=True)
            path = self._path
            assert path is not None

        k_carrot = int(np.searchsorted(path.s, path.s[self._idx] + self.config.lookahead))
        final = k_carrot >= len(path.s) - 1
        carrot_world = path.points[min(k_carrot, len(path.s) - 1)]
        carrot = self._to_robot(pose, carrot_world[None, :])[0]
        error = math.atan2(carrot[1], carrot[0])
        moving = self._moving(pose)
        v_cap = math.sqrt(2.0 * 0.5 * max(to_end - 0.5 * reach, 0.0)) + 0.03
        if self.config.holonomic and self._mode != _ROTATE:
            cmd = self._strafe(dt, carrot, points, moving, v_cap)
            if cmd is not None:
                self._mode, self._blocked_since, self._replanned_in_block = _FOLLOW, None, False
                return cmd
        wants_turn = self._mode == _ROTATE or abs(error) > self.config.rotate_threshold
        if (wants_turn and math.hypot(*carrot) > 0.05 and abs(error) > 0.25
                and self._dwa.rotation_safe(points, xyyaw) and self._dwa.standing_safe(moving)):
            self._mode = _ROTATE
            self._blocked_since = None
            return self._rotate(error, dt)
        self._mode = _FOLLOW

        hi = int(np.searchsorted(path.s, path.s[self._idx] + self.config.lookahead + 0.5))
        window = self._to_robot(pose, path.points[self._idx: hi + 1])
        choice = self._dwa.choose(
            xyyaw, self._last_cmd.v, self._last_cmd.w, dt, points, window, carrot, v_cap, final, moving
        )
        if choice is None or choice.v < 0.02 or choice.fallback:
            self._blocked(t, pose, points)
            if self._mode == _BACKUP:
                cmd = self._backup(pose, dt, points)
                if cmd is not None:
                    return cmd
            if choice is None:
                return self._send(0.0, 0.0)
        else:
            self._blocked_since, self._replanned_in_block = None, False
        return self._send(choice.v, choice.w)

    def _blocked(self, t: float, pose: Pose2D, points: np.ndarray) -> None:
        """Blocked long enough: first replan around what the laser sees, then back up and replan again."""
        if self._blocked_since is None:
            self._blocked_since, self._replanned_in_block = t, False
            return
        waited = t - self._blocked_since
        if waited >= self.config.replan_after_blocked and not self._replanned_in_block:
            self._replanned_in_block = True
            self._try_replan(pose, sensed=True)
        elif waited >= self.config.recovery_after_blocked:
            self._blocked_since = None
            self.recoveries += 1
            backup_ok = self._moving(pose) is None  # backing up blind to a walking human is no recovery
            if backup_ok and self._dwa.backup_clear(points, (pose.x, pose.y, pose.yaw), self.config.backup_distance):
                self._mode, self._backup_from = _BACKUP, (pose.x, pose.y)
            else:
                self._try_replan(pose, sensed=True)

    def _backup(self, pose: Pose2D, dt: float, points: np.ndarray) -> Twist2D | None:
        assert self._backup_from is not None
        moved = math.hypot(pose.x - self._backup_from[0], pose.y - self._backup_from[1])
        if moved < self.config.backup_distance and self._moving(pose) is None and self._dwa.backup_clear(
            points, (pose.x, pose.y, pose.yaw), 0.05
        ):
            v = max(-0.1, self._last_cmd.v - self.config.acc_linear * dt)
            return self._send(v, 0.0)
        self._mode = _FOLLOW
        self._try_replan(pose, sensed=True)
        return None

    def _strafe(self, dt: float, carrot: np.ndarray, points: np.ndarray,
                moving: tuple[np.ndarray, np.ndarray] | None, v_cap: float) -> Twist2D | None:
        """A holonomic robot moves straight at the carrot with its heading kept (forward and sideways speeds, no
        turn), as long as no tracked person is near and the robot's circumscribed circle, swept along that line
        for ``sim_time``, keeps ``min_clearance`` from every scan point; None otherwise, and the dynamic window
        (which turns and drives) decides."""
        cfg = self.config
        distance = float(math.hypot(*carrot))
        if distance < 1e-6 or moving is not None:
            return None
        u = carrot / distance
        speed = min(cfg.max_linear, v_cap)
        ahead = min(distance, speed * cfg.sim_time)
        if len(points):
            along = np.clip(points @ u, 0.0, ahead)
            gap = np.hypot(points[:, 0] - along * u[0], points[:, 1] - along * u[1]) - cfg.circumscribed_radius
            if float(gap.min()) < cfg.min_clearance:
                return None
        last = self._last_cmd
        step = cfg.acc_linear * dt
        v = min(max(speed * float(u[0]), last.v - step), last.v + step)
        vy = min(max(speed * float(u[1]), last.vy - step), last.vy + step)
        w = min(max(0.0, last.w - cfg.acc_angular * dt), last.w + cfg.acc_angular * dt)  # come to a stop turning
        return self._send(v, w, vy)

    def _rotate(self, error: float, dt: float) -> Twist2D:
        cfg = self.config
        target = math.copysign(min(cfg.max_angular, max(0.4, 2.0 * abs(error))), error)
        w0 = self._last_cmd.w
        w = min(max(target, w0 - cfg.acc_angular * dt), w0 + cfg.acc_angular * dt)
        return self._send(0.0, w)

    # -- planning ------------------------------------------------------------------------------------------

    def _plan(self, pose: Pose2D, sensed: bool) -> None:
        grid, goal = self._grid, self._goal
        assert grid is not None and goal is not None
        cost = grid.cost
        if sensed and len(self._tracker.still):
            # Obstacles the map does not have and that stand still (moving ones are the local planner's job).
            pts = self._tracker.still
            pts = pts[np.hypot(pts[:, 0] - pose.x, pts[:, 1] - pose.y) < 3.0]
            if len(pts):
                cost = grid.with_points(pts[:, 0], pts[:, 1])
        self._path = plan(grid, cost, (pose.x, pose.y), (goal.pose.x, goal.pose.y), 0.6 * goal.tolerance)
        self._idx = 0

    def _try_replan(self, pose: Pose2D, sensed: bool) -> None:
        """Replan; keep the old path when the new plan fails (the obstacle may be a human walking away)."""
        try:
            self._plan(pose, sensed)
        except PlanningError as exc:
            self._text = f"replanning failed: {exc}"
            return
        self.replans += 1
        self._monitor.replanned(self._remaining(pose))

    def _track(self, pose: Pose2D) -> None:
        """Move the path index to the nearest path point in a window ahead of the current one."""
        path = self._path
        assert path is not None
        lo = max(self._idx - 10, 0)
        hi = min(self._idx + 60, len(path.s))
        d = np.hypot(path.points[lo:hi, 0] - pose.x, path.points[lo:hi, 1] - pose.y)
        self._idx = lo + int(np.argmin(d))

    def _remaining(self, pose: Pose2D) -> float:
        path = self._path
        assert path is not None
        p = path.points[self._idx]
        return float(path.s[-1] - path.s[self._idx]) + math.hypot(p[0] - pose.x, p[1] - pose.y)

    # -- helpers -------------------------------------------------------------------------------------------

    def _abort(self, reason: str) -> Twist2D:
        self._status, self._text = NavStatus.ABORTED, reason
        self._path = None
        return self._send(0.0, 0.0)

    def _send(self, v: float, w: float, vy: float = 0.0) -> Twist2D:
        self._last_cmd = Twist2D(v, w, vy)
        return self._last_cmd

    def _scan_local(self, scan: LaserScan) -> np.ndarray:
        """Robot-frame points of a scan's valid beams, from where the lidar sits on the robot."""
        ranges = np.asarray(scan.ranges, dtype=float)
        key = (len(ranges), scan.angle_min, scan.angle_increment)
        if self._trig is None or self._trig[0] != key:
            angles = scan.angle_min + scan.angle_increment * np.arange(len(ranges)) + self._lidar[2]
            self._trig = (key, np.cos(angles), np.sin(angles))
        _, cos, sin = self._trig
        ok = np.isfinite(ranges) & (ranges >= scan.range_min) & (ranges <= scan.range_max)
        r = ranges[ok]
        lx, ly, _ = self._lidar
        if lx == 0.0 and ly == 0.0:
            return np.column_stack((r * cos[ok], r * sin[ok]))
        return np.column_stack((lx + r * cos[ok], ly + r * sin[ok]))

    @staticmethod
    def _to_world(pose: Pose2D, local: np.ndarray) -> np.ndarray:
        """World-frame points of a scan taken at ``pose``, kept until the next scan."""
        c, s = math.cos(pose.yaw), math.sin(pose.yaw)
        return np.column_stack((pose.x + c * local[:, 0] - s * local[:, 1], pose.y + s * local[:, 0] + c * local[:, 1]))

    def _moving(self, pose: Pose2D) -> tuple[np.ndarray, np.ndarray] | None:
        """Tracked moving points and their velocities in the robot frame."""
        if not len(self._tracker.points):
            return None
        points, vel = self._tracker.points, self._tracker.velocities
        if len(points) > 48:  # a human's outline at close range: every few centimetres is enough
            keep = np.linspace(0, len(points) - 1, 48).astype(np.intp)
            points, vel = points[keep], vel[keep]
        c, s = math.cos(pose.yaw), math.sin(pose.yaw)
        return (self._to_robot(pose, points),
                np.column_stack((c * vel[:, 0] + s * vel[:, 1], -s * vel[:, 0] + c * vel[:, 1])))

    def _robot_points(self, pose: Pose2D) -> np.ndarray:
        return self._to_robot(pose, self._scan_world)

    @staticmethod
    def _to_robot(pose: Pose2D, points: np.ndarray) -> np.ndarray:
        if not len(points):
            return np.zeros((0, 2))
        c, s = math.cos(pose.yaw), math.sin(pose.yaw)
        dx = points[:, 0] - pose.x
        dy = points[:, 1] - pose.y
        return np.column_stack((c * dx + s * dy, -s * dx + c * dy))

