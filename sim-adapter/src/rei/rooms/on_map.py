# SPDX-License-Identifier: EPL-2.0
"""Generated rooms in a real building (``rei gen-rooms --map FILE.yaml``): an occupancy map furnished with
furniture, humans and goals on its free floors, navigable by the reference navigation, the same for the same
seed.

The floors are the map's free blocks of ``floor_size`` metres (``rei.maps.floor_blocks``, as the language reads
an ``occupancy`` room); everything is placed in the largest area of floors connected side by side. The robot
starts on a random floor, its first goal is among the floors farthest from it (counted along the floors), the
next at least a third of that far from the one before. Humans walk straight lanes of 3 to 6 floors, or are people
who see the robot on routes of 2 or 3 stops (``reactive``, rei.rooms.floors.draw_people). Furniture
is placed floor by floor, as in ``rei.rooms.generator``, and a piece is kept only if:

* it is a type whose footprint is at most 1.2 floors a side (it reaches at most a tenth of a floor into the
  next) and its footprint keeps a gap from every obstacle cell of the map;
* it keeps 0.6 m from any other piece (a lane the reference navigation can take: twice its 0.24 m inflation
  radius and a margin) and a gap from the start, the goals, the humans' lanes and the people's stops;
* every floor without furniture stays reachable from every other, and the start and the goals keep two free
  neighbours.

A map's passages are as narrow as the building's, so floor-level rules cannot promise a path: each drawn room
is checked with the reference planner (``rei.rooms.check``) and drawn again when a leg has none.
"""

from __future__ import annotations

import math
import random
from functools import partial
from pathlib import Path

import numpy as np

from rei.maps import MapError, floor_blocks, load_map, obstacle_mask
from rei.rooms.floors import (
    SIDES,
    component,
    distances,
    draw_people,
    draw_walkers,
    neighbours,
    still_navigable,
)
from rei.rooms.generator import GAP, GenerationError, check_reactive, rect_gap
from rei.rooms.model import DEFAULT_TYPES, Cell, Furniture, Goal, MapSite, Person, Room, RoomTypes

#: Furnished share of the floors per density: the share of the generated grid rooms (thesis 7.4's classes).
SHARES = {"dense": 0.25, "sparse": 0.12}
DEFAULT_DENSITY = "sparse"
DEFAULT_HUMANS = 1
GOALS = 2
#: Smallest gap between two pieces of furniture on a map, m: a lane the reference navigation can take.
LANE = 0.6
#: Gap between a piece of furniture and the map's obstacle cells, m.
WALL_GAP = 0.03
MAX_ATTEMPTS = 40
#: Furniture edge allowed per floor edge (as MAX_FURNITURE / FLOOR in generated grid rooms).
REACH = 1.2
#: The radius (m) of a generated person (the default Human's), and the room it needs beyond it to stand.
PERSON_RADIUS = 0.25
PERSON_ROOM = 0.05


def load_site(yaml: Path, floor_size: float = 1.0, unknown_free: bool = False) -> MapSite:
    """The map's free floor blocks; raises ``MapError`` for a map that can not be read, ``ValueError`` for a
    floor size that leaves no free floor or cuts the map into more than ``rei.maps.MAX_BLOCKS`` blocks."""
    occupancy = load_map(yaml)
    try:
        blocks = floor_blocks(occupancy, floor_size, unknown_free)
    except ValueError as error:  # a floor size that cuts the map into too many blocks
        raise ValueError(f"{yaml}: {error}") from None
    ys, xs = np.nonzero(blocks.free)
    free = frozenset(zip(xs.tolist(), ys.tolist(), strict=True))
    if not free:
        raise ValueError(f"{yaml}: no free floor of {floor_size:g} m in the map (every block touches an obstacle"
                         f"{'' if unknown_free else ' or an unknown cell'})")
    return MapSite(yaml=Path(yaml), floor_size=floor_size, unknown_free=unknown_free, free=free, occupancy=occupancy)


