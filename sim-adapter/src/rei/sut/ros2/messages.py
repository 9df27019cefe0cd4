# SPDX-License-Identifier: EPL-2.0
"""REI's values as ROS 2 messages on DDS (and back), mirroring ``rei.sut.ros1.messages``; ``TOPICS`` names each
topic's DDS name, type and QoS.

Times are simulation seconds plus ``rei.sut.ros_conventions.TIME_OFFSET_NS``, as for ROS 1: rclcpp's
``Clock::started()`` (and code waiting for a valid sim time, such as tf2 buffers and nav2's servers) takes a zero
ROS time for "no /clock yet", and one offset keeps both bridges' stamps identical.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from cyclonedds.core import Policy, Qos
from cyclonedds.idl import IdlStruct
from cyclonedds.util import duration

from rei.geometry import Pose2D, Twist2D, quaternion_of_yaw, yaw_of_quaternion
from rei.maps import OccupancyMap
from rei.robots import FixedJoint
from rei.sut.api import LaserScan, NavGoal, StaticMap
from rei.sut.rasterize import MAP_RESOLUTION, map_grid
from rei.sut.ros2 import types as t
from rei.sut.ros_conventions import Frames, ros_nanoseconds


def stamp(t_sim: float) -> t.Time:
    """The ROS time of simulation time ``t_sim`` (to the nanosecond, so a 10 Hz clock stays on a timer's grid)."""
    sec, nanosec = divmod(ros_nanoseconds(t_sim), 10**9)
    return t.Time(sec=sec, nanosec=nanosec)


def nanoseconds(time: t.Time) -> int:
    return time.sec * 10**9 + time.nanosec


def clock(t_sim: float) -> t.Clock:
    return t.Clock(clock=stamp(t_sim))


def quaternion(yaw: float) -> t.Quaternion:
    x, y, z, w = quaternion_of_yaw(yaw)
    return t.Quaternion(x=x, y=y, z=z, w=w)


def yaw_of(q: t.Quaternion) -> float:
    return yaw_of_quaternion(q.x, q.y, q.z, q.w)


def header(t_sim: float, frame: str) -> t.Header:
    return t.Header(stamp=stamp(t_sim), frame_id=frame)


def odometry(t_sim: float, pose: Pose2D, twist: Twist2D, frames: Frames) -> t.Odometry:
    return t.Odometry(
        header=header(t_sim, frames.odom), child_frame_id=frames.base,
        pose=t.PoseWithCovariance(pose=t.Pose(
            position=t.Point(x=float(pose.x), y=float(pose.y), z=0.0), orientation=quaternion(pose.yaw))),
        twist=t.TwistWithCovariance(twist=t.Twist(
            linear=t.Vector3(x=float(twist.v), y=float(twist.vy)), angular=t.Vector3(z=float(twist.w)))))


def transforms(t_sim: float, odom: Pose2D, frames: Frames, *, with_map: bool) -> t.TFMessage:
    """odom -> base_link from the odometry; map -> odom as identity (the odometry starts at the start pose, in
    world coordinates) when the run offers a map."""
    def transform(parent: str, child: str, pose: Pose2D) -> t.TransformStamped:
        return t.TransformStamped(
            header=header(t_sim, parent), child_frame_id=child,
            transform=t.Transform(translation=t.Vector3(x=float(pose.x), y=float(pose.y)),
                                  rotation=quaternion(pose.yaw)))

    edges = [transform(frames.odom, frames.base, odom)]
    if with_map:
        edges.insert(0, transform(frames.map, frames.odom, Pose2D(0.0, 0.0, 0.0)))
    return t.TFMessage(transforms=edges)


def static_transforms(joints: Sequence[FixedJoint]) -> t.TFMessage:
    """/tf_static: each fixed frame (rei.sut.ros_description: a description's fixed joints, a box robot's lidar) in
    its parent's, as robot_state_publisher publishes a URDF's fixed joints (stamped at t = 0: tf2 takes a static
    transform at every time)."""
    return t.TFMessage(transforms=[t.TransformStamped(
        header=header(0.0, j.parent), child_frame_id=j.child,
        transform=t.Transform(translation=t.Vector3(x=float(j.xyz[0]), y=float(j.xyz[1]), z=float(j.xyz[2])),
                              rotation=t.Quaternion(x=float(j.quaternion[0]), y=float(j.quaternion[1]),
                                                    z=float(j.quaternion[2]), w=float(j.quaternion[3]))))
        for j in joints])


def robot_description(urdf: str) -> t.String:
    return t.String(data=urdf)


def laser_scan(scan: LaserScan, scan_time: float, frames: Frames) -> t.LaserScan:
    count = len(scan.ranges)
    return t.LaserScan(
        header=header(scan.t, frames.laser), angle_min=float(scan.angle_min),
        angle_max=float(scan.angle_min + (count - 1) * scan.angle_increment),
        angle_increment=float(scan.angle_increment), time_increment=0.0, scan_time=float(scan_time),
        range_min=float(scan.range_min), range_max=float(scan.range_max),
        ranges=np.asarray(scan.ranges, dtype=np.float32).tolist(), intensities=[])


def occupancy_grid(static_map: StaticMap, frames: Frames, resolution: float = MAP_RESOLUTION,
                   occupancy: OccupancyMap | None = None) -> t.OccupancyGrid:
    """/map (``rei.sut.rasterize.map_grid``): a map room's own grid, else the static map's rectangles rasterized
    (100 where a cell's centre is inside an obstacle, else 0)."""
    cells = map_grid(static_map, occupancy, resolution)
    return t.OccupancyGrid(
        header=header(0.0, frames.map),
        info=t.MapMetaData(
            map_load_time=stamp(0.0), resolution=float(cells.resolution), width=cells.width, height=cells.height,
            origin=t.Pose(position=t.Point(x=float(cells.x0), y=float(cells.y0)))),
        data=cells.data.tolist())


def navigate_goal(t_sim: float, goal: NavGoal, frames: Frames) -> t.NavigateToPose_Goal:
    """A mission goal as nav2's NavigateToPose goal, in the map frame (the navigator's default tree)."""
    pose = goal.pose
    return t.NavigateToPose_Goal(pose=t.PoseStamped(
        header=header(t_sim, frames.map),
        pose=t.Pose(position=t.Point(x=float(pose.x), y=float(pose.y)), orientation=quaternion(pose.yaw))))


def twist(command: Twist2D) -> t.Twist:
    """REI's command as a /cmd_vel (forward speed, sideways speed and yaw rate)."""
    return t.Twist(linear=t.Vector3(x=float(command.v), y=float(command.vy)), angular=t.Vector3(z=float(command.w)))


def command(message: t.Twist) -> Twist2D:
    """A /cmd_vel as REI's command: forward, yaw rate and sideways (linear.y, which a holonomic robot follows and a
    differential one ignores, as ROS's diff_drive_controller does); the planar robot ignores the rest."""
    return Twist2D(float(message.linear.x), float(message.angular.z), float(message.linear.y))


def _qos(*, transient_local: bool = False, depth: int = 10) -> Qos:
    """rmw_qos_profile_default (reliable, volatile, keep-last 10) as rmw_cyclonedds maps it: Cyclone's default
    100 ms max_blocking_time, and XCDR1, the only data representation rmw_cyclonedds offers and accepts."""
    return Qos(
        Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
        Policy.Durability.TransientLocal if transient_local else Policy.Durability.Volatile,
        Policy.History.KeepLast(depth),
        Policy.DataRepresentation(use_cdrv0_representation=True))


@dataclass(frozen=True, slots=True)
class Topic:
    """A ROS 2 topic on DDS: ``dds_name`` is the ROS name with rmw's ``rt`` prefix (``/scan`` -> ``rt/scan``)."""

    ros_name: str
    type: type[IdlStruct]
    qos: Qos
    to_stack: bool  # True: the bridge publishes it; False: the stack does and the bridge subscribes

    @property
    def dds_name(self) -> str:
        return "rt" + self.ros_name


#: The bridge's topics. Every publisher is reliable: a reliable writer matches reliable and best-effort readers
#: alike (rclcpp's TimeSource reads /clock with ClockQoS, best-effort keep-last 1; nav2's costmaps read /scan
#: with SensorDataQoS, best-effort), whereas a best-effort writer would miss reliable readers. /map is
#: transient-local (depth 1), as nav2's map_server publishes it, so late subscribers get it (ROS 1's latching).
#: /robot_description and /tf_static are transient-local keep-last 1 too, as robot_state_publisher and tf2's
#: StaticTransformBroadcaster publish them: written once, before the stack starts, and kept for late readers.
#: /cmd_vel is read reliable (the default, as nav2's controller_server and teleop publish it); a stack publishing
#: it best-effort would not match.
TOPICS: dict[str, Topic] = {
    "clock": Topic("/clock", t.Clock, _qos(), True),
    "odom": Topic("/odom", t.Odometry, _qos(), True),
    "tf": Topic("/tf", t.TFMessage, _qos(depth=100), True),
    "scan": Topic("/scan", t.LaserScan, _qos(), True),
    "map": Topic("/map", t.OccupancyGrid, _qos(transient_local=True, depth=1), True),
    "robot_description": Topic("/robot_description", t.String, _qos(transient_local=True, depth=1), True),
    "tf_static": Topic("/tf_static", t.TFMessage, _qos(transient_local=True, depth=1), True),
    "cmd_vel": Topic("/cmd_vel", t.Twist, _qos(), False),
}
