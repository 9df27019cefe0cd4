# SPDX-License-Identifier: EPL-2.0
"""Occupancy maps (ROS ``map_server`` format) as rooms: ``load_map`` reads the YAML and its image into the grid
``map_server`` publishes (at most ``MAX_CELLS`` cells); ``merge_rectangles`` and ``floor_blocks`` (at most
``MAX_BLOCKS`` blocks) turn it into obstacles and free floors,
``map_picture`` into the PNG the pages draw under the floors. A bottom
layer of the package, beside ``rei.geometry``: it imports nothing else of ``rei``.
"""

from __future__ import annotations

from rei.maps.blocks import (
    MAX_BLOCKS,
    CellRect,
    FloorBlocks,
    block_grid,
    box_of,
    floor_blocks,
    merge_rectangles,
    obstacle_mask,
)
from rei.maps.occupancy import FREE, MAX_CELLS, MODES, OCCUPIED, UNKNOWN, MapError, OccupancyMap, load_map
from rei.maps.picture import MapPicture, map_picture

__all__ = ["FREE", "MAX_BLOCKS", "MAX_CELLS", "MODES", "OCCUPIED", "UNKNOWN", "CellRect", "FloorBlocks", "MapError",
           "MapPicture", "OccupancyMap", "block_grid", "box_of", "floor_blocks", "load_map", "map_picture",
           "merge_rectangles", "obstacle_mask"]
