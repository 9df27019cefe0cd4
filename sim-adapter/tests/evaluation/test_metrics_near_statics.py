# SPDX-License-Identifier: EPL-2.0
"""The metrics measure the gaps to the static obstacles near the robot's path only (a large room has thousands of
walls): every sample's least gap, and every gap within the close threshold and a margin, are the very gaps
measured to all of them; the rest are +inf, which changes no figure."""

from __future__ import annotations

import numpy as np
import pytest

from rei.evaluation.metrics.compute import _CONTACT_MARGIN, _gaps, _Obstacles, _static_gaps

ROBOT = (0.281, 0.306)


def _walls(rng: np.random.Generator, n: int) -> _Obstacles:
    boxes = np.column_stack([rng.uniform(0, 40, n), rng.uniform(0, 25, n), rng.uniform(-np.pi, np.pi, n),
                             rng.uniform(0.05, 3.0, n), rng.uniform(0.05, 0.6, n)])
    circle = rng.random(n) < 0.2
    return _Obstacles(tuple(f"W_{k}" for k in range(n)), boxes, circle)


def _drive(rng: np.random.Generator, samples: int) -> np.ndarray:
    """A wandering path at 20 Hz and about 0.3 m/s."""
    heading = np.cumsum(rng.normal(0, 0.15, samples))
    xy = np.array([20.0, 12.0]) + np.cumsum(0.015 * np.column_stack([np.cos(heading), np.sin(heading)]), axis=0)
    return np.column_stack([xy, heading])


@pytest.mark.parametrize("seed", [1, 2])
@pytest.mark.parametrize("close", [0.0, 0.25, 2.0])
def test_left_out_gaps_change_no_least_gap_and_no_close_gap(seed: int, close: float) -> None:
    rng = np.random.default_rng(seed)
    walls, pose = _walls(rng, 1200), _drive(rng, 600)
    near, kept = _static_gaps(walls, pose, ROBOT, close)
    assert 0 < len(near.names) < len(walls.names) / 3  # it does leave most of them out
    every = _gaps(pose, ROBOT, walls.boxes, walls.circle)
    column = {name: k for k, name in enumerate(walls.names)}
    same = every[:, [column[name] for name in near.names]]
    np.testing.assert_array_equal(kept.min(axis=1), every.min(axis=1))
    measured = np.isfinite(kept)
    np.testing.assert_array_equal(kept[measured], same[measured])  # a gap measured is the gap
    reach = close + _CONTACT_MARGIN
    assert (same[~measured] > reach).all()  # one left out is beyond the close threshold and the margin
    assert set(zip(*np.nonzero(every < reach), strict=True)) == {
        (row, column[near.names[col]]) for row, col in zip(*np.nonzero(kept < reach), strict=True)}


def test_a_room_without_static_obstacles_or_samples() -> None:
    rng = np.random.default_rng(0)
    empty = _Obstacles((), np.zeros((0, 5)), np.zeros(0, dtype=bool))
    near, gaps = _static_gaps(empty, _drive(rng, 10), ROBOT, 0.25)
    assert near is empty and gaps.shape == (10, 0)
    walls = _walls(rng, 10)
    near, gaps = _static_gaps(walls, np.zeros((0, 3)), ROBOT, 0.25)
    assert near is walls and gaps.shape == (0, 10)
