# SPDX-License-Identifier: EPL-2.0
"""rei.maps.references: the map a room's header names, read as the grammar's lexer reads the text, whatever the
order of the header's unordered group (floorSize before or after the layout), with comments and strings anywhere;
and relocated_imports (rei search) rewrites exactly that string."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from rei.campaign.prepare import relocated_imports
from rei.maps.references import map_path, map_reference

PARTS = ('occupancy "maps/m.yaml"', "floorSize 0.5", 'occupancy "maps/m.yaml" unknownFree')


@pytest.mark.parametrize("header", [
    *(" ".join(p) for p in itertools.permutations(PARTS[:2])),
    *(" ".join(p) for p in itertools.permutations((PARTS[2], PARTS[1]))),
    'floorSize 1 /* the map: */ occupancy // its YAML\n "maps/m.yaml"',
    "floorSize 0.5\n  occupancy 'maps/m.yaml'",
])
def test_the_map_is_read_in_any_order_of_the_header(header: str) -> None:
    text = f'import "cat.rei"\ntestcase T {{\n  room ^Room {header} {{\n    robot r : Waffle on F_1_1\n  }}\n}}\n'
    assert map_path(text, Path("/cases")) == Path("/cases/maps/m.yaml")
    found = map_reference(text)
    assert found is not None and text[found.start:found.end] in ('"maps/m.yaml"', "'maps/m.yaml'")


def test_escapes_are_the_string_s_value_and_absolute_paths_stay() -> None:
    assert map_path(r'room R floorSize 2 occupancy "a \"b\"\\c\u00e9.yaml" { }', Path("/x")) == Path(
        '/x/a "b"\\c\u00e9.yaml')
    assert map_path('room R occupancy "/maps/m.yaml" { }', Path("/x")) == Path("/maps/m.yaml")


@pytest.mark.parametrize("text", [
    "testcase T { room Lab size 6 x 4 floorSize 0.5 { robot r : Waffle on F_0_0 } }",
    'room Lab map "occupancy" { }',
    '// room Office occupancy "x.yaml"\n/* room Office floorSize 1 occupancy "y.yaml" */\nroom Lab size 2 x 2 {}',
    'room Lab size 2 x 2 { object occupancy : Table on F_0_0 } // "occupancy" "z.yaml"',
    'testcase T { room Lab size 2 x 2 { } mission M { goto F_0_0 } } // room X occupancy',
])
def test_other_rooms_and_comments_name_no_map(text: str) -> None:
    assert map_path(text, Path("/x")) is None


def test_a_moved_case_names_the_same_map_when_floor_size_comes_first(tmp_path: Path) -> None:
    text = ('import "cat.rei"\ntestcase T {\n  room R floorSize 0.5 /* "x" */ occupancy "maps/m.yaml" unknownFree {\n'
            '  }\n}\n')
    moved = relocated_imports(text, tmp_path, tmp_path / "search" / "candidates")
    assert moved == text.replace('"maps/m.yaml"', '"../../maps/m.yaml"').replace('"cat.rei"', '"../../cat.rei"')
    assert map_path(moved, tmp_path / "search" / "candidates").resolve() == (tmp_path / "maps" / "m.yaml").resolve()
