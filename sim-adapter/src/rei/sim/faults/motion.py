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
from rei.sim.faults.timing import Timing


def _finite(value: float, what: str) -> None:
    if not math.isfinite(value):
        raise ValueError(f"{what} must be a finite number, got {value}")


@dataclass(frozen=True, slots=True)
class Latency:
    kind: ClassVar[str] = "latency"
    draws: ClassVar[bool] = False
    delay: float  # seconds

    def __post_init__(self) -> None:
        if not (math.isfinite(self.delay) and self.delay > 0.0):
            raise ValueError(f"latency delay must be > 0 s, got {self.delay:g}")

    def periods(self, control_rate: float) -> int:
        """The delay in control periods; it must be a whole number of them at ``control_rate``."""
        exact = self.delay * control_rate
        n = round(exact)
        if n < 1 or abs(exact - n) > 1e-6:
            raise ValueError(f"a command latency of {self.delay:g} s is not a whole number of control periods at "
                             f"{control_rate:g} Hz (periods of {1.0 / control_rate:g} s)")
        return n

    def describe(self) -> str:
        return f"delay {self.delay:g} s"


@dataclass(frozen=True, slots=True)
class Loss:
    kind: ClassVar[str] = "loss"
    draws: ClassVar[bool] = True
    probability: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.probability) and 0.0 < self.probability <= 1.0):
            raise ValueError(f"loss probability must be in (0, 1], got {self.probability:g}")

    def describe(self) -> str:
        return f"probability {self.probability:g}"


@dataclass(frozen=True, slots=True)
class Slip:
    kind: ClassVar[str] = "slip"
    draws: ClassVar[bool] = False
    fraction: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.fraction) and 0.0 < self.fraction <= 1.0):
            raise ValueError(f"slip fraction must be in (0, 1], got {self.fraction:g}")

    def describe(self) -> str:
        return f"fraction {self.fraction:g}"


WHEELS = ("left", "right")


@dataclass(frozen=True, slots=True)
class Stuck:
    kind: ClassVar[str] = "stuck"
    draws: ClassVar[bool] = False
    wheel: str

    def __post_init__(self) -> None:
        if self.wheel not in WHEELS:
            raise ValueError(f"a stuck wheel is 'left' or 'right', got {self.wheel!r}")

    def describe(self) -> str:
        return f"{self.wheel} wheel"


@dataclass(frozen=True, slots=True)
class Drift:
    kind: ClassVar[str] = "drift"
    draws: ClassVar[bool] = False
    scale: float = 1.0
    bias: float = 0.0  # degrees per second

    def __post_init__(self) -> None:
        _finite(self.bias, "drift bias")
        if not (math.isfinite(self.scale) and self.scale > 0.0):
            raise ValueError(f"drift scale must be > 0, got {self.scale:g}")
        if self.scale == 1.0 and self.bias == 0.0:
            raise ValueError("a drift needs a scale other than 1 or a bias other than 0")

    def describe(self) -> str:
        return f"scale {self.scale:g}, bias {self.bias:g} deg/s"


@dataclass(frozen=True, slots=True)
class Offset:
    """A jump of the odometry or a kidnap of the robot: ``dx``, ``dy`` (m, world axes), ``dyaw`` (degrees)."""

    dx: float = 0.0
    dy: float = 0.0
    dyaw: float = 0.0

    def __post_init__(self) -> None:
        for name in ("dx", "dy", "dyaw"):
            _finite(getattr(self, name), name)
        if self.dx == 0.0 and self.dy == 0.0 and self.dyaw == 0.0:
            raise ValueError(f"a {self.kind} needs an offset: dx, dy or dyaw other than 0")  # type: ignore[attr-defined]

    def describe(self) -> str:
        return f"dx {self.dx:g} m, dy {self.dy:g} m, dyaw {self.dyaw:g} deg"


@dataclass(frozen=True, slots=True)
class Jump(Offset):
    kind: ClassVar[str] = "jump"
    draws: ClassVar[bool] = False


@dataclass(frozen=True, slots=True)
class Kidnap(Offset):
    kind: ClassVar[str] = "kidnap"
    draws: ClassVar[bool] = False


class Edges:
    """Whether a window started since the last call (for faults that act once per window: jumps, kidnaps)."""

    __slots__ = ("_timing", "_was")

    def __init__(self, timing: Timing) -> None:
        self._timing = timing
        self._was = False

    def active(self, t: float) -> bool:
        return self._timing.active(t)

    def starts(self, t: float) -> bool:
        active = self._timing.active(t)
        starts = active and not self._was
        self._was = active
        return starts


class CommandFaults:
    """The commands' faults of a schedule, applied at each control tick in the order written, each on the result of
    those before: what the controller commanded becomes what the robot is driven with."""

    __slots__ = ("_history", "_last", "_stages")

    def __init__(self, stages: list[tuple[Timing, Latency | Loss, np.random.Generator | None]],
                 control_rate: float) -> None:
        self._stages = [(timing, kind, rng, kind.periods(control_rate) if isinstance(kind, Latency) else 0)
                        for timing, kind, rng in stages]
        # per stage: the commands it received, newest last (a latency's N + 1 of them)
        self._history: list[deque[Twist2D]] = [deque([Twist2D()] * (n + 1), maxlen=n + 1)
                                               for _, _, _, n in self._stages]
        self._last: list[Twist2D] = [Twist2D() for _ in self._stages]  # what each stage put out last

    def __bool__(self) -> bool:
        return bool(self._stages)

    def apply(self, t: float, command: Twist2D) -> Twist2D:
        for i, (timing, kind, rng, _) in enumerate(self._stages):
            self._history[i].append(command)
            if timing.active(t):
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
    (at the step's start time ``t``)."""

    __slots__ = ("_drive", "_jumps", "_kidnaps", "_odometry")

    def __init__(self, faults: list[tuple[Timing, object]]) -> None:
        self._drive = [(timing, kind) for timing, kind in faults if isinstance(kind, Slip | Stuck)]
        self._odometry = [(timing, kind) for timing, kind in faults if isinstance(kind, Drift)]
        self._jumps = [(Edges(timing), kind) for timing, kind in faults if isinstance(kind, Jump)]
        self._kidnaps = [(Edges(timing), kind) for timing, kind in faults if isinstance(kind, Kidnap)]

    def __bool__(self) -> bool:
        return bool(self._drive or self._odometry or self._jumps or self._kidnaps)

    def drive(self, t: float) -> tuple[float, tuple[bool, bool], float]:
        """The wheels' speed factor (the slips' fractions multiplied), which wheels are stuck, and the factor by
        which the odometry counts the wheels' travel against the robot's (a slipping wheel turns as commanded)."""
        fraction, left, right = 1.0, False, False
        for timing, kind in self._drive:
            if timing.active(t):
                if isinstance(kind, Slip):
                    fraction *= kind.fraction
                else:
                    left, right = left or kind.wheel == "left", right or kind.wheel == "right"
        return fraction, (left, right), 1.0 / fraction

    def odometry(self, t: float, dt: float) -> tuple[float, float]:
        """The odometry's travel factor and the heading (rad) it gains over a step of ``dt`` from ``t``."""
        scale, bias = 1.0, 0.0
        for timing, kind in self._odometry:
            if timing.active(t):
                scale *= kind.scale
                bias += math.radians(kind.bias) * dt
        return scale, bias

    def jumps(self, t: float) -> list[Jump]:
        return [kind for edges, kind in self._jumps if edges.starts(t)]

    def kidnaps(self, t: float) -> list[Kidnap]:
        return [kind for edges, kind in self._kidnaps if edges.starts(t)]
