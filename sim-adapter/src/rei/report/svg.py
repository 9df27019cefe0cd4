# SPDX-License-Identifier: EPL-2.0
"""Small SVG building blocks shared by the map and the charts: the world-to-pixel transform and escaping.

Why hand-written SVG and not a plotting library: the report must open offline from a single file, the plots
are simple, and SVG text is searchable and testable (ids, point counts) without rendering anything.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from html import escape


def num(value: float) -> str:
    """A coordinate with 2 decimals (1/100 px is below what any screen shows) and no '-0'."""
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def esc(text: object) -> str:
    """Text for an attribute or element body."""
    return escape(str(text), quote=True)


@dataclass(frozen=True, slots=True)
class MapTransform:
    """World metres (x right, y up) to SVG pixels (x right, y down), same scale on both axes.

    `bounds` is `(xmin, ymin, xmax, ymax)` in metres; `pad` pixels of margin surround it.
    """

    xmin: float
    ymin: float
    xmax: float
    ymax: float
    scale: float
    pad: float

    @classmethod
    def fit(cls, bounds: Sequence[float], width_px: float, pad: float = 16.0,
            max_height_px: float | None = None) -> MapTransform:
        """The transform that fits `bounds` into `width_px` (and at most `max_height_px`) pixels."""
        xmin, ymin, xmax, ymax = (float(b) for b in bounds)
        if not (xmax > xmin and ymax > ymin) or not all(map(math.isfinite, (xmin, ymin, xmax, ymax))):
            raise ValueError(f"bounds must be finite with max > min, got {list(bounds)}")
        scale = (width_px - 2 * pad) / (xmax - xmin)
        if max_height_px is not None:
            scale = min(scale, (max_height_px - 2 * pad) / (ymax - ymin))
        return cls(xmin, ymin, xmax, ymax, scale, pad)

    @property
    def width(self) -> float:
        return (self.xmax - self.xmin) * self.scale + 2 * self.pad

    @property
    def height(self) -> float:
        return (self.ymax - self.ymin) * self.scale + 2 * self.pad

    def point(self, x: float, y: float) -> tuple[float, float]:
        return (x - self.xmin) * self.scale + self.pad, (self.ymax - y) * self.scale + self.pad

    def length(self, metres: float) -> float:
        return metres * self.scale

    def points_attr(self, xy: Iterable[tuple[float, float]]) -> str:
        """`x,y x,y ...` for a polyline/polygon `points` attribute."""
        return " ".join(f"{num(px)},{num(py)}" for px, py in (self.point(x, y) for x, y in xy))


def box_corners(cx: float, cy: float, sx: float, sy: float, yaw: float) -> list[tuple[float, float]]:
    """The four corners (world frame) of a `sx` x `sy` rectangle centred at (cx, cy), turned by `yaw`."""
    c, s = math.cos(yaw), math.sin(yaw)
    corners = []
    for dx, dy in ((-sx / 2, -sy / 2), (sx / 2, -sy / 2), (sx / 2, sy / 2), (-sx / 2, sy / 2)):
        corners.append((cx + c * dx - s * dy, cy + s * dx + c * dy))
    return corners


def nice_ticks(lo: float, hi: float, count: int = 5) -> list[float]:
    """Round tick values (1, 2, 5 x 10^k steps) covering [lo, hi], about `count` of them."""
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return []
    if hi <= lo:
        hi = lo + 1.0
    raw = (hi - lo) / max(1, count)
    magnitude = 10 ** math.floor(math.log10(raw))
    step = next(m * magnitude for m in (1, 2, 5, 10) if m * magnitude >= raw)
    first = math.ceil(lo / step - 1e-9) * step
    ticks = []
    value = first
    while value <= hi + step * 1e-9:
        ticks.append(round(value, 10))
        value += step
    return ticks
