# SPDX-License-Identifier: EPL-2.0
"""The room editor draws a robot read from its URDF description as its outline (issue #41), turned with its yaw;
a box robot as its catalogue box, as before.

The outline is checked against the URDF's own numbers (a cylinder's radius, a box's sides and offset), not against
what the reader computed, in Debian's chromium through a real edit engine and server (tests/edit/conftest.py).
"""

from __future__ import annotations

import math
from pathlib import Path

from edit_helpers import Editor
from page_helpers import element, open_page
from playwright.sync_api import Page

REPO = Path(__file__).resolve().parents[2]

# A robot whose only collision shape is a 0.4 x 0.2 m box 0.1 m ahead of its origin: its outline is not centred,
# so a turn moves it, unlike a box robot's.
WEDGE_URDF = """<?xml version="1.0"?>
<robot name="wedge">
  <link name="base_link">
    <collision><origin xyz="0.1 0 0.05"/><geometry><box size="0.4 0.2 0.1"/></geometry></collision>
  </link>
  <link name="laser"><collision><geometry><cylinder radius="0.02" length="0.02"/></geometry></collision></link>
  <joint name="laser_joint" type="fixed"><parent link="base_link"/><child link="laser"/>
    <origin xyz="0.1 0 0.12"/></joint>
</robot>
"""
WEDGE_CASE = """import "wedge.rei"
testcase Wedge {
  room Lab size 4 x 3 {
    robot bot : Wedge on F_1_1 yaw 90
  }
  mission M { goto F_3_2 }
}
"""
WEDGE_CATALOGUE = """catalogue Wedges {
  robot type Wedge : urdf "robots/wedge.urdf" speed 0.3 turn 2.0
    lidar link "laser" beams 90 range 0.1 to 3.0 rate 10
}
"""


def _points(attribute: str | None) -> list[tuple[float, float]]:
    """A polygon's points back in world metres (the page draws y up as -y)."""
    assert attribute
    return [(float(x), -float(y)) for x, y in (pair.split(",") for pair in attribute.split())]


def _same_ring(drawn: list[tuple[float, float]], expected: list[tuple[float, float]]) -> bool:
    """The same corners, in any start and direction, to the page's millimetres."""
    if len(drawn) != len(expected):
        return False
    for ring in (expected, expected[::-1]):
        for shift in range(len(ring)):
            turned = ring[shift:] + ring[:shift]
            if all(math.dist(a, b) <= 2e-3 for a, b in zip(drawn, turned, strict=True)):
                return True
    return False


def test_a_round_urdf_robot_is_drawn_as_its_circle_not_a_square(open_editor, page: Page) -> None:
    # copy=False: the case imports its catalogue, which names its URDF, both beside it; nothing is saved
    editor: Editor = open_editor("examples/robots/round_bot.rei", copy=False)
    robot = editor.session.state()["diagram"]["robot"]
    footprint = robot["footprint"]
    # round_bot.urdf: base_link's cylinder of radius 0.17 about the origin holds the wheels and the laser
    assert footprint["outline"]["type"] == "circle", footprint
    assert math.isclose(footprint["outline"]["radius"], 0.17, abs_tol=1e-9), footprint
    assert footprint["description"] == {"file": "round_bot.urdf", "args": {}, "lidar": "laser"}, footprint

    open_page(page, editor)
    body = element(page, "robot", "bot").locator("[data-outline]")
    assert body.count() == 1
    assert body.evaluate("e => e.tagName") == "circle"
    assert body.get_attribute("data-outline") == "circle"
    assert float(body.get_attribute("r") or "nan") == 0.17
    # on F_0_0's centre
    assert (float(body.get_attribute("cx") or "nan"), -float(body.get_attribute("cy") or "nan")) == (
        robot["x"], robot["y"])
    # not the 1 x 1 m box of the metamodel's default sizes
    assert element(page, "robot", "bot").locator("polygon:not(.heading)").count() == 0


def test_a_urdf_robot_polygon_turns_with_its_yaw(open_editor, page: Page, tmp_path: Path) -> None:
    (tmp_path / "robots").mkdir()
    (tmp_path / "robots" / "wedge.urdf").write_text(WEDGE_URDF, encoding="utf-8")
    (tmp_path / "wedge.rei").write_text(WEDGE_CATALOGUE, encoding="utf-8")
    case = tmp_path / "wedge_case.rei"
    case.write_text(WEDGE_CASE, encoding="utf-8")
    editor: Editor = open_editor(case, copy=False)
    robot = editor.session.state()["diagram"]["robot"]
    assert robot["footprint"]["outline"]["type"] == "polygon", robot
    assert robot["footprint"]["description"]["file"] == "robots/wedge.urdf"

    open_page(page, editor)
    x, y = robot["x"], robot["y"]
    # yaw 90: the box's x from -0.1 to 0.3 becomes y, its y from -0.1 to 0.1 becomes -x
    turned = [(x + 0.1, y - 0.1), (x + 0.1, y + 0.3), (x - 0.1, y + 0.3), (x - 0.1, y - 0.1)]
    body = element(page, "robot", "bot").locator('[data-outline="polygon"]')
    drawn = _points(body.get_attribute("points"))
    assert _same_ring(drawn, turned), drawn

    answer = editor.apply({"op": "rotateObject", "name": "bot", "yawDegrees": 180})
    page.reload()
    open_page(page, editor)
    assert answer["diagram"]["robot"]["yaw"] == 180
    drawn = _points(element(page, "robot", "bot").locator('[data-outline="polygon"]').get_attribute("points"))
    assert _same_ring(drawn, [(x - 0.3, y - 0.1), (x + 0.1, y - 0.1), (x + 0.1, y + 0.1), (x - 0.3, y + 0.1)]), drawn


def test_a_box_robot_is_drawn_as_its_box_as_before(open_editor, page: Page) -> None:
    editor: Editor = open_editor("examples/simple_navigation.rei")
    robot = editor.session.state()["diagram"]["robot"]
    footprint = robot["footprint"]
    assert footprint["outline"] is None and footprint["description"] is None, footprint
    open_page(page, editor)
    group = element(page, "robot", "tb3")
    assert group.locator("[data-outline]").count() == 0
    body = group.locator("polygon:not(.heading)")
    assert body.count() == 1
    hx, hy = footprint["sizeX"] / 2, footprint["sizeY"] / 2
    x, y = robot["x"], robot["y"]
    # yaw 0: the catalogue type's box about the floor's centre
    assert _same_ring(_points(body.get_attribute("points")),
                      [(x - hx, y - hy), (x + hx, y - hy), (x + hx, y + hy), (x - hx, y + hy)])
    halo = group.locator(".halo")
    assert math.isclose(float(halo.get_attribute("r") or "nan"), math.hypot(2 * hx, 2 * hy) * 0.6, abs_tol=1e-3)
