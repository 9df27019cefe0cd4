# SPDX-License-Identifier: EPL-2.0
"""run.mcap read back with the mcap package's own reader: channels, schemas, message counts, times, content."""

from __future__ import annotations

import json
import math
from collections import Counter
from pathlib import Path
from typing import Any

import pytest
from mcap.reader import make_reader

from rei.geometry import yaw_of_quaternion
from rei.report import write_mcap
from rei.report.foxglove import SCHEMA_NAMES, schema_bytes
from rei.wamp.recording import RecordingWriter

from .runs import SIGNALS, make_run, state


def strict_json(data: bytes) -> Any:
    """Parse as JSON the way a browser does: Infinity and NaN are errors (Python would accept them)."""
    def reject(token: str) -> None:
        raise ValueError(f"not JSON: {token}")
    return json.loads(data, parse_constant=reject)


def read(path: Path) -> tuple[Any, list[tuple[str, str, int, Any]]]:
    with open(path, "rb") as f:
        reader = make_reader(f)
        summary = reader.get_summary()
        messages = [(channel.topic, schema.name, message.log_time, strict_json(message.data))
                    for schema, channel, message in reader.iter_messages(log_time_order=False)]
    return summary, messages


@pytest.fixture(scope="module")
def recording(tmp_path_factory: pytest.TempPathFactory) -> tuple[Any, list[tuple[str, str, int, Any]]]:
    out = make_run(tmp_path_factory.mktemp("mcap") / "out", laser=True)
    return read(write_mcap(out))


def test_channels_use_json_and_the_foxglove_schemas(recording: tuple[Any, list[Any]]) -> None:
    summary, _ = recording
    channels = {c.topic: c for c in summary.channels.values()}
    schemas = {topic: summary.schemas[c.schema_id] for topic, c in channels.items()}
    assert {topic: s.name for topic, s in schemas.items()} == {
        "/world": "foxglove.SceneUpdate", "/paths": "foxglove.SceneUpdate", "/bodies": "foxglove.SceneUpdate",
        "/tf": "foxglove.FrameTransform", "/laser": "foxglove.LaserScan", "/signals": "foxglove.Log",
        "/mission": "foxglove.Log"}
    assert {c.message_encoding for c in channels.values()} == {"json"}
    assert {s.encoding for s in schemas.values()} == {"jsonschema"}
    assert json.loads(schemas["/laser"].data)["title"] == "foxglove.LaserScan"


def test_message_counts(recording: tuple[Any, list[Any]]) -> None:
    summary, messages = recording
    counts = Counter(topic for topic, *_ in messages)
    assert counts == {"/world": 1, "/paths": 1, "/bodies": 81, "/tf": 81, "/laser": 81,
                      "/signals": len(SIGNALS), "/mission": 2}
    by_id = {c.id: c.topic for c in summary.channels.values()}
    assert {by_id[i]: n for i, n in summary.statistics.channel_message_counts.items()} == counts


def test_log_times_are_simulation_time_in_nanoseconds_in_order(recording: tuple[Any, list[Any]]) -> None:
    _, messages = recording
    times = [t for _, _, t, _ in messages]
    assert times == sorted(times)
    assert [t for topic, _, t, _ in messages if topic == "/tf"][:3] == [0, 50_000_000, 100_000_000]
    signals = [(t, m) for topic, _, t, m in messages if topic == "/signals"]
    assert [t for t, _ in signals] == [round(s["t"] * 1e9) for s in SIGNALS]
    collision = signals[2][1]
    assert collision["timestamp"] == {"sec": 3, "nsec": 0} and collision["level"] == 4
    assert "SIG_GEOM_CLOSE_TRANSIT_COLLISION" in collision["message"] and "table1" in collision["message"]
    assert "utility -10 (total 8)" in collision["message"]


def test_scene_content(recording: tuple[Any, list[Any]]) -> None:
    _, messages = recording
    world = next(m for topic, _, _, m in messages if topic == "/world")
    ids = {e["id"] for e in world["entities"]}
    assert {"table1", "W_0_0_left", "F_0_0", "goal_0", "goal_1"} <= ids and "h1" not in ids
    bodies = [m for topic, _, _, m in messages if topic == "/bodies"]
    last = {e["id"]: e for e in bodies[-1]["entities"]}
    assert set(last) == {"robot", "robot_believed", "h1"}
    robot = last["robot"]["cubes"][0]
    assert robot["pose"]["position"]["x"] == pytest.approx(0.9)  # t = 4 s
    assert robot["pose"]["position"]["z"] == pytest.approx(0.141 / 2)  # standing on the floor
    assert last["h1"]["cylinders"][0]["size"] == {"x": 0.5, "y": 0.5, "z": 1.7}  # from world.json


def test_laser_scan_has_no_infinity(recording: tuple[Any, list[Any]]) -> None:
    _, messages = recording
    scan = next(m for topic, _, _, m in messages if topic == "/laser")
    assert len(scan["ranges"]) == 360 and scan["frame_id"] == "base_link"
    assert scan["ranges"][0] == 0.0 and scan["ranges"][1] == 1.5  # a miss (inf) is 0, a hit stays
    assert scan["end_angle"] == pytest.approx(359 * 2 * 3.141592653589793 / 360)


