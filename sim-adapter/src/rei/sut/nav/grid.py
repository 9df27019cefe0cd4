# SPDX-License-Identifier: EPL-2.0
"""Occupancy grid of the static map: an exact distance field, the lethal mask and the planning cost.

The distance field is computed analytically per obstacle rectangle (no distance transform library needed): each
rectangle only touches the cells within the field's cap around it, so building the grid is linear in the number
of obstacles and costs a few milliseconds for a generated room.
"""

from __future__ import annotations

import math

import numpy as np

from rei.geometry import polygon_distance
from rei.sut.api import StaticMap
from rei.sut.nav.config import NavConfig

_PAD = 0.3  # metres of grid around the floors' bounds, so walls centred on the bounds are fully inside


class CostGrid:
    """The static world rasterised at ``config.resolution``; cell ``[j, i]`` has its centre at ``cell_center``.

    ``distance`` is the distance (capped) from a cell centre to the nearest obstacle or to the outside of the
    floors; ``cost`` is the per-cell planning cost (``inf`` where the robot's centre may not be planned).
    ``surface`` is the signed distance (capped, negative inside) to the obstacles' outlines alone, what a laser
    sees: the localizer matches scans against it.
    """

    def __init__(self, static_map: StaticMap, config: NavConfig) -> None:
        self.config = config
        self.resolution = res = config.resolution
        xmin, ymin, xmax, ymax = static_map.bounds
        if not (xmax > xmin and ymax > ymin):
            raise ValueError(f"static map bounds {static_map.bounds} are empty")
        self.origin = (xmin - _PAD, ymin - _PAD)
        self.width = math.ceil((xmax - xmin + 2 * _PAD) / res)
        self.height = math.ceil((ymax - ymin + 2 * _PAD) / res)
        self.cap = config.inflation_radius + config.cost_decay + 0.2
        xs = self.origin[0] + (np.arange(self.width) + 0.5) * res
        ys = self.origin[1] + (np.arange(self.height) + 0.5) * res
        # Distance to the outside of the floors' bounds (0 outside).
        inside = np.minimum.outer(np.minimum(ys - ymin, ymax - ys), np.minimum(xs - xmin, xmax - xs))
        dist = np.clip(inside, 0.0, self.cap)
        surface = np.full_like(dist, self.cap)
        for k, obstacle in enumerate(static_map.obstacles):
            polygon = static_map.polygons[k] if static_map.polygons else None
            if polygon is not None:
                self._stamp_polygon(dist, surface, xs, ys, obstacle, polygon)
            else:
                self._stamp_rectangle(dist, surface, xs, ys, obstacle)
        self.distance = dist.astype(np.float32)
        self.surface = np.maximum(surface, -self.cap)
        self._surface_flat = self.surface.ravel()
        self.cost = self.cost_from_distance(self.distance)

    def _reach(self, cx: float, cy: float, sx: float, sy: float) -> tuple[int, int, int, int] | None:
        """The cells (i0, i1, j0, j1, ends excluded) an obstacle's rectangle of sizes sx, sy about (cx, cy) reaches
        within the cap; None when none is on the grid."""
        reach = 0.5 * math.hypot(sx, sy) + self.cap
        i0, j0 = self.world_to_cell(cx - reach, cy - reach)
        i1, j1 = self.world_to_cell(cx + reach, cy + reach)
        i0, i1 = max(i0, 0), min(i1 + 1, self.width)
        j0, j1 = max(j0, 0), min(j1 + 1, self.height)
        return None if i0 >= i1 or j0 >= j1 else (i0, i1, j0, j1)

    def _stamp_rectangle(
        self,
        dist: np.ndarray,
        surface: np.ndarray,
        xs: np.ndarray,
        ys: np.ndarray,
        obstacle: tuple[float, float, float, float, float],
    ) -> None:
        cx, cy, yaw, sx, sy = obstacle
        window = self._reach(cx, cy, sx, sy)
        if window is None:
            return
        i0, i1, j0, j1 = window
        dx = xs[i0:i1][None, :] - cx
        dy = ys[j0:j1][:, None] - cy
        c, s = math.cos(yaw), math.sin(yaw)
        lx = np.abs(c * dx + s * dy) - 0.5 * sx
        ly = np.abs(-s * dx + c * dy) - 0.5 * sy
        d = np.hypot(np.maximum(lx, 0.0), np.maximum(ly, 0.0))
        np.minimum(dist[j0:j1, i0:i1], d, out=dist[j0:j1, i0:i1])
        # Signed: inside, minus the depth. The minimum over overlapping rectangles never crosses zero inside
        # their union, so only outlines the laser can see are zero.
        signed = d + np.minimum(np.maximum(lx, ly), 0.0)
        np.minimum(surface[j0:j1, i0:i1], signed, out=surface[j0:j1, i0:i1])

    def _stamp_polygon(self, dist: np.ndarray, surface: np.ndarray, xs: np.ndarray, ys: np.ndarray,
                       obstacle: tuple[float, float, float, float, float],
                       polygon: tuple[tuple[float, float], ...]) -> None:
        """Furniture on a polygon: its cells' distance to the polygon itself (0 inside, minus the depth on the
        signed surface), over the region its bounding box's rectangle reaches."""
        cx, cy, _yaw, sx, sy = obstacle
        window = self._reach(cx, cy, sx, sy)
        if window is None:
            return
        i0, i1, j0, j1 = window
        px, py = np.meshgrid(xs[i0:i1], ys[j0:j1])
        edge, inside = polygon_distance(px, py, np.asarray(polygon, dtype=float))
        np.minimum(dist[j0:j1, i0:i1], np.where(inside, 0.0, edge), out=dist[j0:j1, i0:i1])
        np.minimum(surface[j0:j1, i0:i1], np.where(inside, -edge, edge), out=surface[j0:j1, i0:i1])

    def cost_from_distance(self, distance: np.ndarray) -> np.ndarray:
        """Cell cost: 1 in the open, rising quadratically to ``1 + cost_scale`` at the inflation radius, ``inf``
        inside it. The gradient is what makes A* keep clearance instead of hugging the inflated obstacles."""
        cfg = self.config
        excess = np.clip((cfg.cost_decay - (distance - cfg.inflation_radius)) / cfg.cost_decay, 0.0, 1.0)
        cost = 1.0 + cfg.cost_scale * excess**2
        cost[distance < cfg.inflation_radius] = np.inf
        # A one-cell lethal frame, so the planner never needs bounds checks.
        cost[0, :] = cost[-1, :] = cost[:, 0] = cost[:, -1] = np.inf
        return cost

    def world_to_cell(self, x: float, y: float) -> tuple[int, int]:
        """``(i, j)``: column and row of the cell containing the point (may be outside the grid)."""
        return (math.floor((x - self.origin[0]) / self.resolution),
                math.floor((y - self.origin[1]) / self.resolution))

    def cell_center(self, i: int, j: int) -> tuple[float, float]:
        return (self.origin[0] + (i + 0.5) * self.resolution, self.origin[1] + (j + 0.5) * self.resolution)

    def contains(self, i: int, j: int) -> bool:
        return 0 <= i < self.width and 0 <= j < self.height

    def distance_at(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Distance field at world points, bilinearly interpolated between cell centres; 0 off the grid."""
        fx = (np.asarray(x) - self.origin[0]) / self.resolution - 0.5
        fy = (np.asarray(y) - self.origin[1]) / self.resolution - 0.5
        i = np.floor(fx).astype(np.intp)
        j = np.floor(fy).astype(np.intp)
        ok = (i >= 0) & (i < self.width - 1) & (j >= 0) & (j < self.height - 1)
        i, j = np.where(ok, i, 0), np.where(ok, j, 0)
        ax, ay = fx - i, fy - j
        d = self.distance
        top = d[j, i] * (1.0 - ax) + d[j, i + 1] * ax
        bottom = d[j + 1, i] * (1.0 - ax) + d[j + 1, i + 1] * ax
        return np.where(ok, top * (1.0 - ay) + bottom * ay, 0.0)

    def surface_at(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Signed outline distance at world points and its gradient ``(d, dd/dx, dd/dy)``, bilinear between
        cell centres; ``nan`` off the grid."""
        fx = (x - self.origin[0]) * (1.0 / self.resolution) - 0.5
        fy = (y - self.origin[1]) * (1.0 / self.resolution) - 0.5
        i = fx.astype(np.intp)  # truncation: off-grid points on the low side are caught by ``ok`` below
        j = fy.astype(np.intp)
        ok = (fx >= 0.0) & (i < self.width - 1) & (fy >= 0.0) & (j < self.height - 1)
        k = np.where(ok, j * self.width + i, 0)
        ax, ay = fx - i, fy - j
        f = self._surface_flat
        d00, d10 = f.take(k), f.take(k + 1)
        d01, d11 = f.take(k + self.width), f.take(k + self.width + 1)
        bottom = d00 + (d10 - d00) * ax
        top = d01 + (d11 - d01) * ax
        d = bottom + (top - bottom) * ay
        d[~ok] = np.nan
        gx = ((d10 - d00) + ((d11 - d01) - (d10 - d00)) * ay) * (1.0 / self.resolution)
        gy = (top - bottom) * (1.0 / self.resolution)
        return d, gx, gy

    def with_points(self, px: np.ndarray, py: np.ndarray) -> np.ndarray:
        """The cost grid with extra obstacle points (sensed, not in the static map) inflated into it."""
        radius = self.config.inflation_radius
        n = math.ceil(radius / self.resolution)
        oj, oi = np.mgrid[-n : n + 1, -n : n + 1]
        keep = np.hypot(oi, oj) * self.resolution <= radius + 0.5 * self.resolution
        oi, oj = oi[keep], oj[keep]
        i = np.floor((px - self.origin[0]) / self.resolution).astype(np.intp)
        j = np.floor((py - self.origin[1]) / self.resolution).astype(np.intp)
        ii = (i[:, None] + oi[None, :]).ravel()
        jj = (j[:, None] + oj[None, :]).ravel()
        ok = (ii >= 0) & (ii < self.width) & (jj >= 0) & (jj < self.height)
        cost = self.cost.copy()
        cost[jj[ok], ii[ok]] = np.inf
        return cost
