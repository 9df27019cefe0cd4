# SPDX-License-Identifier: EPL-2.0
"""Shared helpers for the simulation tests: the fixture room, an editable copy of it, a running simulation."""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest

from rei.sim.simulation import Simulation

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
def sim() -> Iterator[Simulation]:
    with Simulation(ROOM) as simulation:
        yield simulation
