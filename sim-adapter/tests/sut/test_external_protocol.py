# SPDX-License-Identifier: EPL-2.0
"""The external-SUT messages (docs/sut.md): what crosses the boundary, bit for bit, and the bad-input rules."""

from __future__ import annotations

import math

import msgpack
import numpy as np
import pytest

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import Controller, LaserScan, NavGoal, NavStatus, Observation, StaticMap
from rei.sut.external import protocol
from rei.sut.external.protocol import Command, Rejected, RobotLimits, Status

LIMITS = RobotLimits(max_linear=0.26, max_angular=1.82)


def _check(payload, tick: int = 4, answered: bool = False):
    return protocol.check_command(payload, current_tick=tick, answered=answered, limits=LIMITS)


def test_an_observation_crosses_msgpack_bit_for_bit() -> None:
    ranges = np.array([0.1 + 1e-17, 1 / 3, math.inf, 3.5], dtype=np.float64)
    scan = LaserScan(t=0.2, angle_min=-math.pi, angle_increment=2 * math.pi / 4, range_min=0.12, range_max=3.5,
                     ranges=ranges)
    observation = Observation(t=0.3, odom=Pose2D(0.1 + 0.2, 1 / 7, -0.5), odom_twist=Twist2D(0.26, -1 / 3), scan=scan)
    wire = msgpack.unpackb(msgpack.packb(protocol.tick_message(3, observation, new_scan=True, scan_time=0.2)))
    assert wire["tick"] == 3 and wire["scan"]["angle_max"] == pytest.approx(math.pi / 2)
    back = protocol.read_observation(wire, None)
    assert back.t == observation.t and back.odom == observation.odom and back.odom_twist == observation.odom_twist
    assert back.scan is not None and back.scan.ranges.tobytes() == ranges.tobytes()
    assert (back.scan.t, back.scan.angle_min, back.scan.angle_increment) == (0.2, -math.pi, math.pi / 2)


def test_a_tick_without_a_new_scan_keeps_the_last_one() -> None:
    scan = LaserScan(0.0, 0.0, 0.1, 0.1, 3.5, np.ones(3))
    message = protocol.tick_message(1, Observation(0.1, Pose2D(0, 0), Twist2D(), scan), new_scan=False,
                                    scan_time=0.2)
    assert message["scan"] is None
    assert protocol.read_observation(message, scan).scan is scan


def test_every_number_is_sent_as_float64() -> None:
    goal = protocol.goal_message(1, NavGoal(0, Pose2D(1, 2, 0), 1))
    packed = msgpack.packb(goal)
    assert goal == {"goal_id": 0, "t": 1.0, "pose": [1.0, 2.0, 0.0], "tolerance": 1.0}
    assert packed.count(b"\xcb") == 5  # t, three pose values, tolerance; goal_id stays an integer


def test_a_valid_command_answers_its_tick() -> None:
    assert _check({"tick": 4, "v": 0.1, "w": -1}) == Command(4, Twist2D(0.1, -1.0))


@pytest.mark.parametrize("payload, reason", [
    ("go", "a command must be a map"),
    ([4, 0.1, 0.0], "a command must be a map"),
    ({"tick": 4, "v": 0.1}, "missing w"),
    ({"tick": 4, "v": 0.1, "w": 0.0, "vx": 1}, "unknown vx"),
    ({"tick": "4", "v": 0.1, "w": 0.0}, "tick must be an integer"),
    ({"tick": 4.0, "v": 0.1, "w": 0.0}, "tick must be an integer"),
    ({"tick": True, "v": 0.1, "w": 0.0}, "tick must be an integer"),
    ({"tick": 4, "v": "fast", "w": 0.0}, "v must be a number"),
    ({"tick": 4, "v": False, "w": 0.0}, "v must be a number"),
    ({"tick": 4, "v": math.nan, "w": 0.0}, "v must be finite"),
    ({"tick": 4, "v": 0.0, "w": -math.inf}, "w must be finite"),
    ({"tick": 5, "v": 0.0, "w": 0.0}, "tick 5 was not published yet"),
])
def test_malformed_commands_are_rejected_with_a_reason(payload, reason: str) -> None:
    result = _check(payload)
    assert isinstance(result, Rejected) and not result.stale
    assert reason in result.reason


def test_late_and_repeated_commands_are_stale() -> None:
    assert _check({"tick": 3, "v": 0.0, "w": 0.0}) == Rejected("tick 3 is already answered", stale=True)
    assert _check({"tick": 4, "v": 0.0, "w": 0.0}, answered=True).stale


def test_absurd_velocities_are_clamped_to_the_robot_s_limits() -> None:
    assert _check({"tick": 4, "v": 100, "w": -1e9}) == Command(4, Twist2D(0.26, -1.82), clamped=True)
    assert _check({"tick": 4, "v": -0.26, "w": 1.82}) == Command(4, Twist2D(-0.26, 1.82), clamped=False)


