# SPDX-License-Identifier: EPL-2.0
"""When a fault acts: a window (``from``/``to``), optionally gated by a pulse train, and values that change over
time (a piecewise linear ramp, the thesis's gain "adjusted during the mission").

Times are simulation seconds. A fault is active at ``t`` when ``from <= t < to`` and, with a pulse train of
``period`` and ``pulse`` (seconds on per period, or ``duty * period``), ``(t - from) mod period < pulse``: the
pulses start at ``from``, ``from + period``, ... Comparisons allow ``EPS`` so that a time computed as a sum of
physics steps (``n / 240``) falls on the side of an edge it was meant to (5.0 is never "just before" 5.0).
"""

from __future__ import annotations

import bisect
import itertools
import math
from collections.abc import Iterator
from dataclasses import dataclass

from rei.sim.faults.kind import number, seconds, within

EPS = 1e-9
"""Seconds by which a computed time may miss a scheduled edge and still count as on it."""
AHEAD = 1e-6
"""Seconds before a window's next edge at which :class:`Window` works its state out again: far more than ``EPS``
and the rounding of an edge's time, far less than a physics step."""


@dataclass(frozen=True, slots=True)
class Timing:
    """When a fault acts. ``whole_run``: nothing about time was said; the fault acts from the first step and marks
    no window (no BEGIN/END events: a run-long fault has no edge, and runs recorded before schedules existed
    stay byte-identical)."""

    start: float = 0.0
    end: float = math.inf
    period: float | None = None
    pulse: float | None = None
    whole_run: bool = False

    def __post_init__(self) -> None:
        if not (math.isfinite(self.start) and self.start >= 0.0):
            raise ValueError(f"'from' must be a time >= 0 s, got {self.start:g}")
        if not self.end > self.start:
            raise ValueError(f"'to' ({self.end:g} s) must be after 'from' ({self.start:g} s)")
        if (self.period is None) != (self.pulse is None):
            raise ValueError("a pulse train needs both a period and a pulse width (pulse= or duty=)")
        if self.period is not None and self.pulse is not None:
            within(self.period, "period", 0.0, unit="s")
            if not (0.0 < self.pulse <= self.period):
                raise ValueError(f"pulse width must be in (0, period = {self.period:g} s], got {self.pulse:g}")

    @classmethod
    def always(cls) -> Timing:
        return cls(whole_run=True)

    @property
    def gated(self) -> bool:
        return self.period is not None

    def active(self, t: float) -> bool:
        if not (self.start - EPS <= t < self.end - EPS):
            return False
        if self.period is None or self.pulse is None:
            return True
        return (t - self.start + EPS) % self.period < self.pulse

    def pulse_number(self, t: float) -> int:
        """The number of the pulse ``t`` falls in (0 without a pulse train), counted as :meth:`active` counts."""
        if self.period is None:
            return 0
        return int(divmod(t - self.start + EPS, self.period)[0])

    def edges(self) -> Iterator[tuple[float, bool]]:
        """The window's edges in time order, ``(t, True)`` where it begins and ``(t, False)`` where it ends; none
        for a whole-run fault, endless for a pulse train without ``to``."""
        if self.whole_run:
            return
        if self.period is None or self.pulse is None:
            yield self.start, True
            if math.isfinite(self.end):
                yield self.end, False
            return
        k = 0
        while True:
            begin = self.start + k * self.period
            if begin >= self.end - EPS:
                return
            yield begin, True
            end = min(begin + self.pulse, self.end)
            if not math.isfinite(end):
                return
            # a pulse as wide as the period ends where the next begins: keep both edges, END first
            yield end, False
            k += 1

    def next_edge(self, t: float) -> float:
        """The first of :meth:`edges` after ``t`` (``inf`` when none is left): until just before it, :meth:`active`
        answers as it does at ``t``."""
        if self.whole_run or t >= self.end:
            return math.inf
        if t < self.start:
            return self.start
        if self.period is None or self.pulse is None:
            return self.end
        k = math.floor((t - self.start) / self.period)
        # the pulse t is in (or, where the division rounded, the one before or after it) and the next one, their
        # times computed as edges() does; each edge with 0 for an END, 1 for a BEGIN (an END first where they meet)
        ahead = [(begin, 1) for begin in (self.start + k * self.period, self.start + (k + 1) * self.period)]
        ahead += [(begin + self.pulse, 0) for begin, _ in ahead]
        edge, begins = min(e for e in ahead if e[0] > t)
        if edge < self.end:
            return edge
        return math.inf if begins else self.end  # the window ends inside a pulse, or between two

    def describe(self) -> str:
        if self.whole_run:
            return "the whole run"
        text = f"from {self.start:g} s" + (f" to {self.end:g} s" if math.isfinite(self.end) else "")
        if self.period is not None and self.pulse is not None:
            text += f", pulses of {self.pulse:g} s every {self.period:g} s"
        return text


