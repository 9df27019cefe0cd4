# SPDX-License-Identifier: EPL-2.0
"""What REI's ROS 1 and ROS 2 mappings agree on (docs/ros.md): frame ids, the clock's offset, what a navigation
action's final status means.

Simulation time t is ROS time ``TIME_OFFSET_NS + t``: rospy and rclcpp both take time 0 for "no clock yet", and
one offset keeps the two bridges' stamps identical.
"""

from __future__ import annotations

from dataclasses import dataclass

from rei.sut.api import NavStatus

TIME_OFFSET_NS = 1000 * 10**9
#: Wall seconds a bridge's tick waits for the stack's /cmd_vel (--cmd-wait of both bridges).
CMD_WAIT = 0.25


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


#: actionlib_msgs/GoalStatus codes (ROS 1 move_base) that end a goal: PREEMPTED, SUCCEEDED, ABORTED, REJECTED,
#: RECALLED, LOST.
ACTIONLIB_FINAL: dict[int, NavStatus] = {2: NavStatus.CANCELLED, 3: NavStatus.SUCCEEDED, 4: NavStatus.ABORTED,
                                         5: NavStatus.ABORTED, 8: NavStatus.CANCELLED, 9: NavStatus.ABORTED}
#: action_msgs/GoalStatus codes (ROS 2, nav2's NavigateToPose) that end a goal: SUCCEEDED, CANCELED, ABORTED.
ACTION_MSGS_FINAL: dict[int, NavStatus] = {4: NavStatus.SUCCEEDED, 5: NavStatus.CANCELLED, 6: NavStatus.ABORTED}
