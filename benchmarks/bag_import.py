# SPDX-License-Identifier: EPL-2.0
"""Import speed of `rei import` for a 10-minute ROS 1 bag: /odom at 50 Hz and /scan (360 beams) at 10 Hz, written
by Debian's rosbag. Reported in messages per second, beside the floor measured in the same run: rosbags reading
and deserializing the same messages, with nothing done with them.

    .venv/bin/python benchmarks/bag_import.py [--minutes 10]
"""

from __future__ import annotations

import argparse
import math
import os
import tempfile
import time
from pathlib import Path

from _examples import generate_example

from rei.bags.importer import import_bag
from rei.sut.ros1.environment import import_rospy

TOPICS = {"pose": "/odom", "scan": "/scan"}


def write_bag(path: Path, minutes: float) -> int:
    import_rospy()
    import rosbag
    import rospy
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import LaserScan

    count = 0
    with rosbag.Bag(str(path), "w") as bag:
        for k in range(int(minutes * 60 * 50)):
            t = k / 50
            stamp = rospy.Time(100) + rospy.Duration.from_sec(t)
            odom = Odometry()
            odom.header.stamp = stamp
            odom.pose.pose.position.x = 3.0 + 2.0 * math.cos(t / 20)  # circles in the 6 x 4 m room
            odom.pose.pose.position.y = 2.0 + 1.2 * math.sin(t / 20)
            odom.pose.pose.orientation.w = 1.0
            bag.write("/odom", odom, stamp)
            count += 1
            if k % 5 == 0:
                scan = LaserScan(angle_min=-math.pi, angle_increment=2 * math.pi / 360, range_min=0.12, range_max=3.5,
                                 ranges=[1.0 + (i % 7) * 0.1 for i in range(360)])
                scan.header.stamp = stamp
                bag.write("/scan", scan, stamp)
                count += 1
    return count


def read_only(path: Path) -> int:
    from rosbags.highlevel import AnyReader

    count = 0
    with AnyReader([path]) as reader:
        for connection, _, raw in reader.messages(connections=reader.connections):
            reader.deserialize(raw, connection.msgtype)
            count += 1
    return count


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="rei-bench-") as tmp:
        bag, case = Path(tmp) / "run.bag", generate_example("simple_navigation", Path(tmp) / "case")
        written = write_bag(bag, args.minutes)
        started = time.perf_counter()
        floor = read_only(bag)
        floor_wall = time.perf_counter() - started
        result = import_bag(bag, Path(tmp) / "out", case, TOPICS)
    assert floor == written == result.messages
    print(f"{args.minutes:g} minutes, {written} messages ({bag.name}): rei import {result.messages_per_second:.0f} "
          f"messages/s ({result.wall_time:.2f} s, {result.states} states); rosbags reading alone "
          f"{floor / floor_wall:.0f} messages/s ({floor_wall:.2f} s): ratio {result.wall_time / floor_wall:.2f}; "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
