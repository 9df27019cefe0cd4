# SPDX-License-Identifier: EPL-2.0
"""`rei import` of a recorded drive in a room from an occupancy map (issue 31): a ROS 1 bag written by Debian's
rosbag, judged by `rei evaluate` against the real map's walls (docs/ros.md): FAR->CLOSE and CLOSE->COLLISION with
the map wall the geometry predicts, at the times it predicts, within one state sample."""

from __future__ import annotations

import csv
import json
from pathlib import Path

from rei.maps import load_map, merge_rectangles, obstacle_mask
from rei.sut.ros1.environment import import_rospy

EXAMPLE = "examples/maps/two_rooms.rei"
MAP = "examples/maps/two_rooms.yaml"
#: The recorded robot drives along +x above the desk of the left room, into the room's right wall.
SPEED, Y, X0 = 0.2, 5.25, 2.9
RATE = 50.0  # poses per second in the bag
DURATION = 6.0


def _write_bag(path: Path) -> Path:
    import_rospy()
    import rosbag
    import rospy
    from nav_msgs.msg import Odometry

    with rosbag.Bag(str(path), "w") as bag:
        for k in range(int(DURATION * RATE)):
            t = k / RATE
            stamp = rospy.Time(100) + rospy.Duration.from_sec(t)
            message = Odometry()
            message.header.stamp, message.header.frame_id, message.child_frame_id = stamp, "odom", "base_link"
            message.pose.pose.position.x, message.pose.pose.position.y = X0 + SPEED * t, Y
            message.pose.pose.orientation.w = 1.0
            message.twist.twist.linear.x = SPEED
            bag.write("/odom", message, stamp)
    return path


def _gap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> float:
    """Distance between two axis-aligned rectangles (xmin, ymin, xmax, ymax); 0 when they touch or overlap."""
    dx, dy = max(b[0] - a[2], a[0] - b[2], 0.0), max(b[1] - a[3], a[1] - b[3], 0.0)
    return (dx * dx + dy * dy) ** 0.5


def _predicted(repo_root: Path, out: Path) -> dict[str, tuple[float, str]]:
    """Per transition: when the footprint first comes within the threshold of a map wall, and which wall (the
    map's obstacle rectangles, named as the generator names them: the bottom-left cell)."""
    occupancy = load_map(repo_root / MAP)
    res = occupancy.resolution
    walls = {f"W_map_{r.col}_{r.row}": (r.col * res, r.row * res, (r.col + r.cols) * res, (r.row + r.rows) * res)
             for r in merge_rectangles(obstacle_mask(occupancy))}
    world = json.loads((out / "case" / "world.json").read_text())
    assert {o["name"] for o in world["objects"] if o["category"] == "WALL"} == set(walls)
    sx, sy = world["robot"]["size"][:2]
    thresholds = json.loads((out / "case" / "monitor.json").read_text())["thresholds"]
    predicted = {}
    for signal, name in (("SIG_GEOM_FAR_TRANSIT_CLOSE", "close"), ("SIG_GEOM_CLOSE_TRANSIT_COLLISION", "collision")):
        for step in range(int(DURATION * 10_000)):
            t = step / 10_000
            x = X0 + SPEED * t
            robot = (x - sx / 2, Y - sy / 2, x + sx / 2, Y + sy / 2)
            gap, wall = min((_gap(robot, box), wall) for wall, box in walls.items())
            if gap <= thresholds[name]:
                predicted[signal] = (t, wall)
                break
    return predicted


def test_a_recorded_drive_into_a_map_wall_is_judged_against_the_real_map(run_cli, repo_root: Path,
                                                                          tmp_path: Path) -> None:
    out = tmp_path / "out"
    bag = _write_bag(tmp_path / "drive.bag")
    imported = run_cli("import", bag, "-o", out, "--case", repo_root / EXAMPLE)
    assert imported.returncode == 0, imported.stdout + imported.stderr
    assert (out / "case" / "map.yaml").is_file() and (out / "case" / "map.pgm").is_file()
    judged = run_cli("evaluate", out)
    assert judged.returncode == 1, judged.stdout + judged.stderr  # MISSION_SIMPLE fails: a wall was hit
    predicted = _predicted(repo_root, out)
    wall = predicted["SIG_GEOM_CLOSE_TRANSIT_COLLISION"][1]
    assert wall.startswith("W_map_") and predicted["SIG_GEOM_FAR_TRANSIT_CLOSE"][1] == wall
    verdicts = {v["requirement"]: v for v in json.loads((out / "summary.json").read_text())["verdicts"]}
    assert verdicts["MISSION_SIMPLE"]["status"] == "fail"
    assert verdicts["MISSION_SIMPLE"]["evidence"][0]["object"] == wall
    seen = {row["signal"]: float(row["t"]) for row in csv.DictReader((out / "events.csv").open())
            if row["object"] == wall}
    for signal, (t, _) in predicted.items():
        # states are sampled at 20 Hz from 50 Hz poses: the first sample at or after the crossing
        assert t <= seen[signal] <= t + 1 / 20 + 1 / RATE + 1e-6, (signal, t, seen)
