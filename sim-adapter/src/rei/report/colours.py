# SPDX-License-Identifier: EPL-2.0
"""One colour per signal kind, fixed, so the same signal looks the same in every report and in the legend.

Why fixed rather than assigned in order of appearance: people compare two reports side by side, and a
collision must not be red in one and green in the other. Danger reads warm (close orange, collision red), the
laser's view of the same zones is a cooler twin (purple, magenta), leaving a zone is a calm colour, mission
events are green/blue/grey.
"""

from __future__ import annotations

import zlib

SIGNAL_COLOURS: dict[str, str] = {
    "SIG_GEOM_FAR_TRANSIT_CLOSE": "#f28e2b",
    "SIG_GEOM_CLOSE_TRANSIT_FAR": "#59a14f",
    "SIG_GEOM_CLOSE_TRANSIT_COLLISION": "#e15759",
    "SIG_GEOM_COLLISION_TRANSIT_CLOSE": "#b07aa1",
    "SIG_LASER_FAR_TRANSIT_CLOSE": "#edc948",
    "SIG_LASER_CLOSE_TRANSIT_FAR": "#8cd17d",
    "SIG_LASER_CLOSE_TRANSIT_COLLISION": "#d4166a",
    "SIG_LASER_COLLISION_TRANSIT_CLOSE": "#9d7660",
    "SIG_MISSION_BEGIN": "#4e79a7",
    "SIG_MISSION_END": "#4e79a7",
    "SIG_MISSION_TASK_START": "#76b7b2",
    "SIG_MISSION_TASK_SUCCESS": "#2ca02c",
    "SIG_MISSION_TASK_FAIL": "#d62728",
    "SIG_MONITOR_DATA_GAP": "#222222",
}

#: For signals a newer monitor may emit that this table does not know yet: stable by name.
_FALLBACK = ("#1f77b4", "#ff7f0e", "#17becf", "#bcbd22", "#7f7f7f", "#8c564b")

#: Order of the signal distribution's bars: geometry, laser (each by zone depth), then mission and gaps.
SIGNAL_ORDER: tuple[str, ...] = tuple(SIGNAL_COLOURS)

ROBOT_TRUE = "#1f3a93"
ROBOT_BELIEVED = "#e67e22"
HUMAN_PATH = "#b5651d"


def signal_colour(signal: str) -> str:
    """The colour of `signal`; unknown names get a fallback colour that depends only on the name."""
    known = SIGNAL_COLOURS.get(signal)
    if known is not None:
        return known
    return _FALLBACK[zlib.crc32(signal.encode()) % len(_FALLBACK)]


def css_colour(rgba: object, default: str = "#999999") -> str:
    """A world.json colour `[r, g, b, a]` in 0..1 as CSS `rgb(...)`; `default` when it is not one."""
    if not isinstance(rgba, list | tuple) or len(rgba) < 3:
        return default
    try:
        r, g, b = (max(0, min(255, round(float(c) * 255))) for c in rgba[:3])
    except (TypeError, ValueError):
        return default
    return f"rgb({r},{g},{b})"


def signal_sort_key(signal: str) -> tuple[int, str]:
    """Known signals in SIGNAL_ORDER, unknown ones after them alphabetically."""
    try:
        return SIGNAL_ORDER.index(signal), ""
    except ValueError:
        return len(SIGNAL_ORDER), signal
