# SPDX-License-Identifier: EPL-2.0
"""The room editor's map picture (rei.edit.occupancy): the map of the engine's diagram, read again when the map
changes, none for other rooms or maps that cannot be read."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

from rei.edit.occupancy import MapPictures

MAPS = Path(__file__).resolve().parents[3] / "examples" / "maps"


def test_the_text_s_map_is_drawn_and_read_again_when_it_changes(tmp_path: Path) -> None:
    for name in ("two_rooms.yaml", "two_rooms.pgm"):
        shutil.copyfile(MAPS / name, tmp_path / name)
    pictures = MapPictures()
    text = _diagram(tmp_path / "two_rooms.yaml")
    first = pictures.of_diagram(text)
    assert first is not None and first["extent"] == [0.0, 0.0, 10.0, 6.0] and first["origin"] == [0.0, 0.0]
    assert first["png"].startswith("data:image/png;base64,")
    assert pictures.of_diagram(text) is first  # unchanged files: the same picture, not read again
    yaml = tmp_path / "two_rooms.yaml"
    yaml.write_text(yaml.read_text(encoding="utf-8").replace("origin: [0.0, 0.0, 0.0]", "origin: [-2.0, 1.0, 0.0]"),
                    encoding="utf-8")
    stat = yaml.stat()
    os.utime(yaml, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    moved = pictures.of_diagram(text)
    assert moved is not None and moved["origin"] == [-2.0, 1.0] and moved["extent"] == [-2.0, 1.0, 8.0, 7.0]


def test_no_picture_for_other_rooms_or_unreadable_maps(tmp_path: Path) -> None:
    pictures = MapPictures()
    assert pictures.of_diagram(None) is None  # a text the engine could not lay out
    assert pictures.of_diagram({"room": {"name": "Lab", "form": "grid", "map": None}}) is None
    assert pictures.of_diagram(_diagram(tmp_path / "missing.yaml")) is None
    assert MapPictures().of_diagram(_diagram(MAPS / "two_rooms.yaml")) is not None


def _diagram(yaml: Path) -> dict:
    """The part of the engine's diagram the picture reads (org.rei.dsl.edit's Diagram.Room.map)."""
    return {"room": {"name": "Office", "form": "occupancy", "map": {"yaml": str(yaml)}}}