def generate_map_room(site: MapSite, density: str | None = None, humans: int | None = None, seed: int = 0,
                      index: int = 1, types: RoomTypes = DEFAULT_TYPES, check: bool = True,
                      reactive: str | None = None) -> Room:
    """Room ``index`` (from 1) of ``rei gen-rooms --map ...``; ``check``: draw again until the reference planner
    finds every leg (``--no-check``: the first room drawn); ``reactive``: people who see the robot with this
    behaviour (or ``mixed``) instead of humans on lanes."""
    from rei.rooms.check import unplannable_legs

    check_reactive(reactive)
    density = density or DEFAULT_DENSITY
    if density not in SHARES:
        raise ValueError(f"density must be one of {', '.join(SHARES)}, got {density!r}")
    humans = DEFAULT_HUMANS if humans is None else humans
    if humans < 0:
        raise ValueError(f"humans must be >= 0, got {humans}")
    if seed < 0 or index < 1:
        raise ValueError(f"seed must be >= 0 and index >= 1, got {seed}, {index}")
    furniture = {name: size for name, size in types.furniture.items()
                 if max(size) <= REACH * site.floor_size}
    if not furniture:
        raise ValueError(f"no furniture type fits a floor of {site.floor_size:g} m (at most "
                         f"{REACH * site.floor_size:g} m a side): choose larger floors")
    area = _largest_area(site.free)
    if len(area) < GOALS + 1:
        raise ValueError(f"{site.yaml}: its largest area of connected free floors has {len(area)} floor(s), too "
                         "few for a start and two goals")
    problems: list[str] = []
    drawn = 0
    for attempt in range(MAX_ATTEMPTS):
        rng = random.Random(f"rei-rooms/map/1/{site.yaml.name}/{site.floor_size}/{density}/{humans}/{seed}/{index}/"
                            f"{attempt}{'' if reactive is None else '/people'}")
        room = _attempt(rng, site, area, furniture, density, humans, seed, index, types, reactive)
        if room is None:
            continue
        drawn += 1
        problems = unplannable_legs(room) if check else []
        if not problems:
            return room
    what = (f"{drawn} drawn, none navigable (last: {problems[0]})" if drawn else
            f"the start, goals and {humans} {'people' if reactive else 'humans'}' "
            f"{'routes' if reactive else 'lanes'} never fit in its {len(area)} connected floors of "
            f"{site.floor_size:g} m")
    raise GenerationError(f"no {density} room with {humans} humans on {site.yaml.name} for seed {seed} index {index} "
                          f"in {MAX_ATTEMPTS} attempts: {what}")


