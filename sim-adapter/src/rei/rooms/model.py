# SPDX-License-Identifier: EPL-2.0
"""A generated room as plain data: floors on a grid, furniture, humans on lanes (or people who see the robot on
routes), the robot and its goals.

Kept apart from the generator so the rendering (``render``), the geometry (``footprint``) and the navigability
check read one small model, and a test can build a room by hand.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from rei.maps import OccupancyMap

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
#: Relative frequency of each default furniture type.
WEIGHTS: dict[str, int] = {"Box": 3, "Chair": 3, "Table": 2, "Shelf": 2, "Bin": 2}
#: The default catalogue's robot type and its footprint.
WAFFLE = ("Waffle", (0.281, 0.306))
#: Edge of a floor block; the generator only writes grid rooms of the default size.
FLOOR = 1.0
#: The largest footprint edge a piece of furniture may have: it reaches at most 0.1 m into a neighbouring floor,
#: which keeps every lane between two pieces wide enough for the reference navigation (rei.rooms.generator).
MAX_FURNITURE = 1.2


@dataclass(frozen=True, slots=True)
class RoomTypes:
    """What a room is furnished from: furniture types with their footprints (x, y) and relative frequencies,
    the robot's type and footprint, and the user catalogue that declares them (None: the default catalogue)."""

    furniture: Mapping[str, tuple[float, float]] = field(default_factory=lambda: dict(FURNITURE))
    weights: Mapping[str, int] = field(default_factory=lambda: dict(WEIGHTS))
    robot: str = WAFFLE[0]
    robot_size: tuple[float, float] = WAFFLE[1]
    catalogue: Path | None = None

    def __hash__(self) -> int:  # the mappings are never changed after construction
        return hash((tuple(self.furniture.items()), tuple(self.weights.items()), self.robot, self.robot_size,
                     self.catalogue))

    def __post_init__(self) -> None:
        if not self.furniture or set(self.weights) != set(self.furniture):
            raise ValueError("room types need furniture, each with a weight")
        for name, (sx, sy) in self.furniture.items():
            if not (0 < sx <= MAX_FURNITURE and 0 < sy <= MAX_FURNITURE):
                raise ValueError(f"type {name} ({sx:g} x {sy:g} m) does not fit a generated room's floor: "
                                 f"furniture of at most {MAX_FURNITURE:g} x {MAX_FURNITURE:g} m is placed")


DEFAULT_TYPES = RoomTypes()


@dataclass(frozen=True, slots=True)
class Furniture:
    name: str
    type: str
    cell: Cell
    yaw: int  # 0 or 90 degrees
    size: tuple[float, float]  # the type's footprint (x, y)

    def half_extents(self) -> tuple[float, float]:
        """Half the footprint along x and y once turned by ``yaw``."""
        sx, sy = self.size
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


#: What generated people who see the robot may do: one of the language's behaviours, or ``mixed`` (each person's
#: drawn from the seed).
BEHAVIOURS = ("avoids", "ignores", "curious", "scared", "blocks")
MIXED = "mixed"


@dataclass(frozen=True, slots=True)
class Person:
    """A person who sees the robot (``human NAME route [...]``): walks its stops in order and round again (``loop``),
    waiting ``wait`` seconds on arriving at each, at ``speed`` m/s from ``start`` seconds on, reacting to the robot
    as ``behaviour`` says; a pedestrian model finds the way between its stops (docs/people.md)."""

    name: str
    stops: tuple[tuple[Cell, int], ...]  # (floor, wait in s)
    speed: float
    start: int
    behaviour: str

    def cells(self) -> list[Cell]:
        return [cell for cell, _ in self.stops]


@dataclass(frozen=True, slots=True)
class Goal:
    cell: Cell
    timeout: int  # seconds for the task


@dataclass(frozen=True, slots=True)
class MapSite:
    """A real building to furnish (``rei gen-rooms --map``): an occupancy map and its free floor blocks of
    ``floor_size`` metres (rei.maps.floor_blocks), ``F_x_y`` counted from the map's origin."""

    yaml: Path
    floor_size: float
    unknown_free: bool
    free: frozenset[Cell]
    occupancy: OccupancyMap = field(compare=False, repr=False)

    def centre(self, cell: Cell) -> tuple[float, float]:
        ox, oy, _ = self.occupancy.origin
        return (ox + (cell[0] + 0.5) * self.floor_size, oy + (cell[1] + 0.5) * self.floor_size)


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
    types: RoomTypes = DEFAULT_TYPES
    site: MapSite | None = None  # a room on an occupancy map; None: a grid of 1 m floors with walls around
    #: people who see the robot instead of humans on lanes, and their behaviour (a BEHAVIOURS or MIXED) when the
    #: room has them (None: humans on lanes, ``walkers``)
    people: tuple[Person, ...] = ()
    reactive: str | None = None

    @property
    def humans(self) -> int:
        return len(self.walkers) + len(self.people)

    @property
    def stem(self) -> str:
        """File name without ``.rei``: sorts by class (or map), seed and index; ``h2`` humans on lanes, ``p2``
        people who see the robot (``p2-curious`` when they do not just avoid it)."""
        kind = self.size if self.site is None else self.site.yaml.stem
        if self.reactive is None:
            humans = f"h{len(self.walkers)}"
        else:
            humans = f"p{len(self.people)}" + ("" if self.reactive == "avoids" else f"-{self.reactive}")
        return f"{kind}_{self.density}_{humans}_s{self.seed}_{self.index:02d}"

    def contains(self, cell: Cell) -> bool:
        if self.site is not None:
            return cell in self.site.free
        return 0 <= cell[0] < self.width and 0 <= cell[1] < self.height

    def centre(self, cell: Cell) -> tuple[float, float]:
        """The floor's centre in the world, m."""
        return floor_centre(cell) if self.site is None else self.site.centre(cell)


def floor_name(cell: Cell) -> str:
    return f"F_{cell[0]}_{cell[1]}"


def floor_centre(cell: Cell) -> tuple[float, float]:
    return ((cell[0] + 0.5) * FLOOR, (cell[1] + 0.5) * FLOOR)
