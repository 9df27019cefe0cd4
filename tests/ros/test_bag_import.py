# SPDX-License-Identifier: EPL-2.0
"""`rei import`: recorded robot runs, in bags written by Debian's real rosbag (ROS 1) and by rosbags (ROS 2,
MCAP), judged by `rei evaluate` in the modelled room (docs/ros.md)."""

from __future__ import annotations

import csv
import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from rei.sut.ros1.environment import import_rospy

EXAMPLE = "examples/simple_navigation.rei"
SPEED, Y, X0 = 0.2, 1.5, 0.5  # the recorded robot drives along +x at the table's height, into table1
RATE = 50.0  # poses per second in the bags
#: The goals the recorded robot was sent: (id, sent at, target, result at (None: never), final status). Goal 0 is
#: reached; goal 1's success comes 1 m short (a false success); goal 2 gets no result before the recording ends.
#: A result for a goal sent before the recording began comes first and must be ignored.
GOALS = [("g0", 0.5, (1.1, Y), 3.0, "SUCCEEDED"), ("g1", 3.5, (1.7, Y + 1.0), 6.0, "SUCCEEDED"),
         ("g2", 7.0, (3.5, 0.5), None, None)]
STALE_RESULT_AT = 0.2


def _x(t: float) -> float:
    return X0 + SPEED * t


def write_ros1_bag(path: Path, *, duration: float = 12.0, pose: Callable[[float], tuple[float, float]] | None = None,
                   backwards_at: float | None = None, goals: bool = False) -> Path:
    """/odom (nav_msgs/Odometry) with Debian's rosbag, as a robot would record it; with ``goals`` also move_base's
    action goals and results (GOALS)."""
    import_rospy()
    import rosbag
    import rospy
    from nav_msgs.msg import Odometry

    pose = pose or (lambda t: (_x(t), Y))
    with rosbag.Bag(str(path), "w") as bag:
        if goals:
            _write_move_base(bag)
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


def _write_move_base(bag) -> None:
    """move_base's /move_base/goal and /move_base/result as actionlib publishes them."""
    import rospy
    from actionlib_msgs.msg import GoalStatus
    from move_base_msgs.msg import MoveBaseActionGoal, MoveBaseActionResult

    def at(t: float) -> rospy.Time:
        return rospy.Time(100) + rospy.Duration.from_sec(t)

    def result(goal_id: str, t: float, status: str) -> None:
        message = MoveBaseActionResult()
        message.header.stamp = at(t)
        message.status.goal_id.id, message.status.status = goal_id, getattr(GoalStatus, status)
        message.status.text = "Goal reached." if status == "SUCCEEDED" else ""
        bag.write("/move_base/result", message, at(t))

    result("before-the-recording", STALE_RESULT_AT, "ABORTED")
    for goal_id, sent, (x, y), done, status in GOALS:
        message = MoveBaseActionGoal()
        message.header.stamp = message.goal_id.stamp = at(sent)
        message.goal_id.id = goal_id
        message.goal.target_pose.header.frame_id = "map"
        message.goal.target_pose.pose.position.x, message.goal.target_pose.pose.position.y = x, y
        message.goal.target_pose.pose.orientation.w = 1.0
        bag.write("/move_base/goal", message, at(sent))
        if done is not None:
            result(goal_id, done, status)


