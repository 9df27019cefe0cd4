# SPDX-License-Identifier: EPL-2.0
"""Contacts between two snapshots are not lost: a bump that ends before the next sample is still reported."""

from __future__ import annotations

from rei.geometry import Twist2D
from rei.sim.simulation import Simulation


def _drive(sim: Simulation, cmd: Twist2D, seconds: float) -> None:
    for _ in range(round(seconds * sim.physics_rate)):
        sim.step(cmd)


def test_a_bump_between_snapshots_is_reported_once(sim: Simulation) -> None:
    assert sim.state().contacts == ()
    _drive(sim, Twist2D(-0.25, 0.0), 4.0)  # backwards from (1, 1) into the left wall
    _drive(sim, Twist2D(0.25, 0.0), 1.5)  # and away again before anyone looks
    x = sim.robot_pose().x
    assert x > 0.3, "the robot drove away from the wall"
    touched = sim.state().contacts
    assert ("tb3", "W_0_0_left") in touched
    assert sim.state().contacts == ()  # reported once: the next snapshot starts afresh
