# SPDX-License-Identifier: EPL-2.0
"""Wire messages of the state and mission topics, built from simulator snapshots (docs/protocol.md).

Why duck types: the simulator's ``rei.sim.state.SimState`` is written in parallel and this module must not import
the simulator (the monitor-side tools and the tests use it without pybullet). Any object with the attributes of
the Protocols below encodes.

Every number that is a float on the wire is converted to a Python ``float`` here, so msgpack writes float64
(numpy float32 would otherwise raise or narrow); ``inf`` (a laser beam that hit nothing) stays ``inf``.
Keys are inserted in a fixed order, so equal inputs pack to equal bytes: recordings are reproducible.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Collection, Iterable, Mapping, Sequence
from typing import Any, Protocol

import msgpack
import numpy as np

from rei.mission.executor import FAULT_EVENTS, MissionEventKind


class Pose2DLike(Protocol):
    """A planar pose (``rei.geometry.Pose2D`` fits)."""

    @property
    def x(self) -> float: ...

    @property
    def y(self) -> float: ...

    @property
    def yaw(self) -> float: ...


class RobotStateLike(Protocol):
    """The robot part of a snapshot: true pose ``(x, y, z, yaw)``, twist ``(vx, vy, wz)``, belief, laser."""

    @property
    def name(self) -> str: ...

    @property
    def pose(self) -> Sequence[float]: ...

    @property
    def twist(self) -> Sequence[float]: ...

    @property
    def odom(self) -> Pose2DLike | Sequence[float]: ...

    @property
    def laser_min(self) -> float: ...

    @property
    def laser_ranges(self) -> np.ndarray | Sequence[float] | None: ...

    @property
    def laser_clearance(self) -> float: ...


class ObjectStateLike(Protocol):
    """A moving object (human or dynamic body) of a snapshot."""

    @property
    def name(self) -> str: ...

    @property
    def category(self) -> str: ...

    @property
    def pose(self) -> Sequence[float]: ...

    @property
    def twist(self) -> Sequence[float]: ...


class SimStateLike(Protocol):
    """One simulator snapshot at simulation time ``t`` (seconds since the run started)."""

    @property
    def t(self) -> float: ...

    @property
    def robot(self) -> RobotStateLike: ...

    @property
    def objects(self) -> Sequence[ObjectStateLike]: ...

    @property
    def contacts(self) -> Sequence[tuple[str, str]]: ...


class LaserMode(enum.Enum):
    """How much of the laser goes on the wire: every beam, only the minimum (thesis min filter), nothing."""

    FULL = "full"
    MIN = "min"
    NONE = "none"


#: Categories of world.json's static obstacles (they never move; floors are not obstacles).
STATIC_CATEGORIES = frozenset({"WALL", "STATIC"})


def _floats(values: Iterable[Any], n: int, what: str) -> list[float]:
    out = [float(v) for v in values]
    if len(out) != n:
        raise ValueError(f"{what} needs {n} numbers, got {len(out)}")
    return out


def _odom(odom: Pose2DLike | Sequence[float]) -> list[float]:
    if hasattr(odom, "yaw"):
        pose = odom  # type: ignore[assignment]
        return [float(pose.x), float(pose.y), float(pose.yaw)]  # type: ignore[union-attr]
    return _floats(odom, 3, "odom")  # type: ignore[arg-type]


def encode_object(name: str, category: str, pose: Sequence[float], twist: Sequence[float]) -> dict[str, Any]:
    """One entry of ``objects``: ``type`` is the object's category (HUMAN, DYNAMIC, STATIC, WALL)."""
    return {
        "name": str(name),
        "type": str(category),
        "pose": _floats(pose, 4, f"pose of {name}"),
        "twist": _floats(twist, 3, f"twist of {name}"),
    }


def static_objects(world: Mapping[str, Any] | None) -> list[dict[str, Any]]:
    """world.json's walls and static furniture at rest, as ``objects`` entries. REI's collector leaves them out
    of its full frames (receivers have them from world.json); a producer may still re-list them
    (docs/protocol.md), as the monitor's tests of that path do."""
    if world is None:
        return []
    return [
        encode_object(o["name"], o["category"], o["pose"], (0.0, 0.0, 0.0))
        for o in world.get("objects", ())
        if o.get("category") in STATIC_CATEGORIES
    ]


