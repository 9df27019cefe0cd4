# SPDX-License-Identifier: EPL-2.0
"""A ROS 2 participant (Cyclone DDS, in the stack's environment) that joins late and keeps the robot's
description: ``description_recorder_dds.py OUT.json`` waits until /clock has passed t = 1 s (long after the bridge
wrote /robot_description and /tf_static), only then creates its readers of both, transient-local as a
robot_state_publisher's subscribers and tf2's static listener read them, and of /scan and /odom (their frames),
and writes what it got to OUT.json.
Started beside a navigation stack by tests/ros/test_ros_robot_description.py."""

from __future__ import annotations

import json
import os
import sys
import time

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from rei.sut.ros2 import types as t

LATE_NS = 1001 * 10**9  # ROS time of t = 1 s (the bridges' stamps are simulation time + 1000 s)
#: What tf2_ros's StaticTransformListener and a robot_description subscriber ask (rclcpp's
#: StaticBroadcasterQoS): reliable, transient-local, keep-last 1; written here, not taken from REI's TOPICS.
#: XCDR1 is the representation rmw_cyclonedds offers and accepts.
XCDR1 = Policy.DataRepresentation(use_cdrv0_representation=True)
LATCHED = Qos(Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
              Policy.Durability.TransientLocal, Policy.History.KeepLast(1), XCDR1)


def main(out: str) -> None:
    participant = DomainParticipant(int(os.environ["ROS_DOMAIN_ID"]))  # CYCLONEDDS_URI: the bridge's loopback
    clock = DataReader(participant, Topic(participant, "rt/clock", t.Clock),
                       qos=Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(1), XCDR1))
    deadline, joined = time.monotonic() + 120.0, 0
    while joined < LATE_NS and time.monotonic() < deadline:
        for sample in clock.take(N=16):
            joined = max(joined, sample.clock.sec * 10**9 + sample.clock.nanosec)
        time.sleep(0.01)
    sensor = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(1), XCDR1)  # SensorDataQoS, as nav2's
    scans = DataReader(participant, Topic(participant, "rt/scan", t.LaserScan), qos=sensor)
    odometry = DataReader(participant, Topic(participant, "rt/odom", t.Odometry), qos=sensor)
    description = DataReader(participant, Topic(participant, "rt/robot_description", t.String), qos=LATCHED)
    static = DataReader(participant, Topic(participant, "rt/tf_static", t.TFMessage), qos=LATCHED)
    kept: dict = {"joined": joined * 1e-9}
    deadline = time.monotonic() + 30.0
    while not {"urdf", "tf_static", "scan_frame", "odom_frames"} <= kept.keys() and time.monotonic() < deadline:
        for sample in scans.take(N=4):
            kept["scan_frame"] = sample.header.frame_id
        for sample in odometry.take(N=4):
            kept["odom_frames"] = [sample.header.frame_id, sample.child_frame_id]
        for sample in description.take(N=4):
            kept["urdf"] = sample.data
        for sample in static.take(N=4):
            kept["tf_static"] = [{"parent": e.header.frame_id, "child": e.child_frame_id,
                                  "translation": [e.transform.translation.x, e.transform.translation.y,
                                                  e.transform.translation.z],
                                  "rotation": [e.transform.rotation.x, e.transform.rotation.y,
                                               e.transform.rotation.z, e.transform.rotation.w]}
                                 for e in sample.transforms]
        time.sleep(0.01)
    with open(out, "w", encoding="utf-8") as file:
        json.dump(kept, file)


if __name__ == "__main__":
    main(sys.argv[1])
