# SPDX-License-Identifier: EPL-2.0
"""The bridge node: REI's external SUT on one side, the robot a ROS 1 navigation stack expects on the other.

Per control period (REI's tick) it publishes /odom, /tf and (when new) /scan stamped with the tick's time, then
/clock, and waits up to ``cmd_wait`` wall seconds for the stack's next /cmd_vel, which answers the tick (without
one, the last command stays, as on a robot base). The stack runs on ``use_sim_time``, so its timers advance only
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

from rei.geometry import Twist2D
from rei.processes import ManagedProcess
from rei.sut.api import NavGoal, NavStatus
from rei.sut.client import (
    EXIT_CALLBACK,
    EXIT_CONNECTION,
    Session,
    SutConnectionError,
    SystemUnderTest,
    Tick,
    run,
)
from rei.sut.ros1.environment import RosUnavailableError, import_rospy, ros_environment
from rei.sut.ros_conventions import ACTIONLIB_FINAL

#: Wall seconds the bridge waits for the move_base action server once the map is out (the stack's start-up).
SERVER_TIMEOUT = 60.0
#: Wall seconds a new goal may take to become ACTIVE before the next /clock goes out anyway.
ACCEPT_TIMEOUT = 1.0
#: Simulation seconds before t = 0 of the clock the stack starts with (one control period).
PRE_START = 0.1
STACK_LOG = "stack.log"


@dataclass(frozen=True, slots=True)
class BridgeSettings:
    cmd_wait: float = 0.25  # wall seconds a tick waits for the stack's /cmd_vel (rei.cli.ros1_bridge.CMD_WAIT)
    action: str = "move_base"
    scan_topic: str = "/scan"
    odom_topic: str = "/odom"
    cmd_topic: str = "/cmd_vel"
    map_topic: str = "/map"


class Ros1Bridge(SystemUnderTest):
    """The SUT callbacks in ROS terms; ``stack`` is the started navigation stack (watched each tick)."""

    def __init__(self, settings: BridgeSettings, stack: ManagedProcess | None) -> None:
        super().__init__()
        import_rospy()
        from rei.sut.ros1 import messages

        self.m = messages
        self.settings = settings
        self.frames = messages.Frames()
        self.stack = stack
        self._lock = threading.Condition()
        self._command: Twist2D | None = None  # the latest /cmd_vel
        self._commands = 0  # /cmd_vel messages received
        self._outcome: dict[int, tuple[NavStatus, str]] = {}  # goal id -> what the action reported last
        self._with_map = False
        self._scan_time = 0.1
        self._t = 0.0  # the current tick's time: goals are stamped with it

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
            self._map.publish(self.m.occupancy_grid(session.static_map, self.frames))
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

    def on_tick(self, tick: Tick) -> Twist2D:
        self._check_stack()
        self._t = tick.t
        self._odom.publish(self.m.odometry(tick.t, tick.odom, tick.observation.odom_twist, self.frames))
        self._tf.publish(self.m.transforms(tick.t, tick.odom, self.frames, with_map=self._with_map))
        if tick.new_scan and tick.scan is not None:
            self._scan.publish(self.m.laser_scan(tick.scan, self._scan_time, self.frames))
        with self._lock:
            seen = self._commands
        self._clock.publish(self.m.clock(tick.t))
        with self._lock:
            self._lock.wait_for(lambda: self._commands > seen, timeout=self.settings.cmd_wait)
            command = self._command
            outcome = self._outcome.get(self.goal.index) if self.goal is not None else None
        if outcome is not None and self.status is NavStatus.ACTIVE:
            self.report(*outcome)
        return command if command is not None else Twist2D()

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

    def _await_server(self) -> None:
        """Until the stack's move_base server answers, in wall time (its own timeout counts the frozen sim time)."""
        found = threading.Event()
        waiter = threading.Thread(target=lambda: self._action.wait_for_server() and found.set(), daemon=True)
        waiter.start()
        deadline = time.monotonic() + SERVER_TIMEOUT
        while not found.wait(0.1):
            self._check_stack()
            if time.monotonic() > deadline:
                raise SutConnectionError(f"no {self.settings.action} action server within {SERVER_TIMEOUT:g} s: the "
                                         "stack must serve move_base_msgs/MoveBaseAction")

    def _check_stack(self) -> None:
        stack = self.stack
        if stack is not None and stack.poll() is not None:
            raise SutConnectionError(f"the ROS {stack.describe_exit()}; last lines of {stack.log}:\n"
                                     f"{stack.log_tail(10)}")

    def _on_cmd_vel(self, message: Any) -> None:  # a rospy thread
        with self._lock:
            self._command = self.m.command(message)
            self._commands += 1
            self._lock.notify_all()

    def _on_feedback(self, goal_id: int, feedback: Any) -> None:  # a rospy thread
        position = feedback.base_position.pose.position
        with self._lock:
            self._outcome[goal_id] = (NavStatus.ACTIVE, f"move_base at ({position.x:.2f}, {position.y:.2f})")

    def _on_done(self, goal_id: int, state: int, result: Any) -> None:  # a rospy thread
        status = ACTIONLIB_FINAL.get(state, NavStatus.ABORTED)
        text = self._action.get_goal_status_text()  # what the server gave set_aborted(text=...) and the like
        with self._lock:
            self._outcome[goal_id] = (status, f"{self.settings.action}: {text}" if text else self.settings.action)


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
        if command:
            print(f"rei ros1-bridge: master {master_uri}; starting {shlex.join(command)} (output: {home / STACK_LOG})",
                  flush=True)
            bridge.stack = ManagedProcess("navigation stack", command, home / STACK_LOG, env=env)
            stack.callback(bridge.stack.stop, 5.0)
        try:
            run(bridge, name=f"rei ros1-bridge {shlex.join(command)}")
        except SutConnectionError:
            raise
        except Exception:  # noqa: BLE001 - the bridge's own bug: say where
            import traceback

            traceback.print_exc()
            return EXIT_CALLBACK
    return 0
