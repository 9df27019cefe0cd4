# SPDX-License-Identifier: EPL-2.0
"""The report's map draws a POLYGON object (furniture on a concave polygon) as its polygon, placed and turned,
not as its bounding box; a box stays its rectangle."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

from polygon_desk import C_DESK, add_polygon_desk

from rei.report.html import render_report
from rei.report.map_svg import _world_layer
from rei.report.run_data import load_run
from rei.report.svg import MapTransform, box_corners

from .runs import make_run


def _polygon_of(svg: str, name: str) -> list[tuple[float, float]]:
    points = re.search(rf'<polygon class="static" points="([^"]+)"[^>]*><title>{name} ', svg)
    assert points is not None, svg
    values = [float(v) for v in re.findall(r"[-\d.]+", points.group(1))]
    return list(zip(values[0::2], values[1::2], strict=True))


def test_the_map_draws_the_desks_polygon_turned_with_it(tmp_path: Path) -> None:
    out = make_run(tmp_path / "run")
    pose = (3.5, 1.5, 0.375, math.pi / 2)
    add_polygon_desk(out / "case", pose=pose)
    world = json.loads((out / "case" / "world.json").read_text(encoding="utf-8"))
    tf = MapTransform.fit((0.0, 0.0, 6.0, 4.0), 600)
    c, s = math.cos(pose[3]), math.sin(pose[3])
    placed = [(pose[0] + c * u - s * v, pose[1] + s * u + c * v) for u, v in C_DESK]
    drawn = _polygon_of(_world_layer(world, tf), "table1")
    assert len(drawn) == len(C_DESK) == 8
    for (x, y), (u, v) in zip(drawn, (tf.point(*p) for p in placed), strict=True):
        assert abs(x - u) < 0.01 and abs(y - v) < 0.01
    # the whole report draws it too; a box (the walls) keeps its four corners
    html = render_report(load_run(out))
    assert len(_polygon_of(html, "table1")) == 8
    wall = next(o for o in world["objects"] if o["category"] == "WALL")
    corners = box_corners(wall["pose"][0], wall["pose"][1], wall["size"][0], wall["size"][1], wall["pose"][3])
    assert f'points="{tf.points_attr(corners)}"' in _world_layer(world, tf)
