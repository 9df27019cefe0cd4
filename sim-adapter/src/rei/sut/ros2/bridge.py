# SPDX-License-Identifier: EPL-2.0
"""The ROS 2 bridge node: REI's external SUT on one side, on the other the robot a ROS 2 navigation stack (Nav2)
expects, on plain DDS - no ROS 2 installation is needed on REI's side.

Before the stack starts it publishes the robot's /robot_description and /tf_static (rei.sut.ros_description).
Per control period (REI's tick, rei.sut.ros_bridge) it publishes /odom, /tf and (when new) /scan stamped with the
tick's time, then /clock, and waits for the stack's next /cmd_vel. The stack's nodes run with ``use_sim_time``, so their timers
advance only with this clock: simulation and stack move in lockstep. REI's goals become goals of nav2's
NavigateToPose action (``rei.sut.ros2.action``); their final state (status topic or get_result reply) becomes the
goal status REI judges. Until the stack's /clock subscription is matched, the start clock is repeated (a volatile
/clock reaches only readers that exist); the run starts once the action server is matched too. The run's DDS
domain is its own (``rei.sut.ros2.environment.DomainLease``), held until the stack is stopped.

Tested against an independent ROS 2 implementation (a ros2-client node on RustDDS, tests/ros) and REI's own
Cyclone-based node; not against rclcpp/rclpy nodes (docs/ros.md says what that leaves open).
"""

from __future__ import annotations

import contextlib
import os
import shlex
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.processes import ManagedProcess
from rei.sut.api import NavGoal, NavStatus
from rei.sut.client import EXIT_CONNECTION, Session, SutConnectionError, Tick
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
from rei.sut.ros_conventions import CMD_WAIT, Frames
from rei.sut.ros_description import RobotDescription, case_robot_description

#: Wall seconds between repetitions of the start clock while the stack comes up.
START_CLOCK_PERIOD = 0.2
#: Wall seconds a goal may stay unanswered (send_goal) by a matched action server before the run ends in error.
ANSWER_TIMEOUT = 10.0


@dataclass(frozen=True, slots=True)
class Ros2BridgeSettings:
    cmd_wait: float = CMD_WAIT  # wall seconds a tick waits for the stack's /cmd_vel
    action: str = "navigate_to_pose"
    domain: int | None = None  # None: a free domain of the run's own (rei.sut.ros2.environment.RUN_DOMAINS)


