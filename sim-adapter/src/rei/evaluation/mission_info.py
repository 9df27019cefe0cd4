# SPDX-License-Identifier: EPL-2.0
"""What the evaluator needs to know about the mission (thesis 6.1.4/6.1.5): its name, start and goals.

It comes from the ``mission_info`` RPC of the mission executor. Two shapes are in use and both are read:
docs/protocol.md's ``{mission, ..., goals: [{index, pose: [x, y, yaw], tolerance, timeout}]}`` and
rei.mission.executor's ``{name, ..., start: {x, y, yaw}, goals: [{index, x, y, yaw, tolerance, timeout}]}``.
A field that is missing is None; the verdicts that need it say so instead of guessing.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any


class MissionInfoError(ValueError):
    """mission_info that can not be read; the message names the field."""


@dataclass(frozen=True, slots=True)
class Goal:
    index: int
    x: float
    y: float
    tolerance: float | None = None


@dataclass(frozen=True, slots=True)
class MissionInfo:
    name: str | None
    testcase: str | None
    goals: tuple[Goal, ...]
    start: tuple[float, float] | None = None

    @classmethod
    def from_message(cls, message: Mapping[str, Any]) -> MissionInfo:
        if not isinstance(message, Mapping):
            raise MissionInfoError(f"mission_info must be a map, got {type(message).__name__}")
        name = message.get("mission", message.get("name"))
        goals_in = message.get("goals", [])
        if not isinstance(goals_in, list):
            raise MissionInfoError(f"mission_info 'goals' must be a list, got {goals_in!r}")
        goals = tuple(_goal(i, g) for i, g in enumerate(goals_in))
        start = message.get("start")
        start_xy = None
        if isinstance(start, Mapping):
            start_xy = (_real(start, "x", "start"), _real(start, "y", "start"))
        testcase = message.get("testcase")
        return cls(str(name) if name is not None else None, str(testcase) if testcase is not None else None,
                   goals, start_xy)


def _goal(position: int, goal: Any) -> Goal:
    where = f"goals[{position}]"
    if not isinstance(goal, Mapping):
        raise MissionInfoError(f"mission_info {where} must be a map, got {goal!r}")
    index = goal.get("index", position)
    if not isinstance(index, int) or isinstance(index, bool):
        raise MissionInfoError(f"mission_info {where}.index must be an integer, got {index!r}")
    pose = goal.get("pose")
    if isinstance(pose, list | tuple) and len(pose) >= 2:
        x, y = (_number(pose[0], f"{where}.pose[0]"), _number(pose[1], f"{where}.pose[1]"))
    else:
        x, y = _real(goal, "x", where), _real(goal, "y", where)
    tolerance = goal.get("tolerance")
    return Goal(index, x, y, _number(tolerance, f"{where}.tolerance") if tolerance is not None else None)


def _real(fields: Mapping[str, Any], key: str, where: str) -> float:
    return _number(fields.get(key), f"{where}.{key}")


def _number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise MissionInfoError(f"mission_info {where} must be a finite number, got {value!r}")
    return float(value)
