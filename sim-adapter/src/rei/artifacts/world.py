# SPDX-License-Identifier: EPL-2.0
"""Reader for ``world.json`` (``rei-world/1``): the typed description of every body, floor and the robot.

``world.sdf`` is what the physics engine loads; ``world.json`` is what everything else reasons about (categories,
footprints, floors, the robot's drive and lidar), so it is read into frozen values once and passed around.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass
from pathlib import Path
from typing import TypeVar

from rei.artifacts._fields import Fields, load_json
from rei.artifacts.errors import ArtifactError
from rei.maps import MapError, OccupancyMap, load_map

WORLD_FORMAT = "rei-world/1"

E = TypeVar("E", bound=enum.StrEnum)


class Category(enum.StrEnum):
    """What an object is, which decides how the simulator treats it (fixed, animated, ignored for contacts)."""

    FLOOR = "FLOOR"
    WALL = "WALL"
    STATIC = "STATIC"
    DYNAMIC = "DYNAMIC"
    HUMAN = "HUMAN"
    ROBOT = "ROBOT"  # catalogue types only: the robot itself is world.json's "robot", never one of its objects

    @property
    def fixed(self) -> bool:
        """Fixed bodies have mass 0 in the simulator."""
        return self in (Category.FLOOR, Category.WALL, Category.STATIC)

    @property
    def moving(self) -> bool:
        return self in (Category.DYNAMIC, Category.HUMAN)


class Shape(enum.StrEnum):
    BOX = "BOX"
    CYLINDER = "CYLINDER"
    MESH = "MESH"
    POLYGON = "POLYGON"  # furniture on a polygon: ObjectSpec.footprint (docs/language.md#catalogues)


Vec3 = tuple[float, float, float]
Pose = tuple[float, float, float, float]
Colour = tuple[float, float, float, float]


@dataclass(frozen=True, slots=True)
class FloorSpec:
    """One floor tile and its neighbours (a floor or wall name, or None for an open side)."""

    name: str
    center: tuple[float, float]
    cell: tuple[int, int]
    top: str | None
    right: str | None
    bottom: str | None
    left: str | None


@dataclass(frozen=True, slots=True)
class ObjectSpec:
    """One body of the world; ``pose`` is its centre ``(x, y, z, yaw)``, ``size`` its full extent."""

    name: str
    category: Category
    type: str
    shape: Shape
    size: Vec3
    pose: Pose
    mass: float
    inertia: Vec3
    colour: Colour
    floor: str | None
    footprint: PolygonFootprint | None = None
    """A POLYGON object's outline about ``pose`` (its bounding box's centre), in its own frame, counter-clockwise,
    convex or not; None for every other shape (a box's footprint is its ``size`` rectangle, a cylinder's circle)."""

    @property
    def outline(self) -> tuple[tuple[float, float], ...] | None:
        """A POLYGON object's vertices placed and turned into the world (None for other shapes)."""
        if self.footprint is None:
            return None
        x, y, _, yaw = self.pose
        c, s = math.cos(yaw), math.sin(yaw)
        return tuple((x + c * u - s * v, y + s * u + c * v) for u, v in self.footprint.points)


@dataclass(frozen=True, slots=True)
class DriveSpec:
    """The drive's wheels and limits; ``kind`` one of :data:`DRIVE_KINDS`. A holonomic drive's sideways speed
    has the forward speed's limit; a differential drive's is 0 (it cannot move sideways)."""

    wheel_radius: float
    wheel_separation: float
    max_linear_velocity: float
    max_angular_velocity: float
    kind: str = "differential"

    @property
    def holonomic(self) -> bool:
        return self.kind == DRIVE_KINDS[1]

    @property
    def max_lateral_velocity(self) -> float:
        return self.max_linear_velocity if self.holonomic else 0.0


