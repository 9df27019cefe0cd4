# SPDX-License-Identifier: EPL-2.0
"""The social metrics (docs/metrics.md "People") of a robot read from its description measure its outline
(world.json robot.footprint), not its bounding box: a round robot of radius 0.17 turned by 45 degrees passing and
meeting a person, against the circle worked out by hand and against the bounding square's figures; the time to
collision of random outlines (an off-centre polygon, the round robot's 64-gon) against the outline gaps the
clearances use (rei.geometry.outline_gaps); the round robot's encounter margin against the circle's."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rei.artifacts.world import CircleFootprint, footprint_polygon
from rei.evaluation.metrics import compute_metrics
from rei.evaluation.metrics.social import ZONES
from rei.wamp.recording import RecordingWriter, stream_path

from .contacts import check_contact_times

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"
R = 0.17  # the round robot's radius
SQUARE = (2 * R, 2 * R)  # its bounding box, what the metrics measured before
RADIUS = 0.25  # the fixture's human h1: a cylinder of diameter 0.5
YAW = math.pi / 4  # the square's corner towards the person: the square reaches R sqrt(2) there, the circle R
DT = 0.05
#: The round footprint is measured as the 64-gon whose sides touch the circle (world.footprint_polygon, as the
#: simulator's chassis): its gaps are short of the circle's by at most this.
POLYGON = R / math.cos(math.pi / 64) - R


def _state(k: int, x: float, y: float, vx: float, person: tuple[float, float, float]) -> dict[str, Any]:
    px, py, pvx = person
    return {"t": DT * k, "robot": {"pose": [x, y, 0.0, YAW], "twist": [vx, 0.0, 0.0]},
            "objects": [{"name": "h1", "type": "HUMAN", "pose": [px, py, 0.85, 0.0], "twist": [pvx, 0.0, 0.0]}],
            "contacts": []}


def _run(tmp_path: Path, states: list[dict[str, Any]], footprint: dict[str, Any] | None) -> Path:
    """A run folder with the fixture's case, its robot a box of the round robot's bounding square or, with
    ``footprint``, the round robot read from a description."""
    run = tmp_path / ("round" if footprint else "square")
    shutil.copytree(FIXTURE, run / "case")
    world = json.loads((FIXTURE / "world.json").read_text())
    world["robot"]["size"] = [*SQUARE, 0.2]
    if footprint is not None:
        world["robot"]["footprint"] = footprint
    (run / "case" / "world.json").write_text(json.dumps(world))
    with RecordingWriter(stream_path(run, "state")) as writer:
        for state in states:
            writer.write(state)
    return run


def _both(tmp_path: Path, states: list[dict[str, Any]], centre: tuple[float, float] = (0.0, 0.0),
          ) -> tuple[dict[str, Any], dict[str, Any]]:
    circle = {"type": "circle", "x": centre[0], "y": centre[1], "radius": R}
    return compute_metrics(_run(tmp_path, states, circle)), compute_metrics(_run(tmp_path, states, None))


def test_a_round_robot_passing_a_person_is_in_her_spaces_as_its_circle_is(tmp_path: Path) -> None:
    """The robot drives along y = 1 at 0.2 m/s (1 cm per sample) from x = -1.5 to 7.5, turned by 45 degrees,
    past a person standing at (3, 1.7): the circle's gap is hypot(x - 3, 0.7) - R - RADIUS, below a zone's edge
    e while |x - 3| < sqrt((e + R + RADIUS)^2 - 0.7^2) = h, so 2 floor(h / 1 cm) + 1 samples (none within 0.5 mm
    of an edge, more than the 64-gon's 0.2 mm). The bounding square, its corner towards her, reaches 0.07 m
    nearer: longer in the inner spaces."""
    d = 0.7
    states = [_state(k, -1.5 + 0.01 * k, 1.0, 0.2, (3.0, 1.0 + d, 0.0)) for k in range(901)]
    round_, square = _both(tmp_path, states)
    counts = {}
    for zone, edge in ZONES:
        h = math.sqrt((edge + R + RADIUS) ** 2 - d**2)
        assert min(h % 0.01, 0.01 - h % 0.01) > 5e-4  # no sample where the 64-gon and the circle could differ
        counts[zone] = 2 * math.floor(h / 0.01) + 1
    assert counts == {"intimate": 103, "personal": 293, "social": 791}
    expected = {"intimate": 103 * DT, "personal": (293 - 103) * DT, "social": (791 - 293) * DT}
    for zone, seconds in expected.items():
        assert round_[f"{zone}_time"] == pytest.approx(seconds, abs=1e-9), zone
    assert round_["clearance_humans_min"] == pytest.approx(d - R - RADIUS, abs=POLYGON + 1e-9)
    # the square: its corner R sqrt(2) out, 0.0704 m nearer the person
    assert square["clearance_humans_min"] == pytest.approx(d - R * math.sqrt(2) - RADIUS, abs=1e-9)
    assert square["intimate_time"] == pytest.approx(round_["intimate_time"] + 0.2, abs=1e-9)
    assert square["ttc_humans_min"] is None and round_["ttc_humans_min"] is None  # side by side: no course


def test_a_round_robot_meets_a_person_walking_at_it_when_its_circle_does(tmp_path: Path) -> None:
    """The robot stands at (1, 1) turned by 45 degrees, the person walks at it along y = 1 from x = 4 at
    0.5 m/s: its circle is touched when her centre is R + RADIUS from the robot's centre, (3 - R - RADIUS) / 0.5
    = 5.16 s ahead at the first sample; the square's corner 0.14 s earlier. With the circle 0.05 m ahead of the
    robot's origin (the footprint is in the robot's frame, turned with its pose: 0.05 m along the 45-degree
    heading, 0.05 / sqrt(2) towards her) it is touched that much earlier."""
    states = [_state(k, 1.0, 1.0, 0.0, (4.0 - 0.025 * k, 1.0, -0.5)) for k in range(3)]
    round_, square = _both(tmp_path, states)
    assert round_["ttc_humans_min"] == pytest.approx((3 - 0.05 - R - RADIUS) / 0.5, abs=POLYGON / 0.5 + 1e-9)
    assert square["ttc_humans_min"] == pytest.approx((3 - 0.05 - R * math.sqrt(2) - RADIUS) / 0.5, abs=1e-9)
    ahead, _ = _both(tmp_path / "ahead", states, centre=(0.05, 0.0))
    # the circle's centre (1 + 0.05 cos 45, 1 + 0.05 sin 45): her line passes 0.0354 m below it
    off = 0.05 * math.sin(YAW)
    expected = (3 - 0.05 - 0.05 * math.cos(YAW) - math.sqrt((R + RADIUS) ** 2 - off**2)) / 0.5
    assert ahead["ttc_humans_min"] == pytest.approx(expected, abs=POLYGON / 0.5 + 1e-6)
    assert ahead["ttc_humans_min"] < round_["ttc_humans_min"] - 0.05


BURGER = np.array([(-0.14, -0.09), (0.05, -0.09), (0.07, -0.05), (0.07, 0.05), (0.05, 0.09), (-0.14, 0.09)])


@pytest.mark.parametrize("outline", ["polygon", "round"])
@pytest.mark.parametrize("circle", [True, False], ids=["cylinder", "box"])
def test_the_outlines_time_to_collision_is_when_its_outline_gap_reaches_zero(outline: str, circle: bool) -> None:
    """Random robots (an off-centre convex polygon, and the round robot's 64-gon about a point ahead of its origin)
    and people (cylinders, or rectangles at any yaw) at constant velocities: where a time is found the outline's
    footprint gap is 0 then and positive just before; where none is, the gap stays positive over the horizon
    (checked every 2 ms)."""
    shape = BURGER if outline == "polygon" else np.array(footprint_polygon(CircleFootprint(0.05, 0.02, R)))
    met, missed = check_contact_times(shape, n=60, seed=11, circle=circle, step=0.002)
    assert met > 10 and missed > 10


@pytest.mark.parametrize("delay", [-4.0, 1.7, 6.0])
def test_a_round_robots_encounter_margin_is_its_circles(delay: float) -> None:
    """A person crossing the round robot's lane (test_encounter_margin's Lane: robot at u = 0.5 m/s, person at
    w = 1 m/s, perpendicular, through the same point O) ``delay`` seconds off: centres within rho = R + RADIUS +
    threshold conflict, and over that disc t - tau = delay + a / u - b / w (a, b the offsets along each path)
    comes at most rho hypot(1 / u, 1 / w) nearer 0. The bounding square's corners reach farther: a smaller margin."""
    from rei.evaluation.metrics.encounter import encounters

    from .test_encounter_margin import HUMAN, THRESHOLD, TOL, Lane, animation

    lane = Lane(0.5, tp=10.0, end=20.0, heading=0.7)
    spec = animation(lane.crossing("h", lane.tp - delay, 1.0))
    shape = np.array(footprint_polygon(CircleFootprint(0.0, 0.0, R)))
    (found,) = encounters(spec, {"h": HUMAN}, lane.t, lane.pose, shape, THRESHOLD)
    expected = max(0.0, abs(delay) - (R + RADIUS + THRESHOLD) * math.hypot(1 / 0.5, 1 / 1.0))
    assert expected - 1e-9 <= found.margin <= expected + TOL + POLYGON * math.hypot(2, 1)
    (square,) = encounters(spec, {"h": HUMAN}, lane.t, lane.pose, SQUARE, THRESHOLD)
    assert square.margin < found.margin - 0.05


