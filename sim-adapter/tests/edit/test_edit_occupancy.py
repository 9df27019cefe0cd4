# SPDX-License-Identifier: EPL-2.0
"""The room editor's map picture (rei.edit.occupancy): the map a test case's text names, relative to the file,
read again when the map changes, none for other rooms, commented-out rooms or maps that cannot be read."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

from rei.edit.occupancy import MapPictures

MAPS = Path(__file__).resolve().parents[3] / "examples" / "maps"


def test_the_text_s_map_is_drawn_and_read_again_when_it_changes(tmp_path: Path) -> None:
    for name in ("two_rooms.yaml", "two_rooms.pgm"):
        shutil.copyfile(MAPS / name, tmp_path / name)
    pictures = MapPictures(tmp_path)
    text = 'testcase T {\n  room Office occupancy "two_rooms.yaml" floorSize 0.5 { robot r : Waffle on F_2_7 }\n}\n'
    first = pictures.of_text(text)
    assert first is not None and first["extent"] == [0.0, 0.0, 10.0, 6.0] and first["origin"] == [0.0, 0.0]
    assert first["png"].startswith("data:image/png;base64,")
    assert pictures.of_text(text) is first  # unchanged files: the same picture, not read again
    yaml = tmp_path / "two_rooms.yaml"
    yaml.write_text(yaml.read_text(encoding="utf-8").replace("origin: [0.0, 0.0, 0.0]", "origin: [-2.0, 1.0, 0.0]"),
                    encoding="utf-8")
    stat = yaml.stat()
    os.utime(yaml, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    moved = pictures.of_text(text)
    assert moved is not None and moved["origin"] == [-2.0, 1.0] and moved["extent"] == [-2.0, 1.0, 8.0, 7.0]


def test_no_picture_for_other_rooms_commented_maps_or_unreadable_maps(tmp_path: Path) -> None:
    pictures = MapPictures(tmp_path)
    assert pictures.of_text("testcase T { room Lab size 6 x 4 { robot r : Waffle on F_0_0 } }") is None
    commented = '// room Office occupancy "x.yaml"\n/* room Office occupancy "y.yaml" */\nroom Lab size 2 x 2 {}'
    assert pictures.of_text(commented) is None
    assert pictures.of_text('room Office occupancy "missing.yaml" { }') is None
    assert MapPictures(MAPS.parent).of_text('room Office occupancy "maps/two_rooms.yaml" { }') is not None
