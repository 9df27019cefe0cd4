# SPDX-License-Identifier: EPL-2.0
"""A bag's topics as checked samples in time order, read with ``rosbags`` (pure Python, Apache-2.0).

Every problem names the bag, the topic and the time: a topic that is missing (with the topics there are), of a
type REI cannot read, with stamps that go backwards, or a bag that is corrupt or cut short.
"""

from __future__ import annotations

import contextlib
import heapq
import math
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from rei.geometry import Pose2D, Twist2D, yaw_of_quaternion
from rei.sut.api import LaserScan, NavStatus
from rei.sut.ros_conventions import ACTION_MSGS_FINAL, ACTIONLIB_FINAL

#: Message types each role accepts (rosbags spells ROS 1 and ROS 2 types alike). Goals: move_base's action goal
#: (ROS 1) or a pose goal such as nav2's /goal_pose; results: move_base's action result (ROS 1) or an action's
#: status array (ROS 2, e.g. /navigate_to_pose/_action/status).
POSE_TYPES = ("nav_msgs/msg/Odometry", "geometry_msgs/msg/PoseStamped", "geometry_msgs/msg/PoseWithCovarianceStamped")
ROLE_TYPES: Mapping[str, tuple[str, ...]] = {
    "pose": POSE_TYPES,
    "odom": ("nav_msgs/msg/Odometry",),
    "scan": ("sensor_msgs/msg/LaserScan",),
    "goal": ("move_base_msgs/msg/MoveBaseActionGoal", "geometry_msgs/msg/PoseStamped"),
    "result": ("move_base_msgs/msg/MoveBaseActionResult", "action_msgs/msg/GoalStatusArray"),
}


class BagError(ValueError):
    """The bag cannot be imported; the message names the bag, the topic and the time."""


@dataclass(frozen=True, slots=True)
class Sample:
    """One message of a role: ``t`` its header stamp (s; the recording time for a message without one), ``value``
    a Pose2D (pose), (Pose2D, Twist2D) (odom), a LaserScan (scan), a RecordedGoal (goal) or a tuple of
    RecordedResult (result)."""

    t: float
    role: str
    value: Any


@dataclass(frozen=True, slots=True)
class RecordedGoal:
    """A navigation goal; ``goal_id`` None for a pose goal, which has none."""

    goal_id: str | None
    pose: Pose2D


@dataclass(frozen=True, slots=True)
class RecordedResult:
    """A goal's state: ``status`` its final state, None while it runs; ``text`` the server's (ROS 2 status arrays
    carry none)."""

    goal_id: str
    status: NavStatus | None
    text: str


def read_samples(bag: Path, topics: Mapping[str, str]) -> Iterator[Sample]:
    """The samples of ``topics`` (role -> topic name) merged in stamp order."""
    with _opened(bag) as reader:
        available = {c.topic: c.msgtype for c in reader.connections}
        for role, topic in topics.items():
            _check_topic(bag, role, topic, available)
        streams = [_stream(bag, reader, role, topic) for role, topic in topics.items()]
        yield from heapq.merge(*streams, key=lambda sample: sample.t)


def topics_of(bag: Path) -> dict[str, str]:
    """topic -> message type of every connection in the bag."""
    with _opened(bag) as reader:
        return {c.topic: c.msgtype for c in reader.connections}


@contextlib.contextmanager
def _opened(bag: Path) -> Iterator[Any]:
    """rosbags' reader of ``bag``; whatever rosbags raises for a bad file becomes a BagError naming it."""
    from rosbags.highlevel import AnyReader

    try:
        with AnyReader([bag]) as reader:
            yield reader
    except BagError:
        raise
    except Exception as error:  # noqa: BLE001 - rosbags raises many kinds for a corrupt or truncated file
        raise BagError(f"{bag}: not a readable bag (corrupt or truncated?): {type(error).__name__}: {error}") from None


def _check_topic(bag: Path, role: str, topic: str, available: Mapping[str, str]) -> None:
    if topic not in available:
        listed = ", ".join(f"{name} ({kind})" for name, kind in sorted(available.items())) or "none"
        raise BagError(f"{bag}: no topic {topic} for the {role} (--{role}-topic); the bag has: {listed}")
    if available[topic] not in ROLE_TYPES[role]:
        raise BagError(f"{bag}: topic {topic} is {available[topic]}; the {role} must be one of "
                       f"{', '.join(ROLE_TYPES[role])}")


def _stream(bag: Path, reader: Any, role: str, topic: str) -> Iterator[Sample]:
    connections = [c for c in reader.connections if c.topic == topic]
    last = -math.inf
    for connection, recorded, raw in reader.messages(connections=connections):
        message = reader.deserialize(raw, connection.msgtype)
        t = _stamp(message, recorded)
        if t < last:
            raise BagError(f"{bag}: topic {topic}: stamp {t:.6f} s comes after {last:.6f} s (stamps must not go "
                           "backwards)")
        last = t
        yield Sample(t, role, _value(role, message))


def _stamp(message: Any, recorded_ns: int) -> float:
    """The header's stamp; the recording time when there is no header or its stamp is zero (an action goal sent
    without one)."""
    header = getattr(message, "header", None)
    if header is not None and (header.stamp.sec or header.stamp.nanosec):
        return header.stamp.sec + header.stamp.nanosec * 1e-9
    return recorded_ns * 1e-9


def _value(role: str, message: Any) -> Any:
    if role == "goal":
        if hasattr(message, "goal_id"):  # MoveBaseActionGoal
            return RecordedGoal(str(message.goal_id.id), _pose2d(message.goal.target_pose.pose))
        return RecordedGoal(None, _pose2d(message.pose))
    if role == "result":
        if hasattr(message, "status_list"):  # action_msgs/GoalStatusArray: every goal the server knows
            return tuple(RecordedResult(bytes(s.goal_info.goal_id.uuid).hex(), ACTION_MSGS_FINAL.get(s.status), "")
                         for s in message.status_list)
        status = message.status
        return (RecordedResult(str(status.goal_id.id), ACTIONLIB_FINAL.get(status.status), str(status.text)),)
    if role == "scan":
        return LaserScan(t=0.0, angle_min=float(message.angle_min), angle_increment=float(message.angle_increment),
                         range_min=float(message.range_min), range_max=float(message.range_max),
                         ranges=np.asarray(message.ranges, dtype=np.float64))
    pose2d = _pose2d(message.pose.pose if hasattr(message.pose, "pose") else message.pose)  # Odometry: .pose.pose
    if role == "odom":
        twist = message.twist.twist
        return pose2d, Twist2D(float(twist.linear.x), float(twist.angular.z))
    return pose2d


def _pose2d(pose: Any) -> Pose2D:
    q = pose.orientation
    return Pose2D(float(pose.position.x), float(pose.position.y), yaw_of_quaternion(q.x, q.y, q.z, q.w))
