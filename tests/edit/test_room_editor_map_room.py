# SPDX-License-Identifier: EPL-2.0
"""The room editor on a room from an occupancy map, in Debian's chromium: the map is drawn under the floors
where the map has its cells, the floors (the map's free blocks) cannot be added to or removed, and furniture
and goals are placed on them as in any room, saved to the `.rei` text."""

from __future__ import annotations

import difflib
import io
import shutil
import time
from collections.abc import Iterator
from pathlib import Path

import png
import pytest
from playwright.sync_api import Browser, Locator, Page

from rei import toolchain
from rei.edit import EditEngine, EditServer, EditSession, engine_command

REPO = Path(__file__).resolve().parents[2]
MAPS = REPO / "examples" / "maps"
SHOTS = REPO / "target" / "edit"


@pytest.fixture
def editor(tmp_path: Path, room_editor_jar: Path, java: toolchain.Java) -> Iterator[tuple[Path, EditSession, str]]:
    """The example map room, copied with its map, open behind a real server."""
    for name in ("two_rooms.rei", "two_rooms.yaml", "two_rooms.pgm"):
        shutil.copyfile(MAPS / name, tmp_path / name)
    case = tmp_path / "two_rooms.rei"
    session = EditSession(case, EditEngine(engine_command(room_editor_jar, java.executable), timeout=120.0))
    server = EditServer(session).start()
    try:
        yield case, session, server.url
    finally:
        server.stop()
        session.close()


@pytest.fixture
def page(browser: Browser) -> Iterator[Page]:
    opened = browser.new_page(viewport={"width": 1400, "height": 900})
    opened.set_default_timeout(60_000)
    errors: list[str] = []
    opened.on("pageerror", lambda error: errors.append(str(error)))
    yield opened
    opened.close()
    assert not errors, f"the page threw: {errors}"


def _floor(page: Page, name: str) -> Locator:
    return page.locator(f'[data-kind="floor"][data-name="{name}"]').first


def _centre(locator: Locator) -> tuple[float, float]:
    box = locator.bounding_box()
    assert box is not None, f"{locator} is not drawn"
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def _settled(session: EditSession, page: Page, version: int) -> int:
    deadline = time.monotonic() + 60.0
    while (now := int(session.status()["version"])) <= version:
        assert time.monotonic() < deadline, "no change reached the editor within 60 s"
        time.sleep(0.05)
    page.wait_for_function("v => (window.reiEdit?.state?.version ?? 0) >= v", arg=now)
    return now


def test_the_map_shows_under_the_floors_and_furniture_and_goals_are_placed_on_them(
    editor: tuple[Path, EditSession, str], page: Page, run_cli
) -> None:
    case, session, url = editor
    before = case.read_text(encoding="utf-8")
    page.goto(url)
    page.locator('[data-kind="robot"]').wait_for()
    page.locator('[data-kind="map"]').wait_for(state="attached")
    assert page.locator('[data-kind="ghost"]').count() == 0  # the map makes the floors: none to add
    assert page.locator('[data-kind="floor"]').count() == len(session.state()["diagram"]["room"]["floors"]) == 129

    # world to screen from two floor centres: F_1_1 at (0.75, 0.75) m, F_18_10 at (9.25, 5.25) m
    (ax, ay), (bx, by) = _centre(_floor(page, "F_1_1")), _centre(_floor(page, "F_18_10"))
    kx, ky = (bx - ax) / 8.5, (ay - by) / 4.5
    assert abs(kx - ky) < 0.01 * kx

    def screen(x: float, y: float) -> tuple[int, int]:
        return round(ax + (x - 0.75) * kx), round(ay - (y - 0.75) * ky)

    picture = page.locator('[data-kind="map"]').bounding_box()
    assert picture is not None
    for found, expected in ((picture["x"], screen(0.0, 0.0)[0]), (picture["y"], screen(0.0, 6.0)[1]),
                            (picture["width"], 10.0 * kx), (picture["height"], 6.0 * ky)):
        assert abs(found - expected) < 1.5, (picture, kx)
    SHOTS.mkdir(parents=True, exist_ok=True)
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
    desk = page.locator('[data-kind="object"][data-name="desk"]').first
    (x0, y0), (x1, y1) = _centre(desk), _centre(_floor(page, "F_14_3"))
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, steps=5)
    page.mouse.move(x1, y1, steps=5)
    page.mouse.up()
    version = _settled(session, page, version)
    page.click("#add-goal")
    page.mouse.click(*_centre(_floor(page, "F_17_9")))
    version = _settled(session, page, version)
    page.click("#save")
    page.locator("#dirty").wait_for(state="hidden")

    after = case.read_text(encoding="utf-8")
    assert run_cli("validate", case).returncode == 0
    changed = [line for line in difflib.ndiff(before.splitlines(), after.splitlines()) if line[:1] in "+-"]
    assert [line[2:].strip() for line in changed if line.startswith("-")] == ["object desk : Table on F_3_9"], changed
    assert [line[2:].strip() for line in changed if line.startswith("+")] == ["object desk : Table on F_14_3",
                                                                              "goto F_17_9"], changed
