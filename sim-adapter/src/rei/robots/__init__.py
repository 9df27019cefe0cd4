# SPDX-License-Identifier: EPL-2.0
"""Robot descriptions (URDF and xacro) read into what REI uses of them: footprint, lidar pose, drive.

A bottom layer, as rei.maps: it imports no other rei package ([robots](../../../../docs/robots.md)).
"""

from rei.robots.description import (
    Circle,
    DescriptionError,
    Drive,
    FixedJoint,
    LidarPose,
    Part,
    Polygon,
    RobotDescription,
    fixed_joints,
    load_description,
)

__all__ = ["Circle", "DescriptionError", "Drive", "FixedJoint", "LidarPose", "Part", "Polygon", "RobotDescription",
           "fixed_joints", "load_description"]
