# SPDX-License-Identifier: EPL-2.0
"""The live view of a room from an occupancy map, in headless Chromium: the map's picture lies under the
translucent floors, each cell where the map puts it (a dark square of the map shows through its floor, the free
cells beside it do not darken theirs)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from playwright.sync_api import Browser
from view_helpers import SHOTS, ViewPage, state_message, synthetic_world, write_case

from rei.view import ViewServer, view_config
from rei.wamp import Router, Topics, WampClient

RESOLUTION = 0.05
#: The mean of red, green and blue of the map canvas's pixel at CSS pixel [px, py].
GREY = """([px, py]) => { const c = document.querySelector('#map'); const r = devicePixelRatio;
          const d = c.getContext('2d').getImageData(Math.round(px * r), Math.round(py * r), 1, 1).data;
          return (d[0] + d[1] + d[2]) / 3; }"""


def _map_case(folder: Path) -> Path:
    """The 6 x 4 m synthetic room with a map of its extent: free, but a 0.6 m occupied square around (1.5, 2.5)
    and unknown cells over x 4..5 m, y 0..1 m."""
    world = synthetic_world()
    world["map"] = {"yaml": "map.yaml", "image": "map.pgm", "resolution": RESOLUTION, "origin": [0.0, 0.0, 0.0],
                    "width": 120, "height": 80, "unknownFree": False}
    case = write_case(folder, world)
    grid = np.full((80, 120), 254, dtype=np.uint8)  # rows from the bottom; flipped into image order below
    grid[44:56, 24:36] = 0
    grid[0:20, 80:100] = 205
    (case / "map.pgm").write_bytes(b"P5\n120 80\n255\n" + grid[::-1].tobytes())
    (case / "map.yaml").write_text("image: map.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                   "occupied_thresh: 0.65\nfree_thresh: 0.196\n", encoding="utf-8")
    return case


def test_the_map_s_picture_shows_under_the_floors_where_the_map_has_it(browser: Browser, router: Router,
                                                                       tmp_path: Path) -> None:
    run_id = "view-map-room"
    config = view_config(router.ws_url, run_id, _map_case(tmp_path / "case"))
    assert config["occupancy"]["extent"] == [0.0, 0.0, 6.0, 4.0]
    with ViewServer(config) as server, WampClient(router.rs_url) as client:
        page = ViewPage(browser, server.url)
        try:
            client.publish(Topics(run_id).state, state_message(0, 0.0, (5.5, 3.5)))
            client.flush()
            page.wait_for("state.robot !== null")
            tf = page.state()["transform"]

            def at(x: float, y: float) -> list[float]:
                return [tf["ox"] + x * tf["scale"], tf["oy"] - y * tf["scale"]]

            def grey(x: float, y: float) -> float:
                return page.page.evaluate(GREY, at(x, y))

            # the picture loads asynchronously: until the square shows, then every place is as it stays
            page.page.wait_for_function(f"p => ({GREY})(p) < 150", arg=at(1.5, 2.5))
            SHOTS.mkdir(parents=True, exist_ok=True)
            page.page.screenshot(path=str(SHOTS / "map-room.png"))
            occupied, unknown, free = grey(1.5, 2.5), grey(4.5, 0.5), grey(2.5, 2.5)
            assert occupied < 150 < unknown < free, (occupied, unknown, free)  # floor over black, grey, white
            assert grey(1.5, 2.5 + 0.45) > 220 and grey(1.5 - 0.45, 2.5) > 220  # the square ends where it should
            assert page.errors == []
        finally:
            page.close()