LONG = [(-0.1, -0.1), (0.9, -0.1), (0.9, 0.1), (-0.1, 0.1)]  # a long robot, its origin near its back end


@pytest.mark.parametrize("footprint", ["outline", "box"])
def test_a_long_robot_turning_its_front_into_a_person_is_at_fault(tmp_path: Path, footprint: str) -> None:
    """The robot's origin stands at (1, 1) while it turns at 0.5 rad/s from a heading of -0.5 rad, and its front
    end, 0.9 m ahead, sweeps into a person standing at (1.6, 1.6): its origin does not move towards her (by the
    origin she walked into it), the outline's point nearest to her does, at the turn rate times its arm. The
    approach is that point's velocity towards her centre, here worked out by sampling the outline's edges every
    0.1 mm. A box robot as long (2 m by 0.2 m, centred on its origin) is still judged by its origin, as it was
    before outlines: its figures stay those it had."""
    w = 0.5
    outline = np.array(LONG)
    states = [{"t": DT * k, "robot": {"pose": [1.0, 1.0, 0.0, -0.5 + w * DT * k], "twist": [0.0, 0.0, w]},
               "objects": [{"name": "h1", "type": "HUMAN", "pose": [1.6, 1.6, 0.85, 0.0], "twist": [0.0, 0.0, 0.0]}],
               "contacts": []} for k in range(60)]
    run = tmp_path / footprint
    shutil.copytree(FIXTURE, run / "case")
    world = json.loads((FIXTURE / "world.json").read_text())
    if footprint == "outline":
        world["robot"]["footprint"] = {"type": "polygon", "points": LONG}
        world["robot"]["size"] = [1.0, 0.2, 0.2]
    else:
        world["robot"]["size"] = [2.0, 0.2, 0.2]
    (run / "case" / "world.json").write_text(json.dumps(world))
    with RecordingWriter(stream_path(run, "state")) as writer:
        for state in states:
            writer.write(state)
    from rei.evaluation.metrics import measure

    measured = measure(run)
    (collision,) = measured.person_collisions
    if footprint == "box":
        assert collision.approach == 0.0 and collision.person_at_fault
        return
    k = round(collision.t / DT)
    centre = np.array([1.6, 1.6])
    expected = []
    for j in (k - 1, k):
        yaw = -0.5 + w * DT * j
        turn = np.array([[math.cos(yaw), -math.sin(yaw)], [math.sin(yaw), math.cos(yaw)]])
        corners = outline @ turn.T + 1.0
        edges = [a + (b - a) * u for a, b in zip(corners, np.roll(corners, -1, axis=0), strict=True)
                 for u in np.linspace(0.0, 1.0, int(np.hypot(*(b - a)) / 1e-4) + 1)]
        nearest = min(edges, key=lambda p: float(np.hypot(*(centre - p))))
        arm = nearest - 1.0
        velocity = w * np.array([-arm[1], arm[0]])
        direction = (centre - nearest) / np.hypot(*(centre - nearest))
        expected.append(float(velocity @ direction))
    assert collision.approach == pytest.approx(max(expected), abs=1e-3)
    assert collision.approach > 0.3 and collision.robot_at_fault
    assert (measured.metrics["collisions_robot_at_fault"], measured.metrics["collisions_person_at_fault"]) == (1, 0)


