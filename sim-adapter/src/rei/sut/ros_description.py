# SPDX-License-Identifier: EPL-2.0
"""The robot's description and fixed frames that both ROS bridges give the stack, as robot_state_publisher would
(docs/ros.md): the URDF text for ``/robot_description`` and the lidar's place for ``/tf_static``.

Both come from the run's ``world.json`` in ``REI_CASE_DIR``: a robot read from a URDF or xacro description has its
expanded description there (``robot.description``, ``robot.urdf``); a box robot's is the URDF REI's simulator
builds for it (``rei.sim.robot_model.render_urdf``). The lidar sits at world.json's lidar pose in the robot's frame
(``base_link``, which is a description's root link), the frame the scans are stamped with.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from rei.artifacts.errors import ArtifactError
from rei.artifacts.world import read_world
from rei.sut.client import SutConnectionError


@dataclass(frozen=True, slots=True)
class RobotDescription:
    """``urdf``: the URDF text; ``lidar``: ``(x, y, z, yaw)`` of the lidar's frame in ``base_link``."""

    urdf: str
    lidar: tuple[float, float, float, float]


def read_robot_description(case_dir: Path) -> RobotDescription:
    """The robot of ``case_dir/world.json``; SutConnectionError if it cannot be read."""
    try:
        robot = read_world(case_dir / "world.json").robot
        if robot.description is not None:
            urdf = robot.description.read_text(encoding="utf-8")
        else:
            from rei.sim.robot_model import render_urdf  # pybullet: imported only for a box robot

            urdf = render_urdf(robot)
    except (ArtifactError, OSError, ValueError) as error:
        raise SutConnectionError(f"the robot's description: {error}") from None
    lidar = robot.lidar
    return RobotDescription(urdf, (lidar.x, lidar.y, lidar.mount_height, lidar.yaw))


def case_robot_description(environ: Mapping[str, str] = os.environ) -> RobotDescription | None:
    """The run's robot (``REI_CASE_DIR``, set for every SUT REI starts and in ``--sut-attach``'s sut.env); None
    without it, when the bridge cannot know the robot."""
    folder = environ.get("REI_CASE_DIR")
    return read_robot_description(Path(folder)) if folder else None
