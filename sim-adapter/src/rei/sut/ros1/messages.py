# SPDX-License-Identifier: EPL-2.0
"""REI's values as ROS 1 messages (and back): clock, odometry, tf, static tf, laser scan, occupancy grid, move_base goal.

Call ``rei.sut.ros1.environment.import_rospy()`` before importing this module. Times are simulation seconds
plus ``TIME_OFFSET``: rospy takes time 0 for "no clock yet", so the run's t = 0 must be a later ROS time.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import rospy
from geometry_msgs.msg import Quaternion, TransformStamped, Twist
from move_base_msgs.msg import MoveBaseGoal
from nav_msgs.msg import OccupancyGrid, Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan as RosLaserScan
from std_msgs.msg import Header
from tf2_msgs.msg import TFMessage

from rei.geometry import Pose2D, Twist2D, quaternion_of_yaw, yaw_of_quaternion
from rei.maps import OccupancyMap
from rei.robots import FixedJoint
from rei.sut.api import LaserScan, NavGoal, StaticMap
from rei.sut.rasterize import MAP_RESOLUTION, map_grid
from rei.sut.ros_conventions import Frames, ros_nanoseconds


def stamp(t: float) -> rospy.Time:
    """The ROS time of simulation time ``t`` (to the nanosecond, so a 10 Hz clock stays on a timer's grid)."""
    return rospy.Time(nsecs=ros_nanoseconds(t))


def clock(t: float) -> Clock:
    return Clock(clock=stamp(t))


def quaternion(yaw: float) -> Quaternion:
    x, y, z, w = quaternion_of_yaw(yaw)
    return Quaternion(x=x, y=y, z=z, w=w)


def yaw_of(q: Quaternion) -> float:
    return yaw_of_quaternion(q.x, q.y, q.z, q.w)


def odometry(t: float, pose: Pose2D, twist: Twist2D, frames: Frames) -> Odometry:
    message = Odometry()
    message.header.stamp, message.header.frame_id, message.child_frame_id = stamp(t), frames.odom, frames.base
    message.pose.pose.position.x, message.pose.pose.position.y = pose.x, pose.y
    message.pose.pose.orientation = quaternion(pose.yaw)
    message.twist.twist.linear.x, message.twist.twist.angular.z = twist.v, twist.w
    message.twist.twist.linear.y = twist.vy  # a holonomic robot's sideways speed, else 0 (the default)
    return message


def transforms(t: float, odom: Pose2D, frames: Frames, *, with_map: bool) -> TFMessage:
    """odom -> base_link from the odometry; map -> odom as identity (the odometry starts at the start pose, in
    world coordinates) when the run offers a map."""
    def transform(parent: str, child: str, pose: Pose2D) -> TransformStamped:
        stamped = TransformStamped()
        stamped.header.stamp, stamped.header.frame_id, stamped.child_frame_id = stamp(t), parent, child
        stamped.transform.translation.x, stamped.transform.translation.y = pose.x, pose.y
        stamped.transform.rotation = quaternion(pose.yaw)
        return stamped

    edges = [transform(frames.odom, frames.base, odom)]
    if with_map:
        edges.insert(0, transform(frames.map, frames.odom, Pose2D(0.0, 0.0, 0.0)))
    return TFMessage(transforms=edges)


def static_transforms(joints: Sequence[FixedJoint]) -> TFMessage:
    """/tf_static: each fixed frame (rei.sut.ros_description: a description's fixed joints, a box robot's lidar) in
    its parent's, as robot_state_publisher publishes a URDF's fixed joints (stamped at t = 0: tf2 takes a static
    transform at every time)."""
    edges = []
    for joint in joints:
        stamped = TransformStamped()
        stamped.header.stamp, stamped.header.frame_id, stamped.child_frame_id = stamp(0.0), joint.parent, joint.child
        t = stamped.transform
        t.translation.x, t.translation.y, t.translation.z = joint.xyz
        t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w = joint.quaternion
        edges.append(stamped)
    return TFMessage(transforms=edges)


def laser_scan(scan: LaserScan, scan_time: float, frames: Frames) -> RosLaserScan:
    count = len(scan.ranges)
    return RosLaserScan(
        header=_header(scan.t, frames.laser), angle_min=scan.angle_min,
        angle_max=scan.angle_min + (count - 1) * scan.angle_increment, angle_increment=scan.angle_increment,
        time_increment=0.0, scan_time=scan_time, range_min=scan.range_min, range_max=scan.range_max,
        ranges=np.asarray(scan.ranges, dtype=np.float32).tolist(), intensities=[])


def occupancy_grid(static_map: StaticMap, frames: Frames, resolution: float = MAP_RESOLUTION,
                   occupancy: OccupancyMap | None = None) -> OccupancyGrid:
    """/map (rei.sut.rasterize.map_grid): a map room's own grid, else the static map's rectangles rasterized (100
    where a cell's centre is inside an obstacle)."""
    cells = map_grid(static_map, occupancy, resolution)
    grid = OccupancyGrid()
    grid.header = _header(0.0, frames.map)
    grid.info.map_load_time, grid.info.resolution = stamp(0.0), cells.resolution
    grid.info.width, grid.info.height = cells.width, cells.height
    grid.info.origin.position.x, grid.info.origin.position.y = cells.x0, cells.y0
    grid.info.origin.orientation.w = 1.0
    grid.data = cells.data.tolist()
    return grid


def move_base_goal(t: float, goal: NavGoal, frames: Frames) -> MoveBaseGoal:
    message = MoveBaseGoal()
    message.target_pose.header = _header(t, frames.map)
    message.target_pose.pose.position.x, message.target_pose.pose.position.y = goal.pose.x, goal.pose.y
    message.target_pose.pose.orientation = quaternion(goal.pose.yaw)
    return message


def command(message: Twist) -> Twist2D:
    """A /cmd_vel as REI's command: forward, yaw rate and sideways (linear.y, which a holonomic robot follows and a
    differential one ignores, as ROS's diff_drive_controller does); the planar robot ignores the rest."""
    return Twist2D(float(message.linear.x), float(message.angular.z), float(message.linear.y))


def _header(t: float, frame: str) -> Header:
    return Header(stamp=stamp(t), frame_id=frame)
