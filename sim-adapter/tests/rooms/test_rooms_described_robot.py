# SPDX-License-Identifier: EPL-2.0
"""`rei gen-rooms --catalogue`: a catalogue's robot read from its URDF description furnishes rooms by its outline's
size (the language's front end reads the description as generation does), not by the 1 x 1 m a type without a box
had; a description that does not read is the catalogue entry's error."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from rei.rooms.catalogue import CatalogueError, room_types

REPO = Path(__file__).resolve().parents[3]
ROUND_BOT = REPO / "examples" / "robots" / "round_bot.urdf"
# A box 0.4 x 0.4 m centred 0.1 m ahead of the origin: its outline reaches 0.3 m forward and 0.1 m back.
AHEAD = """<robot name="ahead">
  <link name="base_footprint"><collision><origin xyz="0.1 0 0.1"/><geometry><box size="0.4 0.4 0.2"/></geometry>
  </collision></link>
  <link name="laser"/>
  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="laser"/><origin xyz="0 0 0.25"/></joint>
</robot>
"""


@pytest.fixture(autouse=True)
def _reader(monkeypatch: pytest.MonkeyPatch) -> None:
    # the Java front end runs REI's Python reader as $REI_PYTHON, which the rei command sets
    monkeypatch.setenv("REI_PYTHON", sys.executable)


def _catalogue(folder: Path, urdf: Path) -> Path:
    path = folder / "robots.rei"
    path.write_text(f'catalogue Robots {{\n  type Crate : object box 0.5 x 0.5 x 0.5\n'
                    f'  robot type Bot : urdf "{urdf}" mass 2 lidar link "laser"\n}}\n', encoding="utf-8")
    return path


def test_a_described_robot_is_the_rectangle_about_its_origin_that_holds_its_outline(tmp_path: Path) -> None:
    types = room_types(_catalogue(tmp_path, ROUND_BOT))
    assert types.robot == "Bot"
    assert types.robot_size == pytest.approx((0.34, 0.34))  # round_bot.urdf: a disc of radius 0.17 about the origin
    (tmp_path / "ahead.urdf").write_text(AHEAD, encoding="utf-8")
    # 0.3 m ahead of the origin, so 0.6 m long about it (its bounding box is 0.4 m); 0.4 m wide
    assert room_types(_catalogue(tmp_path, tmp_path / "ahead.urdf")).robot_size == pytest.approx((0.6, 0.4))


def test_a_described_robot_that_does_not_read_is_an_error_at_its_entry(tmp_path: Path) -> None:
    (tmp_path / "bad.urdf").write_text('<robot name="r">\n  <link name="a">\n</robot>\n', encoding="utf-8")
    catalogue = _catalogue(tmp_path, tmp_path / "bad.urdf")
    with pytest.raises(CatalogueError) as caught:
        room_types(catalogue)
    assert f"{catalogue}:3:" in str(caught.value) and "XML does not parse: mismatched tag" in str(caught.value)
