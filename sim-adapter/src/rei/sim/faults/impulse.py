# SPDX-License-Identifier: EPL-2.0
"""Laser impulse noise (thesis 7.5, Fig. 38-39): additive impulses arriving as a Poisson process.

The thesis fed a Simulink Poisson source into the laser topic; here the same model works on each scan:

* impulses arrive along the beam index as a Poisson process with ``rate`` impulses per beam per scan, so one scan
  of ``N`` beams receives ``Poisson(rate * N)`` impulses, each starting at a uniformly drawn beam;
* an impulse covers ``width`` consecutive beams (wrapping around the scan) and adds one amplitude, drawn uniformly
  in ``[-gain, +gain] * range_max``, to all of them: positive impulses push readings away (or out of range),
  negative ones create phantom obstacles, also on beams that saw nothing (their reading counts as ``range_max``);
* results above ``range_max`` read ``inf`` (no return), results below ``range_min`` read ``range_min``.

The thesis's named settings are "1 %" (low) and "10 %" (high) of the scan corrupted: the presets keep the gain and
the pulse width and scale the rate so that ``rate * width`` is 0.01 and 0.10 (the expected share of corrupted beams,
overlaps aside). A spec string is ``laser:<preset>`` or ``laser:key=value,...`` with keys ``rate``, ``gain``,
``width``, optionally after a preset (``laser:10%,gain=0.8``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np


@dataclass(frozen=True, slots=True)
class LaserFault:
    """Parameters of the impulse noise: ``rate`` per beam per scan, ``gain`` as a fraction of ``range_max``."""

    rate: float
    gain: float
    width: int

    def __post_init__(self) -> None:
        if not (math.isfinite(self.rate) and 0.0 <= self.rate <= 1.0):
            raise ValueError(
                f"laser fault rate must be in [0, 1] impulses per beam per scan, got {self.rate}"
            )
        if not (math.isfinite(self.gain) and self.gain >= 0.0):
            raise ValueError(f"laser fault gain must be >= 0, got {self.gain}")
        if self.width < 1:
            raise ValueError(f"laser fault width must be >= 1 beam, got {self.width}")


_WIDTH = 3
_GAIN = 0.5
PRESETS: dict[str, LaserFault] = {
    "1%": LaserFault(rate=0.01 / _WIDTH, gain=_GAIN, width=_WIDTH),
    "10%": LaserFault(rate=0.10 / _WIDTH, gain=_GAIN, width=_WIDTH),
}
PRESETS["low"] = PRESETS["1%"]
PRESETS["high"] = PRESETS["10%"]


def parse_fault(spec: str) -> LaserFault | None:
    """Parse ``laser:...``; ``none`` or an empty string mean no fault. Raises ``ValueError`` naming the problem."""
    text = spec.strip()
    if text in ("", "none"):
        return None
    kind, sep, body = text.partition(":")
    if kind.strip() != "laser" or not sep:
        raise ValueError(
            f"bad fault spec {spec!r}: expected 'laser:<preset>' or 'laser:rate=R,gain=G,width=W'"
        )
    parts = [p.strip() for p in body.split(",") if p.strip()]
    if not parts:
        raise ValueError(f"bad fault spec {spec!r}: nothing after 'laser:'")
    fault: LaserFault | None = None
    if "=" not in parts[0]:
        preset = PRESETS.get(parts[0])
        if preset is None:
            raise ValueError(
                f"bad fault spec {spec!r}: unknown preset {parts[0]!r}, known: {', '.join(PRESETS)}"
            )
        fault, parts = preset, parts[1:]
    values: dict[str, str] = {}
    for part in parts:
        key, eq, value = (s.strip() for s in part.partition("="))
        if not eq or key not in ("rate", "gain", "width"):
            raise ValueError(f"bad fault spec {spec!r}: {part!r} is not one of rate=, gain=, width=")
        if key in values:
            raise ValueError(f"bad fault spec {spec!r}: {key} given twice")
        values[key] = value
    if fault is None and set(values) != {"rate", "gain", "width"}:
        missing = ", ".join(sorted({"rate", "gain", "width"} - set(values)))
        raise ValueError(f"bad fault spec {spec!r}: missing {missing} (or start with a preset)")
    try:
        changes: dict[str, float | int] = {k: float(v) for k, v in values.items() if k != "width"}
        if "width" in values:
            changes["width"] = int(values["width"])
    except ValueError as exc:
        raise ValueError(f"bad fault spec {spec!r}: {exc}") from None
    try:
        if fault is None:
            return LaserFault(
                rate=float(changes["rate"]), gain=float(changes["gain"]), width=int(changes["width"])
            )
        return replace(fault, **changes)
    except ValueError as exc:
        raise ValueError(f"bad fault spec {spec!r}: {exc}") from None


class LaserFaultInjector:
    """Applies a :class:`LaserFault` to scans with its own seeded generator (same seed, same noise)."""

    __slots__ = ("_range_max", "_range_min", "_rng", "fault")

    def __init__(
        self, fault: LaserFault, rng: np.random.Generator, range_min: float, range_max: float
    ) -> None:
        self.fault = fault
        self._rng = rng
        self._range_min = range_min
        self._range_max = range_max

    def apply(self, ranges: np.ndarray, gain: float | None = None) -> np.ndarray:
        """A new array: ``ranges`` with this scan's impulses added (the input is not modified).

        ``gain``: this scan's gain when a schedule changes it over time (rei.sim.faults.timing.Ramp), else the
        fault's own; the draws are the same either way, so a constant gain records what it always did."""
        n = ranges.shape[0]
        count = int(self._rng.poisson(self.fault.rate * n))
        if count == 0:
            return ranges
        g = self.fault.gain if gain is None else gain
        starts = self._rng.integers(0, n, size=count)
        amplitudes = self._rng.uniform(-g, g, size=count) * self._range_max
        noise = np.zeros(n)
        offsets = np.arange(self.fault.width)
        for start, amplitude in zip(starts, amplitudes, strict=True):
            noise[(start + offsets) % n] += amplitude
        hit = noise != 0.0
        out = ranges.copy()
        base = np.minimum(out[hit], self._range_max)
        noisy = base + noise[hit]
        noisy[noisy >= self._range_max] = np.inf
        out[hit] = np.maximum(noisy, self._range_min)
        return out
