"""The plug-in interface every controller under test implements.

A controller sees only what a real robot would: its odometry, its laser scan and the static map it was given;
never the simulator's true state. The mission executor hands it one goal at a time and reads its status, the way
an action client talks to a navigation action server (thesis 4.3.2, 5.1.6.4).

User controllers register under the entry-point group ``rei.controllers`` (name -> factory taking a ``str``
argument, the text after ``name:`` on the command line).
"""

from __future__ import annotations

import enum
import math
from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np

from rei.artifacts.world import Category, WorldSpec, footprint_polygon
from rei.geometry import Pose2D, Twist2D


class NavStatus(enum.Enum):
    """State of the navigation action (thesis Fig. 22); names match the wire protocol's ``nav_state``."""

    IDLE = "IDLE"
    ACTIVE = "ACTIVE"
    SUCCEEDED = "SUCCEEDED"
    ABORTED = "ABORTED"
    CANCELLED = "CANCELLED"


@dataclass(frozen=True, slots=True)
class LaserScan:
    """One planar scan. Beam i points at ``angle_min + i * angle_increment`` in the lidar's frame (the robot's,
    unless the robot's description places its lidar elsewhere: ``StaticMap.lidar``).

    Ranges beyond ``range_max`` (nothing hit) are reported as ``inf``.
    """

    t: float
    angle_min: float
    angle_increment: float
    range_min: float
    range_max: float
    ranges: np.ndarray


@dataclass(frozen=True, slots=True)
class Observation:
    """What the robot knows at one control step."""

    t: float
    odom: Pose2D
    odom_twist: Twist2D
    scan: LaserScan | None


@dataclass(frozen=True, slots=True)
class NavGoal:
    """A navigation goal in the world frame, with the tolerance the mission accepts."""

    index: int
    pose: Pose2D
    tolerance: float


@dataclass(frozen=True, slots=True)
class StaticMap:
    """What a controller may know in advance: the static world (walls, furniture), as footprint boxes.

    Each obstacle is ``(x, y, yaw, size_x, size_y)`` of an oriented rectangle; cylinders come as their bounding
    square. ``bounds`` is ``(xmin, ymin, xmax, ymax)`` of the floors. Humans and other moving objects are not in it.
    """

    bounds: tuple[float, float, float, float]
    obstacles: tuple[tuple[float, float, float, float, float], ...]
    robot_size: tuple[float, float]
    #: Where the lidar sits on the robot, ``(x, y, yaw)`` in its frame: a scan's beams start there and its angle 0
    #: is that yaw (a robot read from a description; a box robot's lidar is at its centre, facing ahead).
    lidar: tuple[float, float, float] = (0.0, 0.0, 0.0)
    #: A robot read from its description: its outline on the floor in its own frame, a convex polygon
    #: counter-clockwise (a circle as the 64-gon around it); None for a box robot, whose footprint is
    #: ``robot_size`` centred on its origin.
    outline: tuple[tuple[float, float], ...] | None = None
    #: The robot's drive takes a sideways speed ``vy`` (``drive holonomic``).
    holonomic: bool = False
    #: Furniture on a polygon: per obstacle, its polygon in the world (counter-clockwise, convex or not), which
    #: the obstacle's rectangle (its bounding box) holds; None for a rectangle. Empty when no obstacle has one.
    #: REI's navigation and the /map raster take the polygon; the external SUT protocol sends the rectangles.
    polygons: tuple[tuple[tuple[float, float], ...] | None, ...] = ()

    @classmethod
    def of_world(cls, world: WorldSpec) -> StaticMap:
        """Walls and STATIC objects of ``world`` as footprint rectangles (and a POLYGON object's polygon), the
        floors' bounds and the robot's footprint: one definition for the simulation's map and the metrics'
        shortest path (SPL)."""
        statics = [o for o in world.objects if o.category in (Category.WALL, Category.STATIC)]
        obstacles = tuple((o.pose[0], o.pose[1], o.pose[3], o.size[0], o.size[1]) for o in statics)
        polygons = tuple(o.outline for o in statics) if any(o.outline for o in statics) else ()
        robot = world.robot
        lidar = robot.lidar
        outline = None if robot.footprint is None else footprint_polygon(robot.footprint)
        return cls(bounds=world.bounds, obstacles=obstacles, robot_size=(robot.size[0], robot.size[1]),
                   lidar=(lidar.x, lidar.y, lidar.yaw), outline=outline, holonomic=robot.drive.kind == "holonomic",
                   polygons=polygons)

    @property
    def robot_radii(self) -> tuple[float, float]:
        """The robot's circumscribed and inscribed radii about its origin (Nav2's footprint radii): its outline's
        farthest vertex and nearest edge (0 when the origin is outside it), or a box robot's half diagonal and
        half width."""
        if self.outline is None:
            sx, sy = self.robot_size
            return 0.5 * math.hypot(sx, sy), 0.5 * min(sx, sy)
        points = self.outline
        far = max(math.hypot(x, y) for x, y in points)
        near = math.inf
        for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=True):
            length = math.hypot(x1 - x0, y1 - y0)
            if length > 0:
                near = min(near, ((x1 - x0) * (0.0 - y0) - (y1 - y0) * (0.0 - x0)) / length)  # > 0: inside
        return far, max(near, 0.0)


class Controller(ABC):
    """A robot controller under test, stepped by the simulation at its control rate."""

    @abstractmethod
    def reset(self, static_map: StaticMap, start: Pose2D) -> None:
        """Called once before the mission starts."""

    @abstractmethod
    def set_goal(self, goal: NavGoal) -> None:
        """Start working on a new goal; the status becomes ACTIVE."""

    @abstractmethod
    def cancel(self) -> None:
        """Withdraw the current goal (the mission executor's timeout); the status becomes CANCELLED."""

    @abstractmethod
    def step(self, observation: Observation) -> Twist2D:
        """Return the velocity command for the next control period."""

    @property
    @abstractmethod
    def status(self) -> NavStatus:
        """Current state of the navigation action."""

    @property
    def status_text(self) -> str:
        """Why the controller is in its status (e.g. why it aborted); the mission executor copies it into the
        TASK_FAIL reason. Optional: the default says nothing."""
        return ""
