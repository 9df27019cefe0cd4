# SPDX-License-Identifier: EPL-2.0
"""REI's reference navigation (``rei.sut.nav.NavController``) as a ROS 1 ``move_base``: a system under test for
the ROS 1 bridge.

    rei run CASE --sut "ros1:python3 examples/sut/ros1/reference_nav_node.py" --sut-map

It needs ``/use_sim_time`` true, REI's Python environment (``rei`` and numpy importable) and rospy (Debian's
packages are found even from a virtual environment). It listens to ``odom`` (nav_msgs/Odometry), ``scan``
(sensor_msgs/LaserScan) and the latched ``map`` (nav_msgs/OccupancyGrid), serves the ``move_base`` action
(move_base_msgs/MoveBaseAction, goals in the ``map`` frame, which coincides with ``odom`` at the start) once the
map has arrived, and publishes ``cmd_vel`` (geometry_msgs/Twist) exactly once per control period of sim time,
zero when idle. Everything is stepped from the clock: goals and cancellations take effect at once, the action's
feedback and result follow the controller's status at each step. Topic names can be remapped the ROS way
(``odom:=/robot/odom``); private parameters: ``~footprint`` [0.281, 0.306], ``~max_linear`` 0.26,
``~max_angular`` 1.82, ``~goal_tolerance`` 0.25 (move_base goals carry none), ``~period`` 0.1 s of sim time,
``~occupied_threshold`` 65 (unknown cells count as free) and ``~odom_timeout`` 0.05 s of wall time (how long a
step waits for the odometry stamped with its own time, so that it never steers by the previous step's).
"""

from __future__ import annotations

import math
import sys
import threading
import time
import traceback
from collections.abc import Callable, Iterator
from contextlib import contextmanager

try:
    import rospy
except ImportError:  # Debian's ROS packages, from a virtual environment
    sys.path.append("/usr/lib/python3/dist-packages")
    import rospy
import actionlib
import numpy as np
from geometry_msgs.msg import Pose, PoseStamped, Quaternion, Twist
from move_base_msgs.msg import MoveBaseAction, MoveBaseFeedback
from nav_msgs.msg import OccupancyGrid, Odometry
from sensor_msgs.msg import LaserScan as RosLaserScan

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import LaserScan, NavGoal, NavStatus, Observation
from rei.sut.nav import NavController
from rei.sut.rasterize import static_map_of_grid


def yaw_of(q: Quaternion) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def pose2d_of(pose: Pose) -> Pose2D:
    return Pose2D(pose.position.x, pose.position.y, yaw_of(pose.orientation))


def ros_pose(pose: Pose2D) -> Pose:
    out = Pose()
    out.position.x, out.position.y = pose.x, pose.y
    out.orientation.z, out.orientation.w = math.sin(0.5 * pose.yaw), math.cos(0.5 * pose.yaw)
    return out


