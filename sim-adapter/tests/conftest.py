# SPDX-License-Identifier: EPL-2.0
"""Fixtures shared by the package's tests: the hand-written fixture case (a 6 x 4 m room), a copy to edit, and the
same room as a room from an occupancy map."""

from __future__ import annotations

import json
import shutil
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from polygon_desk import add_polygon_desk

ROOM = Path(__file__).resolve().parent / "fixtures" / "room6x4"


@pytest.fixture
def room() -> Path:
    return ROOM


@pytest.fixture
def room_copy(tmp_path: Path) -> Path:
    target = tmp_path / "case"
    shutil.copytree(ROOM, target)
    return target


def add_occupancy_map(case: Path) -> Path:
    """Make the fixture room in ``case`` a room from an occupancy map of its own 6 x 4 m (world.json's ``map``,
    map.yaml and map.pgm: 120 x 80 cells of 0.05 m, free but one occupied cell, column 7 of row 2 from the
    bottom); its floors and walls stay as they are."""
    pixels = np.full((80, 120), 254, dtype=np.uint8)
    pixels[80 - 1 - 2, 7] = 0
    (case / "map.pgm").write_bytes(b"P5\n120 80\n255\n" + pixels.tobytes())
    (case / "map.yaml").write_text("image: map.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                   "occupied_thresh: 0.65\nfree_thresh: 0.196\n", encoding="utf-8")
    world = json.loads((case / "world.json").read_text(encoding="utf-8"))
    world["map"] = {"yaml": "map.yaml", "image": "map.pgm", "resolution": 0.05, "origin": [0.0, 0.0, 0.0],
                    "width": 120, "height": 80, "unknownFree": False}
    (case / "world.json").write_text(json.dumps(world), encoding="utf-8")
    return case


@pytest.fixture
def map_case(room_copy: Path) -> Path:
    return add_occupancy_map(room_copy)


@pytest.fixture
def occupancy_map() -> Callable[[Path], Path]:
    """``add_occupancy_map``, for a test's own copy of the fixture room."""
    return add_occupancy_map



@pytest.fixture
def polygon_case(room_copy: Path) -> Path:
    """The fixture room with its table1 the C-shaped desk of :func:`polygon_desk.add_polygon_desk`."""
    return add_polygon_desk(room_copy)