def test_without_laser_signals_or_case_the_file_still_opens(tmp_path: Path) -> None:
    out = make_run(tmp_path / "out", signals=False, events=False, summary=False, case=False)
    summary, messages = read(write_mcap(out))
    assert {c.topic for c in summary.channels.values()} == {"/paths", "/bodies", "/tf", "/mission"}
    assert len(messages) == 1 + 81 + 81 + 2


def test_schema_files_are_json_named_like_foxglove() -> None:
    for name in SCHEMA_NAMES:
        schema = json.loads(schema_bytes(name))
        assert schema["title"] == f"foxglove.{name}" and schema["type"] == "object"
        assert "timestamp" in schema["properties"] or name == "SceneUpdate"



def _placed(x: float, y: float, yaw: float, px: float, py: float) -> tuple[float, float]:
    """A point of the robot's frame in the world, the robot at (x, y) turned by yaw."""
    c, s = math.cos(yaw), math.sin(yaw)
    return x + c * px - s * py, y + s * px + c * py


@pytest.mark.parametrize("footprint", [
    {"type": "polygon", "points": [[-0.1, -0.08], [0.04, -0.09], [0.07, 0.0], [0.04, 0.09], [-0.1, 0.08]]},
    {"type": "circle", "x": 0.05, "y": 0.0, "radius": 0.17}], ids=["polygon", "circle"])
def test_a_described_robot_is_its_outline_turned_with_its_pose(tmp_path: Path, footprint: dict[str, Any]) -> None:
    """A robot read from its description (world.json robot.footprint) is drawn as its outline at every state,
    true and believed, while it turns at 0.5 rad/s: a polygon as its prism's edges (bottom and top loops in the
    robot's frame, placed at its pose: in the world, the outline's vertices turned and moved), a circle as a
    cylinder of its diameter about its centre (0.05 m ahead of the origin, turned with it). A box robot's file
    is unchanged (test_scene_content)."""
    out = make_run(tmp_path / "out")
    world_file = out / "case" / "world.json"
    world = json.loads(world_file.read_text())
    world["robot"]["footprint"] = footprint
    world_file.write_text(json.dumps(world))
    with RecordingWriter(out / "streams" / "state.msgpack") as writer:
        for i in range(81):
            message = state(i, i / 20)
            message["robot"]["pose"][3] = 0.5 * i / 20
            writer.write(message)
    _, messages = read(write_mcap(out))
    bodies = [m for topic, _, _, m in messages if topic == "/bodies"]
    assert len(bodies) == 81
    height = world["robot"]["size"][2]
    for k, update in enumerate(bodies):
        x, y, yaw = 0.5 + 0.1 * k / 20, 0.5, 0.5 * k / 20
        entities = {e["id"]: e for e in update["entities"]}
        robot, believed = entities["robot"], entities["robot_believed"]
        assert "cubes" not in robot and "cubes" not in believed
        if footprint["type"] == "circle":
            (cylinder,) = robot["cylinders"]
            where = cylinder["pose"]["position"]
            assert (where["x"], where["y"], where["z"]) == pytest.approx((*_placed(x, y, yaw, 0.05, 0.0), height / 2),
                                                                        abs=1e-9)
            assert yaw_of_quaternion(*(cylinder["pose"]["orientation"][a] for a in "xyzw")) == pytest.approx(yaw)
            size = cylinder["size"]
            assert (size["x"], size["y"], size["z"]) == pytest.approx((0.34, 0.34, height))
            assert believed["cylinders"][0]["size"]["x"] == pytest.approx(0.34)
            continue
        bottom, top, upright = robot["lines"]
        assert (bottom["type"], top["type"], upright["type"]) == (1, 1, 2)  # two loops and a list of edges
        place = bottom["pose"]["position"]
        turn = yaw_of_quaternion(*(bottom["pose"]["orientation"][a] for a in "xyzw"))
        drawn = [_placed(place["x"], place["y"], turn, p["x"], p["y"]) for p in bottom["points"]]
        expected = [_placed(x, y, yaw, px, py) for px, py in footprint["points"]]
        assert drawn == [pytest.approx(p, abs=1e-9) for p in expected]
        assert {p["z"] for p in bottom["points"]} == {0.0} and {p["z"] for p in top["points"]} == {height}
        assert [(p["x"], p["y"]) for p in top["points"]] == [(p["x"], p["y"]) for p in bottom["points"]]
        assert len(upright["points"]) == 2 * len(footprint["points"])
        # the believed pose: the odometry's (x, 0.5 + 0.01 t), heading 0 in these states
        believed_place = believed["lines"][0]["pose"]["position"]
        assert (believed_place["x"], believed_place["y"]) == pytest.approx((x, 0.5 + 0.01 * k / 20), abs=1e-9)
