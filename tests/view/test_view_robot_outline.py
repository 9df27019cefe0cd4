# SPDX-License-Identifier: EPL-2.0
"""The live view draws the robot's real outline, in headless Chromium: a robot read from a description is drawn
as world.json's footprint (the round example robot as its circle, not the square of its bounding box; a polygon
turned with the robot's pose about its origin), and a box robot as its box, as before. Checked by the map canvas's
pixels at points of the robot's own frame: filled in the FAR zone's green inside the outline, the floor's colour
outside it."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from playwright.sync_api import Browser
from view_helpers import ViewPage, synthetic_world, write_case

from rei.robots import load_description
from rei.view import ViewServer, view_config
from rei.wamp import Router, Topics, WampClient

ROUND_BOT = Path(__file__).resolve().parents[2] / "examples" / "robots" / "round_bot.urdf"
#: Red, green and blue of the map canvas's pixel at CSS pixel [px, py].
RGB = """([px, py]) => { const c = document.querySelector('#map'); const r = devicePixelRatio;
         const d = c.getContext('2d').getImageData(Math.round(px * r), Math.round(py * r), 1, 1).data;
         return [d[0], d[1], d[2]]; }"""
FAR = (0x59, 0xA1, 0x4F)  # viewer/src/draw/colours.ts ZONE.FAR: no signal was published, so the robot is FAR
FLOOR = (0xEF, 0xEB, 0xE4)  # viewer/src/draw/colours.ts FLOOR
X, Y = 1.5, 2.5  # clear of the synthetic room's table and walls


def _near(rgb: list[int], colour: tuple[int, int, int]) -> bool:
    return max(abs(a - b) for a, b in zip(rgb, colour, strict=True)) <= 12


def _colours(browser: Browser, router: Router, folder: Path, robot: dict[str, Any], yaw: float,
             local: list[tuple[float, float]], run_id: str) -> list[list[int]]:
    """The colours drawn at `local` points of the robot's frame, the robot at (X, Y, yaw) in a synthetic room whose
    world.json robot has the members `robot` (no odometry sent: its dashed ghost would cross the outline)."""
    world = synthetic_world(humans=0)
    world["robot"].update(robot)
    config = view_config(router.ws_url, run_id, write_case(folder, world))
    with ViewServer(config) as server, WampClient(router.rs_url) as client:
        page = ViewPage(browser, server.url)
        try:
            client.publish(Topics(run_id).state, {"seq": 0, "t": 0.0, "objects": [], "robot": {
                "name": "tb3", "pose": [X, Y, 0.0, yaw], "twist": [0.0, 0.0, 0.0], "laser_min": float("inf")}})
            client.flush()
            page.wait_for("state.robot !== null")
            tf = page.state()["transform"]
            c, s = math.cos(yaw), math.sin(yaw)
            colours = []
            for lx, ly in local:
                wx, wy = X + c * lx - s * ly, Y + s * lx + c * ly
                colours.append(page.page.evaluate(RGB, [tf["ox"] + wx * tf["scale"], tf["oy"] - wy * tf["scale"]]))
            assert tf["scale"] > 80, tf  # a pixel is at most 12.5 mm: the points below lie 40 mm or more off edges
            assert page.errors == []
            return colours
        finally:
            page.close()


def test_a_round_robot_is_drawn_as_its_circle_not_its_bounding_square(browser: Browser, router: Router,
                                                                       tmp_path: Path) -> None:
    footprint = load_description(ROUND_BOT, lidar="laser").footprint.to_json()
    assert footprint == {"type": "circle", "x": 0.0, "y": 0.0, "radius": 0.17}
    inside = [(0.0, 0.12), (0.0, -0.12), (-0.12, 0.0)]  # off the heading line, which runs forward (+x)
    corners = [(0.15, 0.15), (-0.15, 0.15), (-0.15, -0.15), (0.15, -0.15)]  # in the 0.34 m square, not the circle
    colours = _colours(browser, router, tmp_path / "round", {"size": [0.34, 0.34, 0.2], "footprint": footprint},
                       0.7, inside + corners, "view-round-robot")
    assert all(_near(rgb, FAR) for rgb in colours[:3]), colours
    assert all(_near(rgb, FLOOR) for rgb in colours[3:]), colours


def test_a_polygon_footprint_turns_with_the_robot_about_its_origin(browser: Browser, router: Router,
                                                                   tmp_path: Path) -> None:
    # a trapezoid narrowing forward, its origin off its middle; the robot faces +y (yaw 90 degrees)
    points = [[-0.2, -0.3], [0.6, -0.1], [0.6, 0.1], [-0.2, 0.3]]
    inside = [(0.3, -0.1), (-0.1, 0.2), (0.5, 0.06)]
    # outside the trapezoid, inside its bounding box centred on the origin (what a box robot's drawing would fill)
    outside = [(0.35, 0.25), (0.35, -0.25), (-0.35, 0.0)]
    # outside it, but at world offset (0.5, 0) from the origin: inside the trapezoid were it drawn unturned
    unturned = [(0.0, -0.5)]
    colours = _colours(browser, router, tmp_path / "polygon",
                       {"size": [0.8, 0.6, 0.2], "footprint": {"type": "polygon", "points": points}},
                       math.pi / 2, inside + outside + unturned, "view-polygon-robot")
    assert all(_near(rgb, FAR) for rgb in colours[:3]), colours
    assert all(_near(rgb, FLOOR) for rgb in colours[3:]), colours


def test_a_box_robot_is_still_drawn_as_its_box(browser: Browser, router: Router, tmp_path: Path) -> None:
    corners = [(0.15, 0.15), (-0.15, 0.15), (-0.15, -0.15), (0.15, -0.15)]  # as the round robot's, now filled
    beyond = [(0.26, 0.26), (-0.26, -0.26)]
    colours = _colours(browser, router, tmp_path / "box", {"size": [0.4, 0.4, 0.2]}, 0.7, corners + beyond,
                       "view-box-robot")
    assert all(_near(rgb, FAR) for rgb in colours[:4]), colours
    assert all(_near(rgb, FLOOR) for rgb in colours[4:]), colours
