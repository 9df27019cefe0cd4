# SPDX-License-Identifier: EPL-2.0
"""The messages of the external-SUT protocol (docs/sut.md): built, read and checked in one place.

Both sides use this module: the simulation (``rei.sut.external.controller``) builds ticks, goals and the ``hello``
answer and checks what the SUT sends; the Python kit (``rei.sut.client``) reads ticks and goals back into the
in-process types of ``rei.sut.api``. Nothing here talks to the network, so every rule is a plain function a test
can pin.

Numbers are sent as float64 (``float()``), so a value crosses the process boundary bit for bit: an external
controller sees exactly the observation an in-process one would.
"""

from __future__ import annotations

import math
import reprlib
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from rei.artifacts.world import FOOTPRINT_TYPES, CircleFootprint, PolygonFootprint, footprint_polygon
from rei.geometry import Pose2D, Twist2D
from rei.sut.api import LaserScan, NavGoal, NavStatus, Observation, StaticMap

PROTOCOL_VERSION = 1
#: The URIs' last components, ``rei.run.<run_id>.sut.<name>`` (contract/vocabulary.json ``sut``).
URI_TEMPLATE = "rei.run.{run_id}.sut.{name}"
FROM_SIMULATION = ("tick", "goal", "cancel", "end")
FROM_SUT = ("command", "status")
PROCEDURES = ("hello",)
#: Statuses a SUT may report (IDLE is the state before any goal, never reported).
REPORTABLE = frozenset({NavStatus.ACTIVE, NavStatus.SUCCEEDED, NavStatus.ABORTED, NavStatus.CANCELLED})
MAX_TEXT = 1000
_COMMAND_FIELDS = frozenset({"tick", "v", "w"})
_COMMAND_OPTIONAL = frozenset({"vy"})  # a holonomic robot's sideways speed; 0 when left out
_STATUS_FIELDS = frozenset({"goal_id", "status", "text"})
_SHORT = reprlib.Repr()
_SHORT.maxstring = _SHORT.maxother = 40
_SHORT.maxlist = _SHORT.maxdict = 4
_SHORT.maxlevel = 2


def uri(run_id: str, name: str) -> str:
    """``rei.run.<run_id>.sut.<name>`` for one of the protocol's names."""
    if name not in (*FROM_SIMULATION, *FROM_SUT, *PROCEDURES):
        raise ValueError(f"no SUT URI named {name!r}")
    return URI_TEMPLATE.format(run_id=run_id, name=name)


@dataclass(frozen=True, slots=True)
class RobotLimits:
    """What clamping uses: the robot's drive limits (m/s, rad/s); ``max_lateral`` is a holonomic drive's sideways
    limit, 0 for a differential drive (which cannot move sideways: its ``vy`` is clamped to 0)."""

    max_linear: float
    max_angular: float
    max_lateral: float = 0.0

    @property
    def holonomic(self) -> bool:
        return self.max_lateral > 0


# -- simulation -> SUT -----------------------------------------------------------------------------------------


def hello_answer(*, run_id: str, clock: str, control_rate: float, deadline: float, start: Pose2D,
                 robot: Mapping[str, Any], goals: int, static_map: StaticMap | None,
                 occupancy: str | None = None) -> dict[str, Any]:
    """The session description ``hello`` returns (docs/sut.md); ``occupancy``: a map room's ``map.yaml``, named
    relative to the case's folder (``REI_CASE_DIR``), offered with the static map."""
    answer: dict[str, Any] = {
        "protocol": PROTOCOL_VERSION, "run_id": run_id, "clock": clock, "control_rate": float(control_rate),
        "deadline": float(deadline), "start": _pose(start), "robot": dict(robot), "goals": goals,
        "map": None if static_map is None else {
            "bounds": [float(v) for v in static_map.bounds],
            "obstacles": [[float(v) for v in box] for box in static_map.obstacles],
        },
    }
    if static_map is not None and static_map.polygons:  # furniture on a polygon; a world of boxes has no member
        answer["map"]["polygons"] = [None if polygon is None else [[float(x), float(y)] for x, y in polygon]
                                     for polygon in static_map.polygons]
    if static_map is not None and occupancy is not None:
        answer["map"]["occupancy"] = occupancy
    return answer


