# SPDX-License-Identifier: EPL-2.0
"""`OUT/run.mcap`: the run as a recording Foxglove Studio opens and plays back.

Why MCAP next to the HTML report: the report answers "what happened" at a glance; the MCAP lets a person scrub
through the run and watch the robot, the people and the laser at the moment a signal fired. Log times are
simulation time in nanoseconds since the run's start, so the timeline matches events.csv and the signals.

Topics (JSON encoding, `jsonschema` schemas named `foxglove.<Type>`):

| topic | schema | messages |
|---|---|---|
| `/world` | foxglove.SceneUpdate | 1: floors, walls, furniture, goals (static, never replaced) |
| `/map` | foxglove.Grid | 1, in a room from an occupancy map: the map's cells (int8, as `map_server` publishes them) |
| `/paths` | foxglove.SceneUpdate | 1: the whole true and believed paths as lines, to see where the run goes |
| `/bodies` | foxglove.SceneUpdate | 1 per state: the robot (a described robot's outline), its believed pose (ghost), humans, dynamic objects |
| `/tf` | foxglove.FrameTransform | 1 per state: `world` -> `base_link` (true pose) |
| `/laser` | foxglove.LaserScan | 1 per state that carries `laser_ranges` (`--laser full`) |
| `/signals` | foxglove.Log | 1 per monitor signal (with its utility when events.csv has it) |
| `/mission` | foxglove.Log | 1 per mission event |
"""

from __future__ import annotations

import heapq
import json
import math
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

from mcap.writer import Writer

from rei.report import foxglove as fg
from rei.report.decimate import decimate
from rei.report.map_svg import _outline
from rei.report.run_data import RunData, load_run
from rei.report.tracks import Tracks, collect_tracks

MCAP_NAME = "run.mcap"
PROFILE = ""  # not ROS: plain JSON messages
_BELIEF_RGBA = (0.9, 0.49, 0.13, 0.35)
_ROBOT_RGBA = (0.12, 0.23, 0.58, 1.0)


def write_mcap(out_dir: Path, case_dir: Path | None = None, *, data: RunData | None = None,
               tracks: Tracks | None = None) -> Path:
    """Write `OUT/run.mcap` for the run in `out_dir` (case files in `case_dir`, default OUT/case); ``data`` and
    ``tracks``: the run already read (rei.report.write_views reads it once for both views)."""
    data = data or load_run(Path(out_dir), case_dir)
    path = Path(out_dir) / MCAP_NAME
    with open(path, "wb") as f:
        _McapRun(data, Writer(f), tracks).write()
    return path


