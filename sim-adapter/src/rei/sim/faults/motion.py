# SPDX-License-Identifier: EPL-2.0
"""The faults of the robot's motion (docs/faults.md has the definitions): what it is told, what it does, what it
believes it did.

* commands: ``latency`` (each command applies ``delay`` seconds, a whole number of control periods, later) and
  ``loss`` (each command dropped with ``probability``, the last applied one staying); rei.run.mission_run applies
  them between the controller (in-process, an external SUT, a ROS bridge alike) and the simulation;
* drive: ``slip`` (the wheels turn as commanded, the ground moves the robot by ``fraction`` of it) and ``stuck``
  (one wheel's velocity forced to 0);
* odometry: ``drift`` (the odometry's travel times ``scale``, its heading turning by ``bias`` degrees per second
  more) and ``jump`` (the odometry pose moved by an offset at each window's start);
* pose: ``kidnap`` (the robot's true pose moved by an offset at each window's start; the odometry is not told).
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from rei.geometry import Twist2D
from rei.sim.faults.kind import Kind, finite, within
from rei.sim.faults.timing import AHEAD, Timing, Window


@dataclass(frozen=True, slots=True)
class Latency(Kind):
    kind: ClassVar[str] = "latency"
    text: ClassVar[str] = "delay {delay:g} s"
    delay: float  # seconds

    def __post_init__(self) -> None:
        within(self.delay, "latency delay", 0.0, unit="s")

    def periods(self, control_rate: float) -> int:
        """The delay in control periods; it must be a whole number of them at ``control_rate``."""
        exact = self.delay * control_rate
        n = round(exact)
        if n < 1 or abs(exact - n) > 1e-6:
            raise ValueError(f"a command latency of {self.delay:g} s is not a whole number of control periods at "
                             f"{control_rate:g} Hz (periods of {1.0 / control_rate:g} s)")
        return n


@dataclass(frozen=True, slots=True)
class Loss(Kind):
    kind: ClassVar[str] = "loss"
    draws: ClassVar[bool] = True
    text: ClassVar[str] = "probability {probability:g}"
    probability: float

    def __post_init__(self) -> None:
        within(self.probability, "loss probability", 0.0, 1.0)


@dataclass(frozen=True, slots=True)
class Slip(Kind):
    kind: ClassVar[str] = "slip"
    text: ClassVar[str] = "fraction {fraction:g}"
    fraction: float

    def __post_init__(self) -> None:
        within(self.fraction, "slip fraction", 0.0, 1.0)


WHEELS = ("left", "right")


@dataclass(frozen=True, slots=True)
class Stuck(Kind):
    kind: ClassVar[str] = "stuck"
    text: ClassVar[str] = "{wheel} wheel"
    wheel: str

    def __post_init__(self) -> None:
        if self.wheel not in WHEELS:
            raise ValueError(f"a stuck wheel is 'left' or 'right', got {self.wheel!r}")


@dataclass(frozen=True, slots=True)
class Drift(Kind):
    kind: ClassVar[str] = "drift"
    text: ClassVar[str] = "scale {scale:g}, bias {bias:g} deg/s"
    scale: float = 1.0
    bias: float = 0.0  # degrees per second

    def __post_init__(self) -> None:
        finite(self.bias, "drift bias")
        within(self.scale, "drift scale", 0.0)
        if self.scale == 1.0 and self.bias == 0.0:
            raise ValueError("a drift needs a scale other than 1 or a bias other than 0")


@dataclass(frozen=True, slots=True)
class Offset(Kind):
    """A jump of the odometry or a kidnap of the robot: ``dx``, ``dy`` (m, world axes), ``dyaw`` (degrees)."""

    text: ClassVar[str] = "dx {dx:g} m, dy {dy:g} m, dyaw {dyaw:g} deg"
    dx: float = 0.0
    dy: float = 0.0
    dyaw: float = 0.0

    def __post_init__(self) -> None:
        for name in ("dx", "dy", "dyaw"):
            finite(getattr(self, name), name)
        if self.dx == 0.0 and self.dy == 0.0 and self.dyaw == 0.0:
            raise ValueError(f"a {self.kind} needs an offset: dx, dy or dyaw other than 0")


@dataclass(frozen=True, slots=True)
class Jump(Offset):
    kind: ClassVar[str] = "jump"


@dataclass(frozen=True, slots=True)
class Kidnap(Offset):
    kind: ClassVar[str] = "kidnap"


class CommandFaults:
    """The commands' faults of a schedule, applied at each control tick in the order written, each on the result of
    those before: what the controller commanded becomes what the robot is driven with."""

    __slots__ = ("_history", "_last", "_stages")

    def __init__(self, stages: list[tuple[Timing, Latency | Loss, np.random.Generator | None]],
                 control_rate: float) -> None:
        self._stages = [(Window(timing), kind, rng, kind.periods(control_rate) if isinstance(kind, Latency)
                         else 0) for timing, kind, rng in stages]
        # per stage: the commands it received, newest last (a latency's N + 1 of them)
        self._history: list[deque[Twist2D]] = [deque([Twist2D()] * (n + 1), maxlen=n + 1)
                                               for _, _, _, n in self._stages]
        self._last: list[Twist2D] = [Twist2D() for _ in self._stages]  # what each stage put out last

    def __bool__(self) -> bool:
        return bool(self._stages)

    def apply(self, t: float, command: Twist2D) -> Twist2D:
        for i, (window, kind, rng, _) in enumerate(self._stages):
            self._history[i].append(command)
            window.at(t)
            if window.active:
                if isinstance(kind, Latency):
                    command = self._history[i][0]  # the command received N ticks ago
                else:
                    assert rng is not None
                    if rng.random() < kind.probability:
                        command = self._last[i]
            self._last[i] = command
        return command


class MotionFaults:
    """The drive, odometry and pose faults of a schedule, as the simulation asks for them at each physics step
    (at the step's start time ``t``, each method once a step, in any order). What they answer is worked out anew
    only where a window's edge is near: between edges a step costs a comparison (benchmarks/faults.py)."""

    __slots__ = ("_drive", "_drive_now", "_jumps", "_jumps_now", "_kidnaps", "_kidnaps_now", "_odometry",
                 "_odometry_now", "_t", "_until", "_windows")

    def __init__(self, faults: list[tuple[Timing, object]]) -> None:
        windows = [(Window(timing), kind) for timing, kind in faults]
        self._windows = [window for window, _ in windows]
        self._drive = [(window, kind) for window, kind in windows if isinstance(kind, Slip | Stuck)]
        self._odometry = [(window, kind) for window, kind in windows if isinstance(kind, Drift)]
        self._jumps = [(window, kind) for window, kind in windows if isinstance(kind, Jump)]
        self._kidnaps = [(window, kind) for window, kind in windows if isinstance(kind, Kidnap)]
        self._t = -math.inf
        self._until = -math.inf
        self._drive_now: tuple[float, tuple[bool, bool], float] = (1.0, (False, False), 1.0)
        self._odometry_now: tuple[float, float, float] | None = None  # dt, scale, bias
        self._jumps_now: list[Jump] = []
        self._kidnaps_now: list[Kidnap] = []

    def __bool__(self) -> bool:
        return bool(self._windows)

    def _at(self, t: float) -> None:
        if t == self._t:
            return
        self._t = t
        if t < self._until - AHEAD:
            if self._jumps_now or self._kidnaps_now:
                self._jumps_now, self._kidnaps_now = [], []  # they act at a window's first step only
            return
        for window in self._windows:
            window.at(t)
        self._until = min((window.until for window in self._windows), default=math.inf)
        fraction, left, right = 1.0, False, False
        for window, kind in self._drive:
            if window.active:
                if isinstance(kind, Slip):
                    fraction *= kind.fraction
                else:
                    left, right = left or kind.wheel == "left", right or kind.wheel == "right"
        self._drive_now = (fraction, (left, right), 1.0 / fraction)
        self._odometry_now = None
        self._jumps_now = [kind for window, kind in self._jumps if window.began]
        self._kidnaps_now = [kind for window, kind in self._kidnaps if window.began]

    def drive(self, t: float) -> tuple[float, tuple[bool, bool], float]:
        """The wheels' speed factor (the slips' fractions multiplied), which wheels are stuck, and the factor by
        which the odometry counts the wheels' travel against the robot's (a slipping wheel turns as commanded)."""
        self._at(t)
        return self._drive_now

    def odometry(self, t: float, dt: float) -> tuple[float, float]:
        """The odometry's travel factor and the heading (rad) it gains over a step of ``dt`` from ``t``."""
        self._at(t)
        now = self._odometry_now
        if now is None or now[0] != dt:
            scale, bias = 1.0, 0.0
            for window, kind in self._odometry:
                if window.active:
                    scale *= kind.scale
                    bias += math.radians(kind.bias) * dt
            now = self._odometry_now = (dt, scale, bias)
        return now[1], now[2]

    def jumps(self, t: float) -> list[Jump]:
        self._at(t)
        return self._jumps_now

    def kidnaps(self, t: float) -> list[Kidnap]:
        self._at(t)
        return self._kidnaps_now
