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
from scipy.spatial import cKDTree

from rei.artifacts import AnimationSpec, Category
from rei.geometry import footprint_gaps
from rei.spline import Trajectory

#: Step (s) at which a schedule is sampled: a person at 1.5 m/s moves 7.5 cm, under a state sample's resolution.
STEP = 0.05


@dataclass(frozen=True, slots=True)
class Encounter:
    """The human nearest to meeting the robot: ``margin`` seconds off, and the ``shift`` (s, signed) of its
    schedule that brings it to the conflict when the robot was there (``margin == abs(shift)``)."""

    human: str
    margin: float
    shift: float


def encounter_margin(animation: AnimationSpec, footprints: dict[str, tuple[np.ndarray, bool]],
                     t: np.ndarray, pose: np.ndarray, robot_size: tuple[float, float],
                     threshold: float) -> float | None:
    """The least margin over the humans of ``animation`` named in ``footprints`` (their ``x, y, yaw, size_x,
    size_y`` row as in world.json and whether it is a circle), for the robot's samples ``t`` and true ``pose``
    ``(T, 3)``; None when no human's path comes within ``threshold`` of the robot's."""
    nearest = nearest_encounter(animation, footprints, t, pose, robot_size, threshold)
    return nearest.margin if nearest is not None else None


def nearest_encounter(animation: AnimationSpec, footprints: dict[str, tuple[np.ndarray, bool]],
                      t: np.ndarray, pose: np.ndarray, robot_size: tuple[float, float],
                      threshold: float) -> Encounter | None:
    """:func:`encounter_margin`'s human, margin and shift (the first human of the least margin)."""
    found = encounters(animation, footprints, t, pose, robot_size, threshold)
    return min(found, key=lambda e: e.margin) if found else None


def encounters(animation: AnimationSpec, footprints: dict[str, tuple[np.ndarray, bool]],
               t: np.ndarray, pose: np.ndarray, robot_size: tuple[float, float],
               threshold: float) -> list[Encounter]:
    """Each human's encounter, in ``animation``'s order; a human whose path never comes that close has none."""
    found = []
    for o in animation.objects:
        if o.category != Category.HUMAN or o.name not in footprints:
            continue
        trajectory = Trajectory([p.t for p in o.points], [(p.x, p.y) for p in o.points], o.loop)
        shift = _shift(trajectory, *footprints[o.name], t, pose, robot_size, threshold)
        if shift is not None:
            found.append(Encounter(o.name, abs(shift), shift))
    return found


def _shift(trajectory: Trajectory, box: np.ndarray, circle: bool, t: np.ndarray, pose: np.ndarray,
           robot_size: tuple[float, float], threshold: float) -> float | None:
    """``t_k - tau`` of the conflicting pair of least ``|t_k - tau|``, None without a conflict."""
    if len(t) == 0:
        return None
    taus = _taus(trajectory, t)
    places = np.array([trajectory.position(float(tau)) for tau in taus])
    # Only schedule places within reach of some robot position can conflict: both footprints' circumradii.
    reach = math.hypot(*robot_size) / 2 + math.hypot(box[3], box[4]) / 2 + max(threshold, 0.0)
    near = cKDTree(pose[:, :2]).query_ball_point(places, reach)
    pairs = [(k, j) for j, ks in enumerate(near) for k in ks]
    if not pairs:
        return None
    k, j = np.array(pairs).T
    obstacles = np.empty((len(k), 1, 5))
    obstacles[:, 0, :2] = places[j]
    obstacles[:, 0, 2:] = box[2:]
    gaps = footprint_gaps(pose[k], robot_size, obstacles, np.array([circle]))[:, 0]
    conflict = gaps < threshold
    if not conflict.any():
        return None
    shifts = t[k[conflict]] - taus[j[conflict]]
    return float(shifts[np.argmin(np.abs(shifts))])


def _taus(trajectory: Trajectory, t: np.ndarray) -> np.ndarray:
    """The schedule times that can be nearest to a robot sample: the samples' own (so a meeting scores exactly 0)
    and STEP apart before and after them. A loop over a period either side: it repeats before its first point too,
    and any phase recurs within a period of every sample. A walk once from its first point, when that is before the
    run (earlier the person waits there, further in time from every sample), to its last (later it stays there)."""
    begin, end = float(t[0]), float(t[-1])
    if trajectory.loop:
        low, high = begin - trajectory.period, end + trajectory.period
    else:
        low, high = min(begin, trajectory.start), max(end, trajectory.end)
    before = begin - STEP * np.arange(math.ceil((begin - low) / STEP), 0, -1)
    return np.concatenate((before, t, np.arange(end + STEP, high + STEP, STEP)))


def footprints_of(names: Sequence[str], boxes: np.ndarray, circle: np.ndarray) -> dict[str, tuple[np.ndarray, bool]]:
    return {name: (boxes[i], bool(circle[i])) for i, name in enumerate(names)}
