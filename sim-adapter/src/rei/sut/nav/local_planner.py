# SPDX-License-Identifier: EPL-2.0
"""Local planner: a dynamic window approach (DWA) scored against the global path and the live laser points.

Everything is computed in the robot frame for all sampled ``(v, w)`` pairs at once with numpy, which keeps one
control step around a millisecond. Collision checking uses the robot's circumscribed circle: conservative, but
exact for turning in place, and the static map's distance field backs up the laser for obstacles the scan
plane misses (objects lower than the lidar).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rei.sut.nav.config import NavConfig
from rei.sut.nav.grid import CostGrid


@dataclass(frozen=True, slots=True)
class Choice:
    """The chosen command and what the planner knew when choosing it."""

    v: float
    w: float
    admissible: int
    clearance: float
    fallback: bool = False


class DynamicWindow:
    """Samples velocities reachable within one control period and scores their forward-simulated arcs."""

    def __init__(self, config: NavConfig, grid: CostGrid | None) -> None:
        self.config = config
        self.grid = grid
        steps = max(1, round(config.sim_time / config.sim_step))
        self.times = config.sim_step * np.arange(0, steps + 1)  # t = 0 included: the current pose
        self.radius = config.circumscribed_radius
        self.reach = config.max_linear * config.sim_time + self.radius + config.preferred_clearance

    def samples(self, v0: float, w0: float, dt: float, v_cap: float) -> tuple[np.ndarray, np.ndarray]:
        cfg = self.config
        v_hi = min(cfg.max_linear, v_cap, v0 + cfg.acc_linear * dt)
        v_lo = max(0.0, v0 - cfg.acc_linear * dt)
        v_lo = min(v_lo, v_hi)
        # Turning rates reachable within a short reaction time, not just one period: with the window of one
        # period, the arcs cannot swerve out of the way of a human walking head-on.
        reach = cfg.acc_angular * max(dt, cfg.turn_reaction_time)
        w_lo = max(-cfg.max_angular, w0 - reach)
        w_hi = min(cfg.max_angular, w0 + reach)
        vs = np.unique(np.append(np.linspace(v_lo, v_hi, cfg.v_samples), 0.0 if v_lo <= 1e-9 else v_lo))
        reverse = max(-0.1, v0 - cfg.acc_linear * dt)
        if reverse < -0.02:  # only ever used to get out of a moving obstacle's way
            vs = np.append(reverse, vs)
        ws = np.linspace(w_lo, w_hi, cfg.w_samples)
        if w_lo < 0.0 < w_hi:
            ws = np.append(ws, 0.0)
        v, w = np.meshgrid(vs, ws, indexing="ij")
        return v.ravel(), w.ravel()

    def arcs(self, v: np.ndarray, w: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Robot-frame poses ``(x, y, yaw)``, each ``(K, S)``, of constant-velocity arcs."""
        t = self.times[None, :]
        vv, ww = v[:, None], w[:, None]
        yaw = ww * t
        straight = np.abs(ww) < 1e-6
        safe_w = np.where(straight, 1.0, ww)
        x = np.where(straight, vv * t, vv / safe_w * np.sin(yaw))
        y = np.where(straight, 0.0, vv / safe_w * (1.0 - np.cos(yaw)))
        return x, y, yaw

    def arc_clearance(
        self, v: np.ndarray, w: np.ndarray, points: np.ndarray, span: np.ndarray | None = None
    ) -> np.ndarray:
        """Clearance ``(K,)`` of the robot circle from laser points (robot frame) over each whole arc.

        Exact and continuous: the distance from a point to a circular arc is its distance to the circle when
        the point's bearing from the centre lies within the arc's sweep, else to the nearer end. That is
        ``K x P`` work instead of ``K x S x P`` for sampled poses. ``span`` (``(K,)`` seconds, default the
        whole horizon) lets arcs that stop at the goal end there.
        """
        k = len(v)
        if not len(points):
            return np.full(k, self.config.preferred_clearance + 1.0)
        near = points[np.einsum("ij,ij->i", points, points) < self.reach * self.reach]
        if not len(near):
            return np.full(k, self.config.preferred_clearance + 1.0)
        # float32: the trigonometry is several times faster and millimetres are plenty.
        f32 = np.float32
        px, py = near[None, :, 0].astype(f32), near[None, :, 1].astype(f32)
        span = (np.full((len(v), 1), self.times[-1]) if span is None else span[:, None]).astype(f32)
        vv, ww = v[:, None].astype(f32), w[:, None].astype(f32)
        turning = np.abs(ww) > 1e-3
        r = np.where(turning, vv / np.where(turning, ww, f32(1.0)), f32(0.0))
        sign = np.where(r >= 0.0, f32(1.0), f32(-1.0))
        qx, qy = px, py - r
        bearing = np.arctan2(sign * qx, -sign * qy)
        bearing = np.where(ww >= 0.0, bearing, -bearing)
        sweep = np.where(bearing < 0.0, bearing + f32(2 * np.pi), bearing)
        on_arc = sweep <= np.abs(ww) * span
        d_circle = np.abs(np.sqrt(qx * qx + qy * qy) - np.abs(r))
        ex = np.where(turning, r * np.sin(ww * span), vv * span)
        ey = np.where(turning, r * (f32(1.0) - np.cos(ww * span)), f32(0.0))
        d_ends = np.sqrt(np.minimum(px * px + py * py, (px - ex) ** 2 + (py - ey) ** 2))
        arc = np.where(on_arc, d_circle, d_ends)
        # Straight (or nearly straight) motion: distance to the segment.
        length = vv * span
        length = np.where(np.abs(length) < 1e-9, f32(1e-9), length)
        u = np.clip(px / length, 0.0, 1.0)
        seg = np.sqrt((px - u * length) ** 2 + py * py)
        d = np.where(turning, arc, seg)
        return d.min(axis=1) - self.radius

    def static_clearance(
        self, x: np.ndarray, y: np.ndarray, pose: tuple[float, float, float], upto: np.ndarray | None = None
    ) -> np.ndarray:
        """Per-arc clearance ``(K,)`` from the static map at sampled robot-frame poses ``(K, S)`` (only the
        samples before ``upto``, a ``(K, S)`` mask, when given)."""
        if self.grid is None or not self.config.use_static_clearance:
            return np.full(x.shape[0], self.config.preferred_clearance + 1.0)
        px, py, pyaw = pose
        c, s = math.cos(pyaw), math.sin(pyaw)
        d = self.grid.distance_at(px + c * x - s * y, py + s * x + c * y)
        if upto is not None:
            d = np.where(upto, d, np.inf)
        return d.min(axis=1) - self.radius

    def choose(
        self,
        pose: tuple[float, float, float],
        v0: float,
        w0: float,
        dt: float,
        points: np.ndarray,
        path_window: np.ndarray,
        carrot: np.ndarray,
        v_cap: float,
        final: bool = False,
        moving: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> Choice | None:
        """Best admissible command, or ``None`` when every arc gets too close to something.

        ``path_window`` and ``carrot`` are in the robot frame: the stretch of global path ahead and the point
        ``lookahead`` metres along it the robot should head for; ``final`` says the carrot is the goal.
        ``moving`` are the tracked moving points and their velocities (robot frame): arcs are checked against
        where those points will be. When a moving obstacle leaves no safe arc, the arc that keeps farthest
        from it is taken rather than standing in its way.
        """
        cfg = self.config
        v, w = self.samples(v0, w0, dt, v_cap)
        x, y, yaw = self.arcs(v, w)
        span, upto = None, None
        if final:
            # Arcs that reach the goal end there (plus braking): the wall behind the goal does not matter.
            closest_t = self.times[np.argmin(np.hypot(carrot[0] - x, carrot[1] - y), axis=1)]
            span = np.minimum(closest_t + v / cfg.acc_linear + cfg.sim_step, self.times[-1])
            upto = self.times[None, :] <= span[:, None] + 1e-9
        lidar = self.arc_clearance(v, w, points, span)
        static = self.static_clearance(x, y, pose, upto)
        now_lidar, now_static = self.point_clearance(points), self._static_now(pose)
        now = min(now_lidar, now_static)
        # Never closer than min_clearance; when already closer (a human walked up), only do not get closer.
        ok = (lidar >= min(cfg.min_clearance, now_lidar - 0.005)) & (
            static >= min(cfg.min_clearance, now_static - 0.005)
        )
        worst = np.minimum(lidar, static)
        fallback = False
        forward = ok & (v >= 0.0)
        if moving is not None and len(moving[0]):
            dynamic, dynamic_now = self.moving_clearance(x, y, *moving)
            worst = np.minimum(worst, dynamic)
            safe = ok & (dynamic >= min(cfg.dynamic_clearance, dynamic_now - 0.005))
            if (safe & forward).any():
                ok = safe & forward
            elif safe.any():  # backing out of a moving obstacle's way
                ok, fallback = safe, True
            elif ok.any():  # no arc is safe: keep farthest from it
                ok, fallback = ok & (dynamic >= dynamic[ok].max() - 1e-6), True
        else:
            ok = forward
        if not ok.any():
            return None
        ex, ey, eyaw = x[:, -1], y[:, -1], yaw[:, -1]
        if final:
            # The carrot is the goal: passing through it counts, so the robot does not creep up on it.
            approach = np.hypot(carrot[0] - x, carrot[1] - y)
            closest = np.argmin(approach, axis=1)
            rows = np.arange(len(v))
            to_carrot = approach[rows, closest]
            ex, ey = x[rows, closest], y[rows, closest]
        else:
            to_carrot = np.hypot(carrot[0] - ex, carrot[1] - ey)
        if len(path_window):
            dpx = ex[:, None] - path_window[None, :, 0]
            dpy = ey[:, None] - path_window[None, :, 1]
            path_dist = np.sqrt(np.min(dpx * dpx + dpy * dpy, axis=1))
        else:
            path_dist = np.zeros_like(ex)
        heading = np.abs(np.angle(np.exp(1j * (np.arctan2(carrot[1] - ey, carrot[0] - ex) - eyaw))))
        heading = np.where(to_carrot < 0.15, 0.0, heading)
        lookahead = max(cfg.lookahead, 1e-3)
        score = (
            cfg.w_carrot * to_carrot / lookahead
            + cfg.w_path * np.minimum(path_dist, 0.5) / 0.5
            + cfg.w_heading * heading / math.pi
            + cfg.w_clearance * np.clip(cfg.preferred_clearance - worst, 0.0, None) / cfg.preferred_clearance
            - cfg.w_speed * v / cfg.max_linear
        )
        score[~ok] = np.inf
        k = int(np.argmin(score))
        return Choice(v=float(v[k]), w=float(w[k]), admissible=int(ok.sum()), clearance=now, fallback=fallback)

    def moving_clearance(
        self, x: np.ndarray, y: np.ndarray, points: np.ndarray, velocities: np.ndarray
    ) -> tuple[np.ndarray, float]:
        """Per-arc clearance ``(K,)`` from moving points extrapolated at constant velocity, and now.

        The prediction runs ``moving_horizon`` seconds, longer than the arcs: past an arc's end the robot is
        assumed to stand at its end, so the planner does not stop where a walking human is about to be.
        """
        extra = max(0, math.ceil((self.config.moving_horizon - self.times[-1]) / self.config.sim_step))
        times = np.concatenate((self.times, self.times[-1] + self.config.sim_step * np.arange(1, extra + 1)))
        if extra:
            x = np.concatenate((x, np.repeat(x[:, -1:], extra, axis=1)), axis=1)
            y = np.concatenate((y, np.repeat(y[:, -1:], extra, axis=1)), axis=1)
        t = times[None, :, None]
        px = points[None, None, :, 0] + velocities[None, None, :, 0] * t
        py = points[None, None, :, 1] + velocities[None, None, :, 1] * t
        d = np.sqrt(np.min((x[:, :, None] - px) ** 2 + (y[:, :, None] - py) ** 2, axis=2)) - self.radius
        now = float(np.sqrt(np.min(points[:, 0] ** 2 + points[:, 1] ** 2))) - self.radius
        return d[:, 1:].min(axis=1), now

    def standing_safe(self, moving: tuple[np.ndarray, np.ndarray] | None) -> bool:
        """Whether turning on the spot keeps clear of the moving points' predicted positions."""
        if moving is None or not len(moving[0]):
            return True
        zero = np.zeros((1, len(self.times)))
        clear, now = self.moving_clearance(zero, zero, *moving)
        return bool(clear[0] >= min(self.config.dynamic_clearance, now - 0.005))

    def point_clearance(self, points: np.ndarray) -> float:
        """Clearance of the robot circle at its current pose from the laser points."""
        if not len(points):
            return self.config.preferred_clearance + 1.0
        return float(np.sqrt(np.min(np.einsum("ij,ij->i", points, points)))) - self.radius

    def _static_now(self, pose: tuple[float, float, float]) -> float:
        if self.grid is None or not self.config.use_static_clearance:
            return self.config.preferred_clearance + 1.0
        d = self.grid.distance_at(np.array([pose[0]]), np.array([pose[1]]))
        return float(d[0]) - self.radius

    def rotation_safe(self, points: np.ndarray, pose: tuple[float, float, float]) -> bool:
        """Turning in place sweeps exactly the circumscribed circle."""
        return min(self.point_clearance(points), self._static_now(pose)) >= 0.0

    def backup_clear(self, points: np.ndarray, pose: tuple[float, float, float], distance: float) -> bool:
        """Whether backing straight up by ``distance`` never gets closer to anything than the rule for arcs."""
        cfg = self.config
        required = min(cfg.min_clearance, self.point_clearance(points) - 0.005)
        if len(points):
            u = np.clip(-points[:, 0] / distance, 0.0, 1.0)
            if float(np.hypot(points[:, 0] + u * distance, points[:, 1]).min()) - self.radius < required:
                return False
        xs = -np.linspace(0.0, distance, 6)[None, :]
        static = float(self.static_clearance(xs, np.zeros_like(xs), pose)[0])
        return static >= min(cfg.min_clearance, self._static_now(pose) - 0.005)