@dataclass(frozen=True, slots=True)
class LidarSpec:
    """The planar lidar; ``x``, ``y``, ``yaw`` its place on the robot (a description's lidar link, else the
    robot's origin) and ``mount_height`` its height above the floor."""

    beams: int
    range_min: float
    range_max: float
    rate: float
    mount_height: float
    x: float = 0.0
    y: float = 0.0
    yaw: float = 0.0


@dataclass(frozen=True, slots=True)
class CircleFootprint:
    """A round robot's outline on the floor, in the robot's frame (its centre need not be the robot's origin)."""

    x: float
    y: float
    radius: float


@dataclass(frozen=True, slots=True)
class PolygonFootprint:
    """An outline on the floor in its body's frame, counter-clockwise: a robot's (convex), or a POLYGON object's
    (a simple polygon, convex or not)."""

    points: tuple[tuple[float, float], ...]


Footprint = CircleFootprint | PolygonFootprint
DRIVE_KINDS = ("differential", "holonomic")
"""world.json's robot.drive.kind, the first when it is absent (contract/vocabulary.json drives)."""
FOOTPRINT_TYPES = ("polygon", "circle")  # world.json's robot.footprint.type (contract/vocabulary.json footprints)

CIRCLE_SIDES = 64


def footprint_polygon(footprint: Footprint) -> tuple[tuple[float, float], ...]:
    """The footprint as a convex polygon, counter-clockwise; a circle as a 64-gon whose sides touch it (never
    inside the true shape, as the description reader draws round shapes: docs/robots.md)."""
    if isinstance(footprint, PolygonFootprint):
        return footprint.points
    reach = footprint.radius / math.cos(math.pi / CIRCLE_SIDES)
    return tuple((footprint.x + reach * math.cos(2 * math.pi * (i + 0.5) / CIRCLE_SIDES),
                  footprint.y + reach * math.sin(2 * math.pi * (i + 0.5) / CIRCLE_SIDES)) for i in range(CIRCLE_SIDES))


@dataclass(frozen=True, slots=True)
class RobotSpec:
    """The robot is built by the simulator from these parameters; its ``pose`` is on the ground (z = 0).

    A robot read from a URDF or xacro description (docs/robots.md) also has its ``footprint`` (the collision shapes'
    outline on the floor, relative to ``pose``), its lidar's ``lidar_pose`` ``(x, y, z, yaw)`` in the robot's frame,
    the lidar's link ``lidar_link`` and the expanded ``description`` in the case folder; ``size`` is then the
    footprint's bounding box (and the lidar's height). A box robot has none of these: its footprint is the ``size`` rectangle centred on ``pose``."""

    name: str
    type: str
    shape: Shape
    size: Vec3
    mass: float
    pose: Pose
    floor: str | None
    drive: DriveSpec
    lidar: LidarSpec
    footprint: Footprint | None = None
    lidar_pose: tuple[float, float, float, float] | None = None
    description: Path | None = None
    #: The description's link the lidar is (the catalogue entry's ``lidar link``); None for a box robot, and in a
    #: world.json written before it was recorded.
    lidar_link: str | None = None

    @property
    def outline(self) -> Footprint:
        """The footprint, a box robot's as the rectangle of its ``size``."""
        if self.footprint is not None:
            return self.footprint
        hx, hy = self.size[0] / 2, self.size[1] / 2
        return PolygonFootprint(((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)))


