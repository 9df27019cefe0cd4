# SPDX-License-Identifier: EPL-2.0
"""Foxglove message builders: REI's world, state and signal data as `foxglove.*` JSON messages.

Why the Foxglove schemas: Foxglove Studio's 3D, Log and plot panels understand them without any plug-in, so a run
opens as a scene that can be scrubbed in time. The schema files (`schemas/*.json`) hold the published field
names (github.com/foxglove/schemas, `schemas/jsonschema`), trimmed to the fields REI writes; Studio selects the
renderer by schema name, the JSON schema documents the message for other tools.
"""

from __future__ import annotations

import base64
import math
from collections.abc import Mapping, Sequence
from importlib import resources
from typing import Any

import numpy as np

from rei.artifacts.world import FOOTPRINT_TYPES
from rei.geometry import quaternion_of_yaw

WORLD_FRAME = "world"
ROBOT_FRAME = "base_link"

#: foxglove.LogLevel values.
INFO, WARNING, ERROR = 2, 3, 4

SCHEMA_NAMES = ("SceneUpdate", "LaserScan", "Log", "FrameTransform", "Grid")
#: foxglove.NumericType of an occupancy value (-1 unknown, 0..100).
INT8 = 2


def schema_bytes(name: str) -> bytes:
    """The JSON schema of `foxglove.<name>` shipped with the package."""
    return resources.files("rei.report").joinpath("schemas", f"{name}.json").read_bytes()


def nanoseconds(t: float) -> int:
    """Simulation seconds as integer nanoseconds (MCAP log times); negative or invalid times become 0."""
    return max(0, round(t * 1e9)) if math.isfinite(t) else 0


