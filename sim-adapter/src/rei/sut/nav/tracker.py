# SPDX-License-Identifier: EPL-2.0
"""Moving-obstacle tracker: which laser points are not in the static map, and how fast they move.

A DWA that treats a walking human as a static obstacle stops in the human's way and gets walked into. Points the
static map does not explain are split into clusters along the scan (consecutive beams closer than a gap), each
cluster's centroid is matched to the nearest centroid of the previous scan, and the centroid's smoothed velocity
is given to all of the cluster's points, so the local planner can check its arcs against where they will be.
Only the ``still`` points go into a replan: a path around where a human was a moment ago leads nowhere.
"""

from __future__ import annotations

import math

import numpy as np

_GAP = 0.2  # metres between consecutive points of one cluster
_MATCH = 0.6  # metres a centroid may move between scans and still be the same object
_MAX_SPEED = 2.0
_MIN_SPEED = 0.08  # slower is noise from the changing visible outline of a standing object
_SMOOTHING = 0.5


class DynamicTracker:
    def __init__(self) -> None:
        self._t: float | None = None
        self._centroids = np.zeros((0, 2))
        self._velocities = np.zeros((0, 2))
        self.points = np.zeros((0, 2))
        self.velocities = np.zeros((0, 2))
        self.still = np.zeros((0, 2))

    def update(self, t: float, points: np.ndarray) -> None:
        """Take the unexplained world points of a new scan, in beam order."""
        labels = _segment(points)
        count = int(labels.max()) + 1 if len(labels) else 0
        centroids = np.zeros((count, 2))
        velocities = np.zeros((count, 2))
        for k in range(count):
            centroids[k] = points[labels == k].mean(axis=0)
        dt = None if self._t is None else t - self._t
        if dt is not None and dt > 1e-6 and len(self._centroids):
            for k in range(count):
                d = np.hypot(*(self._centroids - centroids[k]).T)
                m = int(np.argmin(d))
                if d[m] > _MATCH:
                    continue
                raw = (centroids[k] - self._centroids[m]) / dt
                speed = math.hypot(*raw)
                if speed > _MAX_SPEED:
                    continue
                vel = _SMOOTHING * raw + (1.0 - _SMOOTHING) * self._velocities[m]
                velocities[k] = vel if math.hypot(*vel) >= _MIN_SPEED else 0.0
        self._t, self._centroids, self._velocities = t, centroids, velocities
        moving = np.hypot(velocities[:, 0], velocities[:, 1]) > 0.0 if count else np.zeros(0, bool)
        keep = moving[labels] if len(labels) else np.zeros(0, bool)
        self.points = points[keep]
        self.still = points[~keep]
        self.velocities = velocities[labels[keep]] if len(labels) else np.zeros((0, 2))



def _segment(points: np.ndarray) -> np.ndarray:
    """Cluster label per point: a new cluster starts where consecutive points are more than ``_GAP`` apart."""
    if not len(points):
        return np.zeros(0, dtype=np.intp)
    jumps = np.hypot(*np.diff(points, axis=0).T) > _GAP
    return np.concatenate(([0], np.cumsum(jumps))).astype(np.intp)