def outline(footprint: PolygonFootprint | CircleFootprint) -> dict[str, Any]:
    """``hello``'s ``robot.outline``: the robot's outline on the floor in its own frame, as world.json writes a
    described robot's footprint (a box robot's is its rectangle)."""
    polygon, circle = FOOTPRINT_TYPES
    if isinstance(footprint, CircleFootprint):
        return {"type": circle, "x": float(footprint.x), "y": float(footprint.y), "radius": float(footprint.radius)}
    return {"type": polygon, "points": [[float(x), float(y)] for x, y in footprint.points]}


def tick_message(tick: int, observation: Observation, *, new_scan: bool, scan_time: float,
                 holonomic: bool = False) -> dict[str, Any]:
    """One control period: clock, odometry and (when taken since the previous tick) the newest scan. A holonomic
    robot's odometry twist has its sideways speed third."""
    scan = observation.scan
    twist = observation.odom_twist
    return {
        "tick": tick, "t": float(observation.t),
        "odom": {"pose": _pose(observation.odom),
                 "twist": [float(twist.v), float(twist.w), float(twist.vy)] if holonomic else [float(twist.v),
                                                                                               float(twist.w)]},
        "scan": _scan(scan, scan_time) if new_scan and scan is not None else None,
    }


def goal_message(t: float, goal: NavGoal) -> dict[str, Any]:
    return {"goal_id": goal.index, "t": float(t), "pose": _pose(goal.pose), "tolerance": float(goal.tolerance)}


def cancel_message(t: float, goal_id: int) -> dict[str, Any]:
    return {"goal_id": goal_id, "t": float(t)}


def end_message(t: float, reason: str) -> dict[str, Any]:
    return {"t": float(t), "reason": reason}


def _pose(pose: Pose2D) -> list[float]:
    return [float(pose.x), float(pose.y), float(pose.yaw)]


def _scan(scan: LaserScan, scan_time: float) -> dict[str, Any]:
    count = len(scan.ranges)
    return {
        "t": float(scan.t), "angle_min": float(scan.angle_min),
        "angle_max": float(scan.angle_min + (count - 1) * scan.angle_increment),
        "angle_increment": float(scan.angle_increment), "scan_time": float(scan_time),
        "range_min": float(scan.range_min), "range_max": float(scan.range_max),
        "ranges": np.asarray(scan.ranges, dtype=np.float64).tolist(),
    }


# -- read back by a Python SUT ---------------------------------------------------------------------------------


def read_pose(values: Any) -> Pose2D:
    x, y, yaw = values
    return Pose2D(float(x), float(y), float(yaw))


def read_static_map(hello: Mapping[str, Any]) -> StaticMap | None:
    data = hello.get("map")
    if data is None:
        return None
    return StaticMap(bounds=tuple(float(v) for v in data["bounds"]),  # type: ignore[arg-type]
                     obstacles=tuple(tuple(float(v) for v in box) for box in data["obstacles"]),  # type: ignore[misc]
                     polygons=tuple(None if polygon is None else tuple((float(x), float(y)) for x, y in polygon)
                                    for polygon in data.get("polygons") or ()),
                     **_robot(hello["robot"]))


def robot_only_map(robot: Mapping[str, Any]) -> StaticMap:
    """No static map offered: an empty one with ``hello``'s ``robot`` as read with a map (its size, lidar place,
    outline and drive), for a controller that takes its robot from a StaticMap (``rei nav-sut`` without
    ``--sut-map``)."""
    return StaticMap(bounds=(0.0, 0.0, 0.0, 0.0), obstacles=(), **_robot(robot))