def timestamp(t: float) -> dict[str, int]:
    ns = nanoseconds(t)
    return {"sec": ns // 1_000_000_000, "nsec": ns % 1_000_000_000}


def vector(x: float, y: float, z: float) -> dict[str, float]:
    return {"x": x, "y": y, "z": z}


def yaw_quaternion(yaw: float) -> dict[str, float]:
    return dict(zip("xyzw", quaternion_of_yaw(yaw), strict=True))


def pose(x: float, y: float, z: float, yaw: float = 0.0) -> dict[str, Any]:
    return {"position": vector(x, y, z), "orientation": yaw_quaternion(yaw)}


def colour(rgba: object, default: Sequence[float] = (0.6, 0.6, 0.6, 1.0), alpha: float | None = None
           ) -> dict[str, float]:
    values = list(rgba) if isinstance(rgba, list | tuple) and len(rgba) >= 3 else list(default)
    if len(values) < 4:
        values.append(1.0)
    r, g, b, a = (float(v) for v in values[:4])
    return {"r": r, "g": g, "b": b, "a": a if alpha is None else alpha}


def entity(t: float, entity_id: str, **primitives: list[dict[str, Any]]) -> dict[str, Any]:
    """A SceneEntity in the world frame that stays until replaced (lifetime 0)."""
    return {"timestamp": timestamp(t), "frame_id": WORLD_FRAME, "id": entity_id,
            "lifetime": {"sec": 0, "nsec": 0}, "frame_locked": False, "metadata": [], **primitives}


def body_entity(t: float, name: str, shape: str, size: Sequence[float], centre: Sequence[float],
                yaw: float, rgba: object, alpha: float | None = None) -> dict[str, Any]:
    """A box or cylinder body (world.json conventions: `size` = [x, y, z], `centre` = body centre)."""
    primitive = {"pose": pose(centre[0], centre[1], centre[2], yaw),
                 "size": vector(float(size[0]), float(size[1]), float(size[2])),
                 "color": colour(rgba, alpha=alpha)}
    if shape == "CYLINDER":
        primitive.update(bottom_scale=1.0, top_scale=1.0)
        return entity(t, name, cylinders=[primitive])
    return entity(t, name, cubes=[primitive])


def outline_entity(t: float, name: str, footprint: Mapping[str, Any], height: float, base: Sequence[float],
                   yaw: float, rgba: object) -> dict[str, Any]:
    """A robot drawn as its description's outline (world.json robot.footprint, in the robot's frame) standing
    ``height`` high on ``base`` (x, y, z of its origin), turned by ``yaw``: a circle as a cylinder about its centre,
    a polygon as the edges of its prism (bottom and top loops and the upright edges; SceneUpdate's lines, so the
    schema every run.mcap carries stays as it was)."""
    x, y, z = (float(v) for v in base[:3])
    if footprint["type"] == FOOTPRINT_TYPES[1]:
        c, s = math.cos(yaw), math.sin(yaw)
        fx, fy, d = footprint["x"], footprint["y"], 2 * footprint["radius"]
        return body_entity(t, name, "CYLINDER", (d, d, height), (x + c * fx - s * fy, y + s * fx + c * fy,
                                                                  z + height / 2), yaw, rgba)
    points = footprint["points"]
    loops = [{"type": 1, "pose": pose(x, y, z, yaw), "thickness": 0.01, "scale_invariant": False,
              "points": [vector(px, py, level) for px, py in points], "color": colour(rgba), "indices": []}
             for level in (0.0, height)]
    upright = [vector(px, py, level) for px, py in points for level in (0.0, height)]
    loops.append({"type": 2, "pose": pose(x, y, z, yaw), "thickness": 0.01, "scale_invariant": False,
                  "points": upright, "color": colour(rgba), "indices": []})
    return entity(t, name, lines=loops)


def line_entity(t: float, entity_id: str, points: Sequence[tuple[float, float]], rgba: Sequence[float],
                z: float = 0.02, thickness: float = 0.03) -> dict[str, Any]:
    line = {"type": 0, "pose": pose(0.0, 0.0, 0.0), "thickness": thickness, "scale_invariant": False,
            "points": [vector(x, y, z) for x, y in points], "color": colour(rgba), "indices": []}
    return entity(t, entity_id, lines=[line])


def text_entity(t: float, entity_id: str, text: str, x: float, y: float, z: float) -> dict[str, Any]:
    label = {"pose": pose(x, y, z), "billboard": True, "font_size": 14.0, "scale_invariant": True,
             "color": colour((0.1, 0.1, 0.1, 1.0)), "text": text}
    return entity(t, entity_id, texts=[label])


def scene_update(entities: list[dict[str, Any]]) -> dict[str, Any]:
    return {"deletions": [], "entities": entities}


def frame_transform(t: float, x: float, y: float, yaw: float) -> dict[str, Any]:
    return {"timestamp": timestamp(t), "parent_frame_id": WORLD_FRAME, "child_frame_id": ROBOT_FRAME,
            "translation": vector(x, y, 0.0), "rotation": yaw_quaternion(yaw)}


def laser_scan(t: float, ranges: Sequence[float], mount_height: float) -> dict[str, Any]:
    """A full 360-degree scan in the robot frame: beam i at `i * 2 pi / beams` (rei.sim.lidar).

    JSON has no infinity, so a beam that hit nothing is written as 0 (Foxglove then draws it at the sensor,
    inside the robot) instead of making the whole message invalid JSON.
    """
    beams = len(ranges)
    increment = 2 * math.pi / beams if beams else 0.0
    clean = [float(r) if isinstance(r, int | float) and math.isfinite(r) else 0.0 for r in ranges]
    return {"timestamp": timestamp(t), "frame_id": ROBOT_FRAME, "pose": pose(0.0, 0.0, mount_height),
            "start_angle": 0.0, "end_angle": (beams - 1) * increment, "ranges": clean, "intensities": []}


def occupancy_grid(t: float, cells: np.ndarray, resolution: float, x0: float, y0: float) -> dict[str, Any]:
    """An occupancy map as a foxglove.Grid in the world frame: ``cells`` (rows from the bottom, int8 values as
    ``map_server`` publishes them), cell (0, 0)'s corner at ``(x0, y0)``, for Studio's 3D panel to draw as a
    grid layer under the scene."""
    columns = cells.shape[1]
    return {"timestamp": timestamp(t), "frame_id": WORLD_FRAME, "pose": pose(x0, y0, 0.0),
            "column_count": int(columns), "cell_size": {"x": float(resolution), "y": float(resolution)},
            "row_stride": int(columns), "cell_stride": 1, "fields": [{"name": "occupancy", "offset": 0, "type": INT8}],
            "data": base64.b64encode(np.ascontiguousarray(cells, dtype=np.int8).tobytes()).decode("ascii")}


def log(t: float, level: int, name: str, message: str) -> dict[str, Any]:
    return {"timestamp": timestamp(t), "level": level, "message": message, "name": name, "file": "", "line": 0}
