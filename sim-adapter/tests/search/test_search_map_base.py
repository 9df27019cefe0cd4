# SPDX-License-Identifier: EPL-2.0
"""A search in a real building: a search spec's ``rooms: {map: FILE.yaml, ...}`` base case is the first room
`rei gen-rooms --map` writes, in the search's folder, naming the map relative to itself."""

from __future__ import annotations

import shutil
from pathlib import Path

from spec_helpers import parse

from rei.rooms import generate_map_room, load_site, render
from rei.search.base import with_base_case

MAPS = Path(__file__).resolve().parents[3] / "examples" / "maps"
SPEC = """\
name: building
rooms: {map: maps/two_rooms.yaml, floor_size: 0.5, humans: 1, seed: 2}
parameters:
  - {object: OBJECT, floor: any}
objectives:
  - utility
"""


def test_the_base_case_on_a_map_is_the_room_gen_rooms_writes(tmp_path: Path) -> None:
    (tmp_path / "maps").mkdir()
    for name in ("two_rooms.yaml", "two_rooms.pgm"):
        shutil.copyfile(MAPS / name, tmp_path / "maps" / name)
    room = generate_map_room(load_site(tmp_path / "maps" / "two_rooms.yaml", 0.5), humans=1, seed=2)
    spec = parse(SPEC.replace("OBJECT", room.furniture[0].name), tmp_path)
    assert spec.rooms is not None and spec.rooms.map == (tmp_path / "maps" / "two_rooms.yaml").resolve()
    lines: list[str] = []
    based = with_base_case(spec, tmp_path / "out", lines.append)
    assert based.case == tmp_path / "out" / "base" / f"{room.stem}.rei"
    text = based.case.read_text(encoding="utf-8")
    assert text == render(room, 1, based.case.parent)
    assert 'room Room occupancy "../../maps/two_rooms.yaml" floorSize 0.5 {' in text
