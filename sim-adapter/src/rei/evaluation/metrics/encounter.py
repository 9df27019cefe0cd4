# SPDX-License-Identifier: EPL-2.0
"""The encounter margin: how many seconds earlier or later a human would have had to walk to touch the robot.

A clearance is flat wherever the people are far from the robot while it passes: a person who sets off 30 s too
late is as far as one who sets off 300 s too late. The margin keeps the slope. It is a post-encroachment time
(Allen et al. 1978, the traffic-conflict measure): each human's *scheduled* walk (animation.json, the Catmull-Rom
path the simulator follows, before the start and beyond the end of the run too) against the robot's *recorded*
path. The pairs (robot sample ``k``, schedule time ``tau``) where the human's footprint at its scheduled place would
come within the monitor's collision threshold of the robot's footprint at sample ``k`` form the conflict; the margin
is the least ``|t_k - tau|`` over them. It is 0 when the human did meet the robot, and it has no value for a human
whose path never comes that close to where the robot drove.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from rei.artifacts import AnimationSpec, Category
from rei.geometry import footprint_gaps
from rei.spline import Trajectory

#: Step (s) at which a schedule is sampled: a person at 1.5 m/s moves 7.5 cm, under a state sample's resolution.
STEP = 0.05
#: Robot samples whose candidate pairs are measured at once: bounds the memory when a robot stays near a person.
_BLOCK = 1024


@dataclass(frozen=True, slots=True)
class Encounter:
    """How near a human came to meeting the robot: the ``shift`` (s, signed) of its schedule that brings it to the
    conflict when the robot was there, and so ``margin`` seconds off."""

    human: str
    shift: float

    @property
    def margin(self) -> float:
        return abs(self.shift)


def encounters(animation: AnimationSpec, footprints: dict[str, tuple[np.ndarray, bool]],
               t: np.ndarray, pose: np.ndarray, robot_size: tuple[float, float] | np.ndarray,
               threshold: float) -> list[Encounter]:
    """Each human's encounter, in ``animation``'s order, for the robot's samples ``t`` and true ``pose`` ``(T, 3)``:
    the humans named in ``footprints`` (see :func:`footprints_of`); a human whose path never comes within
    ``threshold`` of the robot's footprint (``robot_size``: its rectangle, or a described robot's outline ``(M, 2)``
    as rei.geometry.footprint_gaps takes them) has none."""
    found = []
    for o in animation.objects:
        if o.category != Category.HUMAN or o.name not in footprints:
            continue
        trajectory = Trajectory([p.t for p in o.points], [(p.x, p.y) for p in o.points], o.loop)
        shift = _shift(trajectory, *footprints[o.name], t, pose, robot_size, threshold)
        if shift is not None:
            found.append(Encounter(o.name, shift))
    return found


def footprints_of(names: Sequence[str], boxes: np.ndarray, circle: np.ndarray) -> dict[str, tuple[np.ndarray, bool]]:
    """:func:`encounters`' footprints: each of ``names`` with its row of ``boxes`` (``x, y, yaw, size_x, size_y``
    as in world.json; only the yaw and the sizes are used, the place is the schedule's) and whether it is a circle
    (a cylinder, of diameter ``size_x``) rather than a rectangle, as the monitor draws it."""
    return {name: (boxes[i], bool(circle[i])) for i, name in enumerate(names)}


def _shift(trajectory: Trajectory, box: np.ndarray, circle: bool, t: np.ndarray, pose: np.ndarray,
           robot_size: tuple[float, float] | np.ndarray, threshold: float) -> float | None:
    """``t_k - tau`` of the conflicting pair of least ``|t_k - tau|``, None without a conflict."""
    if len(t) == 0:
        return None
    places, first, last = _schedule(trajectory, t)
    human = np.array([circle])

    def gaps(k: np.ndarray, j: np.ndarray) -> np.ndarray:
        obstacles = np.empty((len(k), 1, 5))
        obstacles[:, 0, :2] = places[j]
        obstacles[:, 0, 2:] = box[2:]
        return footprint_gaps(pose[k], robot_size, obstacles, human)[:, 0]

    # tau = t_k first, O(T): a human who met the robot scores 0 without the pairs (a robot held by a person).
    k = np.arange(len(t))
    if (gaps(k, np.searchsorted(first, t, side="right") - 1) < threshold).any():
        return 0.0
    # Only schedule places within reach of some robot position can conflict: both footprints' circumradii.
    # An outline is placed about the robot's origin, not its centre: its farthest vertex from the origin.
    robot_reach = (float(np.hypot(*robot_size.T).max()) if isinstance(robot_size, np.ndarray)
                   else math.hypot(*robot_size) / 2)
    reach = robot_reach + math.hypot(box[3], box[4]) / 2 + max(threshold, 0.0)
    schedule = _Grid(places, reach)
    best: float | None = None
    for a in range(0, len(t), _BLOCK):
        k, j = schedule.within(pose[a:a + _BLOCK, :2])
        k += a
        # a place stands from first[j] to last[j]: the nearest of those times to t_k
        shifts = t[k] - np.clip(t[k], first[j], last[j])
        if best is not None:
            nearer = np.abs(shifts) < abs(best)
            k, j, shifts = k[nearer], j[nearer], shifts[nearer]
        conflict = gaps(k, j) < threshold
        if conflict.any():
            shifts = shifts[conflict]
            best = float(shifts[np.argmin(np.abs(shifts))])
    return best


def _schedule(trajectory: Trajectory, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The human's places ``(P, 2)`` at the schedule times that can be nearest to a robot sample, each with the
    first and last of those times it stands there (equal consecutive places merged: a person waiting or standing
    for minutes is one place, not thousands). The times are the samples' own (so a meeting scores exactly 0) and
    STEP apart before and after them: a loop over a period either side (it repeats before its first point too, and
    any phase recurs within a period of every sample); a walk once from its first point (if before the run: before
    that the person waits there, further in time from every sample) to its last (after it the person stays)."""
    begin, end = float(t[0]), float(t[-1])
    if trajectory.loop:
        low, high = begin - trajectory.period, end + trajectory.period
    else:
        low, high = min(begin, trajectory.start), max(end, trajectory.end)
    before = begin - STEP * np.arange(math.ceil((begin - low) / STEP), 0, -1)
    taus = np.unique(np.concatenate((before, t, np.arange(end + STEP, high + STEP, STEP))))
    places = np.array([trajectory.position(float(tau)) for tau in taus])
    starts = np.flatnonzero(np.concatenate(([True], (places[1:] != places[:-1]).any(axis=1))))
    ends = np.append(starts[1:], len(taus)) - 1
    return places[starts], taus[starts], taus[ends]


