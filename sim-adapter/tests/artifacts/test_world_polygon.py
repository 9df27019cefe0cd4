# SPDX-License-Identifier: EPL-2.0
"""world.json's POLYGON objects: the footprint is read about the object's pose (counter-clockwise, whichever way it
was written) and placed by its outline; a POLYGON object without a polygon, or one without area, is refused, naming
the member."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from polygon_desk import C_DESK, add_polygon_desk

from rei.artifacts.errors import ArtifactError
from rei.artifacts.world import PolygonFootprint, Shape, read_world


def test_the_footprint_is_read_and_placed(room_copy: Path) -> None:
    add_polygon_desk(room_copy, pose=(3.5, 1.0, 0.375, math.pi / 2))
    desk = read_world(room_copy / "world.json").object("table1")
    assert desk.shape is Shape.POLYGON and desk.footprint == PolygonFootprint(tuple(C_DESK))
    assert desk.outline is not None
    assert [pytest.approx(p) for p in desk.outline] == [(3.5 - v, 1.0 + u) for u, v in C_DESK]
    assert read_world(room_copy / "world.json").object("h1").outline is None
    # written clockwise (by hand): read counter-clockwise, from the same first vertex
    add_polygon_desk(room_copy, points=(C_DESK[0], *C_DESK[:0:-1]))
    assert read_world(room_copy / "world.json").object("table1").footprint == PolygonFootprint(tuple(C_DESK))


@pytest.mark.parametrize("footprint", [None, {"type": "circle", "x": 0, "y": 0, "radius": 0.5},
                                       {"type": "polygon", "points": [[0, 0], [1, 0]]},
                                       {"type": "polygon", "points": [[0, 0], [1, 0], [2, 0]]}])
def test_a_polygon_object_needs_its_polygon(room_copy: Path, footprint: object) -> None:
    add_polygon_desk(room_copy)
    world = json.loads((room_copy / "world.json").read_text(encoding="utf-8"))
    desk = next(o for o in world["objects"] if o["name"] == "table1")
    if footprint is None:
        del desk["footprint"]
    else:
        desk["footprint"] = footprint
    (room_copy / "world.json").write_text(json.dumps(world), encoding="utf-8")
    with pytest.raises(ArtifactError, match="footprint"):
        read_world(room_copy / "world.json")