def test_a_rectangle_person_is_judged_from_the_nearest_points_of_both_shapes() -> None:
    """The long robot at the origin turns at 1 rad/s; a person's rectangle 1 m by 0.1 m, its near end at x 1.1 and
    y 0.15 to 0.25, is apart from it. The nearest points are the outline's front corner (0.9, 0.1) and her corner
    (1.1, 0.15): the corner moves at (-0.1, 0.9) m/s, 0.121 m/s along them, at fault; measured towards her centre
    (1.6, 0.2), as for a round person there, it would be 0.028 m/s."""
    from rei.evaluation.metrics.social import person_collisions

    t, pose = np.array([0.0, DT]), np.zeros((2, 3))
    collides = np.array([[False], [True]])
    person = np.array([[[1.6, 0.2, 0.0]], [[1.6, 0.2, 0.0]]])
    rate = np.array([1.0, 1.0])
    corner, velocity = np.array([0.9, 0.1]), np.array([-0.1, 0.9])
    for circle, towards in ((False, np.array([1.1, 0.15])), (True, np.array([1.6, 0.2]))):
        (found,) = person_collisions(t, pose, np.zeros((2, 2)), person, ["h"], collides, np.array(LONG), rate,
                                     np.array([[1.0, 0.1, circle]]))
        direction = (towards - corner) / np.hypot(*(towards - corner))
        assert found.approach == pytest.approx(float(velocity @ direction), abs=1e-12)
        assert found.robot_at_fault is not circle, found
