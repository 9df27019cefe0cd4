# SPDX-License-Identifier: EPL-2.0
"""The ROS 2 bridge node: REI's external SUT on one side, on the other the robot a ROS 2 navigation stack (Nav2 on
rmw_cyclonedds) expects, on plain DDS - no ROS 2 installation is needed on REI's side.

Per control period (REI's tick) it publishes /odom, /tf and (when new) /scan stamped with the tick's time, then
/clock, and waits up to ``cmd_wait`` wall seconds for the stack's next /cmd_vel, which answers the tick (without
one, the last command stays, as on a robot base). The stack's nodes run with ``use_sim_time``, so their timers
advance only with this clock: simulation and stack move in lockstep. REI's goals become goals of nav2's
NavigateToPose action (``rei.sut.ros2.action``); their final state on the action's status topic becomes the goal
status REI judges. Until the action server is there, the start clock is repeated (a volatile /clock reaches only
readers that exist, and nav2's nodes need a time to come up).

What could not be verified where REI is developed (no ROS 2 installs there): discovery by and an action round
trip with real ROS 2 nodes; docs/ros.md says so.
"""

from __future__ import annotations

import contextlib
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
from rei.sut.ros_conventions import Frames

#: Wall seconds the bridge waits for the NavigateToPose server once the map is out (the stack's start-up).
SERVER_TIMEOUT = 60.0
#: Wall seconds a new goal may take to be accepted before the next /clock goes out anyway.
ACCEPT_TIMEOUT = 1.0
#: Simulation seconds before t = 0 of the clock the stack starts with (one control period).
PRE_START = 0.1
#: Wall seconds between repetitions of the start clock while the stack comes up.
START_CLOCK_PERIOD = 0.2
STACK_LOG = "stack.log"


@dataclass(frozen=True, slots=True)
class Ros2BridgeSettings:
    cmd_wait: float = 0.25  # wall seconds a tick waits for the stack's /cmd_vel (rei.cli.ros2_bridge.CMD_WAIT)
    action: str = "navigate_to_pose"
    domain: int = 0
    tag: str = "rei"  # Cyclone's discovery tag: the run's own (rei.sut.ros2.environment.run_tag)


