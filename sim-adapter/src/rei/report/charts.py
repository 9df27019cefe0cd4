# SPDX-License-Identifier: EPL-2.0
"""The two charts of the thesis's evaluation: utility over time (Fig. 33) and the distribution of signals
(Fig. 37), as inline SVG.

Why a step line: the total utility only changes at signals and stays constant in between; a sloped line would
suggest a gradual change that never happened. Why horizontal bars: signal names are long, and horizontal bars
keep them readable without rotated text.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence

from rei.report.colours import signal_colour, signal_sort_key
from rei.report.decimate import decimate
from rei.report.run_data import EventRow, SignalRecord
from rei.report.svg import esc, nice_ticks, num

CHART_WIDTH = 900.0
UTILITY_HEIGHT = 280.0
_LEFT, _RIGHT, _TOP, _BOTTOM = 56.0, 16.0, 14.0, 34.0
#: A step line of more points than this is thinned (only in runs with thousands of signals).
MAX_STEP_POINTS = 6000
MAX_EVENT_DOTS = 2000


def step_points(events: Sequence[EventRow], end_t: float) -> list[tuple[float, float]]:
    """The running total as a step function: (0, 0), then a vertical jump at each event, flat until `end_t`."""
    points = [(0.0, 0.0)]
    total = 0.0
    for event in events:
        points.append((event.t, total))
        total = event.total
        points.append((event.t, total))
    points.append((max(end_t, points[-1][0]), total))
    return points


def render_utility(events: Sequence[EventRow], end_t: float,
                   faults: Sequence[tuple[str, float, float | None]] = ()) -> str:
    """`<svg id="utility">`: the running total of events.csv over simulation time; ``faults`` (name, begin, end or
    None while open at the end) are shaded behind it (docs/faults.md)."""
    points = step_points(events, end_t)
    t_max = max(p[0] for p in points) or 1.0
    values = [p[1] for p in points]
    lo, hi = min(0.0, *values), max(0.0, *values)
    if hi - lo < 1e-9:
        lo, hi = lo - 1.0, hi + 1.0
    span = hi - lo
    lo, hi = lo - 0.08 * span, hi + 0.08 * span
    plot_w, plot_h = CHART_WIDTH - _LEFT - _RIGHT, UTILITY_HEIGHT - _TOP - _BOTTOM

    def px(t: float) -> float:
        return _LEFT + t / t_max * plot_w

    def py(v: float) -> float:
        return _TOP + (hi - v) / (hi - lo) * plot_h

    out = [(f'<svg id="utility" xmlns="http://www.w3.org/2000/svg" width="{num(CHART_WIDTH)}" '
           f'height="{num(UTILITY_HEIGHT)}" viewBox="0 0 {num(CHART_WIDTH)} {num(UTILITY_HEIGHT)}" role="img" '
           f'aria-label="total utility over simulation time">'),
           '<g class="axis">']
    for v in nice_ticks(lo, hi, 5):
        out.append(f'<line x1="{num(_LEFT)}" x2="{num(CHART_WIDTH - _RIGHT)}" y1="{num(py(v))}" y2="{num(py(v))}" '
                   f'stroke="#e5e5e5"/>')
        out.append(f'<text x="{num(_LEFT - 6)}" y="{num(py(v) + 4)}" text-anchor="end">{v:g}</text>')
    for t in nice_ticks(0.0, t_max, 8):
        out.append(f'<line x1="{num(px(t))}" x2="{num(px(t))}" y1="{num(_TOP + plot_h)}" '
                   f'y2="{num(_TOP + plot_h + 4)}" stroke="#888"/>')
        out.append(f'<text x="{num(px(t))}" y="{num(_TOP + plot_h + 16)}" text-anchor="middle">{t:g}</text>')
    out.append(f'<line x1="{num(_LEFT)}" x2="{num(CHART_WIDTH - _RIGHT)}" y1="{num(py(0))}" y2="{num(py(0))}" '
               f'stroke="#888" stroke-width="1"/>')
    out.append(f'<text x="{num(_LEFT + plot_w / 2)}" y="{num(UTILITY_HEIGHT - 4)}" text-anchor="middle">'
               f'simulation time [s]</text>')
    out.append(f'<text transform="translate(12 {num(_TOP + plot_h / 2)}) rotate(-90)" text-anchor="middle">'
               f'total utility</text>')
    out.append("</g>")
    if faults:
        out.append('<g id="fault-windows">')
        for name, begin, end in faults:
            stop = min(end if end is not None else t_max, t_max)
            out.append(f'<rect class="fault-window" x="{num(px(begin))}" y="{num(_TOP)}" '
                       f'width="{num(max(px(stop) - px(begin), 1.0))}" height="{num(plot_h)}" fill="#f5a623" '
                       f'fill-opacity="0.18"><title>{esc(name)}: {begin:g} s to '
                       f'{f"{end:g} s" if end is not None else "the end"}</title></rect>')
        out.append("</g>")
    drawn = decimate(points, MAX_STEP_POINTS)
    line = " ".join(f"{num(px(t))},{num(py(v))}" for t, v in drawn)
    out.append(f'<polyline id="utility-line" data-points="{len(drawn)}" points="{line}" fill="none" '
               f'stroke="#1f3a93" stroke-width="2"/>')
    out.append('<g id="utility-events">')
    for event in events[:MAX_EVENT_DOTS]:
        out.append(f'<circle cx="{num(px(event.t))}" cy="{num(py(event.total))}" r="3.5" '
                   f'fill="{signal_colour(event.signal)}"><title>t = {event.t:.2f} s  {esc(event.signal)}  '
                   f'{esc(event.object)}: {event.utility:+g} -&gt; total {event.total:g}</title></circle>')
    out.append("</g>")
    final = points[-1][1]
    out.append(f'<text class="final" x="{num(CHART_WIDTH - _RIGHT)}" y="{num(max(_TOP + 10, py(final) - 6))}" '
               f'text-anchor="end">total {final:g}</text>')
    out.append("</svg>")
    return "\n".join(out)


def signal_counts(signals: Sequence[SignalRecord]) -> list[tuple[str, int]]:
    """(signal, count) in the fixed signal order, so reports of different runs line up."""
    counts = Counter(s.signal for s in signals)
    return sorted(counts.items(), key=lambda item: signal_sort_key(item[0]))


def render_signal_bars(signals: Sequence[SignalRecord]) -> str:
    """`<svg id="signals">`: one bar per signal kind with its count."""
    counts = signal_counts(signals)
    row, label_w, right = 24.0, 300.0, 50.0
    height = max(1, len(counts)) * row + 12
    top = max((c for _, c in counts), default=1)
    bar_w = CHART_WIDTH - label_w - right
    out = [(f'<svg id="signals" xmlns="http://www.w3.org/2000/svg" width="{num(CHART_WIDTH)}" height="{num(height)}" '
           f'viewBox="0 0 {num(CHART_WIDTH)} {num(height)}" role="img" aria-label="number of signals per kind">')]
    for i, (name, count) in enumerate(counts):
        y = 6 + i * row
        w = max(1.0, count / top * bar_w)
        out.append(f'<text class="bar-label" x="{num(label_w - 8)}" y="{num(y + row * 0.62)}" text-anchor="end">'
                   f'{esc(name)}</text>')
        out.append(f'<rect class="bar" data-signal="{esc(name)}" data-count="{count}" x="{num(label_w)}" '
                   f'y="{num(y + 3)}" width="{num(w)}" height="{num(row - 6)}" fill="{signal_colour(name)}">'
                   f'<title>{esc(name)}: {count}</title></rect>')
        out.append(f'<text class="bar-count" x="{num(label_w + w + 6)}" y="{num(y + row * 0.62)}">{count}</text>')
    out.append("</svg>")
    return "\n".join(out)


def finite_or(value: object, default: float) -> float:
    """`value` as a finite float, else `default` (facts from JSON may be missing or null)."""
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return default
    return float(value)
