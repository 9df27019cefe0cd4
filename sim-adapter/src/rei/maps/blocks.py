# SPDX-License-Identifier: EPL-2.0
"""What a room makes of an occupancy map: the obstacle cells merged into rectangles, and the free floor blocks.

A cell is an obstacle when ``map_server`` reads it as occupied (100), and, unless ``unknown_free``, when it is
unknown (-1). Every other value is free: 0, and ``scale`` mode's 1..99, as Nav2's static costmap layer reads them
by default (``trinary_costmap: true``, lethal at 100). A floor block of ``floor_size`` metres is free when every
cell it overlaps is free; blocks count from the map's origin (its bottom-left corner), so ``F_x_y`` is block ``x``
from the left and ``y`` from the bottom, and only blocks wholly inside the map exist.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rei.maps.occupancy import OCCUPIED, UNKNOWN, OccupancyMap

#: The most blocks of ``floor_size`` (free or not, columns x rows) a map may be cut into: 4,000,000, 16 times the
#: floors a room from a map may have. A floor size far below the map's resolution would otherwise ask for more blocks
#: than memory holds (0.0000001 m over 10 x 6 m: 6 * 10^15). A copy of ``maps.max_blocks`` in
#: contract/vocabulary.json, as the Java side's ``MapBlocks.MAX_BLOCKS``.
MAX_BLOCKS = 4_000_000
#: A tolerance of a millionth of a cell, so that 1.0 m over 0.05 m cells is 20 cells, not 20.000000000000004.
_EPS = 1e-6


@dataclass(frozen=True, slots=True)
class CellRect:
    """Cells ``[col, col + cols) x [row, row + rows)`` of the grid (row 0 at the bottom)."""

    col: int
    row: int
    cols: int
    rows: int


def box_of(rect: CellRect, occupancy: OccupancyMap) -> tuple[float, float, float, float]:
    """A rectangle in world metres: ``(centre_x, centre_y, size_x, size_y)``; cell ``(0, 0)``'s corner is the map's
    origin (an axis-aligned map: the loader refuses a yaw)."""
    res = occupancy.resolution
    ox, oy, _ = occupancy.origin
    return (ox + (rect.col + rect.cols / 2) * res, oy + (rect.row + rect.rows / 2) * res,
            rect.cols * res, rect.rows * res)


def obstacle_mask(occupancy: OccupancyMap, unknown_free: bool = False) -> np.ndarray:
    """``(height, width)`` booleans: the cells a robot may not enter (row 0 at the bottom)."""
    grid = occupancy.grid
    mask = grid == OCCUPIED
    return mask if unknown_free else mask | (grid == UNKNOWN)


def merge_rectangles(mask: np.ndarray) -> list[CellRect]:
    """Disjoint rectangles covering exactly the true cells of ``mask``: each row's runs, stacked while the next row
    has the very same run; done along rows and along columns, the fewer kept (walls run both ways)."""
    by_rows = _stack_runs(mask)
    by_cols = [CellRect(r.row, r.col, r.rows, r.cols) for r in _stack_runs(mask.T)]
    return by_rows if len(by_rows) <= len(by_cols) else by_cols


def _stack_runs(mask: np.ndarray) -> list[CellRect]:
    height, width = mask.shape
    padded = np.zeros((height, width + 2), dtype=np.int8)
    padded[:, 1:-1] = mask
    edges = np.diff(padded, axis=1)  # +1 where a run starts, -1 one past its end
    starts_r, starts_c = np.nonzero(edges == 1)
    _, ends_c = np.nonzero(edges == -1)  # same row order as the starts: one end per start
    done: list[CellRect] = []
    open_runs: dict[tuple[int, int], int] = {}  # (start, end) -> first row
    row_of: dict[int, list[tuple[int, int]]] = {}
    for r, c0, c1 in zip(starts_r.tolist(), starts_c.tolist(), ends_c.tolist(), strict=True):
        row_of.setdefault(r, []).append((c0, c1))
    for r in range(height + 1):
        runs = set(row_of.get(r, ()))
        for run in [run for run in open_runs if run not in runs]:
            first = open_runs.pop(run)
            done.append(CellRect(run[0], first, run[1] - run[0], r - first))
        for run in runs:
            open_runs.setdefault(run, r)
    return sorted(done, key=lambda rect: (rect.row, rect.col))


@dataclass(frozen=True, slots=True)
class FloorBlocks:
    """The floor blocks of a map: ``free[y, x]`` for block ``F_x_y`` (``y`` from the bottom)."""

    floor_size: float
    free: np.ndarray

    def names(self) -> list[str]:
        ys, xs = np.nonzero(self.free)
        return [f"F_{x}_{y}" for y, x in zip(ys.tolist(), xs.tolist(), strict=True)]


def block_grid(occupancy: OccupancyMap, floor_size: float) -> tuple[float, float]:
    """The blocks of ``floor_size`` metres the map is cut into, ``(columns, rows)`` (only blocks wholly inside the
    map), as whole floats: infinite at worst, never an allocation."""
    res = occupancy.resolution
    return (float(np.floor(occupancy.width * res / floor_size + _EPS)),
            float(np.floor(occupancy.height * res / floor_size + _EPS)))


def _count(value: float) -> str:
    return f"{value:.0f}" if value < 1e15 else f"{value:g}"


def floor_blocks(occupancy: OccupancyMap, floor_size: float, unknown_free: bool = False) -> FloorBlocks:
    """Which ``floor_size`` blocks of the map are free (every cell they overlap is free). A floor size that cuts
    the map into more than ``MAX_BLOCKS`` blocks is a ``ValueError`` before anything is allocated."""
    if not floor_size > 0:
        raise ValueError(f"floor size {floor_size:g}: expected metres above 0")
    columns, rows = block_grid(occupancy, floor_size)
    if columns * rows > MAX_BLOCKS:
        raise ValueError(f"floor size {floor_size:g} m cuts the map's {occupancy.width} x {occupancy.height} cells of "
                         f"{occupancy.resolution:g} m into {_count(columns)} x {_count(rows)} blocks: at most "
                         f"{MAX_BLOCKS} (free or not); use a larger floor size")
    blocked = obstacle_mask(occupancy, unknown_free)
    res = occupancy.resolution
    eps = _EPS
    # no row of blocks, no block: a long thin map's columns alone may not be counted out
    nx = 0 if rows == 0 else int(columns)
    ny = 0 if columns == 0 else int(rows)
    # Summed-area table of the blocked cells: any block's count in four lookups.
    table = np.zeros((occupancy.height + 1, occupancy.width + 1), dtype=np.int64)
    table[1:, 1:] = blocked.cumsum(axis=0).cumsum(axis=1)

    def bounds(count: int, cells: int) -> tuple[np.ndarray, np.ndarray]:
        index = np.arange(count)
        low = np.floor(index * floor_size / res + eps).astype(np.int64)
        high = np.minimum(np.ceil((index + 1) * floor_size / res - eps).astype(np.int64), cells)
        return low, high

    x0, x1 = bounds(nx, occupancy.width)
    y0, y1 = bounds(ny, occupancy.height)
    counts = (table[np.ix_(y1, x1)] - table[np.ix_(y0, x1)] - table[np.ix_(y1, x0)] + table[np.ix_(y0, x0)])
    return FloorBlocks(floor_size=floor_size, free=counts == 0)
