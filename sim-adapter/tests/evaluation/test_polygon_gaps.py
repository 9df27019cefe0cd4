# SPDX-License-Identifier: EPL-2.0
"""Polygon furniture in the metrics: rei.geometry.polygon_gaps against an independent oracle (shapely's distance
between the robot's rectangle or outline and the concave polygon), and the static clearances of a run measure a
POLYGON object by its polygon, as the monitor does, not by its bounding box."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from polygon_desk import C_DESK, C_DESK_POSE
from shapely import affinity
from shapely.geometry import Polygon, box

from rei.artifacts.world import read_world
from rei.evaluation.metrics.compute import _obstacles, _static_gaps
from rei.geometry import polygon_gaps

ROBOT = (0.281, 0.306)
DESK = np.array(C_DESK) + C_DESK_POSE[:2]


def _poses(seed: int, n: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.column_stack((rng.uniform(2.2, 4.8, n), rng.uniform(-0.2, 2.2, n), rng.uniform(-math.pi, math.pi, n)))


def test_gaps_equal_shapelys_distance_where_apart_and_are_negative_where_overlapping() -> None:
    poses = _poses(5, 400)
    desk = Polygon(DESK)
    robot = box(-ROBOT[0] / 2, -ROBOT[1] / 2, ROBOT[0] / 2, ROBOT[1] / 2)
    oracle = np.array([affinity.translate(affinity.rotate(robot, a, use_radians=True), x, y).distance(desk)
                       for x, y, a in poses])
    gaps = polygon_gaps(poses, ROBOT, DESK)
    apart = oracle > 0
    assert apart.sum() > 100 and (~apart).sum() > 100  # both cases are exercised
    np.testing.assert_allclose(gaps[apart], oracle[apart], atol=1e-9)
    assert (gaps[~apart] < 1e-12).all()
    # a convex outline (a hexagon) as a described robot's
    hexagon = np.array([(0.2 * math.cos(k * math.pi / 3), 0.15 * math.sin(k * math.pi / 3)) for k in range(6)])
    shape = Polygon(hexagon)
    oracle = np.array([affinity.translate(affinity.rotate(shape, a, use_radians=True, origin=(0, 0)), x, y)
                       .distance(desk) for x, y, a in poses])
    gaps = polygon_gaps(poses, hexagon, DESK)
    np.testing.assert_allclose(gaps[oracle > 0], oracle[oracle > 0], atol=1e-9)
    assert (gaps[oracle == 0] < 1e-12).all()


def test_the_static_clearance_is_to_the_polygon_not_its_bounding_box(polygon_case: Path) -> None:
    world = read_world(polygon_case / "world.json")
    statics = _obstacles([world.object("table1")])
    # the robot in the notch, 0.05 m from its back: the bounding box would have it inside
    inside = np.array([[C_DESK_POSE[0] + 0.1 - 0.05 - ROBOT[0] / 2, C_DESK_POSE[1], 0.0]])
    _, gaps = _static_gaps(statics, inside, ROBOT, 0.25)
    assert abs(gaps[0, 0] - 0.05) < 1e-9


def test_ear_clipping_covers_concave_polygons_exactly() -> None:
    """rei.geometry.triangulate (the simulator's prism caps, the metrics' pieces): n - 2 triangles of positive
    area inside the polygon whose areas add up to its own, also with straight corners and many notches."""
    from rei.geometry import triangulate

    star = [(math.cos(k * math.pi / 5) * (1 if k % 2 == 0 else 0.4),
             math.sin(k * math.pi / 5) * (1 if k % 2 == 0 else 0.4)) for k in range(10)]
    comb = [(0, 0), (5, 0), (5, 2), (4, 2), (4, 1), (3, 1), (3, 2), (2, 2), (2, 1), (1, 1), (1, 2), (0, 2)]
    straight = [(0, 0), (1, 0), (2, 0), (3, 0), (3, 2), (2, 2), (2, 1), (1, 1), (1, 2), (0, 2), (0, 1)]
    for points in (C_DESK, star, comb, straight):
        whole = Polygon(points)
        pieces = [Polygon([points[i] for i in t]) for t in triangulate(points)]
        assert len(pieces) == len(points) - 2
        assert all(p.area > 0 and whole.buffer(1e-9).contains(p) for p in pieces)
        assert abs(sum(p.area for p in pieces) - whole.area) < 1e-9
