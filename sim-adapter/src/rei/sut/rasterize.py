# SPDX-License-Identifier: EPL-2.0
"""The static map as an occupancy raster and back (pure numpy): the ROS bridges' /map, and for nodes that take a
/map, its occupied cells as the rectangles REI's navigation plans around."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rei.geometry import Pose2D, polygon_distance
from rei.maps import OccupancyMap, merge_rectangles
from rei.sut.api import StaticMap

#: Cells of the occupancy grid (m) and the margin around the floors, where the walls stand (m).
MAP_RESOLUTION = 0.05
MAP_MARGIN = 0.5


@dataclass(frozen=True, slots=True)
class Raster:
    """``occupied[row, col]``: row-major from the origin ``(x0, y0)`` (the grid's lower left corner), as a ROS
    OccupancyGrid wants; cells of ``resolution`` metres."""

    occupied: np.ndarray
    x0: float
    y0: float
    resolution: float

    @property
    def width(self) -> int:
        return int(self.occupied.shape[1])

    @property
    def height(self) -> int:
        return int(self.occupied.shape[0])

    def occupancy(self) -> np.ndarray:
        """The cells as ROS occupancy values, flat: 100 occupied, 0 free (int8)."""
        return np.where(self.occupied, 100, 0).astype(np.int8).ravel()


def rasterize(static_map: StaticMap, resolution: float = MAP_RESOLUTION, margin: float = MAP_MARGIN) -> Raster:
    """The static map's rectangles (and polygons) rasterized: a cell is occupied where its centre is inside an
    obstacle; the grid reaches ``margin`` beyond the floors."""
    xmin, ymin, xmax, ymax = static_map.bounds
    x0, y0 = xmin - margin, ymin - margin
    width = math.ceil((xmax - xmin + 2 * margin) / resolution)
    height = math.ceil((ymax - ymin + 2 * margin) / resolution)
    cx = x0 + (np.arange(width) + 0.5) * resolution
    cy = y0 + (np.arange(height) + 0.5) * resolution
    occupied = np.zeros((height, width), dtype=bool)
    for k, (x, y, yaw, size_x, size_y) in enumerate(static_map.obstacles):
        reach = math.hypot(size_x, size_y) / 2  # only the cells around the box: a big map has many boxes
        cols = slice(max(0, int((x - reach - x0) / resolution)), min(width, int((x + reach - x0) / resolution) + 1))
        rows = slice(max(0, int((y - reach - y0) / resolution)), min(height, int((y + reach - y0) / resolution) + 1))
        dx, dy = np.meshgrid(cx[cols] - x, cy[rows] - y)
        polygon = static_map.polygons[k] if static_map.polygons else None
        if polygon is not None:  # furniture on a polygon: the cells inside the polygon, not its bounding box
            occupied[rows, cols] |= polygon_distance(dx + x, dy + y, np.asarray(polygon, dtype=float))[1]
            continue
        u = math.cos(yaw) * dx + math.sin(yaw) * dy
        v = -math.sin(yaw) * dx + math.cos(yaw) * dy
        occupied[rows, cols] |= (np.abs(u) <= size_x / 2) & (np.abs(v) <= size_y / 2)
    return Raster(occupied, x0, y0, resolution)


@dataclass(frozen=True, slots=True)
class MapGrid:
    """An occupancy grid as a ROS /map carries it: ``data`` flat int8, row-major from the bottom row, cells of
    ``resolution`` metres from the lower left corner ``(x0, y0)``."""

    data: np.ndarray
    width: int
    height: int
    resolution: float
    x0: float
    y0: float


def map_grid(static_map: StaticMap, occupancy: OccupancyMap | None = None,
             resolution: float = MAP_RESOLUTION) -> MapGrid:
    """What the ROS bridges publish on /map: a map room's own grid (map_server's values, resolution and origin:
    the map the robot team made, unknown cells included), else the static map's rectangles rasterized."""
    if occupancy is not None:
        ox, oy, _ = occupancy.origin
        return MapGrid(occupancy.grid.astype(np.int8).ravel(), occupancy.width, occupancy.height,
                       occupancy.resolution, ox, oy)
    raster = rasterize(static_map, resolution)
    return MapGrid(raster.occupancy(), raster.width, raster.height, resolution, raster.x0, raster.y0)


def static_map_of_grid(data: np.ndarray | list[int], width: int, height: int, resolution: float, origin: Pose2D,
                       robot_size: tuple[float, float], occupied: int = 65) -> StaticMap:
    """An occupancy grid's cells at or above ``occupied`` as rectangles (unknown cells, -1, count as free), merged
    as a map room's obstacles are (``rei.maps.merge_rectangles``: a wall becomes one rectangle, not one per cell).
    ``bounds`` is the grid's extent; ``origin`` its lower left corner and rotation."""
    cells = np.asarray(data, dtype=np.int8).reshape(height, width) >= occupied
    ox, oy, yaw = origin.x, origin.y, origin.yaw
    c, s = math.cos(yaw), math.sin(yaw)
    obstacles = []
    for rect in merge_rectangles(cells):
        lx, ly = (rect.col + rect.cols / 2) * resolution, (rect.row + rect.rows / 2) * resolution
        obstacles.append((ox + c * lx - s * ly, oy + s * lx + c * ly, yaw, rect.cols * resolution,
                          rect.rows * resolution))
    corners = [(ox + c * x - s * y, oy + s * x + c * y) for x in (0.0, width * resolution)
               for y in (0.0, height * resolution)]
    xs, ys = [p[0] for p in corners], [p[1] for p in corners]
    return StaticMap((min(xs), min(ys), max(xs), max(ys)), tuple(obstacles), robot_size)
