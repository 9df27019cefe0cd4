# SPDX-License-Identifier: EPL-2.0
"""The bridge node: REI's external SUT on one side, the robot a ROS 1 navigation stack expects on the other.

Before the stack starts it sets the robot's /robot_description and latches /tf_static (rei.sut.ros_description).
Per control period (REI's tick, rei.sut.ros_bridge) it publishes /odom, /tf and (when new) /scan stamped with the
tick's time, then /clock, and waits for the stack's next /cmd_vel. The stack runs on ``use_sim_time``, so its timers advance only
with this clock: simulation and stack move in lockstep, as fast as the stack answers. REI's goals become goals of
the ``move_base`` action, whose feedback and result become the goal status REI judges.

Topics are separate TCP connections in ROS 1, so nothing orders /scan before /clock at the stack's side; sensors
are published first and in practice arrive first on loopback, but a run through a ROS stack is not guaranteed to
be bit-for-bit repeatable the way REI's own external SUTs are (docs/ros.md).
"""

from __future__ import annotations

import contextlib
import functools
import os
import shlex
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.processes import ManagedProcess
from rei.sut.api import NavGoal, NavStatus
from rei.sut.client import EXIT_CONNECTION, Session, SutConnectionError, Tick
from rei.sut.ros1.environment import RosUnavailableError, import_rospy, ros_environment
from rei.sut.ros_bridge import (
    ACCEPT_TIMEOUT,
    PRE_START,
    SERVER_TIMEOUT,
    STACK_LOG,
    WAIT_NOTE,
    RosBridge,
    run_bridge,
    session_occupancy,
)
from rei.sut.ros_conventions import ACTIONLIB_FINAL, CMD_WAIT
from rei.sut.ros_description import RobotDescription, case_robot_description


@dataclass(frozen=True, slots=True)
class BridgeSettings:
    cmd_wait: float = CMD_WAIT  # wall seconds a tick waits for the stack's /cmd_vel
    action: str = "move_base"
    scan_topic: str = "/scan"
    odom_topic: str = "/odom"
    cmd_topic: str = "/cmd_vel"
    map_topic: str = "/map"


