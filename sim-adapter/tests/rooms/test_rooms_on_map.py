# SPDX-License-Identifier: EPL-2.0
"""Generated rooms on a real building's occupancy map (rei.rooms.on_map, `rei gen-rooms --map`): everything on the
map's free floors, furniture clear of its obstacle cells, every leg found by the reference planner, the same room
for the same seed, written as an `occupancy` room naming the map relative to the file."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from rei.maps import obstacle_mask
from rei.rooms import MapSite, Room, generate_map_room, load_site, render, write_map_rooms
from rei.rooms.check import static_map, unplannable_legs

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "maps" / "two_rooms.yaml"
SHARED_MAPS = ROOT.parent / "shared" / "data" / "maps"


def _obstacle_cells_under(site: MapSite, box: tuple[float, float, float, float]) -> int:
    occupancy = site.occupancy
    ox, oy, _ = occupancy.origin
    res = occupancy.resolution
    mask = obstacle_mask(occupancy, site.unknown_free)
    c0, r0 = math.floor((box[0] - ox) / res), math.floor((box[1] - oy) / res)
    c1, r1 = math.ceil((box[2] - ox) / res), math.ceil((box[3] - oy) / res)
    return int(mask[max(0, r0):r1, max(0, c0):c1].sum())


def _assert_sound(room: Room) -> None:
    site = room.site
    assert site is not None
    cells = [room.start, *(g.cell for g in room.goals), *(c for w in room.walkers for c in w.cells()),
             *(f.cell for f in room.furniture)]
    assert all(cell in site.free for cell in cells)
    assert len({f.cell for f in room.furniture}) == len(room.furniture)
    for item in room.furniture:
        cx, cy = room.centre(item.cell)
        hx, hy = item.half_extents()
        assert _obstacle_cells_under(site, (cx - hx, cy - hy, cx + hx, cy + hy)) == 0, item
        assert max(item.size) <= 1.2 * site.floor_size
    assert unplannable_legs(room) == []


def test_a_room_on_the_example_map_is_sound_and_the_same_for_the_same_seed() -> None:
    site = load_site(EXAMPLE, 0.5)
    room = generate_map_room(site, "sparse", 1, seed=3)
    _assert_sound(room)
    assert 5 <= len(room.furniture) <= round(0.12 * len(site.free)) and len(room.walkers) == 1
    assert {f.type for f in room.furniture} <= {"Box", "Chair", "Bin"}  # 0.5 m floors: no table or shelf
    assert render(generate_map_room(load_site(EXAMPLE, 0.5), "sparse", 1, seed=3)) == render(room)
    assert render(generate_map_room(site, "sparse", 1, seed=4)) != render(room)
    walls = static_map(room).obstacles
    assert len(walls) == 10 + len(room.furniture)  # the map's 10 merged rectangles and the furniture


@pytest.mark.parametrize(("name", "floor_size", "unknown_free"), [("depot", 1.0, False),
                                                                   ("tb3_sandbox", 0.5, True)])
def test_rooms_on_nav2_s_maps_are_sound(name: str, floor_size: float, unknown_free: bool) -> None:
    site = load_site(SHARED_MAPS / f"{name}.yaml", floor_size, unknown_free)
    room = generate_map_room(site, "dense", 2, seed=1)
    _assert_sound(room)
    assert len(room.furniture) > 30 and len(room.walkers) == 2


def test_the_written_room_names_the_map_relative_to_itself(tmp_path: Path) -> None:
    out = tmp_path / "deep" / "rooms"
    site = load_site(EXAMPLE, 0.5)
    (room, path), = write_map_rooms(out, site, seed=2)
    text = path.read_text(encoding="utf-8")
    written = re.search(r'room Room occupancy "([^"]+)" floorSize 0\.5 \{', text)
    assert written is not None and not Path(written.group(1)).is_absolute()
    assert (out / written.group(1)).resolve() == EXAMPLE.resolve()
    assert "`rei gen-rooms --map two_rooms.yaml --floor-size 0.5 --density sparse --humans 1 --seed 2`" in text
    assert f"robot tb3 : Waffle on F_{room.start[0]}_{room.start[1]}" in text
    assert "unknownFree" not in text
    sandbox = render(generate_map_room(load_site(SHARED_MAPS / "tb3_sandbox.yaml", 0.5, True), seed=0), 1, out)
    assert re.search(r'occupancy "[^"]+tb3_sandbox\.yaml" unknownFree floorSize 0\.5 \{', sandbox)


def test_bad_settings_are_refused_with_a_reason(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match=r"no furniture type fits a floor of 0\.2 m"):
        generate_map_room(load_site(EXAMPLE, 0.2))
    with pytest.raises(ValueError, match=r"no free floor of 1 m in the map .* or an unknown cell"):
        load_site(SHARED_MAPS / "tb3_sandbox.yaml", 1.0)  # the arena is all unknown-bordered at 1 m
    grey = np.full((20, 20), 254, dtype=np.uint8)
    (tmp_path / "m.pgm").write_bytes(b"P5\n20 20\n255\n" + grey.tobytes())
    (tmp_path / "m.yaml").write_text("image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                                     "occupied_thresh: 0.65\nfree_thresh: 0.196\n", encoding="utf-8")
    with pytest.raises(ValueError, match="largest area of connected free floors has 1 floor"):
        generate_map_room(load_site(tmp_path / "m.yaml", 1.0))


def test_the_command_writes_map_rooms_and_refuses_a_bad_map(tmp_path: Path) -> None:
    def gen(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "rei.cli", "gen-rooms", *args], capture_output=True, text=True,
                              timeout=120, check=False)

    done = gen("--map", str(EXAMPLE), "--floor-size", "0.5", "--count", "2", "--seed", "5", "-o", str(tmp_path / "a"))
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in (tmp_path / "a").glob("*.rei")) == ["two_rooms_sparse_h1_s5_01.rei",
                                                                      "two_rooms_sparse_h1_s5_02.rei"]
    (tmp_path / "bad.yaml").write_text("image: nowhere.pgm\nresolution: 0.05\n", encoding="utf-8")
    done = gen("--map", str(tmp_path / "bad.yaml"), "-o", str(tmp_path / "b"))
    assert done.returncode == 2 and f"{tmp_path / 'bad.yaml'}:1:1: origin: missing" in done.stderr
    done = gen("--size", "small", "--floor-size", "0.5", "-o", str(tmp_path / "c"))
    assert done.returncode == 2 and "give the map too" in done.stderr