def encode_state(
    state: SimStateLike,
    seq: int,
    *,
    laser: LaserMode = LaserMode.MIN,
    contacts: bool = True,
    odometry: bool = True,
    nav_state: str | enum.Enum | None = None,
    full_frame_objects: Sequence[Mapping[str, Any]] | None = None,
    observed: Collection[str] | None = None,
) -> dict[str, Any]:
    """The state message for ``state``; ``full_frame_objects`` (even empty) makes it a full frame; ``observed``:
    the names of the moving objects to include (None: all).

    Optional keys appear exactly when: ``full`` - a full frame; ``odom`` - ``odometry``; ``laser_min`` and
    ``laser_clearance`` - laser mode FULL or MIN; ``laser_ranges`` - mode FULL and the snapshot has ranges; ``nav_state`` - given;
    ``contacts`` - ``contacts`` (possibly an empty list).
    """
    if seq < 0:
        raise ValueError(f"seq must be >= 0, got {seq}")
    message: dict[str, Any] = {"seq": int(seq), "t": float(state.t)}
    objects = [encode_object(o.name, o.category, o.pose, o.twist) for o in state.objects
               if observed is None or o.name in observed]
    if full_frame_objects is not None:
        message["full"] = True
        objects.extend(dict(o) for o in full_frame_objects)
    message["objects"] = objects
    robot = state.robot
    wire_robot: dict[str, Any] = {
        "name": str(robot.name),
        "pose": _floats(robot.pose, 4, "robot pose"),
        "twist": _floats(robot.twist, 3, "robot twist"),
    }
    if odometry:
        wire_robot["odom"] = _odom(robot.odom)
    if laser is not LaserMode.NONE:
        wire_robot["laser_min"] = float(robot.laser_min)
        wire_robot["laser_clearance"] = float(robot.laser_clearance)
        if laser is LaserMode.FULL and robot.laser_ranges is not None:
            wire_robot["laser_ranges"] = np.asarray(robot.laser_ranges, dtype=np.float64).tolist()
    if nav_state is not None:
        wire_robot["nav_state"] = nav_state.value if isinstance(nav_state, enum.Enum) else str(nav_state)
    message["robot"] = wire_robot
    if contacts:
        message["contacts"] = [[str(a), str(b)] for a, b in state.contacts]
    return message


def encode_mission_event(
    seq: int,
    t: float,
    event: MissionEventKind | str,
    task_index: int = -1,
    goal: Pose2DLike | Sequence[float] | None = None,
    reason: str | None = None,
) -> dict[str, Any]:
    """A mission message. BEGIN/END concern no task: ``task_index`` -1 and ``goal`` nil.

    Task events need a ``task_index`` >= 0 and a goal ``[x, y, yaw]``; TASK_FAIL needs a ``reason``. A fault's
    window edge (``FAULT_LASER_BLACKOUT_BEGIN``, rei.mission.executor.FAULT_EVENTS) concerns no task either; its
    ``reason`` says which fault.
    """
    if isinstance(event, str) and event in FAULT_EVENTS:
        if task_index != -1 or goal is not None:
            raise ValueError(f"{event} concerns no task: task_index must be -1 and goal None")
        if not math.isfinite(float(t)):
            raise ValueError(f"mission event time must be finite, got {t}")
        fault: dict[str, Any] = {"seq": int(seq), "t": float(t), "event": event, "task_index": -1, "goal": None}
        if reason:
            fault["reason"] = str(reason)
        return fault
    kind = MissionEventKind(event)
    per_task = kind in (MissionEventKind.TASK_START, MissionEventKind.TASK_SUCCESS, MissionEventKind.TASK_FAIL)
    if per_task and (task_index < 0 or goal is None):
        raise ValueError(f"{kind.value} needs a task_index >= 0 and a goal")
    if not per_task and (task_index != -1 or goal is not None):
        raise ValueError(f"{kind.value} concerns no task: task_index must be -1 and goal None")
    if kind is MissionEventKind.TASK_FAIL and not reason:
        raise ValueError("TASK_FAIL needs a reason")
    if not math.isfinite(float(t)):
        raise ValueError(f"mission event time must be finite, got {t}")
    message: dict[str, Any] = {
        "seq": int(seq),
        "t": float(t),
        "event": kind.value,
        "task_index": int(task_index),
        "goal": _odom(goal) if goal is not None else None,
    }
    if reason:
        message["reason"] = str(reason)
    return message


def pack(message: Mapping[str, Any]) -> bytes:
    """msgpack bytes of a message, exactly as autobahn's msgpack serializer packs a payload."""
    return msgpack.packb(message, use_bin_type=True)


def unpack(data: bytes) -> Any:
    """Inverse of :func:`pack` (arrays come back as lists, strings as str)."""
    return msgpack.unpackb(data, raw=False)
