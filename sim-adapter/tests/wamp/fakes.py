# SPDX-License-Identifier: EPL-2.0
"""Snapshot objects with the fields of rei.sim.state.SimState, so the wire code is tested without pybullet."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rei.geometry import Pose2D


@dataclass(frozen=True)
class FakeRobot:
    name: str
    pose: tuple[float, float, float, float]
    twist: tuple[float, float, float]
    odom: Pose2D
    laser_min: float
    laser_ranges: np.ndarray | None
    laser_clearance: float


@dataclass(frozen=True)
class FakeObject:
    name: str
    category: str
    pose: tuple[float, float, float, float]
    twist: tuple[float, float, float]


@dataclass(frozen=True)
class FakeState:
    t: float
    robot: FakeRobot
    objects: tuple[FakeObject, ...]
    contacts: tuple[tuple[str, str], ...]


def make_state(step: int, dt: float = 1.0 / 240.0, beams: int = 8) -> FakeState:
    """A deterministic snapshot of step ``step``: a robot driving, one human walking, one contact every 50."""
    t = step * dt
    ranges = np.full(beams, np.inf, dtype=np.float32)
    ranges[: beams // 2] = np.linspace(0.5, 2.0, beams // 2) + 0.1 * math.sin(t)
    robot = FakeRobot(
        "tb3",
        (0.5 + 0.2 * t, 0.5, 0.0, 0.1 * t),
        (0.2, 0.0, 0.1),
        Pose2D(0.5 + 0.19 * t, 0.5, 0.1 * t),
        float(ranges.min()),
        ranges,
        float(ranges.min()) - 0.14,
    )
    human = FakeObject("h1", "HUMAN", (3.0 + math.cos(t), 3.5, 0.85, t), (-math.sin(t), 0.0, 1.0))
    contacts = (("tb3", "h1"),) if step % 50 == 0 else ()
    return FakeState(t, robot, (human,), contacts)
