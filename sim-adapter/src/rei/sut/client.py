# SPDX-License-Identifier: EPL-2.0
"""The Python client kit for external systems under test: write callbacks, not WAMP (docs/sut.md).

A SUT subclasses :class:`SystemUnderTest`, answers ``on_tick`` with a velocity command and reports the goal's
state with ``succeed``/``abort``/``feedback``; :func:`main` connects with the environment REI gives a SUT and runs
it until the run ends::

    from rei.geometry import Twist2D
    from rei.sut.client import SystemUnderTest, Tick, main

    class Forward(SystemUnderTest):
        def on_tick(self, tick: Tick) -> Twist2D:
            return Twist2D(0.1, 0.0)

    main(Forward())

Every callback runs on the calling thread, one message at a time in arrival order, so a SUT needs no locks;
``on_start`` runs first, also when the first goal and tick overtook ``hello``'s result (they wait). The
kit publishes a changed status before the command of the same tick, as the protocol asks. Any in-process
:class:`~rei.sut.api.Controller` runs as an external SUT through :class:`ControllerSut` (``rei nav-sut``).
"""

from __future__ import annotations

import functools
import os
import queue
import sys
import traceback
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NoReturn

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import Controller, LaserScan, NavGoal, NavStatus, Observation, StaticMap
from rei.sut.external import protocol
from rei.sut.external.options import DEFAULT_JOIN_TIMEOUT

#: Exit codes of a kit-based SUT: 1 a callback raised; 2 the run could not be served (not joined, lost, a
#: malformed message from the simulation, a setting the SUT needs is missing such as the map).
EXIT_CALLBACK = 1
EXIT_CONNECTION = 2
_ENVIRONMENT = ("REI_ROUTER_URL", "REI_RUN_ID")


class SutConnectionError(RuntimeError):
    """The SUT could not join the run, or lost it; the message says why."""


@dataclass(frozen=True, slots=True)
class Session:
    """``hello``'s answer: what the SUT may know before the run starts."""

    run_id: str
    clock: str
    control_rate: float
    deadline: float
    start: Pose2D
    robot: Mapping[str, Any]
    goals: int
    static_map: StaticMap | None
    occupancy: Path | None = None  # a map room's map.yaml (map_server format), offered with the static map

    @classmethod
    def from_hello(cls, hello: Mapping[str, Any], case_dir: Path | None = None) -> Session:
        """``case_dir``: the run's case folder (``REI_CASE_DIR``), which ``map.occupancy`` is relative to."""
        return cls(run_id=str(hello["run_id"]), clock=str(hello["clock"]), control_rate=float(hello["control_rate"]),
                   deadline=float(hello["deadline"]), start=protocol.read_pose(hello["start"]), robot=hello["robot"],
                   goals=int(hello["goals"]), static_map=protocol.read_static_map(hello),
                   occupancy=protocol.read_occupancy(hello, case_dir))


@dataclass(frozen=True, slots=True)
class Tick:
    """One control period: the clock, odometry and the newest scan (``new_scan``: taken since the last tick)."""

    tick: int
    observation: Observation
    new_scan: bool

    @property
    def t(self) -> float:
        return self.observation.t

    @property
    def odom(self) -> Pose2D:
        return self.observation.odom

    @property
    def scan(self) -> LaserScan | None:
        return self.observation.scan


class SystemUnderTest:
    """Callbacks of an external SUT; override ``on_tick`` and whichever others you need."""

    # also the state of a subclass whose ``__init__`` does not call ``super().__init__()``
    _goal: NavGoal | None = None
    _report: tuple[int, NavStatus, str] | None = None

    def __init__(self) -> None:
        self._goal: NavGoal | None = None
        self._report: tuple[int, NavStatus, str] | None = None

    # -- callbacks ---------------------------------------------------------------------------------------------

    def on_start(self, session: Session) -> None:
        """Once, before the first goal and tick."""

    def on_goal(self, goal: NavGoal) -> None:
        """A new goal replaces the current one; it is ACTIVE until you report otherwise."""

    def on_cancel(self, goal: NavGoal) -> None:
        """The mission withdrew ``goal`` (its timeout); by default reported CANCELLED."""
        self.report(NavStatus.CANCELLED, "cancelled by the client")

    def on_scan(self, scan: LaserScan) -> None:
        """A new scan, before the ``on_tick`` of the same period."""

    def on_tick(self, tick: Tick) -> Twist2D:
        """The velocity command for this control period."""
        raise NotImplementedError("a SystemUnderTest answers on_tick with a Twist2D")

    def on_end(self, reason: str) -> None:
        """The run is over; the kit returns after this."""

    # -- reporting the goal's state ----------------------------------------------------------------------------

    @property
    def goal(self) -> NavGoal | None:
        """The goal being worked on (None before the first)."""
        return self._goal

    @property
    def status(self) -> NavStatus:
        """What was last reported for the current goal (IDLE before the first goal)."""
        return NavStatus.IDLE if self._report is None else self._report[1]

    def report(self, status: NavStatus, text: str = "") -> None:
        """The current goal's state; sent before the next command if it changed."""
        if self._goal is not None:
            self._report = (self._goal.index, status, text[:protocol.MAX_TEXT])

    def feedback(self, text: str) -> None:
        self.report(NavStatus.ACTIVE, text)

    def succeed(self, text: str = "") -> None:
        self.report(NavStatus.SUCCEEDED, text)

    def abort(self, text: str = "") -> None:
        self.report(NavStatus.ABORTED, text)

    def _start_goal(self, goal: NavGoal) -> None:
        self._goal = goal
        self.report(NavStatus.ACTIVE)


