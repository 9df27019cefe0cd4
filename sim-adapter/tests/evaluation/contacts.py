# SPDX-License-Identifier: EPL-2.0
"""Random encounters to check the time to collision against the footprint gap it must close, for any outline."""

from __future__ import annotations

import math

import numpy as np

from rei.evaluation.metrics.social import TTC_HORIZON, contact_times
from rei.geometry import footprint_gaps


def check_contact_times(shape: tuple[float, float] | np.ndarray, *, n: int, seed: int, circle: bool,
                        step: float) -> tuple[int, int]:
    """``n`` random robots of ``shape`` (a box's size or an outline's points) and people (cylinders when
    ``circle``, else rectangles at any yaw) walking roughly towards them, at constant velocities: where a time is
    found the gap is 0 then and positive just before; where none is, it stays positive over the horizon (checked
    every ``step`` s). Returns how many met and how many missed."""
    rng = np.random.default_rng(seed)
    pose = np.column_stack((rng.uniform(-1, 1, (n, 2)), rng.uniform(-math.pi, math.pi, n)))
    other = np.column_stack((rng.uniform(-3, 3, (n, 2)), rng.uniform(-math.pi, math.pi, n),
                             rng.uniform(0.2, 0.8, (n, 2))))
    if circle:
        other[:, 4] = other[:, 3]
    velocity = rng.uniform(-0.4, 0.4, (n, 2))
    # people walking roughly towards the robot, so that many meet it, many pass it and some walk away
    towards = (pose[:, :2] - other[:, :2]) / np.hypot(*(pose[:, :2] - other[:, :2]).T)[:, None]
    other_velocity = towards * rng.uniform(0.2, 0.8, (n, 1)) + rng.uniform(-0.4, 0.4, (n, 2))
    ttc = contact_times(pose, velocity, shape, other, other_velocity, np.full(n, circle))

    def gap(i: int, tau: np.ndarray) -> np.ndarray:
        robot = np.column_stack((pose[i, 0] + velocity[i, 0] * tau, pose[i, 1] + velocity[i, 1] * tau,
                                 np.full(len(tau), pose[i, 2])))
        moved = np.repeat(other[i][None, :], len(tau), axis=0)
        moved[:, :2] += other_velocity[i] * tau[:, None]
        return footprint_gaps(robot, shape, moved[:, None, :], np.array([circle]))[:, 0]

    met = 0
    for i in range(n):
        start = gap(i, np.array([0.0]))[0]
        if start <= 0:
            assert ttc[i] == 0.0
        elif math.isfinite(ttc[i]):
            met += 1
            touching, before = gap(i, np.array([ttc[i], ttc[i] * (1 - 1e-6)]))
            assert abs(touching) < 1e-9 and before > 0, (i, touching, before)
        else:
            assert gap(i, np.arange(0.0, TTC_HORIZON, step)).min() > 0, i
    return met, int((~np.isfinite(ttc)).sum())
