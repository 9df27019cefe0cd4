# SPDX-License-Identifier: EPL-2.0
"""A running simulation of the fixture room for the simulation tests."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from rei.sim.simulation import Simulation


@pytest.fixture
def sim(room: Path) -> Iterator[Simulation]:
    with Simulation(room) as simulation:
        yield simulation
