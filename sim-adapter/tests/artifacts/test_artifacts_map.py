# SPDX-License-Identifier: EPL-2.0
"""world.json's ``map`` member (a room from an occupancy map): read, its files resolved against the case folder,
and every wrong value refused with the field named. ``map_case``: the fixture room with a map (tests/conftest.py)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rei.artifacts import ArtifactError, read_case, read_world

Edit = Callable[[Path, Callable[[Any], None]], None]


def _error(path: Path) -> str:
    with pytest.raises(ArtifactError) as info:
        read_world(path)
    return str(info.value)


def test_a_world_without_a_map_has_none(room: Path) -> None:
    assert read_world(room / "world.json").map is None


def test_the_map_member_is_read_with_its_files_in_the_case_folder(map_case: Path) -> None:
    spec = read_case(map_case).world.map
    assert spec is not None
    assert (spec.yaml, spec.image) == (map_case / "map.yaml", map_case / "map.pgm")
    assert (spec.resolution, spec.origin, spec.width, spec.height, spec.unknown_free) == (
        0.05, (0.0, 0.0, 0.0), 120, 80, False)
    assert spec.extent == pytest.approx((0.0, 0.0, 6.0, 4.0))
    grid = spec.load().grid
    assert grid.shape == (80, 120) and grid[2, 7] == 100 and int((grid == 100).sum()) == 1


@pytest.mark.parametrize(("change", "expected"), [
    (lambda m: m.update(yaml="../map.yaml"), "map.yaml: expected a file of the case folder, got '../map.yaml'"),
    (lambda m: m.update(yaml="/etc/hostname"), "map.yaml: expected a file of the case folder"),
    (lambda m: m.update(image="gone.pgm"), "map.image: "),
    (lambda m: m.update(resolution=0), "map.resolution: must be > 0, got 0"),
    (lambda m: m.update(origin=[0.0, 0.0, 0.5]), "map.origin: the map's yaw must be 0"),
    (lambda m: m.update(width=0), "map.width: must be > 0, got 0"),
    (lambda m: m.update(height=80.0), "map.height: expected an integer, got float 80.0"),
    (lambda m: m.pop("unknownFree"), "map.unknownFree: required field is missing"),
    (lambda m: m.update(width=100), "bounds: must be the map's extent [0.0, 0.0, 5.0, 4.0]"),
])
def test_a_wrong_map_member_is_named(map_case: Path, edit_json: Edit, change: Callable[[dict], None],
                                     expected: str) -> None:
    edit_json(map_case / "world.json", lambda d: change(d["map"]))
    message = _error(map_case / "world.json")
    assert message.startswith(f"{map_case / 'world.json'}: ") and expected in message, message


def test_a_map_that_does_not_fit_its_description_is_refused_when_loaded(map_case: Path) -> None:
    yaml = map_case / "map.yaml"
    yaml.write_text(yaml.read_text(encoding="utf-8").replace("0.05", "0.1"), encoding="utf-8")
    spec = read_world(map_case / "world.json").map
    assert spec is not None
    with pytest.raises(ArtifactError, match=r"120 x 80 cells of 0\.1 m .* but world\.json describes 120 x 80 cells "
                                            r"of 0\.05 m"):
        spec.load()
    yaml.write_text("image: map.pgm\n", encoding="utf-8")
    with pytest.raises(ArtifactError, match=r"map\.yaml: 1:1: resolution: missing"):
        spec.load()