class Ros1Bridge(RosBridge):
    """The SUT callbacks in ROS terms; ``stack`` is the started navigation stack (watched each tick)."""

    def __init__(self, settings: BridgeSettings, stack: ManagedProcess | None) -> None:
        super().__init__(settings.cmd_wait, stack)
        import_rospy()
        from rei.sut.ros1 import messages

        self.m = messages
        self.settings = settings
        self.cmd_topic = settings.cmd_topic
        self.frames = messages.Frames()
        self._with_map = False
        self._scan_time = 0.1

    # -- SystemUnderTest ---------------------------------------------------------------------------------------

    def on_start(self, session: Session) -> None:
        import actionlib
        import rospy
        from geometry_msgs.msg import Twist
        from move_base_msgs.msg import MoveBaseAction
        from nav_msgs.msg import OccupancyGrid, Odometry
        from sensor_msgs.msg import LaserScan
        from tf2_msgs.msg import TFMessage

        s = self.settings
        self._scan_time = 1.0 / float(session.robot["lidar"]["rate"])
        self._odom = rospy.Publisher(s.odom_topic, Odometry, queue_size=10, tcp_nodelay=True)
        self._scan = rospy.Publisher(s.scan_topic, LaserScan, queue_size=10, tcp_nodelay=True)
        self._tf = rospy.Publisher("/tf", TFMessage, queue_size=10, tcp_nodelay=True)
        rospy.Subscriber(s.cmd_topic, Twist, self._on_cmd_vel, tcp_nodelay=True)
        if session.static_map is not None:
            self._with_map = True
            self._map = rospy.Publisher(s.map_topic, OccupancyGrid, queue_size=1, latch=True)
            self._map.publish(self.m.occupancy_grid(session.static_map, self.frames,
                                                    occupancy=session_occupancy(session)))
        self._action = actionlib.SimpleActionClient(s.action, MoveBaseAction)
        self._await_server()

    def on_goal(self, goal: NavGoal) -> None:
        from actionlib_msgs.msg import GoalStatus

        self._action.send_goal(self.m.move_base_goal(self._t, goal, self.frames),
                               done_cb=functools.partial(self._on_done, goal.index),
                               feedback_cb=functools.partial(self._on_feedback, goal.index))
        # the goal and /clock travel on different connections: wait until the server has it, so it takes
        # effect at this tick and not, some runs, at the next
        deadline = time.monotonic() + ACCEPT_TIMEOUT
        while self._action.get_state() == GoalStatus.PENDING and time.monotonic() < deadline:
            time.sleep(0.0005)

    def on_cancel(self, goal: NavGoal) -> None:
        self._action.cancel_goal()
        self.report(NavStatus.CANCELLED, "cancelled by the client")

    def publish_sensors(self, tick: Tick) -> None:
        self._odom.publish(self.m.odometry(tick.t, tick.odom, tick.observation.odom_twist, self.frames))
        self._tf.publish(self.m.transforms(tick.t, tick.odom, self.frames, with_map=self._with_map))
        if tick.new_scan and tick.scan is not None:
            self._scan.publish(self.m.laser_scan(tick.scan, self._scan_time, self.frames))

    def publish_clock(self, t: float) -> None:
        self._clock.publish(self.m.clock(t))

    def velocity_publishers(self) -> list[tuple[str, str]]:
        import rospy

        return sorted((topic, kind) for topic, kind in rospy.get_published_topics()
                      if kind in ("geometry_msgs/Twist", "geometry_msgs/TwistStamped"))

    def on_end(self, reason: str) -> None:
        with contextlib.suppress(Exception):
            self._action.cancel_all_goals()

    # -- set-up and ROS callbacks ------------------------------------------------------------------------------

    def start_clock(self) -> None:
        """/use_sim_time and a first, latched /clock one period before t = 0: the stack starts with a time and
        waits for REI's; tick 0 is then a step of its own (a sim-time timer fires once per new time)."""
        import rospy
        from rosgraph_msgs.msg import Clock

        rospy.set_param("/use_sim_time", True)
        self._clock = rospy.Publisher("/clock", Clock, queue_size=10, latch=True, tcp_nodelay=True)
        self._clock.publish(self.m.clock(-PRE_START))

    def publish_description(self, description: RobotDescription) -> None:
        """/robot_description (a parameter in ROS 1) and the latched /tf_static, as robot_state_publisher gives
        them; before the stack starts, so its nodes find both when they come up."""
        import rospy
        from tf2_msgs.msg import TFMessage

        rospy.set_param("/robot_description", description.urdf)
        self._tf_static = rospy.Publisher("/tf_static", TFMessage, queue_size=1, latch=True)
        self._tf_static.publish(self.m.static_transforms(description.static))
        self.frames = description.frames(self.frames)  # the odometry's and the scans' frames are the robot's

    def _await_server(self) -> None:
        """Until the stack's move_base server answers, in wall time (its own timeout counts the frozen sim time)."""
        found = threading.Event()
        waiter = threading.Thread(target=lambda: self._action.wait_for_server() and found.set(), daemon=True)
        waiter.start()
        started = time.monotonic()
        deadline, noted = started + SERVER_TIMEOUT, False
        while not found.wait(0.1):
            self.check_stack()
            if not noted and time.monotonic() > started + WAIT_NOTE:
                noted = True
                print(f"rei ros1-bridge: no {self.settings.action} action server after {WAIT_NOTE:g} s (tick 0 waits "
                      f"for it): the stack must serve move_base_msgs/MoveBaseAction as {self.settings.action!r}; "
                      f"waiting up to {SERVER_TIMEOUT:g} s or --sut-join-timeout", flush=True)
            if time.monotonic() > deadline:
                raise SutConnectionError(f"no {self.settings.action} action server within {SERVER_TIMEOUT:g} s: the "
                                         "stack must serve move_base_msgs/MoveBaseAction")

    def _on_cmd_vel(self, message: Any) -> None:  # a rospy thread
        self.command_received(self.m.command(message))

    def _on_feedback(self, goal_index: int, feedback: Any) -> None:  # a rospy thread
        position = feedback.base_position.pose.position
        self.outcome_received(goal_index, NavStatus.ACTIVE, f"move_base at ({position.x:.2f}, {position.y:.2f})")

    def _on_done(self, goal_index: int, state: int, result: Any) -> None:  # a rospy thread
        status = ACTIONLIB_FINAL.get(state, NavStatus.ABORTED)
        text = self._action.get_goal_status_text()  # what the server gave set_aborted(text=...) and the like
        self.outcome_received(goal_index, status, f"{self.settings.action}: {text}" if text else self.settings.action)


def main(command: list[str], *, ros_home: Path, master_uri: str | None, settings: BridgeSettings) -> int:
    """Run the bridge (and ``command``, the stack) until the run's end; the exit code (cli/ros1_bridge.py)."""
    try:
        return _bridge(command, ros_home, master_uri, settings)
    except (RosUnavailableError, SutConnectionError) as error:
        print(f"rei ros1-bridge: {error}", file=sys.stderr, flush=True)
        return EXIT_CONNECTION


def _bridge(command: list[str], home: Path, master_uri: str | None, settings: BridgeSettings) -> int:
    import_rospy()
    import rospy

    from rei.sut.ros1.master import RosMaster, master_online

    with contextlib.ExitStack() as stack:
        if master_uri is None:
            master_uri = stack.enter_context(RosMaster(home)).uri
        elif not master_online(master_uri):
            raise RosUnavailableError(f"no ROS master answers at {master_uri}")
        env = ros_environment(master_uri, home)
        os.environ.update({key: env[key] for key in ("ROS_MASTER_URI", "ROS_IP", "ROS_HOME", "ROS_LOG_DIR")})
        rospy.init_node("rei_bridge", disable_signals=True)
        stack.callback(rospy.signal_shutdown, "the run is over")
        bridge = Ros1Bridge(settings, None)
        bridge.start_clock()
        description = case_robot_description()
        if description is not None:
            bridge.publish_description(description)
        else:
            print("rei ros1-bridge: REI_CASE_DIR not set: no /robot_description or /tf_static", flush=True)
        if command:
            print(f"rei ros1-bridge: master {master_uri}; starting {shlex.join(command)} (output: {home / STACK_LOG})",
                  flush=True)
            bridge.stack = ManagedProcess("navigation stack", command, home / STACK_LOG, env=env)
            stack.callback(bridge.stack.stop, 5.0)
        return run_bridge(bridge, "rei ros1-bridge", command)
