# SPDX-License-Identifier: EPL-2.0
"""The static map as a raster and back (rei.sut.rasterize): what a node taking /map plans around."""

from __future__ import annotations

import math

import numpy as np

from rei.geometry import Pose2D
from rei.sut.api import StaticMap
from rei.sut.rasterize import rasterize, static_map_of_grid

BOXES = ((1.0, 1.0, 0.0, 0.5, 0.3), (2.5, 1.5, 0.0, 1.0, 0.2), (0.0, 1.0, 0.0, 0.1, 2.0), (2.0, 0.5, 0.0, 0.3, 0.3))
MAP = StaticMap((0.0, 0.0, 3.0, 2.0), BOXES, (0.3, 0.3))


def test_a_grid_back_to_rectangles_rasterizes_to_the_same_cells_with_far_fewer_rectangles() -> None:
    raster = rasterize(MAP)
    back = static_map_of_grid(raster.occupancy(), raster.width, raster.height, raster.resolution,
                              Pose2D(raster.x0, raster.y0, 0.0), MAP.robot_size)
    assert np.array_equal(rasterize(back, margin=0.0).occupied, raster.occupied)
    assert len(back.obstacles) <= 3 * len(BOXES)  # runs merged across rows, not one box per cell
    assert back.bounds == (raster.x0, raster.y0, raster.x0 + raster.width * raster.resolution,
                           raster.y0 + raster.height * raster.resolution)


def test_unknown_cells_are_free_and_a_rotated_origin_turns_the_rectangles() -> None:
    data = np.array([[-1, 100], [0, 0]], dtype=np.int8)  # one occupied cell: row 0, column 1
    grid = static_map_of_grid(data.ravel(), 2, 2, 1.0, Pose2D(10.0, 0.0, math.pi / 2), (0.3, 0.3))
    ((x, y, yaw, size_x, size_y),) = grid.obstacles
    assert (round(x, 9), round(y, 9), yaw, size_x, size_y) == (9.5, 1.5, math.pi / 2, 1.0, 1.0)
