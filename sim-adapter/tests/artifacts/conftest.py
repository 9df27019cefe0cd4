# SPDX-License-Identifier: EPL-2.0
"""Shared helpers: a fresh, editable copy of the fixture case for every test that corrupts a file."""

from __future__ import annotations

import json
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

ROOM = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"


@pytest.fixture
def room() -> Path:
    return ROOM


@pytest.fixture
def room_copy(tmp_path: Path) -> Path:
    target = tmp_path / "case"
    shutil.copytree(ROOM, target)
    return target


@pytest.fixture
def edit_json() -> Callable[[Path, Callable[[Any], None]], None]:
    def edit(path: Path, change: Callable[[Any], None]) -> None:
        data = json.loads(path.read_text(encoding="utf-8"))
        change(data)
        path.write_text(json.dumps(data), encoding="utf-8")

    return edit
