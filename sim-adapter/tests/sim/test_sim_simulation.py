# SPDX-License-Identifier: EPL-2.0
"""The Simulation facade: time, static map, state shape, lifetime and option validation."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pybullet as p
import pytest

from rei.geometry import Twist2D
from rei.sim.simulation import Simulation


def test_time_counts_physics_steps(room: Path) -> None:
    with Simulation(room, physics_rate=200.0) as sim:
        assert sim.t == 0.0 and sim.dt == 0.005
        for _ in range(1000):
            sim.step(Twist2D())
        assert sim.steps == 1000 and sim.t == 5.0


def test_static_map_has_walls_and_furniture_only(sim: Simulation) -> None:
    static = sim.static_map()
    assert static.bounds == (0.0, 0.0, 6.0, 4.0)
    assert static.robot_size == (0.281, 0.306)
    assert len(static.obstacles) == 11  # 10 walls + the table; no floors, no human
    assert (4.8, 3.2, 0.0, 1.2, 0.8) in static.obstacles
    assert (0.0, 1.0, 0.0, 0.1, 2.1) in static.obstacles


def test_state_holds_robot_and_moving_objects(sim: Simulation) -> None:
    sim.step(Twist2D(0.1, 0.0))
    state = sim.state()
    assert state.t == pytest.approx(1 / 240)
    assert state.robot.name == "tb3" and len(state.robot.pose) == 4 and len(state.robot.twist) == 3
    assert [(o.name, o.category) for o in state.objects] == [("h1", "HUMAN")]
    ranges = state.robot.laser_ranges
    assert ranges is not None and ranges.shape == (360,) and not ranges.flags.writeable
    assert state.robot.laser_min == float(np.min(ranges))


def test_close_disconnects(room: Path) -> None:
    sim = Simulation(room)
    client = sim.client
    assert p.isConnected(physicsClientId=client)
    sim.close()
    sim.close()  # idempotent
    assert not p.isConnected(physicsClientId=client)


def test_bad_options_are_refused(room: Path) -> None:
    with pytest.raises(ValueError, match="physics_rate"):
        Simulation(room, physics_rate=0.0)
    with pytest.raises(ValueError, match="bad fault spec"):
        Simulation(room, fault="laser:often")
    with pytest.raises(ValueError, match="animation_mode must be one of velocity, force"):
        Simulation(room, animation_mode="teleport")