class _Grid:
    """The points within ``reach`` of query points, by a uniform grid of cells ``reach`` wide: each query looks in
    its cell and the eight around it. A few lines of NumPy instead of a k-d tree, so the metrics do not import
    SciPy's spatial package (half a second on the critical path of every run, issue #37)."""

    __slots__ = ("_cells", "_order", "_points", "_reach")

    def __init__(self, points: np.ndarray, reach: float) -> None:
        self._points = points
        self._reach = reach
        cells = self._cell(points)
        self._order = np.lexsort((cells[:, 1], cells[:, 0]))
        self._cells = cells[self._order]

    def _cell(self, xy: np.ndarray) -> np.ndarray:
        return np.floor(xy / self._reach).astype(np.int64)

    def within(self, queries: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Pairs ``(i, j)``, sorted, of query ``i`` and point ``j`` at most ``reach`` apart."""
        cells = self._cell(queries)
        keys = self._cells[:, 0] * (1 << 32) + self._cells[:, 1]  # sorted: rows ordered by (cx, cy)
        found_i, found_j = [], []
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                wanted = (cells[:, 0] + dx) * (1 << 32) + (cells[:, 1] + dy)
                lo = np.searchsorted(keys, wanted, side="left")
                hi = np.searchsorted(keys, wanted, side="right")
                counts = hi - lo
                i = np.repeat(np.arange(len(queries)), counts)
                # each query's run of sorted rows lo..hi-1, laid end to end
                offsets = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
                found_i.append(i)
                found_j.append(self._order[np.repeat(lo, counts) + offsets])
        i, j = np.concatenate(found_i), np.concatenate(found_j)
        near = np.hypot(*(queries[i] - self._points[j]).T) <= self._reach
        i, j = i[near], j[near]
        order = np.lexsort((j, i))
        return i[order], j[order]
