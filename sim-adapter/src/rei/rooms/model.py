# SPDX-License-Identifier: EPL-2.0
"""A generated room as plain data: floors on a grid, furniture, humans on lanes, the robot and its goals.

Kept apart from the generator so the rendering (``render``), the geometry (``footprint``) and the navigability
check read one small model, and a test can build a room by hand.
"""

from __future__ import annotations

from dataclasses import dataclass

Cell = tuple[int, int]

#: Footprints (x, y) in metres of the default catalogue's STATIC types
#: (metamodels/src/main/resources/org/rei/catalogue/default.catalogue; a test keeps them equal).
FURNITURE: dict[str, tuple[float, float]] = {
    "Box": (0.5, 0.5),
    "Chair": (0.5, 0.5),
    "Table": (1.2, 0.8),
    "Shelf": (1.0, 0.4),
    "Bin": (0.4, 0.4),
}
#: Edge of a floor block; the generator only writes grid rooms of the default size.
FLOOR = 1.0


@dataclass(frozen=True, slots=True)
class Furniture:
    name: str
    type: str
    cell: Cell
    yaw: int  # 0 or 90 degrees

    def half_extents(self) -> tuple[float, float]:
        """Half the footprint along x and y once turned by ``yaw``."""
        sx, sy = FURNITURE[self.type]
        return (sy / 2, sx / 2) if self.yaw == 90 else (sx / 2, sy / 2)


@dataclass(frozen=True, slots=True)
class Walker:
    """A human walking a straight lane of floors back and forth (``loop``): Catmull-Rom through two points
    has zero knot velocities there, so the spline never leaves the lane."""

    name: str
    start: Cell
    end: Cell
    period: int  # seconds from start to end; the way back takes as long

    def cells(self) -> list[Cell]:
        (x0, y0), (x1, y1) = self.start, self.end
        dx, dy = (x1 > x0) - (x1 < x0), (y1 > y0) - (y1 < y0)
        n = max(abs(x1 - x0), abs(y1 - y0))
        return [(x0 + i * dx, y0 + i * dy) for i in range(n + 1)]


@dataclass(frozen=True, slots=True)
class Goal:
    cell: Cell
    timeout: int  # seconds for the task


@dataclass(frozen=True, slots=True)
class Room:
    testcase: str
    size: str
    density: str
    seed: int
    index: int
    width: int
    height: int
    start: Cell
    goals: tuple[Goal, ...]
    furniture: tuple[Furniture, ...]
    walkers: tuple[Walker, ...]

    @property
    def stem(self) -> str:
        """File name without ``.rei``: sorts by class, seed and index."""
        return f"{self.size}_{self.density}_h{len(self.walkers)}_s{self.seed}_{self.index:02d}"

    def contains(self, cell: Cell) -> bool:
        return 0 <= cell[0] < self.width and 0 <= cell[1] < self.height


def floor_name(cell: Cell) -> str:
    return f"F_{cell[0]}_{cell[1]}"


def floor_centre(cell: Cell) -> tuple[float, float]:
    return ((cell[0] + 0.5) * FLOOR, (cell[1] + 0.5) * FLOOR)
