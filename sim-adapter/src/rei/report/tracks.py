# SPDX-License-Identifier: EPL-2.0
"""Where everything went: the robot's true and believed paths and every moving object's path, from the states.

Why a separate pass: the state recording is the largest file of a run (with `--laser full`, 3 KB per message),
so it is streamed once and reduced to plain coordinate lists that the map and the signal markers share.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any


@dataclass(slots=True)
class Track:
    """Positions over time of one body (or of the robot's belief), in the world frame."""

    name: str
    category: str
    t: list[float] = field(default_factory=list)
    x: list[float] = field(default_factory=list)
    y: list[float] = field(default_factory=list)
    yaw: list[float] = field(default_factory=list)

    def add(self, t: float, x: float, y: float, yaw: float) -> None:
        self.t.append(t)
        self.x.append(x)
        self.y.append(y)
        self.yaw.append(yaw)

    def __len__(self) -> int:
        return len(self.t)

    def xy(self) -> list[tuple[float, float]]:
        return list(zip(self.x, self.y, strict=True))

    def at(self, t: float) -> tuple[float, float, float] | None:
        """The pose `(x, y, yaw)` of the last sample at or before `t` (the first one before the track starts).

        Signals carry the time of the state message that caused them, so this is that message's pose.
        """
        if not self.t:
            return None
        i = max(0, bisect.bisect_right(self.t, t + 1e-9) - 1)
        return self.x[i], self.y[i], self.yaw[i]

    def bounds(self) -> tuple[float, float, float, float] | None:
        if not self.t:
            return None
        return min(self.x), min(self.y), max(self.x), max(self.y)


@dataclass(slots=True)
class Tracks:
    """The result of one pass over the states."""

    robot: Track
    believed: Track
    others: dict[str, Track]
    states: int = 0
    laser_scans: int = 0
    first_t: float | None = None
    last_t: float | None = None

    def odometry_error(self) -> tuple[float, float] | None:
        """The largest distance between belief and truth and its time: how far the robot was from where it
        thought it was. None without odometry."""
        worst: tuple[float, float] | None = None
        for t, x, y in zip(self.believed.t, self.believed.x, self.believed.y, strict=True):
            pose = self.robot.at(t)
            if pose is None:
                continue
            error = math.hypot(pose[0] - x, pose[1] - y)
            if worst is None or error > worst[0]:
                worst = (error, t)
        return worst


def collect_tracks(states: Iterable[Mapping[str, Any]]) -> Tracks:
    """Reduce state messages to tracks. Static objects of full frames are skipped (they are in world.json);
    malformed entries are skipped rather than failing a report of a run that may itself have failed."""
    tracks = Tracks(Track("robot", "ROBOT"), Track("odometry", "BELIEF"), {})
    for state in states:
        t = _real(state.get("t"))
        if t is None:
            continue
        tracks.states += 1
        tracks.first_t = t if tracks.first_t is None else tracks.first_t
        tracks.last_t = t
        robot = state.get("robot")
        if isinstance(robot, Mapping):
            pose = _pose(robot.get("pose"), 4)
            if pose is not None:
                tracks.robot.name = str(robot.get("name", "robot"))
                tracks.robot.add(t, pose[0], pose[1], pose[3])
            odom = _pose(robot.get("odom"), 3)
            if odom is not None:
                tracks.believed.add(t, odom[0], odom[1], odom[2])
            if robot.get("laser_ranges"):
                tracks.laser_scans += 1
        for body in state.get("objects") or ():
            if not isinstance(body, Mapping) or body.get("type") not in ("HUMAN", "DYNAMIC"):
                continue
            pose = _pose(body.get("pose"), 4)
            if pose is None:
                continue
            name = str(body.get("name"))
            track = tracks.others.get(name)
            if track is None:
                track = tracks.others[name] = Track(name, str(body.get("type")))
            track.add(t, pose[0], pose[1], pose[3])
    return tracks


def _real(value: object) -> float | None:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        return None
    return float(value)


def _pose(value: object, size: int) -> list[float] | None:
    if not isinstance(value, list | tuple) or len(value) < size:
        return None
    reals = [_real(v) for v in value[:size]]
    if any(r is None for r in reals):
        return None
    return reals  # type: ignore[return-value]