class _McapRun:
    """One MCAP file being written: schemas and channels registered on first use, messages in time order."""

    def __init__(self, data: RunData, writer: Writer, tracks: Tracks | None = None) -> None:
        self.data = data
        self.writer = writer
        self.tracks = tracks
        self.schemas: dict[str, int] = {}
        self.channels: dict[str, int] = {}
        self.sequence: dict[str, int] = {}
        self.bodies = {str(b.get("name")): b for b in (data.world or {}).get("objects") or ()}
        # a robot read from its description is drawn as its outline, a box robot as its box (as before)
        self.footprint = _outline(data.world)[1]
        # the same for every state: worked out once (per state they cost a quarter of the file's time)
        self.robot_size = _robot_size(data.world)
        self.mount_height = _mount_height(data.world)

    def write(self) -> None:
        self.writer.start(profile=PROFILE, library="rei-report")
        self._metadata()
        t0 = 0.0
        if self.data.world is not None:
            self.publish("/world", "SceneUpdate", t0, fg.scene_update(self._static_entities(t0)))
        occupancy = self.data.occupancy
        if occupancy is not None:
            self.publish("/map", "Grid", t0, fg.occupancy_grid(t0, occupancy.grid, occupancy.resolution,
                                                                occupancy.origin[0], occupancy.origin[1]))
        tracks = self.tracks or collect_tracks(self.data.states())
        if len(tracks.robot):
            paths = [fg.line_entity(t0, "true_path", decimate(tracks.robot.xy()), _ROBOT_RGBA)]
            if len(tracks.believed):
                paths.append(fg.line_entity(t0, "believed_path", decimate(tracks.believed.xy()),
                                            (0.9, 0.49, 0.13, 1.0), z=0.03, thickness=0.015))
            self.publish("/paths", "SceneUpdate", t0, fg.scene_update(paths))
        pending = list(self._log_messages())  # small: signals and mission events
        heapq.heapify(pending)
        for state in self.data.states():
            t = state.get("t")
            if not isinstance(t, int | float) or not math.isfinite(t):
                continue
            while pending and pending[0][0] <= t:
                self._publish_log(heapq.heappop(pending))
            self._state(float(t), state)
        while pending:
            self._publish_log(heapq.heappop(pending))
        self.writer.finish()

    def publish(self, topic: str, schema: str, t: float, message: Mapping[str, Any]) -> None:
        if schema not in self.schemas:
            self.schemas[schema] = self.writer.register_schema(
                name=f"foxglove.{schema}", encoding="jsonschema", data=fg.schema_bytes(schema))
        if topic not in self.channels:
            self.channels[topic] = self.writer.register_channel(
                topic=topic, message_encoding="json", schema_id=self.schemas[schema])
            self.sequence[topic] = 0
        ns = fg.nanoseconds(t)
        data = json.dumps(message, separators=(",", ":"), allow_nan=False).encode()
        self.writer.add_message(self.channels[topic], log_time=ns, data=data, publish_time=ns,
                                sequence=self.sequence[topic])
        self.sequence[topic] += 1

    def _metadata(self) -> None:
        facts = {"run_id": self.data.fact("run_id"), "status": self.data.fact("status"),
                 "testcase": (self.data.world or {}).get("testcase"), "mission": self.data.mission_name,
                 "sim_duration": self.data.fact("sim_duration", "sim_time"),
                 "total_utility": self.data.fact("total_utility")}
        self.writer.add_metadata("rei.run", {k: str(v) for k, v in facts.items() if v is not None})

    def _static_entities(self, t: float) -> list[dict[str, Any]]:
        entities = []
        for body in (self.data.world or {}).get("objects") or ():
            if body.get("category") not in ("FLOOR", "WALL", "STATIC"):
                continue
            try:
                x, y, z, yaw = (float(v) for v in body["pose"][:4])
                size = [float(v) for v in body["size"][:3]]
            except (KeyError, TypeError, ValueError):
                continue
            alpha = 0.6 if body["category"] == "WALL" else None
            footprint = body.get("footprint")
            if body.get("shape") == "POLYGON" and isinstance(footprint, dict) and len(footprint.get("points") or ()) >= 3:
                # furniture on a polygon: the edges of its prism, as a described robot's outline is drawn
                entities.append(fg.outline_entity(t, str(body.get("name")), footprint, size[2],
                                                  (x, y, z - size[2] / 2), yaw, body.get("colour")))
                continue
            entities.append(fg.body_entity(t, str(body.get("name")), str(body.get("shape")), size, (x, y, z), yaw,
                                           body.get("colour"), alpha))
        for goal in self.data.goals:
            if math.isfinite(goal.x) and math.isfinite(goal.y):
                d = max(2 * goal.tolerance, 0.1)
                entities.append(fg.body_entity(t, f"goal_{goal.index}", "CYLINDER", (d, d, 0.01),
                                               (goal.x, goal.y, 0.005), 0.0, (0.17, 0.63, 0.17, 0.4)))
                entities.append(fg.text_entity(t, f"goal_{goal.index}_label", f"goal {goal.index}",
                                               goal.x, goal.y, 0.3))
        return entities

    def _state(self, t: float, state: Mapping[str, Any]) -> None:
        entities = []
        robot = state.get("robot")
        if isinstance(robot, Mapping) and _reals(robot.get("pose"), 4):
            x, y, z, yaw = robot["pose"][:4]
            size = self.robot_size
            if self.footprint is None:
                entities.append(fg.body_entity(t, "robot", "BOX", size, (x, y, z + size[2] / 2), yaw, _ROBOT_RGBA))
            else:
                entities.append(fg.outline_entity(t, "robot", self.footprint, size[2], (x, y, z), yaw, _ROBOT_RGBA))
            if _reals(robot.get("odom"), 3):
                ox, oy, oyaw = robot["odom"][:3]
                if self.footprint is None:
                    entities.append(fg.body_entity(t, "robot_believed", "BOX", size, (ox, oy, size[2] / 2), oyaw,
                                                   _BELIEF_RGBA))
                else:
                    entities.append(fg.outline_entity(t, "robot_believed", self.footprint, size[2], (ox, oy, 0.0),
                                                      oyaw, _BELIEF_RGBA))
            self.publish("/tf", "FrameTransform", t, fg.frame_transform(t, x, y, yaw))
            ranges = robot.get("laser_ranges")
            if isinstance(ranges, list) and ranges:
                self.publish("/laser", "LaserScan", t, fg.laser_scan(t, ranges, self.mount_height))
        for body in state.get("objects") or ():
            if not isinstance(body, Mapping) or body.get("type") not in ("HUMAN", "DYNAMIC"):
                continue
            if not _reals(body.get("pose"), 4):
                continue
            name = str(body.get("name"))
            known = self.bodies.get(name) or {}
            shape = str(known.get("shape", "CYLINDER" if body.get("type") == "HUMAN" else "BOX"))
            size = known.get("size") or [0.5, 0.5, 1.7]
            x, y, z, yaw = body["pose"][:4]
            entities.append(fg.body_entity(t, name, shape, size, (x, y, z), yaw,
                                           known.get("colour", (0.88, 0.67, 0.41, 1.0))))
        self.publish("/bodies", "SceneUpdate", t, fg.scene_update(entities))

    def _log_messages(self) -> Iterator[tuple[float, int, str, dict[str, Any]]]:
        """(t, order, topic, Log message) of every signal and mission event; `order` keeps ties stable."""
        utilities = _utilities(self.data)
        order = 0
        for event in self.data.mission_events:
            t = float(event.get("t", 0.0))
            task = event.get("task_index")
            text = f"{event.get('event')}" + ("" if task in (None, -1) else f" task {task}")
            if event.get("reason"):
                text += f": {event['reason']}"
            level = fg.ERROR if event.get("event") == "TASK_FAIL" else fg.INFO
            yield t, order, "/mission", fg.log(t, level, "mission", text)
            order += 1
        for i, record in enumerate(self.data.signals):
            text = f"{record.signal} {record.subject} -> {record.object}"
            if math.isfinite(record.distance):
                text += f" (distance {record.distance:.3f} m)"
            if i < len(utilities):
                text += f"; utility {utilities[i]}"
            yield record.t, order, "/signals", fg.log(record.t, _level(record.signal), "monitor", text)
            order += 1

    def _publish_log(self, item: tuple[float, int, str, dict[str, Any]]) -> None:
        t, _order, topic, message = item
        self.publish(topic, "Log", t, message)


