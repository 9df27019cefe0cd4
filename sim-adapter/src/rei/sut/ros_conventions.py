# SPDX-License-Identifier: EPL-2.0
"""What REI's ROS 1 and ROS 2 mappings agree on (docs/ros.md): frame ids and the clock's offset.

Simulation time t is ROS time ``TIME_OFFSET_NS + t``: rospy and rclcpp both take time 0 for "no clock yet", and
one offset keeps the two bridges' stamps identical.
"""

from __future__ import annotations

from dataclasses import dataclass

TIME_OFFSET_NS = 1000 * 10**9


def ros_nanoseconds(t: float) -> int:
    """The ROS time of simulation time ``t`` in nanoseconds (exact on a 10 Hz grid, as sim-time timers need)."""
    return TIME_OFFSET_NS + round(t * 1e9)


@dataclass(frozen=True, slots=True)
class Frames:
    """Frame ids, with the ROS defaults."""

    map: str = "map"
    odom: str = "odom"
    base: str = "base_link"
    laser: str = "base_scan"
