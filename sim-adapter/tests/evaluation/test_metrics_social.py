# SPDX-License-Identifier: EPL-2.0
"""The social navigation metrics (rei.evaluation.metrics.social, docs/metrics.md "People") on recorded streams
made here, each against a case worked out by hand: a robot passing a standing person (time in Hall's zones), two
centres on a head-on course (time to collision), a robot driving into a person and a person walking into a stopped
robot (who was at fault), people walking a corner and a straight line (path irregularity); the time to collision
also against the monitor's footprint gaps (rei.geometry.footprint_gaps) on random encounters. The room's walls play
no part in these metrics: the drives may leave the room."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from rei.evaluation import Evaluator, Status, replay
from rei.evaluation.metrics import NAMES, compute_metrics, measure
from rei.evaluation.metrics.social import AT_FAULT_SPEED, TTC_HORIZON, ZONES, contact_times
from rei.wamp.recording import RecordingWriter, stream_path

from .contacts import check_contact_times

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"
ROBOT = (0.281, 0.306)  # the fixture's tb3 footprint
HALF_X, HALF_Y = ROBOT[0] / 2, ROBOT[1] / 2
RADIUS = 0.25  # the fixture's human h1: a cylinder of diameter 0.5
DT = 0.05  # 20 Hz


def _person(x: float, y: float, vx: float = 0.0, vy: float = 0.0, name: str = "h1") -> dict[str, Any]:
    return {"name": name, "type": "HUMAN", "pose": [x, y, 0.85, 0.0], "twist": [vx, vy, 0.0]}


def _state(k: int, x: float, y: float, vx: float, people: list[dict[str, Any]], **extra: Any) -> dict[str, Any]:
    return {"t": DT * k, "robot": {"pose": [x, y, 0.0, 0.0], "twist": [vx, 0.0, 0.0]}, "objects": people,
            "contacts": [], **extra}


def _run(tmp_path: Path, states: list[dict[str, Any]], world: dict[str, Any] | None = None) -> Path:
    """A run folder: the fixture's case (or its world.json changed by ``world``) and these state messages."""
    run = tmp_path / "run"
    shutil.copytree(FIXTURE, run / "case")
    if world is not None:
        (run / "case" / "world.json").write_text(json.dumps(world))
    with RecordingWriter(stream_path(run, "state")) as writer:
        for state in states:
            writer.write(state)
    return run


# -- Hall's zones --------------------------------------------------------------------------------------------

def test_a_robot_passing_a_standing_person_spends_the_expected_time_in_each_zone(tmp_path: Path) -> None:
    """The robot drives along y = 1 at 0.2 m/s (1 cm per 20 Hz sample) from x = -1.5 to 7.5 past a person standing
    at (3, 1.453): its footprint's side is dy = 1.453 - 1 - HALF_Y = 0.3 from the person's centre, so the gap is
    hypot(max(|x - 3| - HALF_X, 0), dy) - RADIUS and the gap is below a zone's edge e while |x - 3| < HALF_X +
    sqrt((e + RADIUS)^2 - dy^2) = h. The person stands on a sample (x = 3): 2 floor(h / 1 cm) + 1 samples are
    inside, each standing for 0.05 s; Hall's bands take the inner zone's samples out of the outer ones."""
    dy, v = 0.3, 0.2
    states = [_state(k, -1.5 + 0.01 * k, 1.0, v, [_person(3.0, 1.0 + HALF_Y + dy)]) for k in range(901)]
    m = compute_metrics(_run(tmp_path, states))
    inside = {}
    for zone, edge in ZONES:
        h = HALF_X + math.sqrt((edge + RADIUS) ** 2 - dy**2)
        inside[zone] = 2 * math.floor(h / 0.01) + 1
        # the sampled time is the continuous 2 h / v to within a sample
        assert abs(inside[zone] * DT - 2 * h / v) < DT
    assert inside == {"intimate": 155, "personal": 311, "social": 795}  # h = 0.772, 1.559, 3.979 m
    expected = {"intimate": 155 * DT, "personal": (311 - 155) * DT, "social": (795 - 311) * DT}
    duration = 900 * DT  # no mission: the whole recording
    for zone, seconds in expected.items():
        assert m[f"{zone}_time"] == pytest.approx(seconds, abs=1e-9), zone
        assert m[f"{zone}_share"] == pytest.approx(seconds / duration, abs=1e-12), zone
    # side by side on parallel lanes the centres never meet, the person never walked, nobody collided
    assert m["ttc_humans_min"] is None and m["path_irregularity_humans"] is None
    assert (m["collisions_robot_at_fault"], m["collisions_person_at_fault"]) == (0, 0)
    # the clearance to the person is the gap at the passing: dy - RADIUS
    assert m["clearance_humans_min"] == pytest.approx(dy - RADIUS)