def write_ros2_mcap(folder: Path, duration: float = 12.0, *, storage: str = "mcap", goals: bool = False) -> Path:
    """/pose (geometry_msgs/PoseStamped) in a ROS 2 bag (MCAP or sqlite3 storage), written by rosbags; with
    ``goals`` also nav2's /goal_pose and the NavigateToPose action's status topic (GOALS)."""
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    types = store.types

    def pose_stamped(ns: int, x: float, y: float) -> object:
        return types["geometry_msgs/msg/PoseStamped"](
            header=types["std_msgs/msg/Header"](stamp=time(ns), frame_id="map"),
            pose=types["geometry_msgs/msg/Pose"](
                position=types["geometry_msgs/msg/Point"](x=x, y=y, z=0.0),
                orientation=types["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)))

    def time(ns: int) -> object:
        return types["builtin_interfaces/msg/Time"](sec=ns // 10**9, nanosec=ns % 10**9)

    messages: list[tuple[int, str, str, object]] = []  # (recorded at, topic, type, message)
    for k in range(int(duration * RATE)):
        ns = 100 * 10**9 + round(k / RATE * 1e9)
        messages.append((ns, "/pose", "geometry_msgs/msg/PoseStamped", pose_stamped(ns, _x(k / RATE), Y)))
    if goals:
        messages.extend(_nav2_goals(types, pose_stamped, time))
    plugin = StoragePlugin.MCAP if storage == "mcap" else StoragePlugin.SQLITE3
    with Writer(folder, version=8, storage_plugin=plugin) as writer:
        connections = {}
        for ns, topic, kind, message in sorted(messages, key=lambda m: m[0]):
            if topic not in connections:
                connections[topic] = writer.add_connection(topic, kind, typestore=store)
            writer.write(connections[topic], ns, store.serialize_cdr(message, kind))
    return folder


def _nav2_goals(types, pose_stamped, time) -> list[tuple[int, str, str, object]]:
    """/goal_pose as RViz sends it, and bt_navigator's NavigateToPose status array each time a goal's state
    changes (every goal the server still keeps, as action servers publish it)."""
    kind = "action_msgs/msg/GoalStatusArray"
    codes = {"ACTIVE": 2, "SUCCEEDED": 4}
    uuids = {goal_id: bytes([n + 1] * 16) for n, (goal_id, *_) in enumerate(GOALS)} | {"stale": bytes(16)}
    known: dict[str, int] = {}
    out: list[tuple[int, str, str, object]] = []

    def ns(t: float) -> int:
        return 100 * 10**9 + round(t * 1e9)

    def status_array(t: float) -> None:
        out.append((ns(t), "/navigate_to_pose/_action/status", kind, types[kind](status_list=[
            types["action_msgs/msg/GoalStatus"](
                goal_info=types["action_msgs/msg/GoalInfo"](
                    goal_id=types["unique_identifier_msgs/msg/UUID"](
                        uuid=np.frombuffer(uuids[goal_id], dtype=np.uint8)),
                    stamp=time(ns(t))), status=code)
            for goal_id, code in known.items()])))

    known["stale"] = 6  # ABORTED, before the recording: not one of this run's goals
    status_array(STALE_RESULT_AT)
    events = []
    for goal_id, sent, (x, y), done, status in GOALS:
        out.append((ns(sent), "/goal_pose", "geometry_msgs/msg/PoseStamped", pose_stamped(ns(sent), x, y)))
        events.append((sent + 0.05, goal_id, "ACTIVE"))
        if done is not None:
            events.append((done, goal_id, status))
    for t, goal_id, state in sorted(events):
        known[goal_id] = codes[state]
        status_array(t)
    return out


def _expected_transitions(out: Path) -> dict[str, float]:
    """When the robot's front comes within `close` and `collision` of table1's near edge (world.json, monitor.json)."""
    world = json.loads((out / "case" / "world.json").read_text())
    table = next(o for o in world["objects"] if o["name"] == "table1")
    thresholds = json.loads((out / "case" / "monitor.json").read_text())["thresholds"]
    edge = table["pose"][0] - table["size"][0] / 2 - world["robot"]["size"][0] / 2
    return {signal: (edge - thresholds[name] - X0) / SPEED
            for signal, name in (("SIG_GEOM_FAR_TRANSIT_CLOSE", "close"),
                                 ("SIG_GEOM_CLOSE_TRANSIT_COLLISION", "collision"))}


def _judged(run_cli, repo_root: Path, bag: Path, out: Path, *options: str) -> dict[str, dict]:
    """Import and evaluate; the verdicts by requirement."""
    imported = run_cli("import", bag, "-o", out, "--case", repo_root / EXAMPLE, *options)
    assert imported.returncode == 0, imported.stdout + imported.stderr
    judged = run_cli("evaluate", out)
    assert judged.returncode == 1, judged.stdout + judged.stderr  # MISSION_SIMPLE fails: the table was hit
    verdicts = {v["requirement"]: v for v in json.loads((out / "summary.json").read_text())["verdicts"]}
    assert verdicts["MISSION_SIMPLE"]["status"] == "fail"
    assert verdicts["MISSION_SIMPLE"]["evidence"][0]["object"] == "table1"
    return verdicts


def _write(variant: str, tmp_path: Path, *, goals: bool = False) -> tuple[Path, list[str]]:
    """A bag of ``variant`` and the import's options for it."""
    if variant == "ros1-bag":
        return write_ros1_bag(tmp_path / "drive.bag", goals=goals), []
    storage = variant.removeprefix("ros2-")
    return write_ros2_mcap(tmp_path / "drive", storage=storage, goals=goals), ["--pose-topic", "/pose"]


@pytest.mark.parametrize("variant", ["ros1-bag", "ros2-mcap", "ros2-sqlite3"])
def test_a_recorded_drive_into_the_table_gives_close_and_collision_at_the_right_times(
    variant: str, run_cli, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    bag, options = _write(variant, tmp_path)
    verdicts = _judged(run_cli, repo_root, bag, out, *options)
    assert verdicts["MISSION_SEQUENCE"]["status"] == "not-applicable"  # no goals in the bag
    assert not (out / "streams" / "mission.msgpack").exists()
    events = list(csv.DictReader((out / "events.csv").open()))
    expected = _expected_transitions(out)
    seen = {row["signal"]: float(row["t"]) for row in events if row["object"] == "table1"}
    for signal, t in expected.items():
        # states are sampled at 20 Hz from 50 Hz poses: the first sample at or after the crossing
        assert t <= seen[signal] <= t + 1 / 20 + 1 / RATE + 1e-6, (signal, t, seen)


@pytest.mark.parametrize("variant", ["ros1-bag", "ros2-mcap"])
def test_goals_and_results_in_the_bag_become_the_mission_judged_on_the_recorded_pose(
    variant: str, run_cli, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    bag, options = _write(variant, tmp_path, goals=True)
    verdicts = _judged(run_cli, repo_root, bag, out, *options)
    info = json.loads((out / "mission_info.json").read_text())
    assert [(g["x"], g["y"]) for g in info["goals"]] == [target for _, _, target, _, _ in GOALS]
    tasks = json.loads((out / "summary.json").read_text())["tasks"]
    assert (tasks["goals"], tasks["started"], tasks["succeeded"]) == (3, 3, 1), tasks
    sequence = verdicts["MISSION_SEQUENCE"]
    assert sequence["status"] == "fail", sequence
    texts = [e["text"] for e in sequence["evidence"]]
    assert any(text.startswith("task 1: no correct feedback from the robot: TASK_FAIL at t=6.000 (false success")
               for text in texts), texts
    assert any(text.startswith("task 2: no correct feedback from the robot: TASK_FAIL at t=11.980 (no result")
               for text in texts), texts
    starts = [(row["t"], row["object"]) for row in csv.DictReader((out / "events.csv").open())
              if row["signal"] == "SIG_MISSION_TASK_START"]
    assert [float(t) for t, _ in starts] == [sent for _, sent, _, _, _ in GOALS], starts


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
