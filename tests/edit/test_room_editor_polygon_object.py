# SPDX-License-Identifier: EPL-2.0
"""The room editor draws furniture on a polygon (issue #41: a corner desk, a corner sofa) as its polygon about the
floor's centre, turned with its yaw, not as its bounding box; checked against the catalogue's own vertices, in
Debian's chromium through a real edit engine and server (tests/edit/conftest.py)."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

from edit_helpers import Editor
from page_helpers import element, open_page
from playwright.sync_api import Page
from test_room_editor_robot_outline import _points, _same_ring

REPO = Path(__file__).resolve().parents[2]
# examples/catalogues/corner_office.rei's CornerDesk, its bounding box (2.2 x 2.0) centred on the floor's centre
DESK = [(0, 0), (2.2, 0), (2.2, 0.7), (0.7, 0.7), (0.7, 2.0), (0, 2.0)]


def _placed(x: float, y: float, yaw_degrees: float) -> list[tuple[float, float]]:
    c, s = math.cos(math.radians(yaw_degrees)), math.sin(math.radians(yaw_degrees))
    return [(x + c * (u - 1.1) - s * (v - 1.0), y + s * (u - 1.1) + c * (v - 1.0)) for u, v in DESK]


def test_a_corner_desk_is_drawn_as_its_polygon_and_turns_with_its_yaw(open_editor, page: Page,
                                                                       tmp_path: Path) -> None:
    # the case and the catalogue it imports, beside each other as in examples/
    (tmp_path / "catalogues").mkdir()
    shutil.copy(REPO / "examples" / "catalogues" / "corner_office.rei", tmp_path / "catalogues")
    shutil.copy(REPO / "examples" / "corner_desk.rei", tmp_path)
    editor: Editor = open_editor(tmp_path / "corner_desk.rei", copy=False)
    desk = next(o for o in editor.session.state()["diagram"]["objects"] if o["name"] == "desk")
    assert desk["footprint"]["shape"] == "polygon" and desk["footprint"]["outline"]["type"] == "polygon", desk
    open_page(page, editor)
    x, y = desk["x"], desk["y"]
    body = element(page, "object", "desk").locator('[data-outline="polygon"]')
    assert body.count() == 1
    drawn = _points(body.get_attribute("points"))
    assert _same_ring(drawn, _placed(x, y, 0)), drawn
    # not the bounding box: six corners, one of them inside the box (the open corner's)
    assert len(drawn) == 6 and any(math.dist(p, (x - 0.4, y - 0.3)) < 2e-3 for p in drawn)

    answer = editor.apply({"op": "rotateObject", "name": "desk", "yawDegrees": 90})
    assert next(o for o in answer["diagram"]["objects"] if o["name"] == "desk")["yaw"] == 90
    page.reload()
    open_page(page, editor)
    drawn = _points(element(page, "object", "desk").locator('[data-outline="polygon"]').get_attribute("points"))
    assert _same_ring(drawn, _placed(x, y, 90)), drawn
