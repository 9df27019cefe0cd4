# SPDX-License-Identifier: EPL-2.0
"""Typed, validated readers for the files ``rei generate`` writes (see docs/artifacts.md)."""

from rei.artifacts.animation import (
    AnimatedObject,
    AnimationSpec,
    Behaviour,
    ControlPoint,
    PersonSpec,
    RouteStop,
    read_animation,
)
from rei.artifacts.case import Case, check_sdf_matches_world, read_case
from rei.artifacts.errors import ArtifactError
from rei.artifacts.mission import GoalSpec, MissionSpec, read_mission
from rei.artifacts.monitor import CatalogueEntry, MonitorSpec, read_monitor
from rei.artifacts.sdf import SdfModel, SdfWorld, read_sdf
from rei.artifacts.world import (
    Category,
    DriveSpec,
    FloorSpec,
    LidarSpec,
    MapSpec,
    ObjectSpec,
    RobotSpec,
    Shape,
    WorldSpec,
    read_world,
    read_world_map,
)

__all__ = [
    "AnimatedObject",
    "AnimationSpec",
    "ArtifactError",
    "Behaviour",
    "Case",
    "CatalogueEntry",
    "Category",
    "ControlPoint",
    "DriveSpec",
    "FloorSpec",
    "GoalSpec",
    "LidarSpec",
    "MapSpec",
    "MissionSpec",
    "MonitorSpec",
    "ObjectSpec",
    "PersonSpec",
    "RobotSpec",
    "RouteStop",
    "SdfModel",
    "SdfWorld",
    "Shape",
    "WorldSpec",
    "check_sdf_matches_world",
    "read_animation",
    "read_case",
    "read_mission",
    "read_monitor",
    "read_sdf",
    "read_world",
    "read_world_map",
]
