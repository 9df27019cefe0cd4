# SPDX-License-Identifier: EPL-2.0
"""A campaign's generated rooms in a real building: ``rooms: {map: FILE.yaml, floor_size: M}`` furnishes the
occupancy map as `rei gen-rooms --map` does, each room naming the map relative to OUT/rooms; a case is generated
again when its map changed, and a case written elsewhere (a search's candidates) names its map from there."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rei.campaign import SpecError, parse_spec, plan_campaign
from rei.rooms import generate_map_room, load_site, render

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
MAPS = EXAMPLES / "maps"
MAP = MAPS / "two_rooms.yaml"


def _spec(rooms: dict) -> dict:
    return {"groups": [{"name": "building", "rooms": rooms}]}


def test_rooms_on_a_map_are_planned_as_gen_rooms_writes_them(tmp_path: Path) -> None:
    parsed = parse_spec(_spec({"map": "maps/two_rooms.yaml", "floor_size": 0.5, "count": 2, "seed": 1}),
                        base=EXAMPLES)
    cases = plan_campaign(parsed, tmp_path).cases
    assert [c.key for c in cases] == ["two_rooms_sparse_h1_s1_01", "two_rooms_sparse_h1_s1_02"]
    rooms = tmp_path.resolve() / "rooms"
    named = re.search(r'room Room occupancy "([^"]+)" floorSize 0\.5 \{', cases[0].text)
    assert named is not None and (rooms / named.group(1)).resolve() == MAP.resolve()
    assert cases[0].text == render(generate_map_room(load_site(MAP, 0.5), seed=1, index=1), 2, rooms)


@pytest.mark.parametrize(("rooms", "message"), [
    ({"size": "small", "map": "maps/two_rooms.yaml"}, "give exactly one of 'size' (a room class) and 'map'"),
    ({}, "give exactly one of 'size' (a room class) and 'map'"),
    ({"size": "small", "floor_size": 0.5}, "'floor_size' and 'unknown_free' describe the floors of 'map'"),
    ({"map": "maps/two_rooms.yaml", "floor_size": 0.2}, "no furniture type fits a floor of 0.2 m"),
    ({"map": "maps/nope.yaml"}, "nope.yaml:1:1: file: cannot read the map file"),
])
def test_wrong_map_settings_are_refused_at_the_door(rooms: dict, message: str) -> None:
    with pytest.raises(SpecError, match=r"groups\[0\]: rooms: .*" + re.escape(message)):
        parse_spec(_spec(rooms), base=EXAMPLES)


def test_a_changed_map_regenerates_the_case_and_moved_cases_keep_their_building(tmp_path: Path) -> None:
    from rei.campaign.prepare import relocated_imports, source_digest

    for name in ("two_rooms.rei", "two_rooms.yaml", "two_rooms.pgm"):
        (tmp_path / name).write_bytes((MAPS / name).read_bytes())
    case = tmp_path / "two_rooms.rei"
    before = source_digest(case)
    image = tmp_path / "two_rooms.pgm"
    data = bytearray(image.read_bytes())
    data[-1] ^= 0xFF  # one pixel of the map's image
    image.write_bytes(bytes(data))
    assert source_digest(case) != before
    text = case.read_text(encoding="utf-8")
    moved = relocated_imports(text, tmp_path, tmp_path / "search" / "candidates")
    assert 'room Office occupancy "../../two_rooms.yaml" floorSize 0.5 {' in moved
    assert moved.replace('"../../two_rooms.yaml"', '"two_rooms.yaml"') == text


def test_the_building_example_spec_plans_its_rooms_on_the_map(tmp_path: Path) -> None:
    from rei.campaign import load_spec

    plan = plan_campaign(load_spec(EXAMPLES / "campaigns" / "building.yaml"), tmp_path)
    assert [c.key for c in plan.cases] == [f"two_rooms_sparse_h1_s1_0{i}" for i in (1, 2, 3)]
    assert len(plan.runs) == 3 * 2
    named = re.search(r'occupancy "([^"]+)"', plan.cases[0].text)
    assert named is not None and (tmp_path.resolve() / "rooms" / named.group(1)).resolve() == MAP.resolve()
