# SPDX-License-Identifier: EPL-2.0
"""A search spec whose base case is a generated room (``rooms:``, the campaign spec's settings): read by the
campaign's reader, exclusive with ``case:``, every mistake placed at FILE:LINE:COLUMN; the base case written into
the search's folder is the room `rei gen-rooms` writes with the same settings."""

from __future__ import annotations

from pathlib import Path

import pytest
from spec_helpers import error_of, parse

from rei.campaign.spec import RoomSettings
from rei.rooms import generate_room, render
from rei.search.base import with_base_case

GOOD = """\
name: generated
rooms: {size: small, density: sparse, humans: 1, seed: 0}
parameters:
  - {object: bin1, floor: any}
objectives:
  - utility
"""


def test_a_rooms_spec_parses_to_its_settings_without_a_case(tmp_path: Path) -> None:
    spec = parse(GOOD, tmp_path)
    assert spec.case is None
    assert spec.rooms == RoomSettings(size="small", density="sparse", humans=1, count=1, seed=0)


@pytest.mark.parametrize(("change", "expected"), [
    # both: placed at the second key, 'rooms'
    (("name: generated", "case: case.rei"),
     ("s.yaml:2:1: give either 'case' (a .rei file) or 'rooms' (generated-room settings as in campaign specs), "
      "not both")),
    # a bad setting: at its value
    (("size: small", "size: huge"), "s.yaml:2:15: size must be one of small, medium, large, got 'huge'"),
    (("humans: 1", "humans: 9"), "s.yaml:2:47: a small room holds 0 to "),
    (("seed: 0", "seed: -2"), "s.yaml:2:56: 'seed' must be >= 0, got -2"),
    # an unknown key and count (a search starts from one room): at the key
    (("seed: 0}", "seed: 0, colour: red}"), "s.yaml:2:59: unknown key 'colour'"),
    (("seed: 0}", "seed: 0, count: 3}"), "s.yaml:2:59: a search starts from one generated room: leave out 'count'"),
    (("rooms: {", "rooms: [{"), "s.yaml:2:8: 'rooms' must be a mapping"),
])
def test_room_setting_mistakes_are_placed(tmp_path: Path, change: tuple[str, str], expected: str) -> None:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    text = GOOD.replace(*change, 1)
    if change[1].startswith("rooms: ["):
        text = text.replace("seed: 0}", "seed: 0}]")
    assert error_of(text, tmp_path).startswith(expected)


def test_neither_case_nor_rooms_is_refused_at_the_top(tmp_path: Path) -> None:
    text = GOOD.replace("rooms: {size: small, density: sparse, humans: 1, seed: 0}\n", "")
    assert error_of(text, tmp_path) == ("s.yaml:1:1: give either 'case' (a .rei file) or 'rooms' (generated-room "
                                        "settings as in campaign specs)")


def test_the_base_case_is_the_room_gen_rooms_writes(tmp_path: Path) -> None:
    lines: list[str] = []
    spec = with_base_case(parse(GOOD, tmp_path), tmp_path / "out", lines.append)
    room = generate_room("small", "sparse", 1, 0)
    assert spec.case == tmp_path / "out" / "base" / f"{room.stem}.rei"
    assert spec.case.read_text(encoding="utf-8") == render(room, 1, spec.case.parent)
    # the names the parameters address are on the terminal
    assert "objects: bin1, shelf1, bin2, box1, chair1; humans: walker1; robot: tb3; goals: 0 to 1" in lines[1]
    given = parse(GOOD.replace("rooms: {size: small, density: sparse, humans: 1, seed: 0}", "case: c.rei"),
                  _with_case(tmp_path))
    assert with_base_case(given, tmp_path / "out2", lines.append) is given  # a given case stays as it is


def _with_case(folder: Path) -> Path:
    (folder / "c.rei").write_text("testcase T {}\n", encoding="utf-8")
    return folder


def test_the_example_generated_room_spec_parses() -> None:
    from rei.search.spec import load_search_spec

    example = Path(__file__).resolve().parents[3] / "examples" / "search" / "generated.yaml"
    spec = load_search_spec(example)
    assert spec.case is None and spec.rooms is not None and spec.rooms.humans == 1
    assert [p.key for p in spec.parameters] == ["walker1.start", "walker1.speed", "walker1.points", "chair1.floor"]
