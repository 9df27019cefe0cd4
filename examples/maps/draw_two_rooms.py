# SPDX-License-Identifier: EPL-2.0
"""Draws ``two_rooms.pgm``, the example's occupancy map: two rooms joined by a corridor, 10 x 6 m at 0.05 m.

    python3 examples/maps/draw_two_rooms.py

The image is in ``map_server``'s trinary shades: 254 free, 0 occupied, 205 unknown (the space between the rooms,
never seen by the robot that "mapped" them). Plain Python, so the file can be redrawn anywhere; the committed PGM
is this script's output.
"""

from __future__ import annotations

from pathlib import Path

RESOLUTION = 0.05
WIDTH, HEIGHT = 200, 120  # cells: 10 x 6 m
FREE, OCCUPIED, UNKNOWN = 254, 0, 205
WALL = 3  # cells: 0.15 m thick walls


def cells(metres: float) -> int:
    return round(metres / RESOLUTION)


def draw() -> list[list[int]]:
    """Rows from the bottom (y = 0) up; flipped into image order when written."""
    grid = [[UNKNOWN] * WIDTH for _ in range(HEIGHT)]

    def fill(x0: float, y0: float, x1: float, y1: float, value: int) -> None:
        for row in range(cells(y0), cells(y1)):
            for col in range(cells(x0), cells(x1)):
                grid[row][col] = value

    for x0, x1 in ((0.0, 4.0), (6.0, 10.0)):  # the two rooms, walled
        fill(x0, 0.0, x1, 6.0, OCCUPIED)
        fill(x0 + WALL * RESOLUTION, WALL * RESOLUTION, x1 - WALL * RESOLUTION, 6.0 - WALL * RESOLUTION, FREE)
    fill(3.5, 2.35, 6.5, 3.65, OCCUPIED)  # the corridor's walls ...
    fill(3.5, 2.5, 6.5, 3.5, FREE)  # ... and its 1 m wide floor, through both rooms' walls
    fill(7.5, 4.0, 8.0, 4.5, OCCUPIED)  # a pillar in the right room
    fill(1.0, 0.15, 1.3, 1.5, OCCUPIED)  # a partition in the left room
    return grid


def main() -> None:
    grid = draw()
    header = f"P5\n# two rooms and a corridor, {RESOLUTION} m per cell\n{WIDTH} {HEIGHT}\n255\n".encode("ascii")
    body = bytes(value for row in reversed(grid) for value in row)
    (Path(__file__).resolve().parent / "two_rooms.pgm").write_bytes(header + body)


if __name__ == "__main__":
    main()