class ControllerSut(SystemUnderTest):
    """An in-process :class:`Controller` as an external SUT (what ``rei nav-sut`` runs).

    ``needs_map``: refuse to start without the static map (the run must offer it: ``--sut-map``)."""

    def __init__(self, controller: Controller, *, needs_map: bool = False) -> None:
        super().__init__()
        self.controller = controller
        self.needs_map = needs_map

    def on_start(self, session: Session) -> None:
        static_map = session.static_map
        if static_map is None:
            if self.needs_map:
                raise SutConnectionError("this controller plans on the static map, which the run does not offer; "
                                         "start the run with --sut-map")
            # the robot as hello gives it: with the size alone the lidar sat at the centre, facing ahead, a
            # described robot was its bounding box and a holonomic one differential
            static_map = protocol.robot_only_map(session.robot)
        self.controller.reset(static_map, session.start)

    def on_goal(self, goal: NavGoal) -> None:
        self.controller.set_goal(goal)
        self._mirror()

    def on_cancel(self, goal: NavGoal) -> None:
        self.controller.cancel()
        self._mirror()

    def on_tick(self, tick: Tick) -> Twist2D:
        command = self.controller.step(tick.observation)
        self._mirror()
        return command

    def _mirror(self) -> None:
        if self.controller.status is not NavStatus.IDLE:
            self.report(self.controller.status, self.controller.status_text)


def run(sut: SystemUnderTest, *, environ: Mapping[str, str] = os.environ, name: str | None = None) -> None:
    """Join the run described by ``environ`` (docs/sut.md) and serve ``sut`` until the run's ``end``.

    Raises SutConnectionError when the run cannot be joined or is lost; a callback's exception propagates."""
    from rei.wamp.auth import load_credentials
    from rei.wamp.client import WampClient, WampError

    missing = [key for key in _ENVIRONMENT if not environ.get(key)]
    if missing:
        raise SutConnectionError(f"{', '.join(missing)} not set: a SUT is started by `rei run --sut COMMAND`, or "
                                 "with the variables of OUT/sut.env for `rei run --sut-attach` (docs/sut.md)")
    run_id = environ["REI_RUN_ID"]
    try:
        auth = load_credentials(environ["REI_AUTH_FILE"]) if environ.get("REI_AUTH_FILE") else None
    except (OSError, ValueError, KeyError) as error:
        raise SutConnectionError(f"REI_AUTH_FILE: {error}") from None
    inbox: queue.SimpleQueue[tuple[str, Any]] = queue.SimpleQueue()
    try:
        # RawSocket when offered: ~0.3 ms less per round trip than WebSocket's framing (benchmarks/sut_rtf.py)
        url = environ.get("REI_ROUTER_RAWSOCKET_URL") or environ["REI_ROUTER_URL"]
        client = WampClient(url, environ.get("REI_REALM", "rei"), auth=auth, name="rei-sut").start()
    except (WampError, ValueError) as error:
        raise SutConnectionError(str(error)) from None
    try:
        for topic in protocol.FROM_SIMULATION:
            client.subscribe(protocol.uri(run_id, topic), _enqueue(inbox, topic))
        # an attached SUT may be quicker than the simulation's registration: retry within the default join window
        hello = client.call_when_registered(protocol.uri(run_id, "hello"), {"name": name or type(sut).__name__},
                                            timeout=DEFAULT_JOIN_TIMEOUT)
        case_dir = Path(environ["REI_CASE_DIR"]) if environ.get("REI_CASE_DIR") else None
        _serve(sut, client, run_id, _read(lambda h: Session.from_hello(h, case_dir), hello, "hello's answer"), inbox)
    except WampError as error:
        raise SutConnectionError(str(error)) from None
    except Exception as error:
        if type(error).__module__.startswith("autobahn"):  # refused by the router (e.g. not authorized)
            raise SutConnectionError(_refusal(error, run_id)) from None
        raise
    finally:
        try:
            client.close(timeout=5.0)
        except WampError:
            pass  # leaving a run that is already gone


