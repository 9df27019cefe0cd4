# SPDX-License-Identifier: EPL-2.0
"""The report of a run in a room from an occupancy map: the map's picture under the floors, over exactly the
map's extent, and the map's cells as run.mcap's /map; a map that can not be read is said, not drawn."""

from __future__ import annotations

import base64
import io
import json
import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import png

from rei.report.html import render_report
from rei.report.run_data import load_run

from .runs import make_run

AddMap = Callable[[Path], Path]


def _attributes(tag: str) -> dict[str, str]:
    return dict(re.findall(r'([\w-]+)="([^"]*)"', tag))


def test_the_map_s_picture_lies_under_the_floors_over_the_map_s_extent(tmp_path: Path, occupancy_map: AddMap) -> None:
    out = make_run(tmp_path / "run")
    occupancy_map(out / "case")
    html = render_report(load_run(out))
    image = _attributes(re.search(r"<image id=\"map-occupancy\"[^>]*>", html).group(0))  # type: ignore[union-attr]
    floors = [[float(v) for v in re.findall(r"[-\d.]+", points)]
              for points in re.findall(r'<polygon class="floor" points="([^"]+)"', html)]
    xs = [v for f in floors for v in f[0::2]]
    ys = [v for f in floors for v in f[1::2]]
    # the fixture's floors cover its 6 x 4 m exactly, as the map does
    assert float(image["x"]) == min(xs) and float(image["y"]) == min(ys)
    assert abs(float(image["x"]) + float(image["width"]) - max(xs)) < 0.02
    assert abs(float(image["y"]) + float(image["height"]) - max(ys)) < 0.02
    assert html.index('id="map-occupancy"') < html.index('id="map-world"')  # under the floors
    assert 'class="floor" points' in html and 'fill-opacity="0.45"' in html  # which let it show through
    pixels = png.Reader(file=io.BytesIO(base64.b64decode(image["href"].split(",", 1)[1]))).read()
    rows = np.vstack([np.asarray(row) for row in pixels[2]])
    assert rows.shape == (80, 120) and rows[80 - 1 - 2, 7] == 0 and int((rows == 0).sum()) == 1


def test_other_rooms_have_no_picture_and_a_broken_map_is_noted(tmp_path: Path, occupancy_map: AddMap) -> None:
    out = make_run(tmp_path / "run")
    assert "map-occupancy" not in render_report(load_run(out))
    occupancy_map(out / "case")
    (out / "case" / "map.yaml").write_text("image: map.pgm\nresolution: 0.05\n", encoding="utf-8")
    data = load_run(out)
    assert data.picture is None and data.world is not None
    assert any("the room's occupancy map is not drawn" in note and "origin: missing" in note for note in data.notes)
    assert "map-occupancy" not in render_report(data) and 'class="floor"' in render_report(data)


def test_the_mcap_carries_the_map_as_a_foxglove_grid(tmp_path: Path, occupancy_map: AddMap) -> None:
    from mcap.reader import make_reader

    from rei.report import write_mcap

    out = make_run(tmp_path / "run")
    occupancy_map(out / "case")
    with open(write_mcap(out), "rb") as f:
        found = [(schema.name, json.loads(message.data)) for schema, channel, message in
                 make_reader(f).iter_messages(topics=["/map"])]
    assert [name for name, _ in found] == ["foxglove.Grid"]
    grid = found[0][1]
    assert (grid["frame_id"], grid["column_count"], grid["cell_size"]) == ("world", 120, {"x": 0.05, "y": 0.05})
    assert grid["pose"]["position"] == {"x": 0.0, "y": 0.0, "z": 0.0}
    assert (grid["row_stride"], grid["cell_stride"], grid["fields"]) == (120, 1, [{"name": "occupancy", "offset": 0,
                                                                                    "type": 2}])
    cells = np.frombuffer(base64.b64decode(grid["data"]), dtype=np.int8).reshape(80, 120)
    assert cells[2, 7] == 100 and int((cells != 0).sum()) == 1  # row 2 from the bottom: rows go up from y = 0
