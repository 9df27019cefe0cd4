# SPDX-License-Identifier: EPL-2.0
"""The data collector (thesis 5.1.4, 6.1.2) and the mission-event publisher.

The collector turns simulator snapshots into state messages on ``rei.run.<run_id>.state`` at a rate counted in
SIMULATION time (a run faster than real time still yields ``rate_hz`` messages per simulated second, and the same
seed yields the same messages), with a gap-free ``seq`` from 0. Which data go on the wire is chosen by
:class:`CollectorConfig` - the thesis's "subset of collected data selected in a configuration". It serves the
monitor's configuration on ``rei.run.<run_id>.config``.

The mission publisher emits ``rei.run.<run_id>.mission`` events and serves ``rei.run.<run_id>.mission_info``.

Both append every message they publish to a recording under ``OUT/streams/`` before handing it to the WAMP
client, so the recording is exactly the published stream. With ``client=None`` they only record (offline runs,
determinism checks).
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from types import TracebackType
from typing import TYPE_CHECKING, Any, Self

from rei.wamp.codec import (
    LaserMode,
    MissionEventKind,
    Pose2DLike,
    SimStateLike,
    encode_mission_event,
    encode_state,
    pack,
)
from rei.wamp.recording import RecordingWriter, stream_path
from rei.wamp.topics import Topics

if TYPE_CHECKING:
    from rei.wamp.client import WampClient

_EPS = 1e-9  # tolerance of sim-time schedules against t = n * dt rounding
#: Categories of the objects a state message carries (the others never move; docs/protocol.md).
MOVING_CATEGORIES = frozenset({"HUMAN", "DYNAMIC"})


@dataclass(frozen=True, slots=True)
class CollectorConfig:
    """What the collector publishes and how often (times in simulation seconds).

    ``rate_hz`` 0 publishes every step offered. ``full_frame_period`` 0 makes only the first message a full
    frame. ``objects``: the moving objects published, by name or category (``HUMAN``, ``DYNAMIC``); None: all of
    them. One left out is not in any message, full frames included, and the monitor does not judge it. Every
    message costs the router ~150 us of CPU: rate, laser mode and objects are a budget.
    """

    rate_hz: float = 20.0
    laser: LaserMode = LaserMode.MIN
    contacts: bool = True
    odometry: bool = True
    nav_state: bool = True
    full_frame_period: float = 1.0
    objects: tuple[str, ...] | None = None

    def __post_init__(self) -> None:
        if self.objects is not None:
            object.__setattr__(self, "objects", tuple(self.objects))
            if not all(isinstance(o, str) and o for o in self.objects):
                raise ValueError(f"objects must be names or categories, got {list(self.objects)}")
        if not math.isfinite(self.rate_hz) or self.rate_hz < 0:
            raise ValueError(f"rate_hz must be finite and >= 0, got {self.rate_hz}")
        if not math.isfinite(self.full_frame_period) or self.full_frame_period < 0:
            raise ValueError(f"full_frame_period must be finite and >= 0, got {self.full_frame_period}")
        if not isinstance(self.laser, LaserMode):
            object.__setattr__(self, "laser", LaserMode(self.laser))

    def to_wire(self) -> dict[str, Any]:
        """As served in the config RPC, so the monitor knows which optional fields to expect."""
        return {
            "rate_hz": float(self.rate_hz),
            "laser": self.laser.value,
            "contacts": self.contacts,
            "odometry": self.odometry,
            "nav_state": self.nav_state,
            "full_frame_period": float(self.full_frame_period),
            "objects": list(self.objects) if self.objects is not None else None,
        }

    def observed(self, world: Mapping[str, Any] | None) -> frozenset[str] | None:
        """The names of the moving objects of ``world`` that are published; None: all (no selection).

        Raises ValueError for an entry that is neither a moving object of the world nor a category."""
        if self.objects is None or world is None:
            return None
        moving = {str(o.get("name")): str(o.get("category")) for o in world.get("objects", ())
                  if o.get("category") in MOVING_CATEGORIES}
        for entry in self.objects:
            if entry not in moving and entry not in MOVING_CATEGORIES:
                raise ValueError(f"collector objects: {entry!r} is neither a moving object of the case "
                                 f"({', '.join(sorted(moving)) or 'it has none'}) nor a category "
                                 f"({', '.join(sorted(MOVING_CATEGORIES))})")
        return frozenset(name for name, category in moving.items()
                         if name in self.objects or category in self.objects)


class _SimClock:
    """Due times on a fixed grid k / rate (not 'last + period'), so rounding never drifts the schedule."""

    def __init__(self, period: float) -> None:
        self._period = period
        self._next = 0.0

    def peek(self, t: float) -> bool:
        return t + _EPS >= self._next

    def due(self, t: float) -> bool:
        if t + _EPS < self._next:
            return False
        self._next = (math.floor(t / self._period + _EPS) + 1) * self._period
        return True


def _check_packable(name: str, value: Mapping[str, Any]) -> dict[str, Any]:
    data = dict(value)
    try:
        pack(data)
    except (TypeError, ValueError) as error:
        raise ValueError(f"{name} is not msgpack-serializable: {error}") from error
    return data


class DataCollector:
    """Publishes state messages of one run; call :meth:`step` once per simulation step."""

    def __init__(
        self,
        run_id: str,
        out_dir: str | os.PathLike[str],
        *,
        config: CollectorConfig | None = None,
        client: WampClient | None = None,
        monitor: Mapping[str, Any] | None = None,
        world: Mapping[str, Any] | None = None,
    ) -> None:
        self.topics = Topics(run_id)
        self.config = config or CollectorConfig()
        self._client = client
        self._clock = _SimClock(1.0 / self.config.rate_hz) if self.config.rate_hz > 0 else None
        self._full_clock = (
            _SimClock(self.config.full_frame_period) if self.config.full_frame_period > 0 else None
        )
        self._observed = self.config.observed(world)
        self._served = _check_packable(
            "config",
            {
                "run_id": run_id,
                "topics": self.topics.as_dict(),
                "collector": self.config.to_wire(),
                "monitor": dict(monitor) if monitor is not None else None,
                "world": dict(world) if world is not None else None,
            },
        )
        self._recording = RecordingWriter(stream_path(out_dir, "state"))
        self.seq = 0
        self._last_t = -math.inf
        if client is not None:
            client.register(self.topics.config, self.serve_config)

    def serve_config(self) -> dict[str, Any]:
        """Result of the config RPC: run id, resolved topics, collector settings, monitor.json, world.json."""
        return self._served

    def due(self, t: float) -> bool:
        """Whether :meth:`step` at simulation time ``t`` would publish (no side effect): lets the loop skip
        building snapshots nobody will send."""
        return self._clock is None or self._clock.peek(float(t))

    def step(self, state: SimStateLike, nav_state: Any = None) -> dict[str, Any] | None:
        """Offer the snapshot of a simulation step; publishes it when the sim-time schedule says so."""
        if self._clock is not None and not self._clock.due(float(state.t)):
            return None
        return self.publish(state, nav_state)

    def publish(self, state: SimStateLike, nav_state: Any = None) -> dict[str, Any]:
        """Publish (and record) a state message now, whatever the schedule; returns the message."""
        t = float(state.t)
        if not t > self._last_t:
            raise ValueError(f"state time must increase: {t} after {self._last_t}")
        full = self.seq == 0
        if self._full_clock is not None:
            full = self._full_clock.due(t) or full
        message = encode_state(
            state,
            self.seq,
            laser=self.config.laser,
            contacts=self.config.contacts,
            odometry=self.config.odometry,
            nav_state=nav_state if self.config.nav_state else None,
            # world.json's statics are left out: they never move, and a map room has thousands of them
            full_frame_objects=() if full else None,
            observed=self._observed,
        )
        self._recording.write(message)
        if self._client is not None:
            self._client.publish(self.topics.state, message)
        self.seq += 1
        self._last_t = t
        return message

    def close(self) -> None:
        """Close the recording (the client is the caller's: it flushes on its own close())."""
        self._recording.close()

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()


class MissionPublisher:
    """Publishes mission events of one run and serves its mission information."""

    def __init__(
        self,
        run_id: str,
        out_dir: str | os.PathLike[str],
        *,
        client: WampClient | None = None,
        mission_info: Mapping[str, Any] | None = None,
    ) -> None:
        self.topics = Topics(run_id)
        self._client = client
        self._info = _check_packable("mission_info", mission_info or {})
        self._recording = RecordingWriter(stream_path(out_dir, "mission"))
        self.seq = 0
        if client is not None:
            client.register(self.topics.mission_info, self.serve_mission_info)

    def serve_mission_info(self) -> dict[str, Any]:
        """Result of the mission_info RPC (mission, testcase, environment, robot, goals; docs/protocol.md)."""
        return self._info

    def publish(
        self,
        t: float,
        event: MissionEventKind | str,
        task_index: int = -1,
        goal: Pose2DLike | Sequence[float] | None = None,
        reason: str | None = None,
    ) -> dict[str, Any]:
        """Publish (and record) one mission event; returns the message."""
        message = encode_mission_event(self.seq, t, event, task_index, goal, reason)
        self._recording.write(message)
        if self._client is not None:
            self._client.publish(self.topics.mission, message)
        self.seq += 1
        return message

    def close(self) -> None:
        self._recording.close()

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()
