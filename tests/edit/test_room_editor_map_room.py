# SPDX-License-Identifier: EPL-2.0
"""The room editor on a room from an occupancy map, in Debian's chromium: the map is drawn under the floors
where the map has its cells, the floors (the map's free blocks) cannot be added to or removed, and furniture
and goals are placed on them as in any room, saved to the `.rei` text."""

from __future__ import annotations

import difflib
import io
import shutil
from pathlib import Path

import png
from edit_helpers import SHOTS, Editor
from page_helpers import centre, click_floor, drag, element, open_page, settled
from playwright.sync_api import Page

MAPS = Path(__file__).resolve().parents[2] / "examples" / "maps"


def test_the_map_shows_under_the_floors_and_furniture_and_goals_are_placed_on_them(
    open_editor, page: Page, run_cli, tmp_path: Path
) -> None:
    for name in ("two_rooms.rei", "two_rooms.yaml", "two_rooms.pgm"):  # the example with its map
        shutil.copyfile(MAPS / name, tmp_path / name)
    editor: Editor = open_editor(tmp_path / "two_rooms.rei", copy=False)
    case, session = editor.case, editor.session
    before = case.read_text(encoding="utf-8")
    open_page(page, editor)
    page.locator('[data-kind="map"]').wait_for(state="attached")
    assert page.locator('[data-kind="ghost"]').count() == 0  # the map makes the floors: none to add
    assert page.locator('[data-kind="floor"]').count() == len(session.state()["diagram"]["room"]["floors"]) == 129

    # world to screen from two floor centres: F_1_1 at (0.75, 0.75) m, F_18_10 at (9.25, 5.25) m
    (ax, ay), (bx, by) = centre(element(page, "floor", "F_1_1")), centre(element(page, "floor", "F_18_10"))
    kx, ky = (bx - ax) / 8.5, (ay - by) / 4.5
    assert abs(kx - ky) < 0.01 * kx

    def screen(x: float, y: float) -> tuple[int, int]:
        return round(ax + (x - 0.75) * kx), round(ay - (y - 0.75) * ky)

    picture = page.locator('[data-kind="map"]').bounding_box()
    assert picture is not None
    for found, expected in ((picture["x"], screen(0.0, 0.0)[0]), (picture["y"], screen(0.0, 6.0)[1]),
                            (picture["width"], 10.0 * kx), (picture["height"], 6.0 * ky)):
        assert abs(found - expected) < 1.5, (picture, kx)
    shot = page.screenshot(path=str(SHOTS / "map-room.png"))
    _, _, rows, _ = png.Reader(file=io.BytesIO(shot)).asRGB8()
    pixels = [bytes(row) for row in rows]

    def grey(x: float, y: float) -> float:
        px, py = screen(x, y)
        return sum(pixels[py][3 * px:3 * px + 3]) / 3

    # the partition wall (no floor over it), the unknown space between the rooms, a floor over free cells
    partition, unknown, floor = grey(1.15, 0.8), grey(5.0, 1.0), grey(3.25, 1.25)
    assert partition < 110 < unknown < 215 < floor, (partition, unknown, floor)

    version = int(session.status()["version"])
    drag(page, element(page, "object", "desk"), element(page, "floor", "F_14_3"))
    version = settled(editor, page, version)
    page.click("#add-goal")
    click_floor(page, "F_17_9")
    settled(editor, page, version)
    page.click("#save")
    page.locator("#dirty").wait_for(state="hidden")

    after = case.read_text(encoding="utf-8")
    assert run_cli("validate", case).returncode == 0
    changed = [line for line in difflib.ndiff(before.splitlines(), after.splitlines()) if line[:1] in "+-"]
    assert [line[2:].strip() for line in changed if line.startswith("-")] == ["object desk : Table on F_3_9"], changed
    assert [line[2:].strip() for line in changed if line.startswith("+")] == ["object desk : Table on F_14_3",
                                                                              "goto F_17_9"], changed
