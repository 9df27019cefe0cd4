# SPDX-License-Identifier: EPL-2.0
"""Procedural rooms (thesis 7.4): valid and navigable by construction, the same for the same seed.

A room is drawn on a grid of 1 m floors. The robot starts on the left wall and its first goal is on the right
wall ("the robot starts from one side of the room to reach the other", thesis 7.4.4); later goals are spread
over the room. Humans walk straight lanes of floors back and forth, or (``reactive``) are people who see the robot,
looping round routes of 2 or 3 stops (rei.rooms.floors.draw_people). Furniture is then placed floor by floor,
and a piece is kept only if the room stays navigable for the reference navigation:

* it stays inside the walls with a gap (walls are 0.1 m thick, centred on the room's edge);
* it does not reach into the start, a goal, a human's lane or a person's stop, nor into a neighbour's furniture;
* every floor without furniture stays reachable from every other (4-neighbours), so each goal is reachable
  from the start and from the previous goal, and no floor is cut off;
* the start and every goal keep at least two neighbouring floors free, so the robot can approach and leave.

Furniture reaches at most 0.1 m into a neighbouring floor (a 1.2 m table), so a lane between two pieces is at
least 0.8 m wide and a lane along a wall 0.75 m: wider than the 0.55 m the reference navigation needs
(twice its 0.24 m inflation radius plus a margin). ``rei.rooms.check`` confirms it with the real planner.
Randomness comes only from ``random.Random`` seeded with a string of the settings, which is stable across
Python versions and platforms.
"""

from __future__ import annotations

import math
import random
from functools import partial

from rei.rooms import floors
from rei.rooms.classes import MAX_HUMANS, RoomClass, room_class
from rei.rooms.model import BEHAVIOURS, DEFAULT_TYPES, MIXED, Cell, Furniture, Goal, Person, Room, RoomTypes

#: Wall half thickness plus the gap kept between furniture and a wall, in metres.
WALL_CLEARANCE = 0.05 + 0.03
#: Smallest gap between two pieces of furniture, and how close one may come to a reserved floor's edge.
GAP = 0.05
MAX_ATTEMPTS = 200

class GenerationError(RuntimeError):
    """No room of these settings could be drawn (only possible for settings beyond the documented ones)."""


def check_reactive(reactive: str | None) -> None:
    """``reactive``: the behaviour of generated people who see the robot (or ``mixed``), None for humans on lanes."""
    if reactive is not None and reactive not in (*BEHAVIOURS, MIXED):
        raise ValueError(f"the people's behaviour must be one of {', '.join((*BEHAVIOURS, MIXED))}, got {reactive!r}")


def generate_room(size: str, density: str | None = None, humans: int | None = None, seed: int = 0,
                  index: int = 1, types: RoomTypes = DEFAULT_TYPES, reactive: str | None = None) -> Room:
    """Room ``index`` (from 1) of ``rei gen-rooms --size SIZE --density D --humans N --seed SEED``; ``types``:
    what it is furnished from (``--catalogue``); ``reactive``: the humans are people who see the robot with this
    behaviour (or ``mixed``; ``--people reactive --behaviour B``), None: humans on lanes."""
    check_reactive(reactive)
    cls = room_class(size)
    density = density or cls.default_density
    humans = cls.default_humans if humans is None else humans
    cls.objects(density)  # checks the density
    if not 0 <= humans <= MAX_HUMANS[size]:
        raise ValueError(f"a {size} room holds 0 to {MAX_HUMANS[size]} humans, got {humans}")
    if seed < 0 or index < 1:
        raise ValueError(f"seed must be >= 0 and index >= 1, got {seed}, {index}")
    # people who see the robot draw from a sequence of their own (the same for every behaviour): rooms with humans
    # on lanes stay what they were
    people = "" if reactive is None else "/people"
    for attempt in range(MAX_ATTEMPTS):
        rng = random.Random(f"rei-rooms/1/{size}/{density}/{humans}/{seed}/{index}/{attempt}{people}")
        room = _attempt(rng, cls, density, humans, seed, index, types, reactive)
        if room is not None:
            return room
    raise GenerationError(f"no {size} {density} room with {humans} humans for seed {seed} index {index} "
                          f"after {MAX_ATTEMPTS} attempts")


def generate_rooms(size: str, density: str | None = None, humans: int | None = None, seed: int = 0,
                   count: int = 1, types: RoomTypes = DEFAULT_TYPES, reactive: str | None = None) -> list[Room]:
    return [generate_room(size, density, humans, seed, i, types, reactive) for i in range(1, count + 1)]