def run_on_sim_clock(tick: Callable[[rospy.Time], None], period: rospy.Duration) -> None:
    """Call ``tick(now)`` at the first clock message and then once per ``period`` of sim time, on the grid the
    first clock set, until shutdown; when the clock steps by ``period`` that is exactly once per step.

    Not a rospy.Timer: one created before the first clock fires twice at the second clock message and not at the
    first; one created after it races the next clock message (it anchors at the time its thread starts) and
    re-reads the time before it sleeps, so a clock message arriving in between costs a step. A clock moving
    backwards starts a new grid.
    """
    cond = rospy.rostime.get_rostime_cond()
    slack = 1_000_000  # ns: clocks computed in floating point land a hair before the grid
    t0 = last = due = None
    while True:
        with cond:
            while not rospy.is_shutdown():
                now = rospy.get_rostime().to_nsec()  # 0: no clock yet
                if now and (due is None or now >= due or now < last):
                    break
                cond.wait(0.5)
            else:
                return
        if t0 is None or now < last:
            t0 = now
        try:
            tick(rospy.Time(nsecs=now))
        except Exception:  # noqa: BLE001 - a failing step must not stop the clock
            rospy.logerr("step at %.3f failed:\n%s", now * 1e-9, traceback.format_exc())
        last = now
        due = t0 + ((now - t0 + slack) // period.to_nsec() + 1) * period.to_nsec() - slack


class ReferenceNavNode:
    def __init__(self) -> None:
        size_x, size_y = rospy.get_param("~footprint", [0.281, 0.306])
        self.footprint = (float(size_x), float(size_y))
        self.max_linear = float(rospy.get_param("~max_linear", 0.26))
        self.max_angular = float(rospy.get_param("~max_angular", 1.82))
        self.tolerance = float(rospy.get_param("~goal_tolerance", 0.25))
        self.occupied = int(rospy.get_param("~occupied_threshold", 65))
        self.odom_timeout = float(rospy.get_param("~odom_timeout", 0.05))
        self.nav: NavController | None = None
        self.goals = 0
        self.odom: Odometry | None = None
        self.scan: LaserScan | None = None
        self.odom_arrived = threading.Condition()
        self.cmd_pub = rospy.Publisher("cmd_vel", Twist, queue_size=10)
        self.server = actionlib.SimpleActionServer("move_base", MoveBaseAction, auto_start=False)
        self.server.register_goal_callback(self.on_goal)
        self.server.register_preempt_callback(self.on_preempt)
        self.server_started = False
        rospy.Subscriber("odom", Odometry, self.on_odom, queue_size=10, tcp_nodelay=True)
        rospy.Subscriber("scan", RosLaserScan, self.on_scan, queue_size=10, tcp_nodelay=True)
        rospy.Subscriber("map", OccupancyGrid, self.on_map, queue_size=1)

    @contextmanager
    def action_locked(self) -> Iterator[None]:
        """The action server's own locks (its callbacks run under them): a step and a goal never interleave."""
        with self.server.action_server.lock, self.server.lock:
            yield

    # -- inputs --------------------------------------------------------------------------------------------

    def on_odom(self, msg: Odometry) -> None:
        with self.odom_arrived:
            self.odom = msg
            self.odom_arrived.notify_all()

    def on_scan(self, msg: RosLaserScan) -> None:
        self.scan = LaserScan(msg.header.stamp.to_sec(), msg.angle_min, msg.angle_increment, msg.range_min,
                              msg.range_max, np.asarray(msg.ranges, dtype=float))

    def on_map(self, msg: OccupancyGrid) -> None:
        started = time.perf_counter()
        info = msg.info
        static_map = static_map_of_grid(msg.data, info.width, info.height, info.resolution,
                                        pose2d_of(info.origin), self.footprint, self.occupied)
        nav = NavController(self.max_linear, self.max_angular, self.footprint)
        odom = self.odom
        nav.reset(static_map, pose2d_of(odom.pose.pose) if odom else Pose2D(0.0, 0.0))
        with self.action_locked():
            if self.server_started and self.server.is_active():
                self.server.set_aborted(text="the map changed")
            self.nav = nav
        rospy.loginfo("map %dx%d cells: %d rectangles, navigation ready in %.0f ms", msg.info.width,
                      msg.info.height, len(static_map.obstacles), 1e3 * (time.perf_counter() - started))
        if not self.server_started:
            self.server.start()
            self.server_started = True

    # -- the action (called under the action server's locks) ------------------------------------------------

    def on_goal(self) -> None:
        goal = self.server.accept_new_goal()
        assert self.nav is not None  # the server starts with the first map
        if goal.target_pose.header.frame_id.lstrip("/") not in ("", "map", "odom"):
            rospy.logwarn_once("goals are taken as map-frame poses, got frame %r", goal.target_pose.header.frame_id)
        self.goals += 1
        self.nav.set_goal(NavGoal(self.goals, pose2d_of(goal.target_pose.pose), self.tolerance))

    def on_preempt(self) -> None:
        if self.server.is_new_goal_available():
            return  # on_goal replaces the goal
        if self.nav is not None:
            self.nav.cancel()
        if self.server.is_active():
            self.server.set_preempted(text="cancelled by the client")

    # -- the step ------------------------------------------------------------------------------------------

    def tick(self, now: rospy.Time) -> None:
        odom = self.wait_for_odom(now)
        cmd = Twist2D()
        if odom is not None and self.nav is not None:
            twist = odom.twist.twist
            observation = Observation(now.to_sec(), pose2d_of(odom.pose.pose),
                                      Twist2D(twist.linear.x, twist.angular.z), self.scan)
            with self.action_locked():
                cmd = self.nav.step(observation)
                self.report(self.nav, now)
        msg = Twist()
        msg.linear.x, msg.angular.z = cmd.v, cmd.w
        self.cmd_pub.publish(msg)

    def wait_for_odom(self, now: rospy.Time) -> Odometry | None:
        """The latest odometry, after waiting (a little wall time) for the one stamped ``now``."""
        deadline = time.monotonic() + self.odom_timeout
        with self.odom_arrived:
            while self.odom is None or self.odom.header.stamp < now:
                left = deadline - time.monotonic()
                if left <= 0:
                    rospy.logwarn_once("no odometry stamped with the step's time %.3f: steering by older odometry",
                                       now.to_sec())
                    break
                self.odom_arrived.wait(left)
            return self.odom

    def report(self, nav: NavController, now: rospy.Time) -> None:
        server = self.server
        if not server.is_active():
            return
        status = nav.status
        if status is NavStatus.ACTIVE and nav.pose is not None:
            feedback = MoveBaseFeedback()
            feedback.base_position = PoseStamped(pose=ros_pose(nav.pose))
            feedback.base_position.header.stamp, feedback.base_position.header.frame_id = now, "map"
            server.publish_feedback(feedback)
        elif status is NavStatus.SUCCEEDED:
            server.set_succeeded(text=nav.status_text)
        elif status is NavStatus.ABORTED:
            server.set_aborted(text=nav.status_text)
        elif status is NavStatus.CANCELLED:
            server.set_preempted(text=nav.status_text)


def main() -> None:
    rospy.init_node("rei_reference_nav")
    if not rospy.get_param("/use_sim_time", False):
        rospy.logwarn("/use_sim_time is not true: this node is meant to be stepped by the bridge's /clock")
    node = ReferenceNavNode()
    run_on_sim_clock(node.tick, rospy.Duration.from_sec(float(rospy.get_param("~period", 0.1))))


if __name__ == "__main__":
    main()
