# SPDX-License-Identifier: EPL-2.0
"""REI's values as ROS 1 messages (rei.sut.ros1.messages): times on the grid, frames, the rasterized map."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rei.geometry import Pose2D, Twist2D, quaternion_of_yaw
from rei.robots import FixedJoint
from rei.sut.api import LaserScan, NavGoal, StaticMap
from rei.sut.ros1.environment import import_rospy

import_rospy()  # Debian's ROS 1, installed by scripts/setup-ros1.sh (./run-tests runs it)
from rei.sut.ros1 import messages as m

FRAMES = m.Frames()


def test_simulation_time_is_an_exact_ros_time_after_the_offset() -> None:
    assert [m.stamp(k * 0.1).to_nsec() for k in (0, 1, 3, 10)] == [
        1000_000_000_000, 1000_100_000_000, 1000_300_000_000, 1001_000_000_000]
    assert m.clock(0.3).clock == m.stamp(0.3)


def test_odometry_and_tf_carry_the_pose_in_their_frames() -> None:
    odom = m.odometry(1.0, Pose2D(1.0, 2.0, math.pi / 2), Twist2D(0.2, -0.5), FRAMES)
    assert (odom.header.frame_id, odom.child_frame_id) == ("odom", "base_link")
    assert m.yaw_of(odom.pose.pose.orientation) == pytest.approx(math.pi / 2)
    assert (odom.twist.twist.linear.x, odom.twist.twist.angular.z) == (0.2, -0.5)
    tf = m.transforms(1.0, Pose2D(1.0, 2.0, 0.3), FRAMES, with_map=True)
    assert [(t.header.frame_id, t.child_frame_id) for t in tf.transforms] == [("map", "odom"), ("odom", "base_link")]
    assert len(m.transforms(1.0, Pose2D(0, 0), FRAMES, with_map=False).transforms) == 1


def test_tf_static_places_each_fixed_frame_in_its_parent() -> None:
    joints = (FixedJoint("lidar", "base_link", "base_scan", (0.05, -0.01, 0.18), quaternion_of_yaw(-2.5)),
              FixedJoint("imu_joint", "base_link", "imu_link", (0.0, 0.0, 0.068), (0.0, 0.0, 0.0, 1.0)))
    lidar, imu = m.static_transforms(joints).transforms
    assert (imu.header.frame_id, imu.child_frame_id, imu.transform.translation.z) == ("base_link", "imu_link", 0.068)
    assert (lidar.header.frame_id, lidar.child_frame_id, lidar.header.stamp) == ("base_link", "base_scan", m.stamp(0.0))
    position = lidar.transform.translation
    assert (position.x, position.y, position.z, m.yaw_of(lidar.transform.rotation)) == pytest.approx(
        (0.05, -0.01, 0.18, -2.5))


def test_cmd_vel_s_linear_y_is_the_sideways_speed_both_ways() -> None:
    from geometry_msgs.msg import Twist

    message = Twist()
    message.linear.x, message.linear.y, message.angular.z = 0.1, -0.2, 0.3
    assert m.command(message) == Twist2D(0.1, 0.3, -0.2)
    assert m.odometry(1.0, Pose2D(0.0, 0.0), Twist2D(0.1, 0.3, -0.2), FRAMES).twist.twist.linear.y == -0.2


def test_a_scan_keeps_its_beams_and_misses() -> None:
    ranges = np.array([0.5, math.inf, 3.4])
    scan = m.laser_scan(LaserScan(0.2, -1.0, 1.0, 0.12, 3.5, ranges), 0.1, FRAMES)
    assert scan.header.frame_id == "base_scan" and scan.header.stamp == m.stamp(0.2)
    assert (scan.angle_min, scan.angle_max, scan.scan_time) == (-1.0, 1.0, 0.1)
    assert scan.ranges[0] == pytest.approx(0.5) and math.isinf(scan.ranges[1])


def test_the_map_marks_exactly_the_cells_whose_centres_are_inside_a_box() -> None:
    boxes = ((1.0, 1.0, 0.0, 0.5, 0.3), (2.5, 1.5, 0.7, 1.0, 0.2), (0.0, 1.0, 0.0, 0.1, 2.0))  # the last a wall
    grid = m.occupancy_grid(StaticMap((0.0, 0.0, 3.0, 2.0), boxes, (0.3, 0.3)), FRAMES)
    info = grid.info
    assert (info.width, info.height, info.resolution) == (80, 60, 0.05)
    assert (info.origin.position.x, info.origin.position.y) == (-0.5, -0.5)
    cells = np.array(grid.data, dtype=np.int8).reshape(info.height, info.width)
    expected = np.zeros_like(cells)
    for row in range(info.height):
        for col in range(info.width):
            x, y = -0.5 + (col + 0.5) * 0.05, -0.5 + (row + 0.5) * 0.05
            for bx, by, yaw, sx, sy in boxes:
                u = math.cos(yaw) * (x - bx) + math.sin(yaw) * (y - by)
                v = -math.sin(yaw) * (x - bx) + math.cos(yaw) * (y - by)
                if abs(u) <= sx / 2 and abs(v) <= sy / 2:
                    expected[row, col] = 100
    assert (cells == expected).all() and 0 < (cells == 100).sum() < cells.size


def test_a_goal_is_a_move_base_goal_in_the_map_frame() -> None:
    goal = m.move_base_goal(2.0, NavGoal(1, Pose2D(4.5, 0.5, math.pi), 0.25), FRAMES)
    pose = goal.target_pose
    assert pose.header.frame_id == "map" and (pose.pose.position.x, pose.pose.position.y) == (4.5, 0.5)
    assert abs(m.yaw_of(pose.pose.orientation)) == pytest.approx(math.pi)


def test_odometry_keeps_world_coordinates_so_map_to_odom_is_the_identity() -> None:
    start = Pose2D(0.5, 0.5, 0.7)  # tick 0's odometry is hello's start pose, in map coordinates (docs/sut.md)
    pose = m.odometry(0.0, start, Twist2D(), FRAMES).pose.pose
    assert (pose.position.x, pose.position.y) == (0.5, 0.5) and m.yaw_of(pose.orientation) == pytest.approx(0.7)
    map_odom, odom_base = m.transforms(0.0, start, FRAMES, with_map=True).transforms
    assert (map_odom.header.frame_id, map_odom.child_frame_id) == ("map", "odom")
    move, turn = map_odom.transform.translation, map_odom.transform.rotation
    assert (move.x, move.y, move.z, turn.x, turn.y, turn.z, turn.w) == (0, 0, 0, 0, 0, 0, 1)
    assert (odom_base.transform.translation.x, odom_base.transform.translation.y) == (0.5, 0.5)
