# SPDX-License-Identifier: EPL-2.0
"""Thinning long series for drawing: a two-hour run at 20 Hz has 144,000 poses, a browser needs a few thousand.

Why evenly spaced indices rather than a shape-preserving simplification: it is O(n), deterministic, keeps the
first and last sample (where the robot started and stopped) and keeps time evenly represented, which matters for
a path read next to a time axis. At a few thousand points a room-sized path looks the same either way.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeVar

T = TypeVar("T")

#: Points per path in the HTML map: smooth at any zoom a report is read at, small enough to stay fast.
MAX_PATH_POINTS = 3000


def decimate_indices(count: int, max_points: int) -> list[int]:
    """Indices of at most `max_points` evenly spaced samples of `count`, always the first and the last."""
    if max_points < 2:
        raise ValueError(f"max_points must be >= 2, got {max_points}")
    if count <= max_points:
        return list(range(count))
    step = (count - 1) / (max_points - 1)
    return [round(i * step) for i in range(max_points)]


def decimate(items: Sequence[T], max_points: int = MAX_PATH_POINTS) -> list[T]:
    """At most `max_points` evenly spaced items of `items`, the first and last included."""
    return [items[i] for i in decimate_indices(len(items), max_points)]
