# SPDX-License-Identifier: EPL-2.0
"""A rospy node that joins late and keeps the robot's description: ``description_recorder.py OUT.json`` waits
until the simulation's clock has passed t = 1 s (long after the bridge set /robot_description and latched
/tf_static), then reads the parameter, subscribes /tf_static (and /scan and /odom, for their frames), and
writes what it got to OUT.json. Started beside a navigation stack, on the run's private ROS master, by
tests/ros/test_ros_robot_description.py."""

from __future__ import annotations

import json
import sys
import threading
import time

try:
    import rospy
except ImportError:  # Debian's ROS packages, from a virtual environment
    sys.path.append("/usr/lib/python3/dist-packages")
    import rospy
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage

LATE = 1001.0  # ROS time of t = 1 s (the bridges' stamps are simulation time + 1000 s)


def main(out: str) -> None:
    rospy.init_node("description_recorder", disable_signals=True)
    deadline = time.monotonic() + 120.0
    while rospy.get_rostime().to_sec() < LATE and time.monotonic() < deadline:
        time.sleep(0.01)
    joined = rospy.get_rostime().to_sec()
    got = threading.Event()
    kept: dict = {"joined": joined, "urdf": rospy.get_param("/robot_description", None)}

    def keep(message: TFMessage) -> None:
        kept["tf_static"] = [{"parent": e.header.frame_id, "child": e.child_frame_id,
                              "translation": [e.transform.translation.x, e.transform.translation.y,
                                              e.transform.translation.z],
                              "rotation": [e.transform.rotation.x, e.transform.rotation.y, e.transform.rotation.z,
                                           e.transform.rotation.w]} for e in message.transforms]
        got.set()

    rospy.Subscriber("/tf_static", TFMessage, keep)
    scanned, odometry = threading.Event(), threading.Event()
    rospy.Subscriber("/scan", LaserScan, lambda m: (kept.__setitem__("scan_frame", m.header.frame_id), scanned.set()))
    rospy.Subscriber("/odom", Odometry, lambda m: (kept.__setitem__("odom_frames", [m.header.frame_id,
                                                                                     m.child_frame_id]),
                                                   odometry.set()))
    for event in (got, scanned, odometry):
        event.wait(30.0)
    with open(out, "w", encoding="utf-8") as file:
        json.dump(kept, file)
    rospy.signal_shutdown("recorded")


if __name__ == "__main__":
    main(sys.argv[1])