def test_the_nearest_of_several_people_decides_the_zone(tmp_path: Path) -> None:
    """Standing still at a gap of 1.0 m from one person (personal) and 0.3 m from another (intimate): intimate only."""
    far = _person(1.0 + HALF_X + 1.0 + RADIUS, 1.0)
    near = _person(1.0, 1.0 - HALF_Y - 0.3 - RADIUS, name="h2")
    world = json.loads((FIXTURE / "world.json").read_text())
    h1 = next(o for o in world["objects"] if o["name"] == "h1")
    world["objects"].append({**h1, "name": "h2"})
    m = compute_metrics(_run(tmp_path, [_state(k, 1.0, 1.0, 0.0, [far, near]) for k in range(21)], world))
    assert m["intimate_time"] == pytest.approx(1.0) and m["intimate_share"] == pytest.approx(1.0)
    assert (m["personal_time"], m["social_time"]) == (0.0, 0.0)


def test_without_people_the_social_metrics_have_no_value(tmp_path: Path) -> None:
    m = compute_metrics(_run(tmp_path, [_state(k, 1.0 + 0.01 * k, 1.0, 0.2, []) for k in range(21)]))
    social = ["intimate_time", "intimate_share", "personal_time", "personal_share", "social_time", "social_share",
              "ttc_humans_min", "collisions_robot_at_fault", "collisions_person_at_fault",
              "path_irregularity_humans"]
    assert set(social) <= set(NAMES) and all(m[name] is None for name in social)
    assert m["collision_episodes"] == 0  # the other metrics as before


# -- time to collision ---------------------------------------------------------------------------------------

def test_two_centres_on_a_head_on_course_meet_when_the_gap_is_closed(tmp_path: Path) -> None:
    """The robot at (1, 1) drives +x at 0.2 m/s, the person from (4, 1) walks -x at 0.3 m/s: the footprints' gap
    3 - HALF_X - RADIUS closes at 0.5 m/s. One second recorded: the least time to collision is at the last
    sample, (3 - 0.5 * 1 - HALF_X - RADIUS) / 0.5 = 4.219 s."""
    states = [_state(k, 1.0 + 0.01 * k, 1.0, 0.2, [_person(4.0 - 0.015 * k, 1.0, vx=-0.3)]) for k in range(21)]
    m = compute_metrics(_run(tmp_path, states))
    assert m["ttc_humans_min"] == pytest.approx((3 - 0.5 - HALF_X - RADIUS) / 0.5, abs=1e-9)
    assert m["ttc_humans_min"] == pytest.approx(4.219, abs=1e-9)
    # walking away at 0.3 m/s the person is on no collision course; too slowly towards it, beyond the horizon
    away = [_state(k, 1.0, 1.0, 0.0, [_person(4.0 + 0.015 * k, 1.0, vx=0.3)]) for k in range(21)]
    assert compute_metrics(_run(tmp_path / "away", away))["ttc_humans_min"] is None
    slow = [_state(k, 1.0, 1.0, 0.0, [_person(4.0, 1.0, vx=-0.2)]) for k in range(2)]  # 2.6095 m at 0.2 m/s: 13 s
    assert compute_metrics(_run(tmp_path / "slow", slow))["ttc_humans_min"] is None
    assert TTC_HORIZON == 10.0


