# SPDX-License-Identifier: EPL-2.0
"""A map room's grid as a small greyscale PNG, for the pages that draw the room (the report, the live view, the
room editor): free cells light, occupied black, unknown grey, as ``map_server``'s own images shade them.

A large map is shrunk by a whole factor so that neither side exceeds ``max_side`` pixels; a pixel of the shrunk
image shows the most obstructive of its cells (occupied over unknown over free), so a thin wall never vanishes.
The PNG's first row is the map's top (image order): placed over ``extent``, it needs no flip.
"""

from __future__ import annotations

import base64
import io
import math
from dataclasses import dataclass

import numpy as np
import png

from rei.maps.occupancy import OCCUPIED, UNKNOWN, OccupancyMap

#: Longest side of the picture, pixels: a 30 x 50 m map at 3 cm (1,000 x 1,667 cells) becomes 600 x 1,000.
MAX_SIDE = 1024
#: Shades of the picture: map_server's (map_saver writes free 254, occupied 0, unknown 205).
FREE_SHADE, OCCUPIED_SHADE, UNKNOWN_SHADE = 254, 0, 205


@dataclass(frozen=True, slots=True)
class MapPicture:
    """``png``: the picture; it covers ``extent`` ``(xmin, ymin, xmax, ymax)`` in metres, ``factor`` cells a side
    per pixel."""

    png: bytes
    width: int
    height: int
    factor: int
    extent: tuple[float, float, float, float]

    def data_uri(self) -> str:
        return "data:image/png;base64," + base64.b64encode(self.png).decode("ascii")


def map_picture(occupancy: OccupancyMap, max_side: int = MAX_SIDE) -> MapPicture:
    """The grid as a greyscale PNG of at most ``max_side`` pixels a side."""
    grid = occupancy.grid.astype(np.int16)
    # severity: free 0..99 (scale mode's grey levels keep their order), unknown above them, occupied on top
    severity = np.where(grid == UNKNOWN, OCCUPIED, np.where(grid == OCCUPIED, OCCUPIED + 1, grid))
    factor = max(1, math.ceil(max(occupancy.width, occupancy.height) / max_side))
    if factor > 1:
        rows, cols = math.ceil(occupancy.height / factor), math.ceil(occupancy.width / factor)
        padded = np.zeros((rows * factor, cols * factor), dtype=np.int16)  # padding counts as free
        padded[:occupancy.height, :occupancy.width] = severity
        severity = padded.reshape(rows, factor, cols, factor).max(axis=(1, 3))
    shade = np.where(severity == OCCUPIED + 1, OCCUPIED_SHADE,
                     np.where(severity == OCCUPIED, UNKNOWN_SHADE,
                              np.rint(FREE_SHADE - severity * FREE_SHADE / OCCUPIED))).astype(np.uint8)
    image = shade[::-1]  # row 0 of the grid is the bottom: the picture's first row is the top
    out = io.BytesIO()
    png.Writer(image.shape[1], image.shape[0], greyscale=True, bitdepth=8, compression=9).write(out, image.tolist())
    ox, oy, _ = occupancy.origin
    # a shrunk picture's padding (right and top) reaches beyond the map: its extent grows with it, so the cells
    # stay in place
    side = factor * occupancy.resolution
    return MapPicture(out.getvalue(), int(image.shape[1]), int(image.shape[0]), factor,
                      (ox, oy, ox + image.shape[1] * side, oy + image.shape[0] * side))