class Ros2Bridge(RosBridge):
    """The SUT callbacks in ROS 2 terms over DDS; ``stack`` is the started navigation stack (watched each tick)."""

    middleware = "ROS 2"
    program = "rei ros2-bridge"

    def __init__(self, settings: Ros2BridgeSettings, domain: int, participant: Any,
                 stack: ManagedProcess | None = None) -> None:
        super().__init__(settings.cmd_wait, stack)
        from cyclonedds.pub import DataWriter
        from cyclonedds.topic import Topic

        from rei.sut.ros2 import messages

        self.m = messages
        self.settings = settings
        self.domain = domain
        self.frames = Frames()
        self._participant = participant
        self._goals: dict[int, bytes] = {}  # REI's goal index -> the action's goal id
        self._index_of: dict[bytes, int] = {}  # and back, for the status topic's DDS thread
        self._unanswered: tuple[int, Any, int, float] | None = None  # sequence, goal id, index, deadline
        self._with_map = False
        self._scan_time = 0.1
        self._writers = {key: DataWriter(participant, Topic(participant, topic.dds_name, topic.type), qos=topic.qos)
                         for key, topic in messages.TOPICS.items() if topic.to_stack}
        self._writers["clock"].write(messages.clock(-PRE_START))

    # -- SystemUnderTest ---------------------------------------------------------------------------------------

    def on_start(self, session: Session) -> None:
        from cyclonedds.topic import Topic

        from rei.sut.ros2.action import NavigateToPoseClient
        from rei.sut.ros2.dds import listening_reader

        self._scan_time = 1.0 / float(session.robot["lidar"]["rate"])
        cmd = self.m.TOPICS["cmd_vel"]
        self._cmd_reader = listening_reader(self._participant, Topic(self._participant, cmd.dds_name, cmd.type),
                                            cmd.qos, self._on_cmd_vel)
        if session.static_map is not None:
            self._with_map = True
            self._writers["map"].write(self.m.occupancy_grid(session.static_map, self.frames,
                                                             occupancy=session_occupancy(session)))
        self._action = NavigateToPoseClient(self._participant, self.settings.action, self._on_final)
        self._await_server()

    def on_goal(self, goal: NavGoal) -> None:
        from rei.sut.ros2.action import new_goal_id

        goal_id = new_goal_id()
        self._goals[goal.index] = bytes(goal_id.uuid)
        self._index_of[bytes(goal_id.uuid)] = goal.index
        sequence = self._action.send(goal_id, self.m.navigate_goal(self._t, goal, self.frames))
        self._unanswered = (sequence, goal_id, goal.index, time.monotonic() + ANSWER_TIMEOUT)
        self._check_answer(ACCEPT_TIMEOUT)

    def on_cancel(self, goal: NavGoal) -> None:
        self._cancel(goal.index)
        self.report(NavStatus.CANCELLED, "cancelled by the client")

    def publish_sensors(self, tick: Tick) -> None:
        self._check_answer(0.0)
        w, m = self._writers, self.m
        w["odom"].write(m.odometry(tick.t, tick.odom, tick.observation.odom_twist, self.frames))
        w["tf"].write(m.transforms(tick.t, tick.odom, self.frames, with_map=self._with_map))
        if tick.new_scan and tick.scan is not None:
            w["scan"].write(m.laser_scan(tick.scan, self._scan_time, self.frames))

    def publish_clock(self, t: float) -> None:
        self._writers["clock"].write(self.m.clock(t))

    def on_end(self, reason: str) -> None:
        if self.goal is not None and self.status is NavStatus.ACTIVE:
            with contextlib.suppress(Exception):
                self._cancel(self.goal.index)
        action = getattr(self, "_action", None)
        if action is not None:
            print(f"rei ros2-bridge: {self.settings.action}: {len(self._goals)} goal(s) sent, "
                  f"{action.replies_missed} known accepted from the status topic only (send_goal reply missed), "
                  f"{action.feedback_count} feedback message(s)", flush=True)

    # -- set-up and DDS callbacks ------------------------------------------------------------------------------

    def publish_description(self, description: RobotDescription) -> None:
        """/robot_description and /tf_static, transient-local (as robot_state_publisher gives them): written
        before the stack starts and kept for every reader that comes later."""
        self._writers["robot_description"].write(self.m.robot_description(description.urdf))
        self._writers["tf_static"].write(self.m.static_transforms(description.static))
        self.frames = description.frames(self.frames)  # the odometry's and the scans' frames are the robot's

    def _cancel(self, index: int) -> None:
        from rei.sut.ros2 import types as t

        goal_id = self._goals.get(index)
        if goal_id is not None:
            self._action.cancel(t.UUID(uuid=list(goal_id)))

    def _check_answer(self, timeout: float) -> None:
        """The server's answer to the latest goal, if it has come (waiting up to ``timeout``): a rejected goal is
        ABORTED; a goal unanswered for ANSWER_TIMEOUT ends the run (a stack that takes no goals never will)."""
        if self._unanswered is None:
            return
        sequence, goal_id, index, deadline = self._unanswered
        accepted = self._action.answer(sequence, goal_id, timeout)
        if accepted is not None:
            self._unanswered = None
            if not accepted:
                self.report(NavStatus.ABORTED, f"{self.settings.action} rejected the goal")
        elif time.monotonic() > deadline:
            raise SutConnectionError(
                f"the {self.settings.action} action server (matched on ROS domain {self.domain}) did not answer "
                f"goal {index}'s send_goal request within {ANSWER_TIMEOUT:g} s{self.stack_says()}")

    def _await_server(self) -> None:
        """Until the stack's /clock subscription and NavigateToPose server are matched, in wall time; the start
        clock is repeated until the /clock subscription is there, then sent once more."""
        started = time.monotonic()
        deadline, noted = started + SERVER_TIMEOUT, False
        clock = self._writers["clock"]
        clock_matched = False
        while True:
            self.check_stack()
            if not clock_matched:
                clock_matched = bool(clock.get_matched_subscriptions())
                clock.write(self.m.clock(-PRE_START))  # after the match: once more, which that reader gets
            if clock_matched and self._action.server_ready():
                return
            now = time.monotonic()
            note = not noted and now > started + WAIT_NOTE
            if note or now > deadline:
                missing = ([] if clock_matched else ["a /clock subscription (rt/clock)"]) + [
                    f"the action's {name}" for name in self._action.unmatched()]
            if note:
                noted = True
                print(f"rei ros2-bridge: the stack is not matched after {WAIT_NOTE:g} s on ROS domain {self.domain} "
                      f"(tick 0 waits for it); missing: {', '.join(missing)}; waiting up to {SERVER_TIMEOUT:g} s or "
                      "--sut-join-timeout", flush=True)
            if now > deadline:
                raise SutConnectionError(
                    f"the stack was not matched within {SERVER_TIMEOUT:g} s on ROS domain {self.domain}; missing: "
                    f"{', '.join(missing)}. It must subscribe /clock and serve nav2_msgs/action/NavigateToPose as "
                    f"{self.settings.action!r} on ROS_DOMAIN_ID={self.domain}, on loopback (docs/ros.md)")
            time.sleep(START_CLOCK_PERIOD)

    def _on_cmd_vel(self, reader: Any) -> None:  # a DDS thread
        commands = [self.m.command(message) for message in reader.take(N=64) if hasattr(message, "linear")]
        if commands:
            self.command_received(commands[-1], len(commands))

    def _on_final(self, goal_id: bytes, status: NavStatus) -> None:  # a DDS thread
        index = self._index_of.get(goal_id)
        if index is not None:  # else a goal of another client of the same server
            self.outcome_received(index, status, self.settings.action)