def test_a_course_past_the_robots_corner_meets_its_rounded_corner() -> None:
    """A person (radius 0.25) walking -x at 0.5 m/s, 0.1 m above the line of the robot's top edge, first touches
    the robot's corner (HALF_X, HALF_Y): when its centre is sqrt(0.25^2 - 0.1^2) beyond the corner in x. The same
    scene turned by 90 degrees (robot yaw pi/2) gives the same time."""
    x0 = 2.0
    expected = (x0 - HALF_X - math.sqrt(RADIUS**2 - 0.1**2)) / 0.5
    scene = contact_times(np.array([[0.0, 0.0, 0.0]]), np.zeros((1, 2)), ROBOT,
                          np.array([[x0, HALF_Y + 0.1, 0.0, 0.5, 0.5]]), np.array([[-0.5, 0.0]]), np.array([True]))
    turned = contact_times(np.array([[0.0, 0.0, math.pi / 2]]), np.zeros((1, 2)), ROBOT,
                           np.array([[-(HALF_Y + 0.1), x0, 0.0, 0.5, 0.5]]), np.array([[0.0, -0.5]]),
                           np.array([True]))
    assert scene[0] == pytest.approx(expected, abs=1e-12) and turned[0] == pytest.approx(expected, abs=1e-12)
    # overlapping now: 0; a place not published: unknown
    now = contact_times(np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]), np.zeros((2, 2)), ROBOT,
                        np.array([[0.3, 0.0, 0.0, 0.5, 0.5], [math.nan, math.nan, math.nan, 0.5, 0.5]]),
                        np.zeros((2, 2)), np.array([True, True]))
    assert now[0] == 0.0 and math.isnan(now[1])


@pytest.mark.parametrize("circle", [True, False], ids=["cylinder", "box"])
def test_the_time_to_collision_is_when_the_monitors_footprint_gap_reaches_zero(circle: bool) -> None:
    """Random robots and people (cylinders, or rectangles at any yaw) at constant velocities: where a time is
    found the footprint gap is 0 then and positive just before; where none is, the gap stays positive over the
    horizon (checked every millisecond)."""
    met, missed = check_contact_times(ROBOT, n=300, seed=7, circle=circle, step=0.001)
    assert met > 50 and missed > 50  # plenty of meetings, and of misses


# -- who was at fault ----------------------------------------------------------------------------------------

def test_a_robot_driving_into_a_standing_person_is_at_fault(tmp_path: Path) -> None:
    """The robot drives +x at 0.2 m/s from (1, 1) towards a person standing at (1.8, 1): the gap 0.8 - 0.01 k -
    HALF_X - RADIUS drops below the collision threshold (0.01 m) at sample 40 (t = 2.0), where the robot moves
    straight at the person's centre at 0.2 m/s (and did at the sample before)."""
    states = [_state(k, 1.0 + 0.01 * k, 1.0, 0.2, [_person(1.8, 1.0)]) for k in range(46)]
    measured = measure(_run(tmp_path, states))
    assert measured.metrics["collision_episodes"] == 1
    (collision,) = measured.person_collisions
    assert (collision.person, collision.t, collision.approach) == ("h1", pytest.approx(2.0), pytest.approx(0.2))
    assert (measured.metrics["collisions_robot_at_fault"], measured.metrics["collisions_person_at_fault"]) == (1, 0)
    assert measured.metrics["ttc_humans_min"] == 0.0 and measured.metrics["intimate_time"] > 0


def test_a_robot_the_impact_stopped_by_the_first_sample_is_still_at_fault(tmp_path: Path) -> None:
    """As in the simulator: the contact comes between two samples and by the first sample in COLLISION the impact
    has stopped the robot (0.02 m/s); the sample before shows the 0.2 m/s it drove in with."""
    states = [_state(k, min(1.0 + 0.01 * k, 1.395), 1.0, 0.2 if k < 40 else 0.02, [_person(1.8, 1.0)],
                     contacts=[["tb3", "h1"]] if k >= 40 else []) for k in range(46)]
    measured = measure(_run(tmp_path, states))
    (collision,) = measured.person_collisions
    assert collision.t == pytest.approx(2.0) and collision.approach == pytest.approx(0.2)
    assert measured.metrics["collisions_robot_at_fault"] == 1


