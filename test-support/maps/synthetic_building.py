# SPDX-License-Identifier: EPL-2.0
"""A synthetic occupancy map of a building, for the tests and benchmarks of large map rooms (issue 31).

    .venv/bin/python test-support/maps/synthetic_building.py -o DIR [--seed N]

writes ``DIR/building.yaml`` and ``DIR/building.pgm``: a 30 x 50 m floor of a building at 0.03 m per cell
(1000 x 1667 cells, 1.7 million), as a robot's SLAM would map it: outer walls, a corridor 4.2 m wide along its
length, eight rooms on each side with a door onto the corridor (and every other one a door to its neighbour),
furniture in the rooms, walls whose faces are not straight (a mapped wall has bumps a few cells deep) and a few
specks of noise, unknown space around the building. The map is drawn at test time into a temporary folder; it
is never committed (1.7 MB). Everything is seeded: the same seed draws the same map.

Coordinates are the map's: metres from its origin, which is ``ORIGIN`` (not 0, 0, as real maps are not), so
world x = ORIGIN[0] + metres along the map's width.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

RESOLUTION = 0.03
WIDTH_M, HEIGHT_M = 30.0, 50.0
COLS, ROWS = round(WIDTH_M / RESOLUTION), round(HEIGHT_M / RESOLUTION)  # 1000 x 1667
ORIGIN = (-4.5, -7.5)
FREE, OCCUPIED, UNKNOWN = 254, 0, 205
MARGIN = 0.6  # m of unknown space around the outer walls
OUTER = 0.21  # m, outer walls
INNER = 0.12  # m, walls between rooms
CORRIDOR = (12.9, 17.1)  # m along the width: the corridor's free span (four free 1 m blocks wide)
ROOMS_PER_SIDE = 8
DOOR = 1.1  # m
CORRIDOR_GOALS = ((15.0, 3.0), (15.0, 46.0))
"""Two free points (map metres) in the corridor, 43 m apart: a mission across the building."""


def cells(metres: float) -> int:
    return round(metres / RESOLUTION)


def draw(seed: int = 0) -> np.ndarray:
    """The image as map_server reads it: ``(ROWS, COLS)`` grey values, row 0 the bottom row of the map."""
    rng = np.random.default_rng(seed)
    grid = np.full((ROWS, COLS), UNKNOWN, dtype=np.uint8)

    def fill(x0: float, y0: float, x1: float, y1: float, value: int) -> None:
        grid[cells(y0):cells(y1), cells(x0):cells(x1)] = value

    inside = (MARGIN, MARGIN, WIDTH_M - MARGIN, HEIGHT_M - MARGIN)
    fill(*inside, OCCUPIED)
    x0, y0, x1, y1 = inside[0] + OUTER, inside[1] + OUTER, inside[2] - OUTER, inside[3] - OUTER
    fill(x0, y0, x1, y1, FREE)
    # the corridor's two walls, the rooms between them and the outer walls
    left, right = CORRIDOR
    fill(left - INNER, y0, left, y1, OCCUPIED)
    fill(right, y0, right + INNER, y1, OCCUPIED)
    depth = (y1 - y0) / ROOMS_PER_SIDE
    for k in range(ROOMS_PER_SIDE):
        bottom = y0 + k * depth
        if k:
            fill(x0, bottom - INNER / 2, left, bottom + INNER / 2, OCCUPIED)
            fill(right, bottom - INNER / 2, x1, bottom + INNER / 2, OCCUPIED)
        door = bottom + depth / 2 - DOOR / 2 + rng.uniform(-1.0, 1.0)
        fill(left - INNER, door, left, door + DOOR, FREE)
        fill(right, door, right + INNER, door + DOOR, FREE)
        if k and k % 2 == 0:  # a door to the room below, on both sides
            for a, b in ((x0, left), (right, x1)):
                at = rng.uniform(a + 1.0, b - 1.0 - DOOR)
                fill(at, bottom - INNER, at + DOOR, bottom + INNER, FREE)
        for a, b in ((x0, left - INNER), (right + INNER, x1)):
            _furnish(grid, rng, a, bottom + INNER, b, bottom + depth - INNER)
    _rough_faces(grid, rng)
    free = grid == FREE
    specks = free & (rng.random(grid.shape) < 1e-5)
    grid[specks] = OCCUPIED
    return grid


def _furnish(grid: np.ndarray, rng: np.random.Generator, x0: float, y0: float, x1: float, y1: float) -> None:
    """A few desks, shelves and pillars, kept 0.9 m from the room's walls so the doors stay reachable."""
    for _ in range(int(rng.integers(2, 5))):
        w, h = rng.uniform(0.4, 1.6), rng.uniform(0.4, 0.9)
        if rng.random() < 0.5:
            w, h = h, w
        cx, cy = rng.uniform(x0 + 0.9 + w / 2, x1 - 0.9 - w / 2), rng.uniform(y0 + 0.9 + h / 2, y1 - 0.9 - h / 2)
        grid[cells(cy - h / 2):cells(cy + h / 2), cells(cx - w / 2):cells(cx + w / 2)] = OCCUPIED


def _rough_faces(grid: np.ndarray, rng: np.random.Generator) -> None:
    """Bumps of one to three cells on the free side of wall faces, where a scan saw a wall a little off."""
    occupied = grid == OCCUPIED
    free = grid == FREE
    face = free & (np.roll(occupied, 1, 0) | np.roll(occupied, -1, 0) | np.roll(occupied, 1, 1)
                   | np.roll(occupied, -1, 1))
    rows, cols = np.nonzero(face & (rng.random(grid.shape) < 0.08))
    for r, c, length in zip(rows.tolist(), cols.tolist(), rng.integers(1, 4, len(rows)).tolist(), strict=True):
        if occupied[r, c - 1] or occupied[r, c + 1]:  # a vertical face: the bump runs along it
            grid[r:r + length, c] = OCCUPIED
        else:
            grid[r, c:c + length] = OCCUPIED


def write(folder: Path, seed: int = 0, name: str = "building") -> Path:
    """Draw the map and write ``folder/name.pgm`` and ``folder/name.yaml``; the YAML's path."""
    folder.mkdir(parents=True, exist_ok=True)
    grid = draw(seed)
    header = f"P5\n# synthetic building, seed {seed}\n{COLS} {ROWS}\n255\n".encode("ascii")
    (folder / f"{name}.pgm").write_bytes(header + np.ascontiguousarray(grid[::-1]).tobytes())
    yaml = folder / f"{name}.yaml"
    yaml.write_text(f"image: {name}.pgm\nresolution: {RESOLUTION}\norigin: [{ORIGIN[0]}, {ORIGIN[1]}, 0.0]\n"
                    "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n", encoding="utf-8")
    return yaml


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-o", "--output", type=Path, required=True, help="folder to write building.yaml/.pgm in")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    print(write(args.output, args.seed))


if __name__ == "__main__":
    main()
