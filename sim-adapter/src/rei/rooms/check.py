# SPDX-License-Identifier: EPL-2.0
"""Is a generated room navigable by the reference navigation? Its global planner, on the room's static map.

The generator's rules (``rei.rooms.generator``) are conservative floor-level reasoning; this check asks the
planner the robot will actually use (``rei.sut.nav``, default parameters) for a path along every leg of the
mission, start -> goal 1 -> goal 2 ..., in the static map the simulation will build from the same room: walls
1.1 x 0.1 m centred on the room's edge (as the generator of world.json draws them) and the furniture's
catalogue footprints; on an occupancy map (``rei gen-rooms --map``), the map's obstacle cells merged into
rectangles, as the generated world's walls. Humans are not in the static map, as for the robot.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import Any

from rei.maps import box_of, merge_rectangles, obstacle_mask
from rei.rooms.model import FLOOR, MapSite, Room
from rei.sut.api import StaticMap
from rei.sut.nav.config import NavConfig
from rei.sut.nav.global_planner import PlanningError, plan
from rei.sut.nav.grid import CostGrid

_WALL = (1.1 * FLOOR, 0.1)


def static_map(room: Room) -> StaticMap:
    """The room's walls and furniture as ``(x, y, yaw, size_x, size_y)`` rectangles; on a map, its obstacle cells
    merged into rectangles as the generated world's walls are (rei.maps)."""
    furniture = []
    for item in room.furniture:
        hx, hy = item.half_extents()
        furniture.append((*room.centre(item.cell), 0.0, 2 * hx, 2 * hy))
    if room.site is not None:
        return _on_map(room.site, furniture, room.types.robot_size)
    obstacles: list[tuple[float, float, float, float, float]] = []
    w, h = room.width * FLOOR, room.height * FLOOR
    for i in range(room.width):
        x = (i + 0.5) * FLOOR
        obstacles += [(x, 0.0, 0.0, *_WALL), (x, h, 0.0, *_WALL)]
    for j in range(room.height):
        y = (j + 0.5) * FLOOR
        obstacles += [(0.0, y, 0.0, _WALL[1], _WALL[0]), (w, y, 0.0, _WALL[1], _WALL[0])]
    return StaticMap(bounds=(0.0, 0.0, w, h), obstacles=(*obstacles, *furniture), robot_size=room.types.robot_size)


def _on_map(site: MapSite, furniture: list[tuple[float, float, float, float, float]],
            robot_size: tuple[float, float]) -> StaticMap:
    occupancy = site.occupancy
    walls = [(cx, cy, 0.0, sx, sy) for cx, cy, sx, sy in
             (box_of(rect, occupancy) for rect in merge_rectangles(obstacle_mask(occupancy, site.unknown_free)))]
    ox, oy, _ = occupancy.origin
    bounds = (ox, oy, ox + occupancy.width * occupancy.resolution, oy + occupancy.height * occupancy.resolution)
    return StaticMap(bounds=bounds, obstacles=(*walls, *furniture), robot_size=robot_size)


def diagram_static_map(diagram: dict[str, Any]) -> StaticMap:
    """``static_map`` of a test case as the room editor's diagram (rei.edit) gives it: its walls as drawn, its
    objects at their poses; for rei.search, which checks edited test cases."""
    room = diagram["room"]
    size = float(room["floorSize"])
    obstacles = [(float(w["x"]), float(w["y"]), 0.0, float(w["sizeX"]), float(w["sizeY"])) for w in room["walls"]]
    for item in diagram.get("objects") or []:
        fp = item["footprint"]
        obstacles.append((float(item["x"]), float(item["y"]), math.radians(float(item["yaw"])),
                          float(fp["sizeX"]), float(fp["sizeY"])))
    xs = [float(f["x"]) * size for f in room["floors"]]
    ys = [float(f["y"]) * size for f in room["floors"]]
    robot = diagram["robot"]["footprint"]
    return StaticMap(bounds=(min(xs), min(ys), max(xs) + size, max(ys) + size), obstacles=tuple(obstacles),
                     robot_size=(float(robot["sizeX"]), float(robot["sizeY"])))


def unplannable_legs(room: Room, config: NavConfig | None = None) -> list[str]:
    """One message per leg the reference global planner finds no path for; empty when the room is navigable."""
    cells = [room.start, *(goal.cell for goal in room.goals)]
    return unplannable(static_map(room), [(str(c), room.centre(c)) for c in cells], config)


def unplannable(static: StaticMap, stops: Sequence[tuple[str, tuple[float, float]]],
                config: NavConfig | None = None) -> list[str]:
    """One message per leg between consecutive named ``stops`` (the start, then each goal) that the reference
    global planner finds no path for in ``static``; shared with rei.search, which checks edited test cases."""
    config = config or NavConfig()
    grid = CostGrid(static, config)
    problems = []
    for leg, ((a, pa), (b, pb)) in enumerate(itertools.pairwise(stops)):
        try:
            plan(grid, grid.cost, pa, pb, goal_radius=0.1)
        except PlanningError as error:
            problems.append(f"leg {leg} {a} -> {b}: {error}")
    return problems