class Ros2Bridge(SystemUnderTest):
    """The SUT callbacks in ROS 2 terms over DDS; ``stack`` is the started navigation stack (watched each tick)."""

    def __init__(self, settings: Ros2BridgeSettings, participant: Any, stack: ManagedProcess | None = None) -> None:
        super().__init__()
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        from rei.sut.ros2 import messages

        self.m = messages
        self.settings = settings
        self.frames = Frames()
        self.stack = stack
        self._participant = participant
        self._lock = threading.Condition()
        self._command: Twist2D | None = None  # the latest /cmd_vel
        self._commands = 0  # /cmd_vel messages received
        self._goals: dict[int, bytes] = {}  # REI's goal index -> the action's goal id
        self._outcome: dict[bytes, tuple[NavStatus, str]] = {}  # goal id -> final state
        self._with_map = False
        self._scan_time = 0.1
        self._t = 0.0  # the current tick's time: goals are stamped with it
        self._writers = {key: DataWriter(participant, Topic(participant, topic.dds_name, topic.type), qos=topic.qos)
                         for key, topic in messages.TOPICS.items() if topic.to_stack}
        self._writers["clock"].write(messages.clock(-PRE_START))

    # -- SystemUnderTest ---------------------------------------------------------------------------------------

    def on_start(self, session: Session) -> None:
        from cyclonedds.core import Listener
        from cyclonedds.sub import DataReader
        from cyclonedds.topic import Topic

        from rei.sut.ros2.action import NavigateToPoseClient

        self._scan_time = 1.0 / float(session.robot["lidar"]["rate"])
        cmd = self.m.TOPICS["cmd_vel"]
        self._cmd_reader = DataReader(self._participant, Topic(self._participant, cmd.dds_name, cmd.type),
                                      qos=cmd.qos, listener=Listener(on_data_available=self._on_cmd_vel))
        if session.static_map is not None:
            self._with_map = True
            self._writers["map"].write(self.m.occupancy_grid(session.static_map, self.frames))
        self._action = NavigateToPoseClient(self._participant, self.settings.action, self._on_final)
        self._await_server()

    def on_goal(self, goal: NavGoal) -> None:
        from rei.sut.ros2.action import new_goal_id

        goal_id = new_goal_id()
        self._goals[goal.index] = bytes(goal_id.uuid)
        accepted = self._action.send(goal_id, self.m.navigate_goal(self._t, goal, self.frames), ACCEPT_TIMEOUT)
        if accepted is False:
            self.report(NavStatus.ABORTED, f"{self.settings.action} rejected the goal")
        elif accepted is None:
            print(f"rei ros2-bridge: {self.settings.action} did not answer goal {goal.index} within "
                  f"{ACCEPT_TIMEOUT:g} s; its status may still come", file=sys.stderr, flush=True)

    def on_cancel(self, goal: NavGoal) -> None:
        self._cancel(goal.index)
        self.report(NavStatus.CANCELLED, "cancelled by the client")

    def on_tick(self, tick: Tick) -> Twist2D:
        self._check_stack()
        self._t = tick.t
        w, m = self._writers, self.m
        w["odom"].write(m.odometry(tick.t, tick.odom, tick.observation.odom_twist, self.frames))
        w["tf"].write(m.transforms(tick.t, tick.odom, self.frames, with_map=self._with_map))
        if tick.new_scan and tick.scan is not None:
            w["scan"].write(m.laser_scan(tick.scan, self._scan_time, self.frames))
        with self._lock:
            seen = self._commands
        w["clock"].write(m.clock(tick.t))
        with self._lock:
            self._lock.wait_for(lambda: self._commands > seen, timeout=self.settings.cmd_wait)
            command = self._command
            goal_id = self._goals.get(self.goal.index) if self.goal is not None else None
            outcome = self._outcome.get(goal_id) if goal_id is not None else None
        if outcome is not None and self.status is NavStatus.ACTIVE:
            self.report(*outcome)
        return command if command is not None else Twist2D()

    def on_end(self, reason: str) -> None:
        if self.goal is not None and self.status is NavStatus.ACTIVE:
            with contextlib.suppress(Exception):
                self._cancel(self.goal.index)

    # -- set-up and DDS callbacks ------------------------------------------------------------------------------

    def _cancel(self, index: int) -> None:
        from rei.sut.ros2 import types as t

        goal_id = self._goals.get(index)
        if goal_id is not None:
            self._action.cancel(t.UUID(uuid=list(goal_id)))

    def _await_server(self) -> None:
        """Until the stack's NavigateToPose server is discovered, in wall time, repeating the start clock."""
        deadline = time.monotonic() + SERVER_TIMEOUT
        while not self._action.server_ready():
            self._check_stack()
            if time.monotonic() > deadline:
                raise SutConnectionError(
                    f"no {self.settings.action} action server within {SERVER_TIMEOUT:g} s: the stack must serve "
                    f"nav2_msgs/action/NavigateToPose on ROS_DOMAIN_ID {self.settings.domain} with "
                    "rmw_cyclonedds_cpp (the bridge's CYCLONEDDS_URI keeps it on loopback)")
            self._writers["clock"].write(self.m.clock(-PRE_START))
            time.sleep(START_CLOCK_PERIOD)

    def _check_stack(self) -> None:
        stack = self.stack
        if stack is not None and stack.poll() is not None:
            raise SutConnectionError(f"the ROS 2 {stack.describe_exit()}; last lines of {stack.log}:\n"
                                     f"{stack.log_tail(10)}")

    def _on_cmd_vel(self, reader: Any) -> None:  # a DDS thread
        commands = [self.m.command(message) for message in reader.take(N=64) if hasattr(message, "linear")]
        if commands:
            with self._lock:
                self._command = commands[-1]
                self._commands += len(commands)
                self._lock.notify_all()

    def _on_final(self, goal_id: bytes, status: NavStatus) -> None:  # a DDS thread
        with self._lock:
            self._outcome[goal_id] = (status, self.settings.action)


def main(command: list[str], *, ros_home: Path, settings: Ros2BridgeSettings) -> int:
    """Run the bridge (and ``command``, the stack) until the run's end; the exit code (cli/ros2_bridge.py)."""
    try:
        return _bridge(command, ros_home, settings)
    except SutConnectionError as error:
        print(f"rei ros2-bridge: {error}", file=sys.stderr, flush=True)
        return EXIT_CONNECTION


def _bridge(command: list[str], home: Path, settings: Ros2BridgeSettings) -> int:
    from cyclonedds.domain import Domain, DomainParticipant

    from rei.sut.ros2.environment import cyclone_config, ros2_environment

    home.mkdir(parents=True, exist_ok=True)
    config = cyclone_config(settings.tag)
    domain = Domain(settings.domain, config)  # kept alive for the participant's lifetime
    participant = DomainParticipant(settings.domain)
    with contextlib.ExitStack() as stack:
        bridge = Ros2Bridge(settings, participant)
        if command:
            print(f"rei ros2-bridge: domain {settings.domain}, discovery tag {settings.tag}; starting "
                  f"{shlex.join(command)} (output: {home / STACK_LOG})", flush=True)
            env = ros2_environment(settings.domain, config, home, os.environ)
            bridge.stack = ManagedProcess("navigation stack", command, home / STACK_LOG, env=env)
            stack.callback(bridge.stack.stop, 5.0)
        try:
            run(bridge, name=f"rei ros2-bridge {shlex.join(command)}")
        except SutConnectionError:
            raise
        except Exception:  # noqa: BLE001 - the bridge's own bug: say where
            import traceback

            traceback.print_exc()
            return EXIT_CALLBACK
    del participant, domain
    return 0
