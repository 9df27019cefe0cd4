# SPDX-License-Identifier: EPL-2.0
"""The room editor's state of a room from an occupancy map, from a real edit engine: the picture under the floors is
the map of the engine's diagram (the DSL's reading of the room, so every order of its header works: here
floorSize first), and the paths the page receives are relative to the case's folder, not the machine's."""

from __future__ import annotations

import shutil
from pathlib import Path

from edit_helpers import Editor

REPO_ROOT = Path(__file__).resolve().parents[2]
MAPS = REPO_ROOT / "examples" / "maps"


def test_a_map_room_written_floor_size_first_is_drawn_on_its_map(open_editor, tmp_path: Path) -> None:
    folder = tmp_path / "case"
    (folder / "maps").mkdir(parents=True)
    for name in ("two_rooms.yaml", "two_rooms.pgm"):
        shutil.copyfile(MAPS / name, folder / "maps" / name)
    text = (MAPS / "two_rooms.rei").read_text(encoding="utf-8")
    header = 'room Office occupancy "two_rooms.yaml" floorSize 0.5'
    assert header in text
    case = folder / "two_rooms.rei"
    case.write_text(text.replace(header, 'room Office floorSize 0.5 /* map: */ occupancy "maps/two_rooms.yaml"'),
                    encoding="utf-8")
    editor: Editor = open_editor(case, copy=False)
    state = editor.session.state()
    assert state["occupancy"] is not None, state["issues"]
    assert state["occupancy"]["extent"] == [0.0, 0.0, 10.0, 6.0] and state["occupancy"]["png"].startswith("data:")
    room_map = state["diagram"]["room"]["map"]
    assert (room_map["yaml"], room_map["image"]) == ("maps/two_rooms.yaml", "maps/two_rooms.pgm")
    assert str(tmp_path) not in str(state["diagram"])
