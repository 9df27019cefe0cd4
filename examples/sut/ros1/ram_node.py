# SPDX-License-Identifier: EPL-2.0
"""The "ramming script" as a ROS 1 system under test: turn 2 s at 0.2318 rad/s, then drive 12 s at 0.26 m/s
(from the simple_navigation example's start, straight into table1), whatever the goals say.

    rei run CASE --sut "ros1:python3 examples/sut/ros1/ram_node.py"

It needs ``/use_sim_time`` true. The timeline (``rei.sut.script.ScriptController``, the ``script:FILE``
controller; the private parameter ``~script`` names another script file) starts at the first clock message and
is published on ``cmd_vel`` (geometry_msgs/Twist, a script's sideways speed as ``linear.y``) once per ``~period``
(0.1 s) of sim time. It serves the ``move_base`` action (move_base_msgs/MoveBaseAction): any goal is accepted and
SUCCEEDED once the timeline has played; a cancelled goal stops the script (the robot stands still, later goals are
aborted).
"""

from __future__ import annotations

import sys

try:
    import rospy
except ImportError:  # Debian's ROS packages, from a virtual environment
    sys.path.append("/usr/lib/python3/dist-packages")
    import rospy
import actionlib
from geometry_msgs.msg import Twist
from move_base_msgs.msg import MoveBaseAction
from reference_nav_node import run_on_sim_clock  # the sibling example: one tick per clock step

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import NavStatus, Observation, StaticMap
from rei.sut.script import ScriptController, load_script, parse_script

RAM_THE_TABLE = "2.0 0.0 0.2318\n12.0 0.26 0.0\n"


class RamNode:
    def __init__(self) -> None:
        path = rospy.get_param("~script", "")
        self.script = ScriptController(load_script(path) if path else parse_script(RAM_THE_TABLE, "ram"))
        self.script.reset(StaticMap((0.0, 0.0, 1.0, 1.0), (), (0.0, 0.0)), Pose2D(0.0, 0.0))  # both ignored
        self.cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        self.server = actionlib.SimpleActionServer("move_base", MoveBaseAction, auto_start=False)
        self.server.register_goal_callback(self.on_goal)
        self.server.register_preempt_callback(self.on_preempt)
        self.server.start()

    def on_goal(self) -> None:  # under the action server's locks, as on_preempt
        self.server.accept_new_goal()
        self.report()

    def on_preempt(self) -> None:
        if not self.server.is_new_goal_available():
            self.script.cancel()
            if self.server.is_active():
                self.server.set_preempted(text="cancelled by the client")

    def tick(self, now: rospy.Time) -> None:
        with self.server.action_server.lock, self.server.lock:
            cmd = self.script.step(Observation(now.to_sec(), Pose2D(0.0, 0.0), Twist2D(), None))
            self.report()
        msg = Twist()
        msg.linear.x, msg.linear.y, msg.angular.z = cmd.v, cmd.vy, cmd.w  # vy: a script's fourth column
        self.cmd_pub.publish(msg)

    def report(self) -> None:
        if not self.server.is_active():
            return
        status, text = self.script.status, self.script.status_text
        if status is NavStatus.SUCCEEDED:
            self.server.set_succeeded(text=text)
        elif status is NavStatus.CANCELLED:
            self.server.set_aborted(text=f"the script was cancelled: {text}")


def main() -> None:
    rospy.init_node("rei_ram")
    if not rospy.get_param("/use_sim_time", False):
        rospy.logwarn("/use_sim_time is not true: this node is meant to be stepped by the bridge's /clock")
    node = RamNode()
    run_on_sim_clock(node.tick, rospy.Duration.from_sec(float(rospy.get_param("~period", 0.1))))


if __name__ == "__main__":
    main()
