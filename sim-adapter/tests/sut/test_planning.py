# SPDX-License-Identifier: EPL-2.0
"""Grid, global planner and tracker on their own: exact distances, paths that keep clearance, velocities."""

from __future__ import annotations

import numpy as np
import pytest

from rei.sut.nav import NavConfig
from rei.sut.nav.global_planner import PlanningError, plan
from rei.sut.nav.grid import CostGrid
from rei.sut.nav.tracker import DynamicTracker

from .kinematic import rect_room

CONFIG = NavConfig()


def test_distance_field_is_the_exact_distance_to_a_rotated_box():
    grid = CostGrid(rect_room(4, 4, [(2.0, 2.0, np.pi / 4, 0.4, 0.4)]), CONFIG)
    half_diagonal = 0.2 * np.sqrt(2.0)
    # Along the x axis the rotated square's corner is closest.
    assert grid.distance_at(np.array([2.0 + half_diagonal + 0.3]), np.array([2.0]))[0] == pytest.approx(0.3, abs=0.01)
    assert grid.distance_at(np.array([2.0]), np.array([2.0]))[0] == 0.0
    assert np.isinf(grid.cost[grid.world_to_cell(2.0, 2.0)[::-1]])


def test_path_keeps_the_inflation_radius_and_is_pruned():
    static_map = rect_room(6, 4, [(3.0, 2.0, 0.0, 1.2, 0.8)])
    grid = CostGrid(static_map, CONFIG)
    path = plan(grid, grid.cost, (1.0, 2.0), (5.0, 2.0), 0.15)
    clearance = grid.distance_at(path.points[:, 0], path.points[:, 1])
    assert clearance.min() >= CONFIG.inflation_radius - 0.01
    assert path.end == (5.0, 2.0)
    assert path.length < 6.0
    assert np.allclose(np.diff(path.s)[:-1], 0.05)


def test_goal_near_a_wall_is_moved_to_the_nearest_plannable_point_within_the_tolerance():
    grid = CostGrid(rect_room(3, 3), CONFIG)
    path = plan(grid, grid.cost, (1.5, 1.5), (2.85, 1.5), 0.3)
    assert 2.85 - path.end[0] <= 0.3 and grid.distance_at(np.array([path.end[0]]), np.array([1.5]))[0] >= 0.23
    with pytest.raises(PlanningError, match="is blocked"):
        plan(grid, grid.cost, (1.5, 1.5), (2.9, 1.5), 0.05)
    with pytest.raises(PlanningError, match="outside the map"):
        plan(grid, grid.cost, (1.5, 1.5), (9.0, 1.5), 0.3)


def test_tracker_gives_moving_points_their_velocity_and_keeps_still_ones_apart():
    tracker = DynamicTracker()
    arc = np.column_stack((np.linspace(-0.2, 0.2, 9), np.zeros(9)))
    post = np.array([[3.0, 3.0], [3.02, 3.0], [3.04, 3.0]])
    for k in range(8):  # the velocity is smoothed: it converges over a few scans
        tracker.update(0.1 * k, np.vstack((arc + (1.0, 0.05 * k), post)))
    assert len(tracker.points) == 9
    assert tracker.velocities.mean(axis=0) == pytest.approx((0.0, 0.5), abs=0.05)
    assert len(tracker.still) == 3