def _robot(robot: Mapping[str, Any]) -> dict[str, Any]:
    """StaticMap's fields about the robot, from ``hello``'s ``robot``."""
    size = (float(robot["footprint"][0]), float(robot["footprint"][1]))
    lidar = robot.get("lidar", {})
    return {"robot_size": size,
            "lidar": (float(lidar.get("x", 0.0)), float(lidar.get("y", 0.0)), float(lidar.get("yaw", 0.0))),
            "outline": _described_outline(robot.get("outline"), size), "holonomic": robot.get("drive") == "holonomic"}


def _described_outline(data: Any, size: tuple[float, float]) -> tuple[tuple[float, float], ...] | None:
    """``hello``'s ``robot.outline`` as StaticMap.outline: a circle as the polygon around it (as world.json's
    footprint is read); None without one, or when it is the ``footprint`` rectangle centred on the origin (a box
    robot, whose footprint is its size, as the in-process controllers get it)."""
    if not isinstance(data, Mapping):
        return None
    polygon, circle = FOOTPRINT_TYPES
    if data.get("type") == circle:
        return footprint_polygon(CircleFootprint(float(data["x"]), float(data["y"]), float(data["radius"])))
    if data.get("type") != polygon:
        return None
    points = tuple((float(x), float(y)) for x, y in data["points"])
    hx, hy = size[0] / 2, size[1] / 2
    return None if set(points) == {(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)} else points


def read_occupancy(hello: Mapping[str, Any], case_dir: Path | None = None) -> Path | None:
    """The map room's ``map.yaml`` the static map came from (``map.occupancy``, relative to ``case_dir``: the
    run's case folder, ``REI_CASE_DIR``), or None."""
    data = hello.get("map")
    path = data.get("occupancy") if isinstance(data, Mapping) else None
    if not isinstance(path, str):
        return None
    return Path(path) if case_dir is None else case_dir / path


def read_scan(data: Mapping[str, Any]) -> LaserScan:
    return LaserScan(t=float(data["t"]), angle_min=float(data["angle_min"]),
                     angle_increment=float(data["angle_increment"]), range_min=float(data["range_min"]),
                     range_max=float(data["range_max"]), ranges=np.asarray(data["ranges"], dtype=np.float64))


def read_goal(data: Mapping[str, Any]) -> NavGoal:
    return NavGoal(int(data["goal_id"]), read_pose(data["pose"]), float(data["tolerance"]))


def read_observation(data: Mapping[str, Any], last_scan: LaserScan | None) -> Observation:
    """The tick as an in-process controller's Observation; ``last_scan`` stands in when the tick has none."""
    odom = data["odom"]
    v, w, *lateral = odom["twist"]  # a holonomic robot's [v, w, vy]
    scan = read_scan(data["scan"]) if data.get("scan") is not None else last_scan
    return Observation(t=float(data["t"]), odom=read_pose(odom["pose"]),
                       odom_twist=Twist2D(float(v), float(w), float(lateral[0]) if lateral else 0.0), scan=scan)


# -- SUT -> simulation: the rules of docs/sut.md, "What happens to bad input" ---------------------------------


@dataclass(frozen=True, slots=True)
class Command:
    """A command that passed the checks; ``clamped`` says it was limited to the robot's speeds."""

    tick: int
    twist: Twist2D
    clamped: bool = False


@dataclass(frozen=True, slots=True)
class Status:
    goal_id: int
    status: NavStatus
    text: str


@dataclass(frozen=True, slots=True)
class Rejected:
    """Not applied. ``stale``: well formed but for a past tick or another goal (ignored); else malformed."""

    reason: str
    stale: bool = False