def _level(signal: str) -> int:
    if "TRANSIT_COLLISION" in signal or signal.endswith("TASK_FAIL") or "DATA_GAP" in signal:
        return fg.ERROR
    if "FAR_TRANSIT_CLOSE" in signal:
        return fg.WARNING
    return fg.INFO


def _utilities(data: RunData) -> list[str]:
    """`+u (total T)` per signal when events.csv lists exactly the recorded signals in order."""
    events = data.events or []
    if len(events) != len(data.signals) or any(e.signal != s.signal for e, s in zip(events, data.signals,
                                                                                     strict=True)):
        return []
    return [f"{e.utility:+g} (total {e.total:g})" for e in events]


def _reals(value: object, size: int) -> bool:
    return (isinstance(value, list | tuple) and len(value) >= size
            and all(isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)
                    for v in value[:size]))


def _robot_size(world: Mapping[str, Any] | None) -> tuple[float, float, float]:
    robot = (world or {}).get("robot") or {}
    size = robot.get("size")
    if _reals(size, 3):
        return float(size[0]), float(size[1]), float(size[2])
    return 0.3, 0.3, 0.15


def _mount_height(world: Mapping[str, Any] | None) -> float:
    lidar = ((world or {}).get("robot") or {}).get("lidar") or {}
    height = lidar.get("mountHeight", 0.17)
    return float(height) if isinstance(height, int | float) else 0.17
