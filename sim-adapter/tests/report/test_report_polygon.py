# SPDX-License-Identifier: EPL-2.0
"""The report's map draws a POLYGON object (furniture on a concave polygon) as its polygon, placed and turned,
not as its bounding box; a box stays its rectangle."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from mcap.reader import make_reader
from polygon_desk import C_DESK, add_polygon_desk

from rei.geometry import yaw_of_quaternion
from rei.report import write_mcap
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


def test_run_mcap_draws_the_desk_as_its_prisms_edges(tmp_path: Path) -> None:
    """run.mcap's /world has the desk as the edges of its polygon's prism (SceneUpdate lines), placed and turned,
    from the floor to its height; a box stays a cube."""
    out = make_run(tmp_path / "run")
    pose = (3.5, 1.5, 0.375, math.pi / 2)
    add_polygon_desk(out / "case", pose=pose)
    with open(write_mcap(out), "rb") as f:
        (world,) = [json.loads(m.data) for _, channel, m in make_reader(f).iter_messages() if channel.topic == "/world"]
    entities = {e["id"]: e for e in world["entities"]}
    bottom, top, upright = entities["table1"]["lines"]
    place = bottom["pose"]["position"]
    turn = yaw_of_quaternion(*(bottom["pose"]["orientation"][a] for a in "xyzw"))
    assert (place["x"], place["y"], place["z"], turn) == pytest.approx((pose[0], pose[1], 0.0, pose[3]))
    assert [(p["x"], p["y"]) for p in bottom["points"]] == [pytest.approx(p) for p in C_DESK]
    assert {p["z"] for p in top["points"]} == {0.75} and len(upright["points"]) == 2 * len(C_DESK)
    assert "cubes" in entities["W_0_0_bottom"] and "lines" not in entities["W_0_0_bottom"]