def test_vy_is_a_holonomic_robot_s_and_clamped_to_0_for_a_differential_one() -> None:
    holonomic = RobotLimits(max_linear=0.26, max_angular=1.82, max_lateral=0.26)
    assert protocol.check_command({"tick": 4, "v": 0, "w": 0, "vy": -0.2}, current_tick=4, answered=False,
                                  limits=holonomic) == Command(4, Twist2D(0.0, 0.0, -0.2))
    assert protocol.check_command({"tick": 4, "v": 0, "w": 0, "vy": 9}, current_tick=4, answered=False,
                                  limits=holonomic) == Command(4, Twist2D(0.0, 0.0, 0.26), clamped=True)
    assert _check({"tick": 4, "v": 0.1, "w": 0, "vy": 0.2}) == Command(4, Twist2D(0.1, 0.0, 0.0), clamped=True)
    assert _check({"tick": 4, "v": 0.1, "w": 0, "vy": 0}) == Command(4, Twist2D(0.1, 0.0), clamped=False)
    for payload, reason in (({"tick": 4, "v": 0, "w": 0, "vy": "left"}, "vy must be a number"),
                            ({"tick": 4, "v": 0, "w": 0, "vy": math.inf}, "vy must be finite"),
                            ({"tick": 4, "v": 0, "vy": 0.1}, "missing w")):
        result = _check(payload)
        assert isinstance(result, Rejected) and reason in result.reason, result


def test_a_holonomic_robot_s_tick_has_its_sideways_odometry_third() -> None:
    observation = Observation(t=0.5, odom=Pose2D(1.0, 2.0, 0.1), odom_twist=Twist2D(0.1, 0.2, -0.3), scan=None)
    differential = protocol.tick_message(5, observation, new_scan=False, scan_time=0.1)
    holonomic = protocol.tick_message(5, observation, new_scan=False, scan_time=0.1, holonomic=True)
    assert differential["odom"]["twist"] == [0.1, 0.2] and holonomic["odom"]["twist"] == [0.1, 0.2, -0.3]
    assert protocol.read_observation(holonomic, None).odom_twist == Twist2D(0.1, 0.2, -0.3)
    assert protocol.read_observation(differential, None).odom_twist == Twist2D(0.1, 0.2)


def test_hello_s_outline_is_the_footprint_as_world_json_writes_it() -> None:
    from rei.artifacts.world import CircleFootprint, PolygonFootprint

    assert protocol.outline(CircleFootprint(0.05, 0, 0.17)) == {"type": "circle", "x": 0.05, "y": 0.0, "radius": 0.17}
    square = PolygonFootprint(((-0.1, -0.1), (0.1, -0.1), (0.1, 0.1), (-0.1, 0.1)))
    assert protocol.outline(square) == {"type": "polygon", "points": [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1],
                                                                      [-0.1, 0.1]]}
    assert all(isinstance(v, float) for point in protocol.outline(square)["points"] for v in point)


def test_a_controller_s_static_map_takes_a_described_robot_s_outline_and_drive_from_hello() -> None:
    """rei nav-sut plans as the in-process navigation does: with a described robot's outline (a circle as the
    polygon around it) and its holonomic drive; a box robot's outline, its footprint rectangle, leaves it planned by
    its size, as before."""
    from rei.artifacts.world import CircleFootprint, PolygonFootprint, footprint_polygon

    box = PolygonFootprint(((-0.2, -0.15), (0.2, -0.15), (0.2, 0.15), (-0.2, 0.15)))
    hello = {"map": {"bounds": [0, 0, 4, 4], "obstacles": []},
             "robot": {"footprint": [0.4, 0.3], "outline": protocol.outline(box), "drive": "differential"}}
    static_map = protocol.read_static_map(hello)
    assert static_map is not None and static_map.outline is None and not static_map.holonomic
    hello["robot"].update(outline=protocol.outline(CircleFootprint(0.0, 0.0, 0.17)), drive="holonomic")
    static_map = protocol.read_static_map(hello)
    assert static_map is not None and static_map.holonomic
    assert static_map.outline == footprint_polygon(CircleFootprint(0.0, 0.0, 0.17))


class _Keeps(Controller):
    """A controller that keeps the map it was reset with and stands."""

    static_map: StaticMap | None = None

    def reset(self, static_map: StaticMap, start: Pose2D) -> None:
        self.static_map = static_map

    def set_goal(self, goal: NavGoal) -> None:
        pass

    def cancel(self) -> None:
        pass

    def step(self, observation: Observation) -> Twist2D:
        return Twist2D(0.0, 0.0)

    @property
    def status(self) -> NavStatus:
        return NavStatus.IDLE


