# SPDX-License-Identifier: EPL-2.0
"""The robot's description and fixed frames that both ROS bridges give the stack, as robot_state_publisher would
(docs/ros.md): the URDF text for ``/robot_description``, the fixed joints for ``/tf_static`` and the frames the
odometry and the scans are in.

All come from the run's ``world.json`` in ``REI_CASE_DIR``. A robot read from a URDF or xacro description has its
expanded description there (``robot.description``, ``robot.urdf``): ``/tf_static`` is every fixed joint of it, the
odometry's child frame its root link (TurtleBot3's ``base_footprint``, where REI's robot pose is) and the scans'
frame its lidar link (world.json's ``lidarLink``, the catalogue entry's ``lidar link``). A box robot's description
is the URDF REI's simulator builds for it (``rei.sim.robot_model.render_urdf``), and its frames are ROS's defaults:
``base_link`` and its lidar ``base_scan`` at world.json's lidar pose, the one fixed frame on ``/tf_static``.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from rei.artifacts.errors import ArtifactError
from rei.artifacts.world import RobotSpec, read_world
from rei.geometry import quaternion_of_yaw
from rei.robots import DescriptionError, FixedJoint, fixed_joints
from rei.sut.client import SutConnectionError
from rei.sut.ros_conventions import Frames


@dataclass(frozen=True, slots=True)
class RobotDescription:
    """``urdf``: the URDF text; ``base``: the odometry's child frame (the robot's origin); ``laser``: the scans'
    frame; ``static``: the fixed frames for /tf_static, parents before children as the file lists them."""

    urdf: str
    base: str
    laser: str
    static: tuple[FixedJoint, ...]

    def frames(self, frames: Frames) -> Frames:
        """``frames`` with this robot's base and lidar frames."""
        return Frames(map=frames.map, odom=frames.odom, base=self.base, laser=self.laser)


def read_robot_description(case_dir: Path) -> RobotDescription:
    """The robot of ``case_dir/world.json``; SutConnectionError if it cannot be read."""
    try:
        robot = read_world(case_dir / "world.json").robot
        if robot.description is None:
            return _box(robot)
        urdf = robot.description.read_text(encoding="utf-8")
        root, joints = fixed_joints(urdf, robot.description)
    except (ArtifactError, OSError, ValueError, DescriptionError) as error:
        raise SutConnectionError(f"the robot's description: {error}") from None
    laser = robot.lidar_link
    if laser is None:  # a world.json from before lidarLink: the scans stayed on base_scan, placed at the lidar pose
        laser = Frames().laser
        if all(laser != j.child for j in joints):
            joints = (*joints, _lidar(robot, root, laser))
    return RobotDescription(urdf, root, laser, joints)


def _box(robot: RobotSpec) -> RobotDescription:
    from rei.sim.robot_model import render_urdf  # pybullet: imported only for a box robot

    frames = Frames()
    return RobotDescription(render_urdf(robot), frames.base, frames.laser, (_lidar(robot, frames.base, frames.laser),))


def _lidar(robot: RobotSpec, parent: str, child: str) -> FixedJoint:
    """The lidar's frame at world.json's lidar pose in the robot's frame."""
    lidar = robot.lidar
    return FixedJoint("lidar", parent, child, (lidar.x, lidar.y, lidar.mount_height), quaternion_of_yaw(lidar.yaw))


def case_robot_description(environ: Mapping[str, str] = os.environ) -> RobotDescription | None:
    """The run's robot (``REI_CASE_DIR``, set for every SUT REI starts and in ``--sut-attach``'s sut.env); None
    without it, when the bridge cannot know the robot."""
    folder = environ.get("REI_CASE_DIR")
    return read_robot_description(Path(folder)) if folder else None