class Window:
    """A timing as a run's time passes (asked at times that never decrease): whether it is ``active`` and whether it
    ``began`` at the time last asked, for the kinds that act once a window (a freeze's held scan, a jump, a
    kidnap): active now and not when last asked, or in a pulse other than then (a pulse as wide as its period,
    or one whose gap no step falls in, begins anew as its BEGIN event says). Between edges it answers from what
    it worked out last: the motion's faults ask at every physics step."""

    __slots__ = ("_pulse", "_t", "active", "began", "timing", "until")

    def __init__(self, timing: Timing) -> None:
        self.timing = timing
        self.active = False
        self.began = False
        self.until = -math.inf  # from AHEAD before this time on, the state is worked out again
        self._t = -math.inf
        self._pulse = -1

    def at(self, t: float) -> None:
        """Move to ``t``: ``active`` and ``began`` then answer for it."""
        if t == self._t:
            return
        self._t = t
        if t < self.until - AHEAD:
            self.began = False
            return
        active = self.timing.active(t)
        pulse = self.timing.pulse_number(t)
        self.began = active and (not self.active or pulse != self._pulse)
        self.active, self._pulse = active, pulse
        self.until = self.timing.next_edge(t)


@dataclass(frozen=True, slots=True)
class Ramp:
    """A value over time: linear between ``points`` ``(t, value)`` (times increasing), constant before the first
    and after the last. One point is a constant."""

    points: tuple[tuple[float, float], ...]

    def __post_init__(self) -> None:
        if not self.points:
            raise ValueError("a ramp needs at least one value")
        times = [t for t, _ in self.points]
        if any(not math.isfinite(t) or t < 0 for t in times):
            raise ValueError(f"ramp times must be >= 0 s, got {times}")
        if any(b <= a for a, b in itertools.pairwise(times)):
            raise ValueError(f"ramp times must increase, got {', '.join(f'{t:g}' for t in times)}")
        if any(not math.isfinite(v) for _, v in self.points):
            raise ValueError("ramp values must be finite numbers")

    @classmethod
    def constant(cls, value: float) -> Ramp:
        return cls(((0.0, value),))

    @property
    def is_constant(self) -> bool:
        return len(self.points) == 1

    @property
    def low(self) -> float:
        return min(v for _, v in self.points)

    def value(self, t: float) -> float:
        points = self.points
        if t <= points[0][0]:
            return points[0][1]
        if t >= points[-1][0]:
            return points[-1][1]
        i = bisect.bisect_right([p[0] for p in points], t)
        (t0, v0), (t1, v1) = points[i - 1], points[i]
        return v0 + (v1 - v0) * (t - t0) / (t1 - t0)

    def text(self) -> str:
        """The spec form: ``0.5`` or ``0.2@0/0.8@30`` (value@time, ...)."""
        if self.is_constant:
            return repr(self.points[0][1])
        return "/".join(f"{v!r}@{t!r}" for t, v in self.points)


def parse_ramp(text: str) -> Ramp:
    """``0.5`` (constant) or ``0.2@0/0.8@30/0.8@60`` (value@seconds, linear between, constant outside)."""
    parts = [p.strip() for p in text.split("/")]
    if len(parts) == 1 and "@" not in parts[0]:
        return Ramp.constant(number(parts[0], "value"))
    points = []
    for part in parts:
        value, at, t = (s.strip() for s in part.partition("@"))
        if not at:
            raise ValueError(f"{part!r}: expected value@seconds, e.g. 0.8@30")
        points.append((seconds(t, "time"), number(value, "value")))
    return Ramp(tuple(points))