def check_command(payload: Any, *, current_tick: int, answered: bool, limits: RobotLimits) -> Command | Rejected:
    """A ``command`` against the tick the simulation last published (``answered``: a command for it was taken)."""
    if not isinstance(payload, Mapping):
        return Rejected(f"a command must be a map {{tick, v, w, vy?}}, got {_kind(payload)}")
    keys = set(payload)
    if not _COMMAND_FIELDS <= keys <= _COMMAND_FIELDS | _COMMAND_OPTIONAL:
        missing = sorted(_COMMAND_FIELDS - keys)
        extra = sorted(map(str, keys - _COMMAND_FIELDS - _COMMAND_OPTIONAL))
        return Rejected("a command has the fields tick, v, w and optionally vy"
                        + (f"; missing {', '.join(missing)}" if missing else "")
                        + (f"; unknown {', '.join(extra)}" if extra else ""))
    tick = payload["tick"]
    if not is_int(tick) or tick < 0:
        return Rejected(f"tick must be an integer >= 0, got {tick!r}")
    values = []
    for name in ("v", "w", "vy"):
        value = payload.get(name, 0.0)
        if not _is_number(value):
            return Rejected(f"{name} must be a number, got {_kind(value)}")
        if not math.isfinite(value):
            return Rejected(f"{name} must be finite, got {value!r}")
        values.append(float(value))
    if tick > current_tick:
        return Rejected(f"tick {tick} was not published yet (the last is {current_tick})")
    if tick < current_tick or answered:
        return Rejected(f"tick {tick} is already answered", stale=True)
    v, w, vy = values
    clamped_v = max(-limits.max_linear, min(limits.max_linear, v))
    clamped_w = max(-limits.max_angular, min(limits.max_angular, w))
    # a differential drive's sideways limit is 0: its vy is clamped to nothing, and counted as clamped
    clamped_vy = max(-limits.max_lateral, min(limits.max_lateral, vy))
    return Command(tick, Twist2D(clamped_v, clamped_w, clamped_vy),
                   clamped=(clamped_v, clamped_w, clamped_vy) != (v, w, vy))


def check_status(payload: Any, *, current_goal: int | None) -> Status | Rejected:
    """A ``status`` against the goal the simulation last sent (None before the first)."""
    if not isinstance(payload, Mapping):
        return Rejected(f"a status must be a map {{goal_id, status, text?}}, got {_kind(payload)}")
    keys = set(payload)
    if not {"goal_id", "status"} <= keys <= _STATUS_FIELDS:
        return Rejected(f"a status has the fields goal_id, status and optionally text, got {sorted(map(str, keys))}")
    goal_id, name, text = payload["goal_id"], payload["status"], payload.get("text", "")
    if not is_int(goal_id):
        return Rejected(f"goal_id must be an integer, got {goal_id!r}")
    try:
        status = NavStatus(name)
    except (ValueError, TypeError):
        status = None
    if status not in REPORTABLE:
        return Rejected(f"status must be one of {', '.join(sorted(s.value for s in REPORTABLE))}, got {name!r}")
    if not isinstance(text, str) or len(text) > MAX_TEXT:
        return Rejected(f"text must be a string of at most {MAX_TEXT} characters")
    if goal_id != current_goal:
        return Rejected(f"status for goal {goal_id}, the current goal is {current_goal}", stale=True)
    assert status is not None
    return Status(goal_id, status, text)


@dataclass(frozen=True, slots=True)
class KeywordArguments:
    """A message sent with keyword arguments (``publish(uri, tick=3, v=0.1, w=0.0)``), which REI does not take: the
    checks reject it naming them, not as a map of odd fields."""

    args: tuple[Any, ...]
    kwargs: Mapping[str, Any]


def is_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _kind(value: Any) -> str:
    if isinstance(value, KeywordArguments):
        return (f"keyword arguments ({', '.join(map(str, value.kwargs))}): send the map as the message's single "
                f"positional argument (args[0])")
    return f"{type(value).__name__} {_SHORT.repr(value)}"  # reprlib: a 1 MB payload is not copied to be cut