def main(sut: SystemUnderTest, *, name: str | None = None) -> NoReturn:
    """``run(sut)`` as a program: exit 0 at the run's end, 1 if a callback raised, 2 if the run could not be
    served (see EXIT_CONNECTION)."""
    try:
        run(sut, name=name)
    except SutConnectionError as error:
        print(f"rei sut: {error}", file=sys.stderr, flush=True)
        sys.exit(EXIT_CONNECTION)
    except Exception:  # noqa: BLE001 - the SUT's own bug: say where, and exit so the run sees it at once
        traceback.print_exc()
        sys.exit(EXIT_CALLBACK)
    sys.exit(0)


def _refusal(error: Exception, run_id: str) -> str:
    """What the router's refusal says (not autobahn's repr of it), with the usual cause of a not_authorized."""
    uri, args = getattr(error, "error", None), getattr(error, "args", ())
    text = f"{uri}: {args[0]}" if uri and args and isinstance(args[0], str) else str(error)
    if uri == "wamp.error.not_authorized":
        text += (f" (the sut role may use only rei.run.<REI_RUN_ID>.sut.tick, goal, cancel, end, command, status "
                 f"and hello: is REI_RUN_ID={run_id!r} the id of the run you joined?)")
    return f"the router refused: {text}"


def _read(reader: Any, payload: Any, what: str) -> Any:
    """``reader(payload)``; a message the kit cannot read is the run's fault, not the SUT's callback's."""
    try:
        return reader(payload)
    except (KeyError, TypeError, ValueError, AttributeError) as error:
        raise SutConnectionError(f"malformed {what} from the simulation ({type(error).__name__}: {error}): "
                                 f"{str(payload)[:200]}") from None


def _enqueue(inbox: queue.SimpleQueue[tuple[str, Any]], topic: str) -> Any:
    def handler(payload: Any = None, *args: Any, **kwargs: Any) -> None:  # on the client's thread: queue only
        inbox.put((topic, payload))
    return handler


def _serve(sut: SystemUnderTest, client: Any, run_id: str, session: Session,
           inbox: queue.SimpleQueue[tuple[str, Any]]) -> None:
    command_uri, status_uri = protocol.uri(run_id, "command"), protocol.uri(run_id, "status")
    published: tuple[int, NavStatus, str] | None = None

    def send_status() -> None:
        nonlocal published
        if sut._report is not None and sut._report != published:
            published = sut._report
            goal_id, status, text = published
            client.publish(status_uri, {"goal_id": goal_id, "status": status.value, "text": text})

    sut.on_start(session)
    last_scan: LaserScan | None = None
    while True:
        try:
            topic, payload = inbox.get(timeout=0.5)
        except queue.Empty:
            if client.failure is not None:
                raise SutConnectionError(f"lost the run's router: {client.failure}")
            continue
        if topic == "tick":
            observation = _read(functools.partial(protocol.read_observation, last_scan=last_scan), payload, "tick")
            new_scan = payload.get("scan") is not None
            if new_scan and observation.scan is not None:
                last_scan = observation.scan
                sut.on_scan(observation.scan)
            current = Tick(int(payload["tick"]), observation, new_scan)
            twist = sut.on_tick(current)
            if not isinstance(twist, Twist2D):  # else an AttributeError inside the kit, naming neither
                raise TypeError(f"{type(sut).__name__}.on_tick returned {twist!r:.100} for tick {current.tick} "
                                f"(t={current.t:.3f} s): it must return a Twist2D, e.g. Twist2D(0.2, 0.0)")
            send_status()
            command = {"tick": int(payload["tick"]), "v": float(twist.v), "w": float(twist.w)}
            if twist.vy != 0.0:  # only then: a differential robot's SUT sends what it always sent
                command["vy"] = float(twist.vy)
            client.publish(command_uri, command)
        elif topic == "goal":
            goal = _read(protocol.read_goal, payload, "goal")
            sut._start_goal(goal)
            sut.on_goal(goal)
            send_status()
        elif topic == "cancel":
            if sut.goal is not None and sut.goal.index == payload.get("goal_id"):
                sut.on_cancel(sut.goal)
                send_status()
        elif topic == "end":
            sut.on_end(str(payload.get("reason", "")))
            return
