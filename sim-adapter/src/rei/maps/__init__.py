# SPDX-License-Identifier: EPL-2.0
"""Occupancy maps (ROS ``map_server`` format) as rooms: ``load_map`` reads the YAML and its image into the grid
``map_server`` publishes; ``merge_rectangles`` and ``floor_blocks`` turn it into obstacles and free floors,
``map_picture`` into the PNG the pages draw under the floors. A bottom
layer of the package, beside ``rei.geometry``: it imports nothing else of ``rei``.
"""

from __future__ import annotations

from rei.maps.blocks import CellRect, FloorBlocks, box_of, floor_blocks, merge_rectangles, obstacle_mask
from rei.maps.occupancy import FREE, MODES, OCCUPIED, UNKNOWN, MapError, OccupancyMap, load_map
from rei.maps.picture import MapPicture, map_picture

__all__ = ["FREE", "MODES", "OCCUPIED", "UNKNOWN", "CellRect", "FloorBlocks", "MapError", "MapPicture",
           "OccupancyMap", "box_of", "floor_blocks", "load_map", "map_picture", "merge_rectangles",
           "obstacle_mask"]
