# SPDX-License-Identifier: EPL-2.0
"""Humans follow their Catmull-Rom trajectories in the physics world, upright, in both drive modes."""

from __future__ import annotations

import math
from pathlib import Path

import pybullet as p
import pytest

from rei.geometry import Twist2D
from rei.sim.simulation import Simulation
from rei.spline import Trajectory

# control points of h1 in the fixture; the loop closes after another 4 s (period 14 s)
CONTROL = {
    0.0: (1.5, 2.7),
    4.0: (3.5, 2.7),
    6.0: (3.5, 1.9),
    10.0: (1.5, 1.9),
    14.0: (1.5, 2.7),
    18.0: (3.5, 2.7),
}


@pytest.mark.parametrize("mode", ["velocity", "force"])
def test_human_passes_control_points_on_time(room: Path, mode: str) -> None:
    with Simulation(room, animation_mode=mode) as sim:
        errors = {}
        for t_control, (x, y) in CONTROL.items():
            while sim.t < t_control - 1e-9:
                sim.step(Twist2D(0.0, 0.0))
            (human,) = sim.state().objects
            errors[t_control] = math.hypot(human.pose[0] - x, human.pose[1] - y)
            assert human.pose[2] == pytest.approx(0.85, abs=0.01)  # still standing on the floor
            assert abs(human.pose[3]) < 0.01  # upright, not spinning
        assert max(errors.values()) < 0.02, errors


def test_human_velocity_follows_the_spline(sim: Simulation) -> None:
    spline = Trajectory([0.0, 4.0, 6.0, 10.0], [(1.5, 2.7), (3.5, 2.7), (3.5, 1.9), (1.5, 1.9)], loop=True)
    while sim.t < 2.0 - 1e-9:
        sim.step(Twist2D(0.0, 0.0))
    (human,) = sim.state().objects
    assert human.name == "h1" and human.category == "HUMAN"
    vx, vy = spline.velocity(2.0)
    assert human.twist[0] == pytest.approx(vx, abs=0.02)
    assert human.twist[1] == pytest.approx(vy, abs=0.02)
    assert math.hypot(vx, vy) > 0.3  # it is really walking


def test_human_pushes_through_after_being_blocked(room: Path) -> None:
    """A human whose path crosses the robot pushes it away and is back on its trajectory soon after."""
    with Simulation(room) as sim:
        robot = sim.robot_body
        # park the robot on the human's path at (2.5, 2.7), which h1 crosses at about t = 2 s
        p.resetBasePositionAndOrientation(robot, (2.5, 2.7, 0.0), (0, 0, 0, 1), physicsClientId=sim.client)
        touched = False
        while sim.t < 4.0 - 1e-9:
            sim.step(Twist2D(0.0, 0.0))
            touched = touched or ("tb3", "h1") in sim.state().contacts
        assert touched
        (human,) = sim.state().objects
        assert math.hypot(human.pose[0] - 3.5, human.pose[1] - 2.7) < 0.05
