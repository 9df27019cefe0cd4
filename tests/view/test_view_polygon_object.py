# SPDX-License-Identifier: EPL-2.0
"""The live view draws furniture on a polygon (issue #41) as world.json's footprint placed at its pose and turned
by its yaw, in headless Chromium: the map canvas is the furniture's colour inside the polygon and the floor's in
its open notch, which its bounding box would cover."""

from __future__ import annotations

import math
from pathlib import Path

from playwright.sync_api import Browser
from test_view_robot_outline import FLOOR, RGB, _near
from view_helpers import ViewPage, synthetic_world, write_case

from rei.view import ViewServer, view_config
from rei.wamp import Router, Topics, WampClient

#: A C-shaped desk about its centre, its notch (0.7 m wide, 0.6 m deep) opening towards its -x.
C_DESK = [[-0.5, -0.7], [0.5, -0.7], [0.5, 0.7], [-0.5, 0.7], [-0.5, 0.35], [0.1, 0.35], [0.1, -0.35],
          [-0.5, -0.35]]
X, Y, YAW = 3.5, 1.8, math.pi / 2  # turned a quarter: the notch opens towards -y


def test_a_polygon_desk_is_drawn_as_its_polygon_turned_not_its_box(browser: Browser, router: Router,
                                                                   tmp_path: Path) -> None:
    world = synthetic_world(humans=0)
    table = next(o for o in world["objects"] if o["name"] == "table1")
    table.update(shape="POLYGON", size=[1.0, 1.4, 0.75], pose=[X, Y, 0.375, YAW],
                 footprint={"type": "polygon", "points": C_DESK})
    config = view_config(router.ws_url, "view-polygon-desk", write_case(tmp_path / "case", world))
    inside = [(0.3, 0.0), (-0.3, 0.55), (-0.3, -0.55)]  # the back and both arms
    notch = [(-0.3, 0.0), (-0.1, 0.15)]  # in the bounding box, outside the polygon
    with ViewServer(config) as server, WampClient(router.rs_url) as client:
        page = ViewPage(browser, server.url)
        try:
            client.publish(Topics("view-polygon-desk").state, {"seq": 0, "t": 0.0, "objects": [], "robot": {
                "name": "tb3", "pose": [0.8, 0.8, 0.0, 0.0], "twist": [0.0, 0.0, 0.0], "laser_min": float("inf")}})
            client.flush()
            page.wait_for("state.robot !== null")
            tf = page.state()["transform"]
            c, s = math.cos(YAW), math.sin(YAW)
            colours = []
            for lx, ly in inside + notch:
                wx, wy = X + c * lx - s * ly, Y + s * lx + c * ly
                colours.append(page.page.evaluate(RGB, [tf["ox"] + wx * tf["scale"], tf["oy"] - wy * tf["scale"]]))
            assert page.errors == []
        finally:
            page.close()
    assert not any(_near(rgb, FLOOR) for rgb in colours[:3]), colours
    assert all(_near(rgb, FLOOR) for rgb in colours[3:]), colours