def _attempt(rng: random.Random, cls: RoomClass, density: str, humans: int, seed: int, index: int,
             types: RoomTypes, reactive: str | None = None) -> Room | None:
    w, h = cls.width, cls.height
    room_floors = floors.grid(w, h)
    start = (0, rng.randrange(h))
    goals = _goals(rng, cls, start)
    if reactive is None:
        walkers = floors.draw_walkers(rng, humans, start, goals, partial(_lane, cls), room_floors, floor_size=1.0,
                                      tries=100)
        people: list[Person] | None = []
    else:
        walkers = []
        people = floors.draw_people(rng, humans, start, goals, room_floors, reactive, tries=100)
    if walkers is None or people is None:
        return None
    robot_cells = {start, *goals}
    reserved = robot_cells | {c for walker in walkers for c in walker.cells()} | {
        c for person in people for c in person.cells()}
    placed: dict[Cell, Furniture] = {}
    wanted = cls.objects(density)
    counters: dict[str, int] = {}
    candidates = [(x, y) for x in range(w) for y in range(h) if (x, y) not in reserved]
    rng.shuffle(candidates)
    for cell in candidates:
        if len(placed) == wanted:
            break
        for _ in range(3):
            kind = rng.choices(list(types.weights), weights=list(types.weights.values()))[0]
            sx, sy = types.furniture[kind]
            item = Furniture("", kind, cell, rng.choice((0, 90)) if sx != sy else 0, (sx, sy))
            if _fits(item, placed, reserved, w, h) and floors.still_navigable(cell, placed, robot_cells, room_floors):
                counters[kind] = counters.get(kind, 0) + 1
                placed[cell] = Furniture(f"{kind.lower()}{counters[kind]}", kind, cell, item.yaw, item.size)
                break
    if len(placed) < wanted:
        return None
    name = f"{cls.size.capitalize()}{density.capitalize()}_{seed}_{index}"
    timeouts = [_timeout(a, b) for a, b in zip((start, *goals), goals, strict=False)]
    return Room(name, cls.size, density, seed, index, w, h, start,
                tuple(Goal(c, t) for c, t in zip(goals, timeouts, strict=True)),
                tuple(placed.values()), tuple(walkers), types, people=tuple(people), reactive=reactive)


def _goals(rng: random.Random, cls: RoomClass, start: Cell) -> list[Cell]:
    """First goal on the far wall, then goals at least a third of the room's perimeter apart."""
    goals = [(cls.width - 1, rng.randrange(cls.height))]
    far = (cls.width + cls.height) // 3
    cells = [(x, y) for x in range(cls.width) for y in range(cls.height)]
    while len(goals) < cls.goals:
        options = [c for c in cells if c != start and c not in goals and _manhattan(c, goals[-1]) >= far]
        goals.append(rng.choice(options))
    return goals


def _lane(cls: RoomClass, rng: random.Random) -> tuple[Cell, Cell]:
    """A walker's lane: 3 to 6 floors along a row or a column of the room, walked from either end."""
    horizontal = rng.random() < 0.5
    span = cls.width if horizontal else cls.height
    length = rng.randint(3, min(6, span))
    a = rng.randrange(span - length + 1)
    b = rng.randrange(cls.height if horizontal else cls.width)
    first, last = ((a, b), (a + length - 1, b)) if horizontal else ((b, a), (b, a + length - 1))
    return (last, first) if rng.random() < 0.5 else (first, last)


def _fits(item: Furniture, placed: dict[Cell, Furniture], reserved: set[Cell], w: int, h: int) -> bool:
    """Inside the walls, clear of reserved floors and of the furniture around (see the module doc)."""
    box = _rect(item.cell, item.half_extents())
    if box[0] < WALL_CLEARANCE or box[1] < WALL_CLEARANCE or box[2] > w - WALL_CLEARANCE or box[3] > h - WALL_CLEARANCE:
        return False
    x, y = item.cell
    for cell in ((x + dx, y + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy):
        other = placed.get(cell)
        if other is not None and rect_gap(box, _rect(cell, other.half_extents())) < GAP:
            return False
        if cell in reserved and rect_gap(box, _rect(cell, (0.5, 0.5))) < GAP:
            return False
    return True


def _rect(cell: Cell, half: tuple[float, float]) -> tuple[float, float, float, float]:
    cx, cy = cell[0] + 0.5, cell[1] + 0.5
    return (cx - half[0], cy - half[1], cx + half[0], cy + half[1])


def rect_gap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> float:
    """Distance between two axis-aligned rectangles; <= 0 when they touch or overlap."""
    dx, dy = max(b[0] - a[2], a[0] - b[2]), max(b[1] - a[3], a[1] - b[3])
    return math.hypot(dx, dy) if dx > 0 and dy > 0 else max(dx, dy)


def _manhattan(a: Cell, b: Cell) -> int:
    return abs(a[0] - b[0]) + abs(a[1] - b[1])


def _timeout(a: Cell, b: Cell) -> int:
    """Time for a task: 30 s plus 6 s per metre of the way on the grid, rounded up to 5 s."""
    return int(5 * math.ceil((30 + 6 * _manhattan(a, b)) / 5))

