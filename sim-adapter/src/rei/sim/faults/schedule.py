# SPDX-License-Identifier: EPL-2.0
"""A run's fault schedule: faults in the order written, each a kind of one sensor and its timing.

Seeds: the schedule's first fault draws from the run's fault seed (the first child of the run's seed sequence,
as the run-long ``--fault laser:...`` always did, so such runs record what they did before schedules existed);
fault ``k >= 1`` from that seed's child ``k - 1``. A fault draws only on the scans where it is active.

Events: every window edge of a fault is a mission-topic event ``FAULT_<SENSOR>_<KIND>_BEGIN``/``_END`` (contract/
vocabulary.json ``faults``), which the default patterns publish as ``SIG_FAULT_...`` signals (cep/patterns/
faults.vepl). Besides the laser's kinds, the motion's (rei.sim.faults.motion): odometry, drive, commands, pose.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from rei.sim.faults.laser import LaserEffect, LaserKind
from rei.sim.faults.motion import (
    CommandFaults,
    Drift,
    Jump,
    Kidnap,
    Latency,
    Loss,
    MotionFaults,
    Slip,
    Stuck,
)
from rei.sim.faults.timing import EPS, Timing, Window

SENSORS = ("laser", "odometry", "drive", "commands", "pose")
"""In the order of contract/vocabulary.json's ``faults.kinds``."""
EDGES = ("BEGIN", "END")


def event_name(sensor: str, kind: str, begin: bool) -> str:
    """The mission event of a window edge, e.g. ``FAULT_LASER_BLACKOUT_BEGIN`` (contract: faults.event)."""
    return f"FAULT_{sensor.upper()}_{kind.upper()}_{EDGES[0] if begin else EDGES[1]}"


@dataclass(frozen=True, slots=True)
class Fault:
    """One fault: what it does (``effect``, a kind of ``sensor``) and when (``timing``)."""

    sensor: str
    effect: LaserKind | Drift | Jump | Slip | Stuck | Latency | Loss | Kidnap
    timing: Timing

    @property
    def kind(self) -> str:
        return self.effect.kind

    def event(self, begin: bool) -> str:
        return event_name(self.sensor, self.kind, begin)

    def describe(self) -> str:
        what = self.effect.describe()
        return f"{self.sensor} {self.kind}" + (f" ({what})" if what else "") + f", {self.timing.describe()}"


@dataclass(frozen=True, slots=True)
class FaultSchedule:
    faults: tuple[Fault, ...] = ()

    def __bool__(self) -> bool:
        return bool(self.faults)

    def __add__(self, other: FaultSchedule) -> FaultSchedule:
        return FaultSchedule(self.faults + other.faults)

    def of(self, sensor: str) -> tuple[tuple[int, Fault], ...]:
        """The faults of ``sensor`` with their index in the schedule (which picks their seed)."""
        return tuple((i, f) for i, f in enumerate(self.faults) if f.sensor == sensor)

    def commands(self, generators: list[np.random.Generator | None], control_rate: float) -> CommandFaults:
        """The commands' faults at ``control_rate`` (raises ``ValueError`` for a latency that is not a whole
        number of its periods), with their generators from :func:`fault_generators` (none given: to check the
        schedule only)."""
        return CommandFaults([(f.timing, f.effect, generators[i] if generators else None)  # type: ignore[misc]
                              for i, f in self.of("commands")], control_rate)

    def motion(self) -> MotionFaults:
        """The drive, odometry and pose faults."""
        return MotionFaults([(f.timing, f.effect) for f in self.faults if f.sensor in ("drive", "odometry", "pose")])


def fault_generators(schedule: FaultSchedule, fault_seed: np.random.SeedSequence
                     ) -> list[np.random.Generator | None]:
    """Each fault's generator by the rule above; None for kinds that draw nothing."""
    count = len(schedule.faults)
    seeds = [fault_seed, *(fault_seed.spawn(count - 1) if count > 1 else ())]
    return [np.random.default_rng(s) if f.effect.draws else None
            for f, s in zip(schedule.faults, seeds, strict=True)]


class LaserFaults:
    """Applies a schedule's laser faults to each scan, in the order written, those active at the scan's time."""

    __slots__ = ("_effects", "_last")

    def __init__(self, schedule: FaultSchedule, generators: list[np.random.Generator | None], *,
                 range_min: float, range_max: float, angle_min: float, angle_increment: float,
                 beams: int) -> None:
        self._effects = [(Window(fault.timing), LaserEffect(fault.effect, generators[i],  # type: ignore[arg-type]
                                                    range_min, range_max, angle_min, angle_increment, beams))
                         for i, fault in schedule.of("laser")]
        self._last: np.ndarray | None = None

    def __bool__(self) -> bool:
        return bool(self._effects)

    def apply(self, t: float, ranges: np.ndarray) -> np.ndarray:
        """The scan the robot gets at ``t`` (``ranges`` itself when no fault is active)."""
        last = self._last
        for window, effect in self._effects:
            window.at(t)
            if window.active:
                ranges = effect.apply(t, ranges, window.began, last)
        self._last = ranges
        return ranges


@dataclass(frozen=True, slots=True)
class FaultEdge:
    t: float  # when the schedule puts it (the event is published at the first step at or after it)
    index: int
    fault: Fault
    begin: bool

    @property
    def event(self) -> str:
        return self.fault.event(self.begin)


class FaultClock:
    """The schedule's window edges as simulation time passes: :meth:`due` returns those reached, in time order
    (ties in schedule order, an END before a BEGIN at the same time)."""

    __slots__ = ("_next", "_streams", "next_t")

    def __init__(self, schedule: FaultSchedule) -> None:
        self._streams: list[Iterator[tuple[float, bool]]] = [f.timing.edges() for f in schedule.faults]
        self._next: list[FaultEdge | None] = [self._pull(i, f) for i, f in enumerate(schedule.faults)]
        self.next_t = self._earliest()

    def _pull(self, index: int, fault: Fault) -> FaultEdge | None:
        edge = next(self._streams[index], None)
        return None if edge is None else FaultEdge(edge[0], index, fault, edge[1])

    def _earliest(self) -> float:
        return min((e.t for e in self._next if e is not None), default=float("inf"))

    def due(self, t: float) -> list[FaultEdge]:
        """The edges at or before ``t`` not yet returned. Cheap when none is due (one comparison)."""
        if t < self.next_t - EPS:
            return []
        out: list[FaultEdge] = []
        for i, edge in enumerate(self._next):
            while edge is not None and edge.t <= t + EPS:
                out.append(edge)
                edge = self._pull(i, edge.fault)
            self._next[i] = edge
        self.next_t = self._earliest()
        out.sort(key=lambda e: (e.t, e.begin, e.index))
        return out
