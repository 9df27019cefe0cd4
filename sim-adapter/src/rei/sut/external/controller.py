# SPDX-License-Identifier: EPL-2.0
"""The simulation's side of an external SUT: a ``Controller`` whose decisions come over the run's router.

The mission loop cannot tell it from an in-process controller: ``set_goal``/``cancel`` publish the goal messages,
``step`` publishes the tick and returns the SUT's command, ``status`` is the last status the SUT reported. What
the SUT sends arrives on the WAMP client's thread and is queued; only the simulation thread reads the queue, so
every rule (docs/sut.md) is applied in arrival order at a point the loop chose: that is what makes lockstep runs
deterministic.

Lockstep: ``step`` waits for the command of its tick, at most ``deadline`` seconds (the first tick:
``first_deadline``, as a stack may finish its start-up only once ``hello`` gave it the map), checking meanwhile
that a started SUT is still alive. Realtime: ``step`` takes what has arrived and does not wait.
"""

from __future__ import annotations

import queue
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rei.geometry import Pose2D, Twist2D
from rei.processes import ManagedProcess
from rei.sut.api import Controller, NavGoal, NavStatus, Observation, StaticMap
from rei.sut.external import protocol
from rei.sut.external.options import Clock
from rei.sut.external.protocol import Command, Rejected, RobotLimits, Status

if TYPE_CHECKING:
    from rei.wamp.client import WampClient

#: Rejections logged one by one (the rest are only counted).
LOGGED_REJECTIONS = 10
#: Messages from the SUT waiting to be applied, at most; more are dropped and counted as rejected.
MAX_INBOX = 10_000
_POLL = 0.2  # seconds between two liveness checks of a started SUT while waiting


class SutError(RuntimeError):
    """The SUT broke the run (silent past its deadline, exited, never joined); the message is the evidence."""


@dataclass(slots=True)
class SutStats:
    """What ``OUT/sim.json`` reports under ``sut``."""

    clock: Clock
    commands: int = 0
    clamped: int = 0
    rejected: int = 0
    stale: int = 0
    statuses: int = 0
    dropped: int = 0  # arrived while MAX_INBOX messages were waiting
    round_trips: list[float] = field(default_factory=list)  # seconds, lockstep: tick published -> command taken
    first_rejections: list[str] = field(default_factory=list)
    exit_code: int | None = None

    def to_json(self) -> dict[str, Any]:
        trips = sorted(self.round_trips)
        return {
            "clock": self.clock, "commands": self.commands, "clamped": self.clamped, "rejected": self.rejected,
            "stale": self.stale, "dropped": self.dropped, "statuses": self.statuses, "first_rejections": self.first_rejections,
            "round_trip_ms": None if not trips else {
                "p50": 1000 * _quantile(trips, 0.5), "p99": 1000 * _quantile(trips, 0.99), "max": 1000 * trips[-1]},
            "exit_code": self.exit_code,
        }


def _quantile(ordered: list[float], q: float) -> float:
    return ordered[min(len(ordered) - 1, int(q * len(ordered)))]