def main(command: list[str], *, ros_home: Path, settings: Ros2BridgeSettings) -> int:
    """Run the bridge (and ``command``, the stack) until the run's end; the exit code (cli/ros2_bridge.py)."""
    try:
        return _bridge(command, ros_home, settings)
    except SutConnectionError as error:
        print(f"rei ros2-bridge: {error}", file=sys.stderr, flush=True)
        return EXIT_CONNECTION


def _bridge(command: list[str], home: Path, settings: Ros2BridgeSettings) -> int:
    from cyclonedds.domain import Domain, DomainParticipant

    from rei.sut.ros2.environment import DomainLease, DomainUnavailableError, cyclone_config, ros2_environment

    home.mkdir(parents=True, exist_ok=True)
    config = cyclone_config()
    try:
        lease = DomainLease.claim(settings.domain)
    except DomainUnavailableError as error:
        raise SutConnectionError(str(error)) from None
    with lease:  # released after the stack is stopped (the ExitStack below closes first)
        domain = Domain(lease.domain, config)  # kept alive for the participant's lifetime
        participant = DomainParticipant(lease.domain)
        with contextlib.ExitStack() as stack:
            bridge = Ros2Bridge(settings, lease.domain, participant)
            print(f"rei ros2-bridge: ROS domain {lease.domain} (the run's own), loopback only", flush=True)
            description = case_robot_description()
            if description is not None:
                bridge.publish_description(description)
            else:
                print("rei ros2-bridge: REI_CASE_DIR not set: no /robot_description or /tf_static", flush=True)
            if command:
                print(f"rei ros2-bridge: starting {shlex.join(command)} with ROS_DOMAIN_ID={lease.domain} "
                      f"(output: {home / STACK_LOG})", flush=True)
                env = ros2_environment(lease.domain, config, home, os.environ)
                bridge.stack = ManagedProcess("navigation stack", command, home / STACK_LOG, env=env)
                stack.callback(bridge.stack.stop, 5.0)
            code = run_bridge(bridge, "rei ros2-bridge", command)
        del participant, domain
    return code