def test_a_controller_run_without_the_static_map_gets_the_robot_hello_describes() -> None:
    """rei nav-sut SPEC without --sut-map: the controller's empty map had the robot's size alone, so its lidar sat
    at the centre facing ahead (the Waffle's is 0.064 m back), a described robot was its bounding box and a
    holonomic robot differential; now the robot is what the same hello gives with a map."""
    from rei.artifacts.world import CircleFootprint, footprint_polygon
    from rei.sut.client import ControllerSut, Session

    robot = {"name": "bot", "footprint": [0.34, 0.34], "max_linear": 0.3, "max_angular": 2.0, "drive": "holonomic",
             "max_lateral": 0.3, "outline": protocol.outline(CircleFootprint(0.0, 0.0, 0.17)),
             "lidar": {"beams": 360, "range_min": 0.12, "range_max": 3.5, "rate": 10.0, "x": -0.064, "y": 0.01,
                       "yaw": 0.5}}
    hello = {"run_id": "r", "clock": "lockstep", "control_rate": 10.0, "deadline": 10.0, "start": [0.5, 0.5, 0.0],
             "robot": robot, "goals": 1, "map": None}
    controller = _Keeps()
    ControllerSut(controller).on_start(Session.from_hello(hello))
    kept = controller.static_map
    assert kept is not None and kept.obstacles == ()
    assert kept.robot_size == (0.34, 0.34) and kept.lidar == (-0.064, 0.01, 0.5) and kept.holonomic
    assert kept.outline == footprint_polygon(CircleFootprint(0.0, 0.0, 0.17))
    with_map = protocol.read_static_map({**hello, "map": {"bounds": [0, 0, 4, 4], "obstacles": []}})
    assert with_map is not None
    assert (kept.robot_size, kept.lidar, kept.outline, kept.holonomic) == (
        with_map.robot_size, with_map.lidar, with_map.outline, with_map.holonomic)


def test_statuses_follow_the_action_server_s_states() -> None:
    assert protocol.check_status({"goal_id": 1, "status": "SUCCEEDED", "text": "there"}, current_goal=1) == \
        Status(1, NavStatus.SUCCEEDED, "there")
    assert protocol.check_status({"goal_id": 1, "status": "ABORTED"}, current_goal=1) == \
        Status(1, NavStatus.ABORTED, "")
    assert protocol.check_status({"goal_id": 0, "status": "SUCCEEDED"}, current_goal=1).stale  # type: ignore[union-attr]


@pytest.mark.parametrize("payload, reason", [
    (None, "a status must be a map"),
    ({"goal_id": 1}, "the fields goal_id, status"),
    ({"goal_id": 1, "status": "ACTIVE", "extra": 1}, "the fields goal_id, status"),
    ({"goal_id": 1, "status": "IDLE"}, "status must be one of ABORTED, ACTIVE, CANCELLED, SUCCEEDED"),
    ({"goal_id": 1, "status": "DONE"}, "status must be one of"),
    ({"goal_id": "1", "status": "ACTIVE"}, "goal_id must be an integer"),
    ({"goal_id": 1, "status": "ACTIVE", "text": 5}, "text must be a string"),
    ({"goal_id": 1, "status": "ACTIVE", "text": None}, "text must be a string"),
    ({"goal_id": 1, "status": "ACTIVE", "text": "x" * 1001}, "at most 1000 characters"),
])
def test_malformed_statuses_are_rejected(payload, reason: str) -> None:
    result = protocol.check_status(payload, current_goal=1)
    assert isinstance(result, Rejected) and not result.stale and reason in result.reason


def test_uris_are_the_run_s_and_only_the_protocol_s() -> None:
    assert protocol.uri("r1", "tick") == "rei.run.r1.sut.tick"
    with pytest.raises(ValueError, match="no SUT URI named 'state'"):
        protocol.uri("r1", "state")


def test_a_message_with_keyword_arguments_is_rejected_naming_them() -> None:
    """publish(uri, tick=0, v=0.1, w=0.0) was rejected as "missing tick, v, w; unknown args, kwargs": fields the
    user never sent."""
    from rei.sut.external.controller import _odd

    sent = _odd((), {"tick": 0, "v": 0.1, "w": 0.0})
    for result in (_check(sent, tick=0), protocol.check_status(_odd((), {"goal_id": 0, "status": "ACTIVE"}),
                                                                 current_goal=0)):
        assert isinstance(result, Rejected)
        assert "keyword arguments (" in result.reason and "args[0]" in result.reason, result.reason
        assert "unknown" not in result.reason
    assert "keyword arguments (tick, v, w): send the map" in _check(sent, tick=0).reason
