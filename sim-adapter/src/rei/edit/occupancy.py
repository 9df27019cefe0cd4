# SPDX-License-Identifier: EPL-2.0
"""The occupancy map under a room from an occupancy map, for the room editor's page: the map of the engine's
diagram (``room.map``: the DSL's own reading of the room, relative paths resolved), as the picture the report and
the live view draw.

A map that cannot be read gives no picture: the validator already puts its error on the room. Pictures are kept
while the map's files are unchanged, so a State costs no map reading.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from rei.maps import MapError, load_map, map_picture


class MapPictures:
    """The picture of the map a diagram's room is drawn on, cached by the map files' modification times."""

    def __init__(self) -> None:
        self._key: tuple[Any, ...] | None = None
        self._value: dict[str, Any] | None = None

    def of_diagram(self, diagram: Mapping[str, Any] | None) -> dict[str, Any] | None:
        """``{png, extent, origin}`` (a data URI, the metres it covers, the map's origin), or None for a room
        without a map (or a text the engine could not lay out)."""
        room = (diagram or {}).get("room") or {}
        occupancy = room.get("map")
        if not occupancy:
            return None
        yaml = Path(occupancy["yaml"])
        key = (yaml, *_stamps(yaml))
        if key != self._key:
            self._key, self._value = key, _picture(yaml)
        return self._value


def _picture(yaml: Path) -> dict[str, Any] | None:
    try:
        occupancy = load_map(yaml)
    except MapError:
        return None
    picture = map_picture(occupancy)
    return {"png": picture.data_uri(), "extent": list(picture.extent), "origin": list(occupancy.origin[:2])}


def _stamps(yaml: Path) -> tuple[int | None, ...]:
    """The YAML's and the images' (any file beside it) modification times: a changed map is read again."""
    stamps: list[int | None] = []
    for path in (yaml, *sorted(yaml.parent.glob(f"{yaml.stem}*"))) if yaml.parent.is_dir() else (yaml,):
        try:
            stamps.append(path.stat().st_mtime_ns)
        except OSError:
            stamps.append(None)
    return tuple(stamps)

