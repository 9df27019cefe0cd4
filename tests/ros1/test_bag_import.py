# SPDX-License-Identifier: EPL-2.0
"""`rei import`: recorded robot runs, in bags written by Debian's real rosbag (ROS 1) and by rosbags (ROS 2,
MCAP), judged by `rei evaluate` in the modelled room (docs/ros.md)."""

from __future__ import annotations

import csv
import json
from collections.abc import Callable
from pathlib import Path

import pytest

from rei.sut.ros1.environment import import_rospy

EXAMPLE = "examples/simple_navigation.rei"
SPEED, Y, X0 = 0.2, 1.5, 0.5  # the recorded robot drives along +x at the table's height, into table1
RATE = 50.0  # poses per second in the bags


def _x(t: float) -> float:
    return X0 + SPEED * t


def write_ros1_bag(path: Path, *, duration: float = 12.0, pose: Callable[[float], tuple[float, float]] | None = None,
                   backwards_at: float | None = None) -> Path:
    """/odom (nav_msgs/Odometry) with Debian's rosbag, as a robot would record it."""
    import_rospy()
    import rosbag
    import rospy
    from nav_msgs.msg import Odometry

    pose = pose or (lambda t: (_x(t), Y))
    with rosbag.Bag(str(path), "w") as bag:
        for k in range(int(duration * RATE)):
            t = k / RATE
            received = rospy.Time(100) + rospy.Duration.from_sec(t)  # the recorder's clock always goes on
            if backwards_at is not None and t >= backwards_at:
                t -= 0.5
            stamp = rospy.Time(100) + rospy.Duration.from_sec(t)
            message = Odometry()
            message.header.stamp, message.header.frame_id, message.child_frame_id = stamp, "odom", "base_link"
            message.pose.pose.position.x, message.pose.pose.position.y = pose(t)
            message.pose.pose.orientation.w = 1.0
            message.twist.twist.linear.x = SPEED
            bag.write("/odom", message, received)
    return path


def write_ros2_mcap(folder: Path, duration: float = 12.0) -> Path:
    """/pose (geometry_msgs/PoseStamped) in a ROS 2 bag with MCAP storage, written by rosbags."""
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    types = store.types
    kind = "geometry_msgs/msg/PoseStamped"
    with Writer(folder, version=8, storage_plugin=StoragePlugin.MCAP) as writer:
        connection = writer.add_connection("/pose", kind, typestore=store)
        for k in range(int(duration * RATE)):
            ns = 100 * 10**9 + round(k / RATE * 1e9)
            message = types[kind](
                header=types["std_msgs/msg/Header"](stamp=types["builtin_interfaces/msg/Time"](
                    sec=ns // 10**9, nanosec=ns % 10**9), frame_id="map"),
                pose=types["geometry_msgs/msg/Pose"](
                    position=types["geometry_msgs/msg/Point"](x=_x(k / RATE), y=Y, z=0.0),
                    orientation=types["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)))
            writer.write(connection, ns, store.serialize_cdr(message, kind))
    return folder


def _expected_transitions(out: Path) -> dict[str, float]:
    """When the robot's front comes within `close` and `collision` of table1's near edge (world.json, monitor.json)."""
    world = json.loads((out / "case" / "world.json").read_text())
    table = next(o for o in world["objects"] if o["name"] == "table1")
    thresholds = json.loads((out / "case" / "monitor.json").read_text())["thresholds"]
    edge = table["pose"][0] - table["size"][0] / 2 - world["robot"]["size"][0] / 2
    return {signal: (edge - thresholds[name] - X0) / SPEED
            for signal, name in (("SIG_GEOM_FAR_TRANSIT_CLOSE", "close"),
                                 ("SIG_GEOM_CLOSE_TRANSIT_COLLISION", "collision"))}


def _judged(run_cli, repo_root: Path, bag: Path, out: Path, *options: str) -> list[dict[str, str]]:
    imported = run_cli("import", bag, "-o", out, "--case", repo_root / EXAMPLE, *options)
    assert imported.returncode == 0, imported.stdout + imported.stderr
    judged = run_cli("evaluate", out)
    assert judged.returncode == 1, judged.stdout + judged.stderr  # MISSION_SIMPLE fails: the table was hit
    verdicts = {v["requirement"]: v for v in json.loads((out / "summary.json").read_text())["verdicts"]}
    assert verdicts["MISSION_SIMPLE"]["status"] == "fail"
    assert verdicts["MISSION_SIMPLE"]["evidence"][0]["object"] == "table1"
    assert verdicts["MISSION_SEQUENCE"]["status"] == "not-applicable"  # no goals in the bag
    return list(csv.DictReader((out / "events.csv").open()))


@pytest.mark.parametrize("variant", ["ros1-bag", "ros2-mcap"])
def test_a_recorded_drive_into_the_table_gives_close_and_collision_at_the_right_times(
    variant: str, run_cli, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    if variant == "ros1-bag":
        events = _judged(run_cli, repo_root, write_ros1_bag(tmp_path / "drive.bag"), out)
    else:
        events = _judged(run_cli, repo_root, write_ros2_mcap(tmp_path / "drive"), out, "--pose-topic", "/pose")
    expected = _expected_transitions(out)
    seen = {row["signal"]: float(row["t"]) for row in events if row["object"] == "table1"}
    for signal, t in expected.items():
        # states are sampled at 20 Hz from 50 Hz poses: the first sample at or after the crossing
        assert t <= seen[signal] <= t + 1 / 20 + 1 / RATE + 1e-6, (signal, t, seen)


@pytest.mark.parametrize("problem, message", [
    ("missing topic", "no topic /amcl for the pose (--pose-topic); the bag has: /odom (nav_msgs/msg/Odometry)"),
    ("wrong type", "topic /odom is nav_msgs/msg/Odometry; the scan must be one of sensor_msgs/msg/LaserScan"),
    ("backwards", "topic /odom: stamp 105.500000 s comes after 105.980000 s"),
    ("truncated", "not a readable bag (corrupt or truncated?)"),
    ("outside", "is outside the room of case"),
])
def test_a_bag_that_cannot_be_imported_is_named_with_topic_and_time_and_leaves_nothing(
    problem: str, message: str, run_cli, repo_root: Path, tmp_path: Path
) -> None:
    bag = tmp_path / "drive.bag"
    options: list[str] = []
    if problem == "backwards":
        write_ros1_bag(bag, duration=8.0, backwards_at=6.0)
    elif problem == "outside":
        write_ros1_bag(bag, duration=4.0, pose=lambda t: (_x(t) + 10.0 * (t > 2.0), Y))
    else:
        write_ros1_bag(bag, duration=4.0)
    if problem == "missing topic":
        options = ["--pose-topic", "/amcl"]
    elif problem == "wrong type":
        options = ["--scan-topic", "/odom"]
    elif problem == "truncated":
        data = bag.read_bytes()
        bag.write_bytes(data[: len(data) // 2])
    out = tmp_path / "out"
    result = run_cli("import", bag, "-o", out, "--case", repo_root / EXAMPLE, *options)
    assert result.returncode == 2, result.stdout
    assert message in result.stderr and str(bag) in result.stderr, result.stderr
    assert not (out / "streams").exists() and not (out / "sim.json").exists()
