# SPDX-License-Identifier: EPL-2.0
"""The laser's fault kinds and what each does to a scan while it is active (docs/faults.md has the definitions).

* ``impulse``: the thesis's Poisson impulse noise (rei.sim.faults.impulse), its gain read from a ramp at the
  scan's time;
* ``freeze``: every scan reads the scan delivered last before the window began (the same ranges, bit for bit);
* ``blackout``: every beam reads no return (``inf``);
* ``occlusion``: the beams whose angle lies in ``[angle_from, angle_to]`` (degrees, counter-clockwise from the
  robot's forward axis, the sector running counter-clockwise from the first to the second; a second a whole turn or
  more after the first is every beam) read ``range``;
* ``noise``: every beam with a return reads ``r + N(0, sigma^2)``, beams without a return stay without.

Results below ``range_min`` read ``range_min``, results at or above ``range_max`` read ``inf`` (no return), as
the lidar reports them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from rei.sim.faults.impulse import LaserFault, LaserFaultInjector
from rei.sim.faults.kind import Kind, finite, within
from rei.sim.faults.timing import Ramp


@dataclass(frozen=True, slots=True)
class Impulse(Kind):
    kind: ClassVar[str] = "impulse"
    draws: ClassVar[bool] = True
    rate: float
    gain: Ramp
    width: int

    def __post_init__(self) -> None:
        LaserFault(self.rate, max(self.gain.low, 0.0), self.width)  # the same checks as the run-long fault's
        within(self.gain.low, "laser fault gain", 0.0, closed=True)

    @property
    def base(self) -> LaserFault:
        return LaserFault(self.rate, self.gain.points[0][1], self.width)

    def describe(self) -> str:
        return f"rate {self.rate:g}, gain {self.gain.text()}, width {self.width}"


@dataclass(frozen=True, slots=True)
class Freeze(Kind):
    kind: ClassVar[str] = "freeze"


@dataclass(frozen=True, slots=True)
class Blackout(Kind):
    kind: ClassVar[str] = "blackout"


@dataclass(frozen=True, slots=True)
class Occlusion(Kind):
    kind: ClassVar[str] = "occlusion"
    text: ClassVar[str] = "angles {angle_from:g}..{angle_to:g} deg at {range:g} m"
    angle_from: float
    angle_to: float
    range: float

    def __post_init__(self) -> None:
        for value in (self.angle_from, self.angle_to):
            finite(value, "occlusion angle", "of degrees")
        within(self.range, "occlusion range", 0.0, closed=True, unit="m")


@dataclass(frozen=True, slots=True)
class RangeNoise(Kind):
    kind: ClassVar[str] = "noise"
    draws: ClassVar[bool] = True
    text: ClassVar[str] = "sigma {sigma:g} m"
    sigma: float

    def __post_init__(self) -> None:
        within(self.sigma, "noise sigma", 0.0, unit="m")


LaserKind = Impulse | Freeze | Blackout | Occlusion | RangeNoise
LASER_KINDS: tuple[type[LaserKind], ...] = (Impulse, Freeze, Blackout, Occlusion, RangeNoise)
"""In the order of contract/vocabulary.json's ``faults.kinds.laser``."""


class LaserEffect:
    """One laser fault's effect on the scans of a run: its kind, its own generator, what a freeze holds."""

    __slots__ = ("_held", "_impulses", "_in_sector", "_range_max", "_range_min", "_rng", "kind")

    def __init__(self, kind: LaserKind, rng: np.random.Generator | None, range_min: float, range_max: float,
                 angle_min: float, angle_increment: float, beams: int) -> None:
        self.kind = kind
        self._rng = rng
        self._range_min = range_min
        self._range_max = range_max
        self._held: np.ndarray | None = None
        self._impulses = (LaserFaultInjector(kind.base, rng, range_min, range_max)
                          if isinstance(kind, Impulse) and rng is not None else None)
        self._in_sector: np.ndarray | None = None
        if isinstance(kind, Occlusion):
            angles = np.degrees(angle_min + angle_increment * np.arange(beams))
            span = kind.angle_to - kind.angle_from
            # a whole turn or more (0 to 360, -180 to 180) is every beam, not the one a remainder of 0 would leave
            width = 360.0 if span >= 360.0 else span % 360.0
            # both ends inside to within 1e-9 degrees (a beam at 30 degrees may compute as 29.999999999999996)
            self._in_sector = (angles - kind.angle_from + 1e-9) % 360.0 <= width + 2e-9

    def apply(self, t: float, ranges: np.ndarray, starts: bool, last: np.ndarray | None) -> np.ndarray:
        """This scan while the fault is active; ``starts``: the first scan of a window; ``last``: the scan
        delivered before this one (None before the first)."""
        kind = self.kind
        if isinstance(kind, Impulse):
            assert self._impulses is not None
            return self._impulses.apply(ranges, None if kind.gain.is_constant else kind.gain.value(t))
        if isinstance(kind, Freeze):
            if starts or self._held is None:
                self._held = last if last is not None else ranges
            return self._held
        if isinstance(kind, Blackout):
            return np.full(ranges.shape[0], np.inf)
        if isinstance(kind, Occlusion):
            assert self._in_sector is not None
            out = ranges.copy()
            out[self._in_sector] = self._clamp(np.array([kind.range]))[0]
            return out
        assert self._rng is not None
        noise = self._rng.normal(0.0, kind.sigma, size=ranges.shape[0])  # every beam: draws independent of hits
        out = ranges.copy()
        hit = np.isfinite(out) & (out < self._range_max)
        out[hit] = self._clamp(out[hit] + noise[hit])
        return out

    def _clamp(self, values: np.ndarray) -> np.ndarray:
        values = np.maximum(values, self._range_min)
        values[values >= self._range_max] = np.inf
        return values
