# SPDX-License-Identifier: EPL-2.0
"""A rospy node that keeps the first /map it gets (latched): ``map_recorder.py OUT.npz`` writes the cells (int8,
as the message's ``data``), width, height, resolution and origin, then exits. Started beside a navigation stack,
on the run's private ROS master, by tests/ros/test_ros1_bridge_map_room.py."""

from __future__ import annotations

import sys
import threading

try:
    import rospy
except ImportError:  # Debian's ROS packages, from a virtual environment
    sys.path.append("/usr/lib/python3/dist-packages")
    import rospy
import numpy as np
from nav_msgs.msg import OccupancyGrid


def main(out: str) -> None:
    got = threading.Event()

    def keep(message: OccupancyGrid) -> None:
        info = message.info
        np.savez(out, data=np.asarray(message.data, dtype=np.int8), width=info.width, height=info.height,
                 resolution=info.resolution, origin=[info.origin.position.x, info.origin.position.y],
                 frame=message.header.frame_id)
        got.set()

    rospy.init_node("map_recorder", disable_signals=True)
    rospy.Subscriber("map", OccupancyGrid, keep)
    got.wait(120.0)
    rospy.signal_shutdown("recorded")


if __name__ == "__main__":
    main(sys.argv[1])
