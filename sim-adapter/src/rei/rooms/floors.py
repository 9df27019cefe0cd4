# SPDX-License-Identifier: EPL-2.0
"""Floors side by side, for both room generators: a grid room's floors are all the cells of its rectangle, a map
room's the map's free blocks. What is reachable, how far, whether a room stays navigable with one more piece
of furniture, and where humans walk are the same questions on both."""

from __future__ import annotations

import random
from collections import deque
from collections.abc import Callable, Collection, Iterable, Mapping

from rei.rooms.model import BEHAVIOURS, MIXED, Cell, Person, Walker

#: The four sides of a floor (4-neighbours), in the order both generators have always walked them.
SIDES = ((-1, 0), (1, 0), (0, -1), (0, 1))
HUMAN_SPEED = (0.4, 0.7)  # m/s
#: People who see the robot: desired walking speeds (m/s, to 0.1), stops per route, the fewest floors between two
#: consecutive stops (along the floors), the waits at a stop (s) and the latest start (s).
PEOPLE_SPEED = (0.8, 1.4)
PEOPLE_STOPS = (2, 3)
PEOPLE_LEG = 3
PEOPLE_WAITS = (0, 0, 1, 2, 3)
PEOPLE_START = 5


def grid(width: int, height: int) -> frozenset[Cell]:
    """Every floor of a ``width`` x ``height`` grid room."""
    return frozenset((x, y) for x in range(width) for y in range(height))


def neighbours(cell: Cell) -> Iterable[Cell]:
    for dx, dy in SIDES:
        yield (cell[0] + dx, cell[1] + dy)


def component(origin: Cell, floors: Collection[Cell]) -> set[Cell]:
    """The floors reachable from ``origin`` side by side."""
    seen = {origin}
    queue = deque([origin])
    while queue:
        for n in neighbours(queue.popleft()):
            if n in floors and n not in seen:
                seen.add(n)
                queue.append(n)
    return seen


def distances(floors: Collection[Cell], origin: Cell) -> dict[Cell, int]:
    """Floors from ``origin`` along the floors (4-neighbours)."""
    distance = {origin: 0}
    queue = deque([origin])
    while queue:
        cell = queue.popleft()
        for n in neighbours(cell):
            if n in floors and n not in distance:
                distance[n] = distance[cell] + 1
                queue.append(n)
    return distance


def still_navigable(cell: Cell, placed: Mapping[Cell, object], robot_cells: Iterable[Cell],
                    floors: Collection[Cell]) -> bool:
    """Whether the free floors stay connected with ``cell`` furnished, and the start and goals (``robot_cells``)
    keep two free neighbours. The free floors are connected before (the room's area is, and every piece kept
    them so), so they stay connected exactly when ``cell``'s free neighbours still reach each other: a search from
    one of them that stops once it has met the others, mostly a few floors around ``cell``, where a search of the
    whole area per piece would make a large building's furnishing quadratic."""
    def free(c: Cell) -> bool:
        return c in floors and c not in placed and c != cell

    for c in robot_cells:
        if sum(free(n) for n in neighbours(c)) < 2:
            return False
    around = [n for n in neighbours(cell) if free(n)]
    if len(around) < 2:
        return True
    missing = set(around[1:])
    seen = {around[0]}
    queue = deque([around[0]])
    while queue and missing:
        for n in neighbours(queue.popleft()):
            if n not in seen and free(n):
                seen.add(n)
                missing.discard(n)
                queue.append(n)
    return not missing


def draw_walkers(rng: random.Random, humans: int, start: Cell, goals: Iterable[Cell],
                 lane: Callable[[random.Random], tuple[Cell, Cell]], floors: Collection[Cell], floor_size: float,
                 tries: int) -> list[Walker] | None:
    """One straight lane per human, so that humans do not walk into each other: ``lane`` draws its first and last
    floor, kept when every floor between lies in ``floors`` and away from the robot's start (and its neighbours),
    the goals and the lanes before; a human walks it at a speed drawn from ``HUMAN_SPEED`` (``floor_size`` metres
    a floor). None when a human's lane is not found in ``tries`` draws."""
    banned = {start, *neighbours(start), *goals}
    walkers: list[Walker] = []
    for number in range(1, humans + 1):
        for _ in range(tries):
            first, last = lane(rng)
            walker = Walker(f"walker{number}", first, last, 0)
            cells = set(walker.cells())
            if not cells <= floors or cells & banned:
                continue
            period = max(2, round((len(cells) - 1) * floor_size / rng.uniform(*HUMAN_SPEED)))
            walkers.append(Walker(walker.name, first, last, period))
            banned |= cells
            break
        else:
            return None
    return walkers


def draw_people(rng: random.Random, humans: int, start: Cell, goals: Iterable[Cell], floors: Collection[Cell],
                behaviour: str, tries: int, stops_on: Collection[Cell] | None = None,
                around: Callable[[Cell], Iterable[Cell]] | None = None) -> list[Person] | None:
    """People who see the robot, each on a route of 2 or 3 stops round which it loops: every stop a floor of
    ``floors`` away from the robot's start (and its neighbours), the goals and every other person's stops, each at
    least ``PEOPLE_LEG`` floors along the floors from the one before (and the last from the first), so a person
    walks across the room, and the pedestrian model finds its way between them around what the caller then places
    (the caller keeps furniture off the stops and every free floor reachable). ``behaviour``: theirs, or ``mixed``
    (each drawn). None when a person's route is not found in ``tries`` draws. ``stops_on``: the floors a stop may
    be on (default: ``floors``); ``around``: the floors next to a stop that no other person's stop may be on (floors
    smaller than two bodies: neighbouring starts would overlap)."""
    banned = {start, *neighbours(start), *goals}
    people: list[Person] = []
    for number in range(1, humans + 1):
        for _ in range(tries):
            stops = _route(rng, floors, banned, stops_on)
            if stops is not None:
                break
        else:
            return None
        waits = [rng.choice(PEOPLE_WAITS) for _ in stops]
        speed = round(rng.uniform(*PEOPLE_SPEED), 1)
        drawn = rng.choice(BEHAVIOURS)  # drawn whatever the setting, so a fixed behaviour keeps the same room
        people.append(Person(f"person{number}", tuple(zip(stops, waits, strict=True)), speed,
                             rng.randint(0, PEOPLE_START), drawn if behaviour == MIXED else behaviour))
        banned |= set(stops) if around is None else {c for stop in stops for c in (stop, *around(stop))}
    return people


def _route(rng: random.Random, floors: Collection[Cell], banned: Collection[Cell],
           stops_on: Collection[Cell] | None = None) -> list[Cell] | None:
    allowed = sorted(c for c in (floors if stops_on is None else stops_on) if c not in banned)
    if not allowed:
        return None
    stops = [rng.choice(allowed)]
    for _ in range(rng.randint(*PEOPLE_STOPS) - 1):
        apart = distances(floors, stops[-1])
        options = [c for c in allowed if c not in stops and apart.get(c, 0) >= PEOPLE_LEG]
        if not options:
            return None
        stops.append(rng.choice(options))
    if distances(floors, stops[-1]).get(stops[0], 0) < PEOPLE_LEG:  # the way back round the loop is a walk too
        return None
    return stops
