# SPDX-License-Identifier: EPL-2.0
"""People of rooms generated on a map of small floors (`rei gen-rooms --map two_rooms.yaml --floor-size 0.5
--people reactive`) can stand where they start: the people model refuses a person 0.25 m from the walkable area's
edge (a floor beside a wall block) or 0.5 m from another (two starts on neighbouring floors), so such a room's run
stopped at its start ('person4 cannot stand at (7.25, 4.25)', 'person2 ... too close to agent')."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

from rei.rooms import generate_map_room, load_site

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "maps" / "two_rooms.yaml"
RADIUS = 0.25  # the default Human's, which generated people are


def test_generated_people_on_half_metre_floors_have_room_to_stand() -> None:
    site = load_site(EXAMPLE, floor_size=0.5)
    size = site.floor_size
    for index in range(1, 7):
        room = generate_map_room(site, "dense", 6, seed=4, index=index, reactive="avoids")
        starts = [p.stops[0][0] for p in room.people]
        for a, b in itertools.combinations(starts, 2):  # bodies apart: more than two radii between centres
            assert math.dist(a, b) * size > 2 * RADIUS + 0.05, (index, a, b)
        furniture = {f.cell: f for f in room.furniture}
        for person in room.people:
            for cell, _ in person.stops:
                # every block round a stop is free and carries no furniture: the stop's centre is a floor and a
                # half from the nearest wall, and a body from any furniture
                ring = [(cell[0] + dx, cell[1] + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy]
                assert all(c in site.free for c in ring), (index, person.name, cell)
                assert not any(c in furniture for c in ring), (index, person.name, cell)