class ExternalController(Controller):
    """A controller in another process, reached through ``client`` (the simulation's session)."""

    def __init__(self, client: WampClient, run_id: str, *, clock: Clock, deadline: float, limits: RobotLimits,
                 scan_time: float, first_deadline: float | None = None, now: Callable[[], float] | None = None,
                 log: Callable[[str], None] = print) -> None:
        self._client = client
        self._run_id = run_id
        self.clock: Clock = clock
        self.deadline = deadline
        self.first_deadline = max(deadline, first_deadline or deadline)
        self._limits = limits
        self._scan_time = scan_time
        self._process: ManagedProcess | None = None
        self._log = log
        self.stats = SutStats(clock)
        self._inbox: queue.SimpleQueue[tuple[str, Any, float]] = queue.SimpleQueue()
        self._tick = -1
        self._answered = True
        self._scan_t: float | None = None
        self._goal: int | None = None
        self._status = NavStatus.IDLE
        self._text = ""
        self._command = Twist2D()
        self._last_heard = time.monotonic()
        self._joined = False
        self._hello: dict[str, Any] | None = None
        self.name: str | None = None  # what the SUT called itself in hello
        self._t = 0.0  # the last tick's time
        # the simulation clock: the mission executor sets a goal (or cancels it) at the time of the tick that
        # follows, before ``step`` sees that tick, so stamping with the last tick's time would be a period early
        self._now = now if now is not None else (lambda: self._t)

    # -- set-up ------------------------------------------------------------------------------------------------

    def attach(self, hello: dict[str, Any]) -> None:
        """Subscribe to the SUT's topics and register ``hello`` (answering ``hello``); before the SUT starts."""
        self._hello = hello
        for name in protocol.FROM_SUT:
            self._client.subscribe(protocol.uri(self._run_id, name), self._receiver(name))
        self._client.register(protocol.uri(self._run_id, "hello"), self._on_hello)

    def attach_process(self, process: ManagedProcess) -> None:
        """The started SUT: watched while waiting, its log's tail quoted in errors."""
        self._process = process

    def wait_joined(self, timeout: float, what: str) -> None:
        """Until the SUT has called ``hello`` (it subscribed before); SutError after ``timeout`` s or its exit."""
        deadline = time.monotonic() + timeout
        while not self._joined:
            self._check_alive("before it joined")
            if time.monotonic() >= deadline:
                raise SutError(f"{what} did not join within {timeout:g} s (it must subscribe, then call "
                               f"{protocol.uri(self._run_id, 'hello')}){self._log_tail()}")
            time.sleep(0.05)
        self._last_heard = time.monotonic()

    def end(self, t: float, reason: str) -> None:
        """Tell the SUT the run is over (it should exit)."""
        self._client.publish(protocol.uri(self._run_id, "end"), protocol.end_message(t, reason))

    # -- Controller --------------------------------------------------------------------------------------------

    def reset(self, static_map: StaticMap, start: Pose2D) -> None:
        """The SUT got the map and start pose from ``hello``; nothing to send here."""

    def set_goal(self, goal: NavGoal) -> None:
        self._goal = goal.index
        self._status, self._text = NavStatus.ACTIVE, ""  # the action client's view until the server reports
        self._client.publish(protocol.uri(self._run_id, "goal"), protocol.goal_message(self._now(), goal))

    def cancel(self) -> None:
        if self._goal is not None:
            self._client.publish(protocol.uri(self._run_id, "cancel"), protocol.cancel_message(self._now(), self._goal))
        if self._status is NavStatus.ACTIVE:
            self._status, self._text = NavStatus.CANCELLED, "cancelled by the client"

    @property
    def status(self) -> NavStatus:
        return self._status

    @property
    def status_text(self) -> str:
        return self._text

    def step(self, observation: Observation) -> Twist2D:
        self._t = observation.t
        self._tick += 1
        self._answered = False
        scan = observation.scan
        new_scan = scan is not None and scan.t != self._scan_t
        if new_scan:
            assert scan is not None
            self._scan_t = scan.t
        sent = time.monotonic()
        self._client.publish(protocol.uri(self._run_id, "tick"),
                             protocol.tick_message(self._tick, observation, new_scan=new_scan,
                                                   scan_time=self._scan_time, holonomic=self._limits.holonomic))
        if self.clock == "realtime":
            self._take_arrived()
            return self._command
        return self._await_command(sent)

    # -- internals ---------------------------------------------------------------------------------------------

    def _receiver(self, name: str) -> Callable[..., None]:
        def receive(*args: Any, **kwargs: Any) -> None:  # on the client's thread: queue only
            if self._inbox.qsize() >= MAX_INBOX:  # a flooding SUT must not eat the simulation's memory
                self.stats.dropped += 1  # written by this thread only
                return
            self._inbox.put((name, args[0] if len(args) == 1 and not kwargs else _odd(args, kwargs),
                             time.monotonic()))
        return receive

    def _on_hello(self, *args: Any, **kwargs: Any) -> dict[str, Any]:
        about = args[0] if args and isinstance(args[0], dict) else {}
        name = about.get("name")
        self.name = name[:100] if isinstance(name, str) and name else None
        self._joined = True
        assert self._hello is not None
        return self._hello

    def _await_command(self, sent: float) -> Twist2D:
        allowed, option = (self.deadline, "--sut-deadline") if self._tick else (self.first_deadline,
                                                                                  "--sut-join-timeout for tick 0")
        deadline = sent + allowed
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise SutError(f"no command for tick {self._tick} at t={self._t:.3f} s within {allowed:g} s "
                               f"({option}){self._rejection_note()}{self._log_tail()}")
            try:
                name, payload, arrived = self._inbox.get(timeout=min(_POLL, remaining))
            except queue.Empty:
                self._check_alive(f"while tick {self._tick} at t={self._t:.3f} s waited for its command")
                continue
            command = self._apply(name, payload)
            if command is not None:
                self.stats.round_trips.append(arrived - sent)
                return command.twist

    def _take_arrived(self) -> None:
        while True:
            try:
                name, payload, _ = self._inbox.get_nowait()
            except queue.Empty:
                break
            command = self._apply(name, payload)
            if command is not None:
                self._command = command.twist
        self._check_alive(f"at tick {self._tick}, t={self._t:.3f} s")
        silent = time.monotonic() - self._last_heard
        if silent > self.deadline:
            raise SutError(f"nothing from the system under test for {silent:.1f} s at tick {self._tick}, "
                           f"t={self._t:.3f} s (--sut-deadline {self.deadline:g}){self._log_tail()}")

    def _apply(self, name: str, payload: Any) -> Command | None:
        """One message from the SUT, by the rules of docs/sut.md; the command if it answers the current tick."""
        self._last_heard = time.monotonic()
        if name == "status":
            status = protocol.check_status(payload, current_goal=self._goal)
            if isinstance(status, Status):
                self.stats.statuses += 1
                self._status, self._text = status.status, status.text
            else:
                self._reject("status", status)
            return None
        # realtime commands may answer any tick up to the current one; only one per tick in lockstep
        lockstep = self.clock == "lockstep"
        command = protocol.check_command(payload, current_tick=self._tick, answered=self._answered,
                                         limits=self._limits) if lockstep else _realtime(payload, self._tick,
                                                                                           self._limits)
        if isinstance(command, Rejected):
            self._reject("command", command)
            return None
        self.stats.commands += 1
        self.stats.clamped += command.clamped
        self._answered = True
        return command

    def _reject(self, name: str, rejection: Rejected) -> None:
        if rejection.stale:
            self.stats.stale += 1
            return
        self.stats.rejected += 1
        if len(self.stats.first_rejections) < LOGGED_REJECTIONS:
            entry = f"tick {self._tick} (t={self._t:.3f} s): {name} rejected: {rejection.reason}"
            self.stats.first_rejections.append(entry)
            self._log(f"sut: {entry}")

    def _check_alive(self, when: str) -> None:
        process = self._process
        if process is None or process.poll() is None:
            return
        self.stats.exit_code = process.poll()
        raise SutError(f"the {process.describe_exit()} {when}{self._log_tail()}")

    def _rejection_note(self) -> str:
        stats = self.stats
        if not stats.rejected:
            if self._tick == 0 and not (stats.statuses or stats.stale or stats.dropped):
                return ("; nothing at all came from it since it called hello: it hangs, or it subscribed to tick "
                        "only after calling hello, and the router drops events for which nobody is subscribed "
                        "(subscribe to tick, goal, cancel and end first, docs/sut.md)")
            return ""
        count = "1 message was" if stats.rejected == 1 else f"{stats.rejected} messages were"
        last = "the last" if stats.rejected == len(stats.first_rejections) else "the last logged"
        return f"; {count} rejected, {last}: {stats.first_rejections[-1]}"

    def _log_tail(self) -> str:
        if self._process is None:
            return ""
        tail = self._process.log_tail(10).strip()
        return f"; last lines of sut.log:\n{tail}" if tail else "; sut.log is empty"


def _realtime(payload: Any, tick: int, limits: RobotLimits) -> Command | Rejected:
    """Realtime: a command for any tick already published is taken (the newest wins)."""
    answered = tick
    if isinstance(payload, Mapping) and protocol.is_int(payload.get("tick")) and 0 <= payload["tick"] <= tick:
        answered = payload["tick"]
    return protocol.check_command(payload, current_tick=answered, answered=False, limits=limits)


def _odd(args: tuple[Any, ...], kwargs: dict[str, Any]) -> Any:
    """A message that is not one positional map: passed on as is, so the checks reject it with a reason."""
    return protocol.KeywordArguments(args, kwargs) if kwargs else list(args)
