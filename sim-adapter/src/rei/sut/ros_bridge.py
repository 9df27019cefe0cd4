# SPDX-License-Identifier: EPL-2.0
"""What REI's ROS 1 and ROS 2 bridges share: the lockstep tick, the watch on the stack, the start-up timings.

Per control period a bridge publishes the robot's sensors stamped with the tick's time, then the clock, and waits
up to ``cmd_wait`` wall seconds for the stack's next /cmd_vel, which answers the tick (without one, the last
command stays, as on a robot base). The middleware's parts are the subclass's: ``publish_sensors`` and
``publish_clock``; its threads call ``command_received`` and ``outcome_received``.
"""

from __future__ import annotations

import shlex
import sys
import threading
import traceback

from rei.geometry import Twist2D
from rei.maps import MapError, OccupancyMap, load_map
from rei.processes import ManagedProcess
from rei.sut.api import NavStatus
from rei.sut.client import EXIT_CALLBACK, Session, SutConnectionError, SystemUnderTest, Tick, run
from rei.sut.ros_conventions import CMD_WAIT

#: Wall seconds a bridge waits for the stack's navigation action server (the stack's start-up).
SERVER_TIMEOUT = 60.0
#: Wall seconds of waiting for the stack's action server after which a bridge says what it waits for, once: REI's
#: --sut-join-timeout (60 s, as SERVER_TIMEOUT, and counted from earlier) ends the run first, and its error shows
#: the last lines of OUT/sut.log, so this line is what names the cause.
WAIT_NOTE = 5.0
#: Wall seconds a new goal may take to be taken by the server before the next clock goes out anyway.
ACCEPT_TIMEOUT = 1.0
#: Simulation seconds before t = 0 of the clock the stack starts with (one control period).
PRE_START = 0.1
#: The stack's output, in the bridge's ROS home.
STACK_LOG = "stack.log"
#: Control periods without a single /cmd_vel after which a bridge says so (once, in OUT/sut.log): a stack that
#: publishes its commands on another topic leaves the robot standing and each tick waiting ``cmd_wait``.
SILENT_TICKS = 20


def session_occupancy(session: Session) -> OccupancyMap | None:
    """A map room's original map (``hello``'s ``map.occupancy``), which /map carries instead of the rasterized
    rectangles; None for every other room."""
    if session.occupancy is None:
        return None
    try:
        return load_map(session.occupancy)
    except MapError as error:
        raise SutConnectionError(f"the map room's occupancy map: {error}") from None


class RosBridge(SystemUnderTest):
    """The tick, the latest /cmd_vel and the action's last word per goal; ``stack`` (the started navigation
    stack, or None) is watched at each tick. ``middleware`` names it in messages ("ROS", "ROS 2")."""

    middleware = "ROS"
    program = "rei ros1-bridge"
    cmd_topic = "/cmd_vel"

    def __init__(self, cmd_wait: float = CMD_WAIT, stack: ManagedProcess | None = None) -> None:
        super().__init__()
        self.cmd_wait = cmd_wait
        self.stack = stack
        self._lock = threading.Condition()
        self._command: Twist2D | None = None  # the latest /cmd_vel
        self._commands = 0  # /cmd_vel messages received
        self._outcome: dict[int, tuple[NavStatus, str]] = {}  # REI's goal index -> what the action said last
        self._t = 0.0  # the current tick's time: goals are stamped with it

    # -- for the subclass ----------------------------------------------------------------------------------

    def publish_sensors(self, tick: Tick) -> None:
        raise NotImplementedError

    def publish_clock(self, t: float) -> None:
        raise NotImplementedError

    def command_received(self, command: Twist2D, count: int = 1) -> None:  # a middleware thread
        with self._lock:
            self._command = command
            self._commands += count
            self._lock.notify_all()

    def outcome_received(self, goal_index: int, status: NavStatus, text: str) -> None:  # a middleware thread
        with self._lock:
            self._outcome[goal_index] = (status, text)

    def velocity_publishers(self) -> list[tuple[str, str]] | None:
        """The topics the stack publishes velocity commands on, with their types (geometry_msgs/Twist or
        TwistStamped), for the warning of a silent /cmd_vel; None when the middleware cannot list them."""
        return None

    def warn_silent(self, tick: Tick) -> None:
        """No /cmd_vel in the first SILENT_TICKS periods: say where the stack's commands may have gone."""
        try:
            found = self.velocity_publishers()
        except Exception as error:  # noqa: BLE001 - only a hint: the warning goes out without it
            found, failed = None, f" (could not list the stack's topics: {error})"
        else:
            failed = ""
        expected = (self.cmd_topic, "geometry_msgs/Twist")
        elsewhere = [f"{kind} on {topic}" for topic, kind in found or () if (topic, kind) != expected]
        if found is None:
            hint = f"; does it publish geometry_msgs/Twist (not TwistStamped) on {self.cmd_topic}?{failed}"
        elif elsewhere:
            hint = f"; it publishes {', '.join(elsewhere)}: REI reads geometry_msgs/Twist on {self.cmd_topic}"
        else:
            hint = f"; nothing publishes geometry_msgs/Twist on {self.cmd_topic}"
        print(f"{self.program}: no {self.cmd_topic} from the {self.middleware} stack in the first {tick.tick + 1} "
              f"control periods (tick {tick.tick}, t={tick.t:.3f} s): the robot stands still and each tick waits "
              f"{self.cmd_wait:g} s{hint}", file=sys.stderr, flush=True)

    def check_stack(self) -> None:
        stack = self.stack
        if stack is not None and stack.poll() is not None:
            raise SutConnectionError(f"the {self.middleware} {stack.describe_exit()}{self.stack_says()}")

    def stack_says(self) -> str:
        """The stack's last lines for an error's end (where it says why it failed), if REI started it."""
        if self.stack is None:
            return ""
        return f"; last lines of {self.stack.log}:\n{self.stack.log_tail(10)}"

    # -- SystemUnderTest -----------------------------------------------------------------------------------

    def on_tick(self, tick: Tick) -> Twist2D:
        self.check_stack()
        self._t = tick.t
        self.publish_sensors(tick)
        with self._lock:
            seen = self._commands
        self.publish_clock(tick.t)
        with self._lock:
            self._lock.wait_for(lambda: self._commands > seen, timeout=self.cmd_wait)
            command = self._command
            silent = self._commands == 0
            outcome = self._outcome.get(self.goal.index) if self.goal is not None else None
        if silent and tick.tick == SILENT_TICKS - 1:
            self.warn_silent(tick)
        if outcome is not None and self.status is NavStatus.ACTIVE:
            self.report(*outcome)
        return command if command is not None else Twist2D()


def run_bridge(bridge: RosBridge, name: str, command: list[str]) -> int:
    """Run the bridge's SUT session until the run's end: 0, or EXIT_CALLBACK with the trace of a bug of the
    bridge's own (a broken connection or stack, SutConnectionError, goes to the caller)."""
    try:
        run(bridge, name=f"{name} {shlex.join(command)}")
    except SutConnectionError:
        raise
    except Exception:  # noqa: BLE001 - the bridge's own bug: say where
        traceback.print_exc()
        return EXIT_CALLBACK
    return 0
