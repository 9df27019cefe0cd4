# SPDX-License-Identifier: EPL-2.0
"""The report of a simulated run in a room from an occupancy map (`rei sim`, then `rei report`), laid out by
headless Chromium (Playwright on Debian's chromium):
the map's picture covers exactly the map's extent (the generated map walls' union) and shows its cells where the
map has them: a wall dark, the unknown space between the rooms grey, a free floor light."""

from __future__ import annotations

import io
from pathlib import Path

import png
from playwright.sync_api import Browser

EXAMPLE = "examples/maps/two_rooms.rei"
EXTENT = (0.0, 0.0, 10.0, 6.0)  # examples/maps/two_rooms.yaml: 200 x 120 cells of 0.05 m from the origin


def test_the_report_draws_the_map_under_the_floors_where_the_map_is(run_cli, repo_root: Path, tmp_path: Path,
                                                                     browser: Browser) -> None:
    out = tmp_path / "run"
    simulated = run_cli("sim", repo_root / EXAMPLE, "-o", out, "--no-humans", timeout=300)
    assert simulated.returncode == 0, simulated.stdout + simulated.stderr
    reported = run_cli("report", out)
    assert reported.returncode == 0, reported.stdout + reported.stderr
    page = browser.new_page(viewport={"width": 1100, "height": 900})
    try:
        page.goto((out / "report.html").as_uri())
        picture = page.locator("#map-occupancy")
        picture.scroll_into_view_if_needed()
        box = picture.bounding_box()
        assert box is not None and box["width"] > 500
        walls = [b for b in (w.bounding_box() for w in page.locator("#map-world polygon.wall").all()) if b]
        assert len(walls) == 10  # the map's merged obstacle rectangles
        left, top = min(w["x"] for w in walls), min(w["y"] for w in walls)
        right = max(w["x"] + w["width"] for w in walls)
        bottom = max(w["y"] + w["height"] for w in walls)
        for found, expected in ((box["x"], left), (box["y"], top), (box["x"] + box["width"], right),
                                (box["y"] + box["height"], bottom)):
            # Chromium's boxes of the walls take in their outlines (0.8 px strokes, mitred); a cell is ~4 px
            assert abs(found - expected) < 2.0, (box, left, top, right, bottom)
        width, height, rows, _ = png.Reader(file=io.BytesIO(page.screenshot())).asRGB8()
        pixels = [bytes(row) for row in rows]

        def grey(x: float, y: float) -> float:
            """The mean of red, green and blue on screen at world (x, y), m."""
            px = round(box["x"] + (x - EXTENT[0]) / (EXTENT[2] - EXTENT[0]) * box["width"])
            py = round(box["y"] + (EXTENT[3] - y) / (EXTENT[3] - EXTENT[1]) * box["height"])
            assert 0 <= px < width and 0 <= py < height
            return sum(pixels[py][3 * px:3 * px + 3]) / 3

        partition, unknown, floor = grey(1.15, 0.8), grey(5.0, 1.0), grey(3.25, 1.25)
        assert partition < 110 < unknown < 200 < floor, (partition, unknown, floor)
    finally:
        page.close()
