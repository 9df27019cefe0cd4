# SPDX-License-Identifier: EPL-2.0
"""Global planner: A* on the 8-connected cost grid, then pruning that never trades away clearance.

Plain A* on an inflated grid gives a staircase path; pruning it by line of sight alone would pull the path back
against the inflated obstacles. A shortcut is therefore only taken when it keeps at least the clearance of the
cells it replaces (or the preferred clearance, whichever is smaller), so paths straighten in the open and stay
centred in doorways.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass

import numpy as np

from rei.sut.nav.grid import CostGrid

_SQRT2 = math.sqrt(2.0)


class PlanningError(Exception):
    """No path: the message says why (it becomes the controller's abort reason)."""


@dataclass(frozen=True, slots=True)
class Path:
    """A path resampled at a fixed spacing: ``points[k]`` is at arc length ``s[k]`` from the start."""

    points: np.ndarray
    s: np.ndarray

    @property
    def length(self) -> float:
        return float(self.s[-1])

    @property
    def end(self) -> tuple[float, float]:
        return float(self.points[-1, 0]), float(self.points[-1, 1])


def astar(cost: np.ndarray, start: tuple[int, int], goal: tuple[int, int]) -> list[tuple[int, int]] | None:
    """Cheapest 8-connected cell path from ``start`` to ``goal`` (``(i, j)`` cells), or ``None``.

    Step cost is the step length (1 or sqrt 2) times the entered cell's cost; the octile heuristic is admissible
    because every cost is >= 1. The grid's border must be ``inf`` (``CostGrid`` guarantees it).
    """
    _, width = cost.shape
    flat = cost.ravel().tolist()
    s = start[1] * width + start[0]
    g = goal[1] * width + goal[0]
    if math.isinf(flat[s]) or math.isinf(flat[g]):
        return None
    gi, gj = goal
    steps = ((1, 1.0), (-1, 1.0), (width, 1.0), (-width, 1.0),
             (width + 1, _SQRT2), (width - 1, _SQRT2), (-width + 1, _SQRT2), (-width - 1, _SQRT2))
    best = {s: 0.0}
    parent = {s: -1}
    closed = set()
    heap = [(0.0, 0.0, s)]
    push, pop = heapq.heappush, heapq.heappop
    while heap:
        _, gs, node = pop(heap)
        if node == g:
            cells = []
            while node != -1:
                cells.append((node % width, node // width))
                node = parent[node]
            cells.reverse()
            return cells
        if node in closed:
            continue
        closed.add(node)
        for offset, length in steps:
            nxt = node + offset
            c = flat[nxt]
            if c == math.inf or nxt in closed:
                continue
            ng = gs + length * c
            if ng < best.get(nxt, math.inf):
                best[nxt] = ng
                parent[nxt] = node
                dx = abs(nxt % width - gi)
                dy = abs(nxt // width - gj)
                h = dx + dy + (_SQRT2 - 2.0) * min(dx, dy)
                push(heap, (ng + h, ng, nxt))
    return None


def plan(
    grid: CostGrid,
    cost: np.ndarray,
    start: tuple[float, float],
    goal: tuple[float, float],
    goal_radius: float,
    spacing: float = 0.05,
) -> Path:
    """A pruned, resampled path from ``start`` to ``goal`` (or to the nearest plannable point within
    ``goal_radius`` of it when the goal itself is too close to an obstacle). Raises ``PlanningError``."""
    cfg = grid.config
    si, sj = grid.world_to_cell(*start)
    gi, gj = grid.world_to_cell(*goal)
    if not grid.contains(gi, gj):
        raise PlanningError(f"goal ({goal[0]:.2f}, {goal[1]:.2f}) is outside the map")
    if not grid.contains(si, sj):
        raise PlanningError(f"robot ({start[0]:.2f}, {start[1]:.2f}) is outside the map")
    cost = _with_start_escape(grid, cost, si, sj)
    target = goal
    if math.isinf(cost[gj, gi]):
        found = _nearest_free(grid, cost, goal, goal_radius)
        if found is None:
            raise PlanningError(
                f"goal ({goal[0]:.2f}, {goal[1]:.2f}) is blocked: no point within {goal_radius:.2f} m of it "
                f"keeps {cfg.inflation_radius:.2f} m from obstacles"
            )
        (gi, gj), target = found
    cells = astar(cost, (si, sj), (gi, gj))
    if cells is None:
        raise PlanningError(f"no path to goal ({goal[0]:.2f}, {goal[1]:.2f}): it is enclosed or the way is blocked")
    xy = np.array([grid.cell_center(i, j) for i, j in cells])
    xy[0] = start
    xy[-1] = target
    clearance = grid.distance[[j for _, j in cells], [i for i, _ in cells]]
    pruned = prune(grid, cost, xy, clearance)
    return resample(pruned, spacing)


def _with_start_escape(grid: CostGrid, cost: np.ndarray, si: int, sj: int) -> np.ndarray:
    """Let the path leave the inflated zone when the robot already stands in it (pushed there by a human, or
    started close to a wall): cells near the start that are not inside the inscribed radius become expensive
    instead of forbidden."""
    if not math.isinf(cost[sj, si]):
        return cost
    cfg = grid.config
    n = math.ceil(max(0.35, cfg.inflation_radius + 0.1) / grid.resolution)
    j0, j1 = max(sj - n, 0), min(sj + n + 1, grid.height)
    i0, i1 = max(si - n, 0), min(si + n + 1, grid.width)
    jj, ii = np.mgrid[j0:j1, i0:i1]
    near = np.hypot(ii - si, jj - sj) <= n
    window = cost[j0:j1, i0:i1]
    relax = near & np.isinf(window) & (grid.distance[j0:j1, i0:i1] >= cfg.inscribed_radius)
    relax[[0, -1], :] = False
    relax[:, [0, -1]] = False
    out = cost.copy()
    out[j0:j1, i0:i1][relax] = 1.0 + 3.0 * cfg.cost_scale
    if math.isinf(out[sj, si]):
        out[sj, si] = 1.0 + 3.0 * cfg.cost_scale
    return out


def _nearest_free(
    grid: CostGrid, cost: np.ndarray, goal: tuple[float, float], radius: float
) -> tuple[tuple[int, int], tuple[float, float]] | None:
    n = math.ceil(radius / grid.resolution) + 1
    gi, gj = grid.world_to_cell(*goal)
    j0, j1 = max(gj - n, 0), min(gj + n + 1, grid.height)
    i0, i1 = max(gi - n, 0), min(gi + n + 1, grid.width)
    jj, ii = np.mgrid[j0:j1, i0:i1]
    cx = grid.origin[0] + (ii + 0.5) * grid.resolution
    cy = grid.origin[1] + (jj + 0.5) * grid.resolution
    d = np.hypot(cx - goal[0], cy - goal[1])
    d[np.isinf(cost[j0:j1, i0:i1]) | (d > radius)] = np.inf
    k = int(np.argmin(d))
    if math.isinf(d.flat[k]):
        return None
    return (int(ii.flat[k]), int(jj.flat[k])), (float(cx.flat[k]), float(cy.flat[k]))


def prune(grid: CostGrid, cost: np.ndarray, xy: np.ndarray, clearance: np.ndarray) -> np.ndarray:
    """Greedy line-of-sight pruning that keeps the clearance of the replaced cells (see module docstring)."""
    cfg = grid.config
    preferred = cfg.inflation_radius + cfg.cost_decay
    n = len(xy)
    keep = [0]
    a = 0
    while a < n - 1:
        b = a + 1
        floor = min(float(clearance[a]), float(clearance[b]))
        while b + 1 < n:
            floor = min(floor, float(clearance[b + 1]))
            if not _segment_ok(grid, cost, xy[a], xy[b + 1], min(preferred, floor) - 1e-6):
                break
            b += 1
        keep.append(b)
        a = b
    return xy[keep]


def _segment_ok(grid: CostGrid, cost: np.ndarray, p: np.ndarray, q: np.ndarray, min_distance: float) -> bool:
    length = float(np.hypot(*(q - p)))
    k = max(2, int(length / (0.5 * grid.resolution)) + 1)
    t = np.linspace(0.0, 1.0, k)
    x = p[0] + t * (q[0] - p[0])
    y = p[1] + t * (q[1] - p[1])
    i = np.floor((x - grid.origin[0]) / grid.resolution).astype(np.intp)
    j = np.floor((y - grid.origin[1]) / grid.resolution).astype(np.intp)
    if np.isinf(cost[j, i]).any():
        return False
    return bool(grid.distance[j, i].min() >= min_distance)


def resample(xy: np.ndarray, spacing: float) -> Path:
    """The polyline as points ``spacing`` apart (first and last points kept exactly)."""
    seg = np.hypot(np.diff(xy[:, 0]), np.diff(xy[:, 1]))
    s_vertices = np.concatenate(([0.0], np.cumsum(seg)))
    total = float(s_vertices[-1])
    if total < 1e-9:
        return Path(points=xy[:1].copy(), s=np.zeros(1))
    s = np.append(np.arange(0.0, total, spacing), total)
    points = np.column_stack((np.interp(s, s_vertices, xy[:, 0]), np.interp(s, s_vertices, xy[:, 1])))
    return Path(points=points, s=s)
