# SPDX-License-Identifier: EPL-2.0
"""Fixtures shared by the package's tests: the hand-written fixture case (a 6 x 4 m room) and a copy to edit."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

ROOM = Path(__file__).resolve().parent / "fixtures" / "room6x4"


@pytest.fixture
def room() -> Path:
    return ROOM


@pytest.fixture
def room_copy(tmp_path: Path) -> Path:
    target = tmp_path / "case"
    shutil.copytree(ROOM, target)
    return target