def _ring(cell: Cell) -> list[Cell]:
    """The eight floors round a floor."""
    return [(cell[0] + dx, cell[1] + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy]


def generate_map_rooms(site: MapSite, density: str | None = None, humans: int | None = None, seed: int = 0,
                       count: int = 1, types: RoomTypes = DEFAULT_TYPES, check: bool = True,
                       reactive: str | None = None) -> list[Room]:
    return [generate_map_room(site, density, humans, seed, i, types, check, reactive) for i in range(1, count + 1)]


def _attempt(rng: random.Random, site: MapSite, area: list[Cell], furniture: dict[str, tuple[float, float]],
             density: str, humans: int, seed: int, index: int, types: RoomTypes,
             reactive: str | None = None) -> Room | None:
    floors = set(area)
    roomy = [c for c in area if sum(n in floors for n in neighbours(c)) >= 2]
    if not roomy:
        return None
    start = rng.choice(roomy)
    goals = _goals(rng, floors, roomy, start)
    if goals is None:
        return None
    if reactive is None:
        walkers = draw_walkers(rng, humans, start, goals, partial(_lane, sorted(floors)), floors,
                               floor_size=site.floor_size, tries=200)
        people: list[Person] | None = []
    else:
        walkers = []
        # floors smaller than a body and its room (0.5 m): the people model refuses a person 0.25 m from a wall
        # block or from another person, so a stop has free floors all round, none of them another's stop
        small = site.floor_size < 2 * (PERSON_RADIUS + PERSON_ROOM)
        roomy = {c for c in floors if all(n in floors for n in _ring(c))} if small else None
        people = draw_people(rng, humans, start, goals, floors, reactive, tries=200, stops_on=roomy,
                             around=_ring if small else None)
    if walkers is None or people is None:
        return None
    robot_cells = {start, *goals}
    kept = _ring if reactive is not None and site.floor_size < 2 * (PERSON_RADIUS + PERSON_ROOM) else (lambda c: ())
    reserved = robot_cells | {c for walker in walkers for c in walker.cells()} | {
        c for person in people for stop in person.cells() for c in (stop, *kept(stop))}
    blocked = _blocked_table(site)
    weights = {name: types.weights[name] for name in furniture}
    wanted = max(1, round(SHARES[density] * len(area)))
    placed: dict[Cell, Furniture] = {}
    counters: dict[str, int] = {}
    candidates = [c for c in area if c not in reserved]
    rng.shuffle(candidates)
    for cell in candidates:
        if len(placed) == wanted:
            break
        kind = rng.choices(list(weights), weights=list(weights.values()))[0]
        sx, sy = furniture[kind]
        item = Furniture("", kind, cell, rng.choice((0, 90)) if sx != sy else 0, (sx, sy))
        if _fits(item, site, blocked, placed, reserved) and still_navigable(cell, placed, robot_cells, floors):
            counters[kind] = counters.get(kind, 0) + 1
            placed[cell] = Furniture(f"{kind.lower()}{counters[kind]}", kind, cell, item.yaw, item.size)
    name = f"{_identifier(site.yaml.stem)}{density.capitalize()}_{seed}_{index}"
    stops = (start, *goals)
    timeouts = [_timeout(_distance(floors, a, b), site.floor_size) for a, b in zip(stops, goals, strict=False)]
    xs = [c[0] for c in site.free]
    ys = [c[1] for c in site.free]
    return Room(name, "map", density, seed, index, max(xs) + 1, max(ys) + 1, start,
                tuple(Goal(c, t) for c, t in zip(goals, timeouts, strict=True)), tuple(placed.values()),
                tuple(walkers), types, site, tuple(people), reactive)


def _largest_area(free: frozenset[Cell]) -> list[Cell]:
    """The largest set of free floors connected side by side, sorted (so the seed alone decides)."""
    seen: set[Cell] = set()
    best: set[Cell] = set()
    for cell in sorted(free):
        if cell in seen:
            continue
        area = component(cell, free)
        seen |= area
        if len(area) > len(best):
            best = area
    return sorted(best)


def _distance(floors: set[Cell], a: Cell, b: Cell) -> int:
    return distances(floors, a).get(b, 0)


def _goals(rng: random.Random, floors: set[Cell], roomy: list[Cell], start: Cell) -> list[Cell] | None:
    """The first goal among the roomy floors farthest from the start, the next at least a third of that far."""
    from_start = distances(floors, start)
    reach = max(from_start.values())
    if reach < 2:
        return None
    far = sorted(c for c in roomy if from_start.get(c, 0) >= 0.8 * reach)
    if not far:
        return None
    goals = [rng.choice(far)]
    while len(goals) < GOALS:
        from_last = distances(floors, goals[-1])
        options = sorted(c for c in roomy if c != start and c not in goals and from_last.get(c, 0) >= reach / 3)
        if not options:
            return None
        goals.append(rng.choice(options))
    return goals


def _lane(cells: list[Cell], rng: random.Random) -> tuple[Cell, Cell]:
    """A walker's lane: 3 to 6 floors straight on from one of ``cells`` (it may leave them: the caller checks)."""
    first = rng.choice(cells)
    dx, dy = rng.choice(SIDES)
    length = rng.randint(3, 6)
    return first, (first[0] + (length - 1) * dx, first[1] + (length - 1) * dy)


def _blocked_table(site: MapSite) -> np.ndarray:
    """Summed-area table of the map's obstacle cells: any rectangle's count in four lookups."""
    mask = obstacle_mask(site.occupancy, site.unknown_free)
    table = np.zeros((mask.shape[0] + 1, mask.shape[1] + 1), dtype=np.int64)
    table[1:, 1:] = mask.cumsum(axis=0).cumsum(axis=1)
    return table


def _fits(item: Furniture, site: MapSite, blocked: np.ndarray, placed: dict[Cell, Furniture],
          reserved: set[Cell]) -> bool:
    box = _rect(site, item.cell, item.half_extents())
    occupancy = site.occupancy
    ox, oy, _ = occupancy.origin
    res = occupancy.resolution
    c0 = max(0, math.floor((box[0] - WALL_GAP - ox) / res))
    r0 = max(0, math.floor((box[1] - WALL_GAP - oy) / res))
    c1 = min(occupancy.width, math.ceil((box[2] + WALL_GAP - ox) / res))
    r1 = min(occupancy.height, math.ceil((box[3] + WALL_GAP - oy) / res))
    if blocked[r1, c1] - blocked[r0, c1] - blocked[r1, c0] + blocked[r0, c0] > 0:
        return False
    reach = math.ceil(LANE / site.floor_size) + 1
    x, y = item.cell
    half = site.floor_size / 2
    for cell in ((x + dx, y + dy) for dx in range(-reach, reach + 1) for dy in range(-reach, reach + 1) if dx or dy):
        other = placed.get(cell)
        if other is not None and rect_gap(box, _rect(site, cell, other.half_extents())) < LANE:
            return False
        if cell in reserved and rect_gap(box, _rect(site, cell, (half, half))) < GAP:
            return False
    return True


def _rect(site: MapSite, cell: Cell, half: tuple[float, float]) -> tuple[float, float, float, float]:
    cx, cy = site.centre(cell)
    return (cx - half[0], cy - half[1], cx + half[0], cy + half[1])


def _timeout(floors_apart: int, floor_size: float) -> int:
    """Time for a task: 30 s plus 6 s per metre of the way along the floors, rounded up to 5 s."""
    return int(5 * math.ceil((30 + 6 * floors_apart * floor_size) / 5))


def _identifier(stem: str) -> str:
    """A test case name from the map's file name: letters and digits, starting with a capital."""
    words = [w for w in "".join(c if c.isalnum() else " " for c in stem).split() if w]
    name = "".join(w[:1].upper() + w[1:] for w in words) or "Map"
    return name if name[0].isalpha() else f"Map{name}"


__all__ = ["MapError", "generate_map_room", "generate_map_rooms", "load_site"]