def test_a_person_walking_into_a_stopped_robot_is_at_fault(tmp_path: Path) -> None:
    """The robot stands at (1, 1); the person walks -x at 0.3 m/s from (2, 1) into it. A robot creeping forward
    at less than AT_FAULT_SPEED, or pushed back, is not at fault either."""
    for name, vx in (("stopped", 0.0), ("creeping", AT_FAULT_SPEED * 0.8), ("pushed", -0.1)):
        states = [_state(k, 1.0, 1.0, vx, [_person(2.0 - 0.015 * k, 1.0, vx=-0.3)]) for k in range(46)]
        measured = measure(_run(tmp_path / name, states))
        (collision,) = measured.person_collisions
        assert collision.approach == pytest.approx(vx) and collision.person_at_fault, name
        assert (measured.metrics["collisions_robot_at_fault"],
                measured.metrics["collisions_person_at_fault"]) == (0, 1), name


def test_the_requirement_judges_the_monitors_collision_by_the_recorded_state(tmp_path: Path) -> None:
    """End to end through the evaluator: the recorded drive into the person, and the monitor's per-object signal
    at its first sample, fail NO_ROBOT_AT_FAULT_COLLISION with the person, time and approach speed; the person
    walking into the stopped robot passes it. The same collision fails MISSION_WITH_HUMAN_TRAJECTORY either way."""
    world = json.loads((FIXTURE / "world.json").read_text())
    monitor = json.loads((FIXTURE / "monitor.json").read_text())
    drives = {"robot": [_state(k, 1.0 + 0.01 * k, 1.0, 0.2, [_person(1.8, 1.0)]) for k in range(46)],
              "person": [_state(k, 1.0, 1.0, 0.0, [_person(2.0 - 0.015 * k, 1.0, vx=-0.3)]) for k in range(46)]}
    statuses = {}
    for name, states in drives.items():
        run = _run(tmp_path / name, states)
        first = measure(run).person_collisions[0].t
        signals = [("SIG_MISSION_BEGIN", 0.0, "mission"), ("SIG_OBJECT_COLLISION_BEGIN", round(first, 3), "h1"),
                   ("SIG_MISSION_END", 2.25, "mission")]
        messages = [{"seq": i, "t": t, "signal": signal, "subject": "tb3", "object": obj, "distance": 0.0}
                    for i, (signal, t, obj) in enumerate(signals)]
        summary = replay(messages, Evaluator(run, monitor_config=monitor, world=world), run_id=name,
                         sim_duration=2.25)
        verdict = summary.verdict("NO_ROBOT_AT_FAULT_COLLISION")
        statuses[name] = (verdict.status, summary.verdict("MISSION_WITH_HUMAN_TRAJECTORY").status)
        if name == "robot":
            assert verdict.message == ("1 collision(s) with people with the robot at fault, first with h1 at "
                                       "t=2.000 (0.20 m/s towards them)")
            assert (verdict.evidence[0].t, verdict.evidence[0].object) == (2.0, "h1")
            assert summary.metrics["collisions_robot_at_fault"] == 1
        else:
            assert verdict.evidence[0].text.startswith("person at fault: h1 walked into the robot")
            assert summary.metrics["collisions_person_at_fault"] == 1
    assert statuses == {"robot": (Status.FAIL, Status.FAIL), "person": (Status.PASS, Status.FAIL)}


# -- path irregularity ---------------------------------------------------------------------------------------

def test_path_irregularity_is_the_heading_change_per_metre_walked_averaged_over_people(tmp_path: Path) -> None:
    """h1 walks 1 m east then 1 m north at 1 m/s (a quarter turn in 2 m: pi/4 rad/m), h2 walks 2 m straight
    (0 rad/m), h3 stands (no walk: left out): the mean is pi/8. The robot stands far away."""
    world = json.loads((FIXTURE / "world.json").read_text())
    h1 = next(o for o in world["objects"] if o["name"] == "h1")
    world["objects"] += [{**h1, "name": "h2"}, {**h1, "name": "h3"}]
    states = []
    for k in range(41):
        corner = (0.5 + 0.05 * min(k, 20), 2.0 + 0.05 * max(k - 20, 0))
        people = [_person(*corner, name="h1"), _person(3.0 + 0.05 * k, 0.5, name="h2"),
                  _person(5.0, 3.5, name="h3")]
        states.append(_state(k, 5.5, 0.5, 0.0, people))
    m = compute_metrics(_run(tmp_path, states, world))
    assert m["path_irregularity_humans"] == pytest.approx(math.pi / 8, abs=1e-12)
