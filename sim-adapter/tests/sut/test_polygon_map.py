# SPDX-License-Identifier: EPL-2.0
"""Furniture on a polygon in the static map: REI's navigation plans around the polygon (its distance field is the
distance to the polygon, as shapely measures it) and the /map raster fills the polygon, not its bounding box, so
the open notch of a C-shaped desk is free to plan into; an external SUT gets the bounding box
as its obstacle and the polygon beside it."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from polygon_desk import C_DESK, C_DESK_POSE
from shapely.geometry import Point, Polygon

from rei.artifacts.world import read_world
from rei.sut.api import StaticMap
from rei.sut.nav import NavConfig
from rei.sut.nav.global_planner import PlanningError, plan
from rei.sut.nav.grid import CostGrid
from rei.sut.rasterize import rasterize

NOTCH = (C_DESK_POSE[0] - 0.2, C_DESK_POSE[1])  # 0.3 m from the notch's back, 0.35 m from its arms


def test_the_notch_is_free_in_the_distance_field_the_plan_and_the_raster(polygon_case: Path) -> None:
    static_map = StaticMap.of_world(read_world(polygon_case / "world.json"))
    assert sum(p is not None for p in static_map.polygons) == 1
    grid = CostGrid(static_map, NavConfig())
    # the field around the desk alone (no walls) is the distance to its polygon at every cell centre, as shapely
    # measures it (0 inside), up to the field's cap and the floors' edge (the field's distance to their outside)
    k = next(k for k, p in enumerate(static_map.polygons) if p is not None)
    alone = CostGrid(dataclasses.replace(static_map, obstacles=(static_map.obstacles[k],),
                                         polygons=(static_map.polygons[k],)), NavConfig())
    desk = Polygon(np.array(C_DESK) + C_DESK_POSE[:2])
    cells = [(i, j) for i in range(alone.width) for j in range(alone.height)
             if 2.5 <= alone.cell_center(i, j)[0] <= 4.5 and 0.2 <= alone.cell_center(i, j)[1] <= 1.8]
    centres = [Point(alone.cell_center(i, j)) for i, j in cells]
    xmin, ymin, xmax, ymax = static_map.bounds
    expected = np.array([min(0.0 if desk.contains(c) else desk.exterior.distance(c),
                             max(0.0, min(c.x - xmin, xmax - c.x, c.y - ymin, ymax - c.y))) for c in centres])
    measured = np.array([alone.distance[j, i] for i, j in cells])
    near = expected < alone.cap - 0.05
    assert near.sum() > 500 and sum(desk.contains(c) for c in centres) > 100
    np.testing.assert_allclose(measured[near], expected[near], atol=1e-5)

    path = plan(grid, grid.cost, (1.0, 1.0), NOTCH, 0.05)
    assert np.hypot(path.end[0] - NOTCH[0], path.end[1] - NOTCH[1]) <= 0.05
    raster = rasterize(static_map)
    row, col = (int((v - o) / raster.resolution) for v, o in ((NOTCH[1], raster.y0), (NOTCH[0], raster.x0)))
    assert not raster.occupied[row, col]
    assert raster.occupied[row, int((C_DESK_POSE[0] + 0.3 - raster.x0) / raster.resolution)]  # the desk's back

    # its bounding box alone (what an external SUT is sent) would have the notch blocked
    boxes = dataclasses.replace(static_map, polygons=())
    with pytest.raises(PlanningError):
        plan(CostGrid(boxes, NavConfig()), CostGrid(boxes, NavConfig()).cost, (1.0, 1.0), NOTCH, 0.05)
    assert rasterize(boxes).occupied[row, col]


def test_hello_offers_the_polygon_beside_its_rectangle(polygon_case: Path, room: Path) -> None:
    """An external SUT's static map: the desk's rectangle among the obstacles and its polygon in map.polygons,
    which REI's kit reads back into StaticMap.polygons (rei nav-sut plans with it); a world of boxes has no such
    member."""
    from rei.geometry import Pose2D
    from rei.sut.external.protocol import hello_answer, read_static_map

    def hello(case: Path) -> dict:
        static_map = StaticMap.of_world(read_world(case / "world.json"))
        return hello_answer(run_id="r", clock="lockstep", control_rate=10.0, deadline=1.0, start=Pose2D(1.0, 1.0),
                            robot={"footprint": [0.281, 0.306]}, goals=2, static_map=static_map)

    answer = hello(polygon_case)
    polygons = answer["map"]["polygons"]
    assert len(polygons) == len(answer["map"]["obstacles"]) and sum(p is not None for p in polygons) == 1
    read = read_static_map(answer)
    assert read is not None and read.polygons == StaticMap.of_world(read_world(polygon_case / "world.json")).polygons
    grid = CostGrid(read, NavConfig())  # rei nav-sut plans into the notch as the in-process navigation does
    assert np.hypot(*np.subtract(plan(grid, grid.cost, (1.0, 1.0), NOTCH, 0.05).end, NOTCH)) <= 0.05
    assert "polygons" not in hello(room)["map"] and read_static_map(hello(room)).polygons == ()  # type: ignore[union-attr]