@dataclass(frozen=True, slots=True)
class MapSpec:
    """A room made from a ROS occupancy map: the case folder's copy of the map (``yaml`` and ``image``, resolved
    against the folder) and the grid's geometry, ``origin`` the lower left corner of cell (0, 0) in the world."""

    yaml: Path
    image: Path
    resolution: float
    origin: tuple[float, float, float]
    width: int
    height: int
    unknown_free: bool

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)`` the image covers, m."""
        ox, oy, _ = self.origin
        return ox, oy, ox + self.width * self.resolution, oy + self.height * self.resolution

    def load(self) -> OccupancyMap:
        """The grid ``map_server`` would publish for this map (``rei.maps.load_map``), checked against world.json's
        description of it; raises :class:`~rei.artifacts.errors.ArtifactError`."""
        try:
            occupancy = load_map(self.yaml)
        except MapError as error:
            raise ArtifactError(error.path, f"{error.line}:{error.column}: {error.field}: {error.detail}") from None
        found = (occupancy.width, occupancy.height, occupancy.resolution, occupancy.origin)
        if found != (self.width, self.height, self.resolution, self.origin):
            raise ArtifactError(self.yaml, f"{occupancy.width} x {occupancy.height} cells of "
                                           f"{occupancy.resolution:g} m from {list(occupancy.origin)}, but world.json "
                                           f"describes {self.width} x {self.height} cells of {self.resolution:g} m "
                                           f"from {list(self.origin)}")
        return occupancy


@dataclass(frozen=True, slots=True)
class WorldSpec:
    path: Path
    testcase: str
    environment: str
    floor_size: float
    bounds: tuple[float, float, float, float]
    floors: tuple[FloorSpec, ...]
    objects: tuple[ObjectSpec, ...]
    robot: RobotSpec
    map: MapSpec | None = None  # a room from an occupancy map; None for every other room

    def object(self, name: str) -> ObjectSpec:
        for obj in self.objects:
            if obj.name == name:
                return obj
        raise KeyError(name)


def read_world(path: Path | str) -> WorldSpec:
    """Read and validate ``world.json``; raises :class:`~rei.artifacts.errors.ArtifactError`."""
    path = Path(path)
    root = load_json(path, WORLD_FORMAT)
    bounds = root.vector("bounds", 4)
    if bounds[2] <= bounds[0] or bounds[3] <= bounds[1]:
        raise root.error(f"must be [xmin, ymin, xmax, ymax] with max > min, got {list(bounds)}", "bounds")
    floors = tuple(_floor(f) for f in root.items("floors"))
    objects = tuple(_object(o) for o in root.items("objects"))
    _unique(root, "objects", [o.name for o in objects])
    _unique(root, "floors", [f.name for f in floors])
    robot = _robot(root.child("robot"), path.parent)
    if robot.name in {o.name for o in objects}:
        raise root.error(f"robot name {robot.name!r} is also an object name", "robot.name")
    occupancy = _map(root.child("map"), path.parent) if root.has("map") else None
    if occupancy is not None and not all(math.isclose(b, e, abs_tol=1e-6)
                                         for b, e in zip(bounds, occupancy.extent, strict=True)):
        raise root.error(f"must be the map's extent {list(occupancy.extent)} in a room from an occupancy map, "
                         f"got {list(bounds)}", "bounds")
    return WorldSpec(
        path=path,
        testcase=root.text("testcase"),
        environment=root.text("environment"),
        floor_size=root.number("floorSize", positive=True),
        bounds=(bounds[0], bounds[1], bounds[2], bounds[3]),
        floors=floors,
        objects=objects,
        robot=robot,
        map=occupancy,
    )


def read_world_map(path: Path | str) -> MapSpec | None:
    """Only the ``map`` member of ``world.json`` (None when the room is not from an occupancy map), for the pages
    that draw the map and need nothing else of the world; raises :class:`~rei.artifacts.errors.ArtifactError`."""
    path = Path(path)
    root = load_json(path, WORLD_FORMAT)
    return _map(root.child("map"), path.parent) if root.has("map") else None


def _map(m: Fields, folder: Path) -> MapSpec:
    """The ``map`` member; its files must be in the case folder (a case folder is self-contained)."""
    def file(key: str) -> Path:
        name = m.text(key)
        resolved = (folder / name).resolve()
        if Path(name).is_absolute() or not resolved.is_relative_to(folder.resolve()):
            raise m.error(f"expected a file of the case folder, got {name!r}", key)
        if not resolved.is_file():
            raise m.error(f"{folder / name} is missing", key)
        return folder / name

    origin = m.vector("origin", 3)
    if origin[2] != 0.0:
        raise m.error(f"the map's yaw must be 0 (REI rooms are axis-aligned), got {origin[2]}", "origin")
    width, height = m.integer("width"), m.integer("height")
    for key, count in (("width", width), ("height", height)):
        if count <= 0:
            raise m.error(f"must be > 0, got {count}", key)
    return MapSpec(yaml=file("yaml"), image=file("image"), resolution=m.number("resolution", positive=True),
                   origin=(origin[0], origin[1], origin[2]), width=width, height=height,
                   unknown_free=m.flag("unknownFree"))


def _unique(root: Fields, key: str, names: list[str]) -> None:
    seen: set[str] = set()
    for name in names:
        if name in seen:
            raise root.error(f"name {name!r} is used twice", key)
        seen.add(name)


def _enum(fields: Fields, key: str, kind: type[E]) -> E:
    value = fields.text(key)
    try:
        return kind(value)
    except ValueError:
        allowed = ", ".join(m.value for m in kind)
        raise fields.error(f"unknown value {value!r}, expected one of {allowed}", key) from None


def _floor(f: Fields) -> FloorSpec:
    center = f.vector("center", 2)
    cell = f.value.get("cell") if isinstance(f.value, dict) else None
    if not (isinstance(cell, list) and len(cell) == 2 and all(type(c) is int for c in cell)):
        raise f.error("expected a list of 2 integers", "cell")
    return FloorSpec(
        name=f.text("name"),
        center=(center[0], center[1]),
        cell=(cell[0], cell[1]),
        top=f.optional_text("top"),
        right=f.optional_text("right"),
        bottom=f.optional_text("bottom"),
        left=f.optional_text("left"),
    )


def _object(o: Fields) -> ObjectSpec:
    category = _enum(o, "category", Category)
    if category is Category.ROBOT:
        raise o.error("the robot belongs in \"robot\", not in objects", "category")
    mass = o.number("mass", non_negative=True)
    if category.fixed and mass != 0.0:
        raise o.error(f"a {category.value} object must have mass 0, got {mass}", "mass")
    if not category.fixed and mass <= 0.0:
        raise o.error(f"a {category.value} object must have mass > 0, got {mass}", "mass")
    size = o.vector("size", 3)
    if min(size) <= 0:
        raise o.error(f"all sizes must be > 0, got {list(size)}", "size")
    pose = o.vector("pose", 4)
    inertia = o.vector("inertia", 3, non_negative=True)
    colour = o.vector("colour", 4)
    shape = _enum(o, "shape", Shape)
    footprint = None
    if shape is Shape.POLYGON:
        if not o.has("footprint"):
            raise o.error("a POLYGON object needs its footprint", "footprint")
        footprint = _footprint(o.child("footprint"))
        if not isinstance(footprint, PolygonFootprint):
            raise o.error("a POLYGON object's footprint is a polygon", "footprint")
        points = footprint.points
        twice_area = sum(points[i - 1][0] * points[i][1] - points[i][0] * points[i - 1][1] for i in range(len(points)))
        if twice_area == 0:
            raise o.error("a POLYGON object's footprint has no area", "footprint")
        if twice_area < 0:  # the generator writes it counter-clockwise; a hand-written one may go the other way
            footprint = PolygonFootprint(points[:1] + points[:0:-1])
    return ObjectSpec(
        name=o.text("name"),
        category=category,
        type=o.text("type"),
        shape=shape,
        size=(size[0], size[1], size[2]),
        pose=(pose[0], pose[1], pose[2], pose[3]),
        mass=mass,
        inertia=(inertia[0], inertia[1], inertia[2]),
        colour=(colour[0], colour[1], colour[2], colour[3]),
        floor=o.optional_text("floor"),
        footprint=footprint,
    )


def _footprint(f: Fields) -> Footprint:
    kind = f.text("type")
    polygon, circle = FOOTPRINT_TYPES
    if kind == circle:
        radius = f.number("radius", positive=True)
        return CircleFootprint(f.number("x"), f.number("y"), radius)
    if kind != polygon:
        raise f.error(f"unknown value {kind!r}, expected one of {', '.join(FOOTPRINT_TYPES)}", "type")
    points = f.value.get("points") if isinstance(f.value, dict) else None
    if not (isinstance(points, list) and len(points) >= 3 and all(
            isinstance(p, list) and len(p) == 2 and all(isinstance(c, int | float) and not isinstance(c, bool)
                                                        for c in p) for p in points)):
        raise f.error("expected a list of at least 3 [x, y] points", "points")
    return PolygonFootprint(tuple((float(x), float(y)) for x, y in points))


def _robot(r: Fields, folder: Path) -> RobotSpec:
    size = r.vector("size", 3)
    if min(size) <= 0:
        raise r.error(f"all sizes must be > 0, got {list(size)}", "size")
    pose = r.vector("pose", 4)
    d = r.child("drive")
    lidar = r.child("lidar")
    beams = lidar.integer("beams")
    if beams <= 0:
        raise lidar.error(f"must be > 0, got {beams}", "beams")
    range_min = lidar.number("rangeMin", non_negative=True)
    range_max = lidar.number("rangeMax", positive=True)
    if range_max <= range_min:
        raise lidar.error(f"must be > rangeMin ({range_min}), got {range_max}", "rangeMax")
    lidar_pose = _pose4(r, "lidarPose") if r.has("lidarPose") else None
    if lidar_pose is not None and not math.isclose(lidar_pose[2], lidar.number("mountHeight"), abs_tol=1e-9):
        raise r.error(f"must be at lidar.mountHeight {lidar.number('mountHeight')} m high, got {lidar_pose[2]}",
                      "lidarPose")
    lx, ly, _, lyaw = lidar_pose or (0.0, 0.0, 0.0, 0.0)
    return RobotSpec(
        name=r.text("name"),
        type=r.text("type"),
        shape=_enum(r, "shape", Shape),
        size=(size[0], size[1], size[2]),
        mass=r.number("mass", positive=True),
        pose=(pose[0], pose[1], pose[2], pose[3]),
        floor=r.optional_text("floor"),
        drive=DriveSpec(
            wheel_radius=d.number("wheelRadius", positive=True),
            wheel_separation=d.number("wheelSeparation", positive=True),
            max_linear_velocity=d.number("maxLinearVelocity", positive=True),
            max_angular_velocity=d.number("maxAngularVelocity", positive=True),
            kind=_drive_kind(d),
        ),
        lidar=LidarSpec(
            beams=beams,
            range_min=range_min,
            range_max=range_max,
            rate=lidar.number("rate", positive=True),
            mount_height=lidar.number("mountHeight", non_negative=True),
            x=lx,
            y=ly,
            yaw=lyaw,
        ),
        footprint=_footprint(r.child("footprint")) if r.has("footprint") else None,
        lidar_pose=lidar_pose,
        description=_description(r, folder) if r.has("description") else None,
        lidar_link=r.text("lidarLink") if r.has("lidarLink") else None,
    )


def _drive_kind(d: Fields) -> str:
    if not d.has("kind"):
        return DRIVE_KINDS[0]
    kind = d.text("kind")
    if kind not in DRIVE_KINDS:
        raise d.error(f"unknown value {kind!r}, expected one of {', '.join(DRIVE_KINDS)}", "kind")
    return kind


def _pose4(r: Fields, key: str) -> tuple[float, float, float, float]:
    v = r.vector(key, 4)
    return v[0], v[1], v[2], v[3]


def _description(r: Fields, folder: Path) -> Path:
    """The expanded URDF, a file of the case folder (a case folder is self-contained)."""
    name = r.text("description")
    resolved = (folder / name).resolve()
    if Path(name).is_absolute() or not resolved.is_relative_to(folder.resolve()):
        raise r.error(f"expected a file of the case folder, got {name!r}", "description")
    return folder / name
