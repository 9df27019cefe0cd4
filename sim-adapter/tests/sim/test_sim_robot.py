# SPDX-License-Identifier: EPL-2.0
"""The differential-drive robot: it moves as commanded, its odometry follows, its limits hold."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from rei.geometry import Twist2D
from rei.sim.simulation import Simulation


def _drive(sim: Simulation, cmd: Twist2D, seconds: float) -> None:
    for _ in range(round(seconds * sim.physics_rate)):
        sim.step(cmd)


def test_straight_drive_odometry_matches_true_pose(sim: Simulation) -> None:
    _drive(sim, Twist2D(0.2, 0.0), 2.0)
    state = sim.state()
    x, y, z, yaw = state.robot.pose
    assert sim.t == pytest.approx(2.0)
    assert x - 1.0 == pytest.approx(0.4, abs=0.02)  # it really moved ~0.4 m (a short acceleration phase)
    assert abs(y - 1.0) < 0.01 and abs(yaw) < 0.01 and abs(z) < 0.005
    odom = state.robot.odom
    assert math.hypot(odom.x - x, odom.y - y) < 0.01
    assert sim.observation().odom == odom
    assert sim.observation().odom_twist.v == pytest.approx(0.2, abs=0.005)
    assert state.robot.twist[0] == pytest.approx(0.2, abs=0.01)


def test_turning_odometry_follows(sim: Simulation) -> None:
    _drive(sim, Twist2D(0.15, 0.5), 3.0)
    state = sim.state()
    x, y, _, yaw = state.robot.pose
    assert yaw == pytest.approx(1.5, abs=0.15)  # turned ~ w * t
    assert math.hypot(state.robot.odom.x - x, state.robot.odom.y - y) < 0.02
    assert abs(state.robot.odom.yaw - yaw) < 0.02


def test_commands_are_clamped_to_the_limits(sim: Simulation) -> None:
    _drive(sim, Twist2D(5.0, 0.0), 1.5)
    assert math.hypot(*sim.state().robot.twist[:2]) == pytest.approx(0.26, abs=0.01)
    _drive(sim, Twist2D(0.0, -20.0), 1.5)
    assert sim.state().robot.twist[2] == pytest.approx(-1.82, abs=0.1)


def test_seeded_odometry_noise_is_reproducible(room: Path) -> None:
    poses = []
    for seed in (5, 5, 6):
        with Simulation(room, seed=seed, odom_noise=0.02, humans=False) as sim:
            _drive(sim, Twist2D(0.2, 0.3), 2.0)
            poses.append((sim.state().robot.odom, sim.state().robot.pose))
    assert poses[0] == poses[1]
    assert poses[0][0] != poses[2][0]
    assert poses[0][1] == pytest.approx(poses[2][1], abs=1e-9)  # noise touches odometry only
    true = poses[0][1]
    assert math.hypot(poses[0][0].x - true[0], poses[0][0].y - true[1]) < 0.05


def test_contact_with_a_wall_is_reported(sim: Simulation) -> None:
    assert sim.state().contacts == ()
    _drive(sim, Twist2D(-0.2, 0.0), 6.0)  # backwards into the left wall (inner face x = 0.05)
    state = sim.state()
    assert state.contacts == (("tb3", "W_0_0_left"),)
    assert state.robot.pose[0] == pytest.approx(0.05 + 0.281 / 2, abs=0.02)
    _drive(sim, Twist2D(0.2, 0.0), 1.0)
    sim.state()  # reports what was touched since the last snapshot: the wall, at the start of this second
    assert sim.state().contacts == ()
