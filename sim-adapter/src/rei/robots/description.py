# SPDX-License-Identifier: EPL-2.0
"""A robot's description (URDF, usually through xacro) read into what REI uses of it: the footprint, the lidar's
pose and the differential drive.

Every file goes through xacro first (with the given xacro arguments), as ROS launch files do with TurtleBot3's
``.urdf`` files, which declare ``xacro:arg``; a plain URDF comes out unchanged. The expanded XML is parsed by
ROS's own URDF parser (``urdf_parser_py``). Poses are those of the zero configuration (every joint at 0),
relative to the description's root link (``base_footprint`` in ROS's conventions: on the floor, under the robot).

The footprint is the **convex hull** of the robot's collision shapes projected onto the floor (all of them,
whatever their height), or a **circle** when one vertical cylinder's disc holds every other shape's projection
(round robots). A convex hull rather than the union: the union of a TurtleBot3 Burger's parts is three pieces
(its wheels stand 1 mm clear of its body), and the monitor's and the metrics' distances take one simple polygon;
the hull only adds gaps between parts that no obstacle fits into. Each shape's own projection is kept in
``parts`` for later exact use. Round shapes enter a polygon as circumscribed 64-gons whose edges touch the circle
at the axis directions, so a bounding box is exact and the polygon never lies inside the true shape.
"""

from __future__ import annotations

import contextlib
import difflib
import io
import math
import re
import xml.parsers.expat
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

#: Sides of the polygon a circle or a disc's projection becomes inside a polygon footprint.
CIRCLE_SIDES = 64
#: A cylinder whose axis is this close to vertical (1 - |cos|) projects to a circle.
VERTICAL_TOLERANCE = 1e-9
#: Two joint axes this close to parallel (1 - |cos|) belong to the same wheel axle.
AXLE_TOLERANCE = 1e-3
#: Slack for one outline lying inside a circle, m.
CONTAINS_TOLERANCE = 1e-9
#: A polygon footprint's vertex is dropped when no shape's point then lies more than this outside it, m.
SIMPLIFY = 1e-5


class DescriptionError(Exception):
    """A description that cannot be used: names the file, and the line when the parser gives one."""

    def __init__(self, path: Path | str, detail: str, line: int | None = None, column: int | None = None) -> None:
        self.path = Path(path)
        self.detail = detail
        self.line = line
        self.column = column
        where = str(path) if line is None else f"{path}:{line}" + ("" if column is None else f":{column}")
        super().__init__(f"{where}: {detail}")


@dataclass(frozen=True, slots=True)
class Circle:
    x: float
    y: float
    radius: float

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)``, m."""
        return self.x - self.radius, self.y - self.radius, self.x + self.radius, self.y + self.radius

    def to_json(self) -> dict[str, Any]:
        return {"type": "circle", "x": self.x, "y": self.y, "radius": self.radius}


@dataclass(frozen=True, slots=True)
class Polygon:
    """A convex polygon, counter-clockwise, no point repeated."""

    points: tuple[tuple[float, float], ...]

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        xs = [x for x, _ in self.points]
        ys = [y for _, y in self.points]
        return min(xs), min(ys), max(xs), max(ys)

    @property
    def area(self) -> float:
        pts = self.points
        return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1], strict=True))

    def to_json(self) -> dict[str, Any]:
        return {"type": "polygon", "points": [list(p) for p in self.points]}


Outline = Circle | Polygon


@dataclass(frozen=True, slots=True)
class Part:
    """One collision shape's projection: its link, its kind (box, cylinder, sphere, mesh) and outline."""

    link: str
    kind: str
    outline: Outline


@dataclass(frozen=True, slots=True)
class LidarPose:
    """The lidar link's frame relative to the root link at the zero configuration: m, and rad about z."""

    link: str
    x: float
    y: float
    z: float
    yaw: float
    #: Roll and pitch of the frame: a lidar mounted tilted or upside down (REI's lidar scans level).
    roll: float = 0.0
    pitch: float = 0.0


@dataclass(frozen=True, slots=True)
class Drive:
    """A differential drive from two continuous wheel joints with cylinder collision shapes."""

    left_joint: str
    right_joint: str
    wheel_separation: float
    wheel_radius: float


@dataclass(frozen=True, slots=True)
class RobotDescription:
    path: Path
    name: str
    #: The root link every pose is relative to.
    base_link: str
    footprint: Outline
    parts: tuple[Part, ...]
    lidar: LidarPose | None
    drive: Drive | None
    #: What the description does not say, each with why (the catalogue supplies these).
    missing: tuple[str, ...]
    #: Read but not used: meshes that are not there, xacro's own warnings.
    warnings: tuple[str, ...]
    links: tuple[str, ...] = field(default=())
    #: The expanded URDF (after xacro).
    urdf: str = ""
    #: Every file the read depends on: the description, the files xacro included, the collision meshes read
    #: (absolute). A reader that keeps what it read (the generator's JVM) reads again when one of them changes.
    sources: tuple[Path, ...] = ()

    def to_json(self) -> dict[str, Any]:
        xmin, ymin, xmax, ymax = self.footprint.bounds
        lidar = self.lidar
        drive = self.drive
        return {
            "file": str(self.path),
            "name": self.name,
            "base_link": self.base_link,
            "footprint": self.footprint.to_json(),
            "bounds": {"xmin": xmin, "ymin": ymin, "xmax": xmax, "ymax": ymax},
            "parts": [{"link": p.link, "kind": p.kind, "outline": p.outline.to_json()} for p in self.parts],
            "lidar": None if lidar is None else {"link": lidar.link, "x": lidar.x, "y": lidar.y, "z": lidar.z,
                                                 "yaw": lidar.yaw, "roll": lidar.roll, "pitch": lidar.pitch},
            "drive": None if drive is None else {
                "type": "differential", "left_joint": drive.left_joint, "right_joint": drive.right_joint,
                "wheel_separation": drive.wheel_separation, "wheel_radius": drive.wheel_radius},
            "missing": list(self.missing),
            "warnings": list(self.warnings),
        }


def load_description(path: Path | str, args: Mapping[str, str] | None = None,
                     lidar: str | None = None) -> RobotDescription:
    """Read the URDF or xacro file ``path`` with xacro arguments ``args``; ``lidar`` names the lidar's link.

    Raises :class:`DescriptionError` for a missing file, XML that does not parse, a xacro error, a URDF the
    parser refuses, a lidar link that does not exist and a robot without any collision shape."""
    path = Path(path)
    if not path.is_file():
        raise DescriptionError(path, "no such file" if not path.exists() else "not a file")
    warnings: list[str] = []
    sources = [path.resolve()]
    text = _expand(path.resolve(), dict(args or {}), warnings, shown=path, sources=sources)
    robot = _parse_urdf(path, text, warnings, args or {})
    links = {link.name: link for link in robot.links}
    frames = _link_frames(path, robot, args or {})
    base = next(iter(frames))
    resolver = _MeshResolver(path.resolve().parent)
    for link in robot.links:
        for visual in link.visuals:
            geometry = visual.geometry
            if _is_mesh(geometry) and resolver.find(geometry.filename) is None:
                warnings.append(f"link {link.name}: visual mesh {geometry.filename} not found: visual skipped")
    parts: list[Part] = []
    for link in robot.links:
        for collision in link.collisions:
            try:
                part = _project(link.name, frames[link.name] @ _origin(collision.origin), collision.geometry,
                                resolver, warnings)
            except _ShapeError as error:
                raise DescriptionError(path, f"link {link.name}: {error}",
                                       _line_of_name(path, link.name, args or {})) from None
            if part is not None:
                parts.append(part)
            mesh = resolver.find(collision.geometry.filename) if _is_mesh(collision.geometry) else None
            if mesh is not None:
                sources.append(mesh.resolve())
    if not parts:
        left_out = [w for w in warnings if "collision" in w and "left out" in w]
        raise DescriptionError(path, "the robot has no collision shape (its links' <collision> elements are "
                                     "what REI takes as its body and footprint)"
                               + (f"; left out: {'; '.join(left_out)}" if left_out else ""))
    footprint = _footprint(parts)
    if _flat(footprint):
        # a point or a segment: no outline for the simulator's body, the monitor or the metrics to take
        raise DescriptionError(path, "the robot's collision shapes have no area on the floor ("
                                     + ", ".join(f"{p.link} {p.kind}" for p in parts) + ")")
    missing: list[str] = []
    lidar_pose = None
    if lidar is None:
        hint = [name for name in links if re.search(r"scan|laser|lidar", name, re.IGNORECASE)]
        missing.append("lidar: no link named as the lidar" + (f" (candidates: {', '.join(hint)})" if hint else ""))
    elif lidar not in links:
        close = difflib.get_close_matches(lidar, list(links), n=1, cutoff=0.6)
        # a misspelt argument (namespce) is why a prefixed name is not there: say so beside the link
        undeclared = [w for w in warnings if w.startswith("xacro argument '")]
        raise DescriptionError(path, f"no link named '{lidar}' for the lidar"
                                     + (f"; did you mean '{close[0]}'?" if close else f" (links: {', '.join(links)})")
                                     + "".join(f"; {w}" for w in undeclared))
    else:
        lidar_pose = _lidar_pose(lidar, frames[lidar])
    drive, why = _drive(robot, frames, links)
    if drive is None:
        missing.append(f"drive: {why}")
    missing.append("lidar beams, range and rate; speeds and accelerations; mass: not in a URDF")
    return RobotDescription(path=path, name=robot.name, base_link=base, footprint=footprint,
                            parts=tuple(parts), lidar=lidar_pose, drive=drive, missing=tuple(missing),
                            warnings=tuple(dict.fromkeys(warnings)), links=tuple(links), urdf=text,
                            sources=tuple(dict.fromkeys(sources)))


@dataclass(frozen=True, slots=True)
class FixedJoint:
    """A fixed joint of a description: its ``child`` link's frame in its ``parent`` link's, ``xyz`` (m) and the
    ``quaternion`` ``(x, y, z, w)`` of its ``<origin>``'s roll, pitch and yaw."""

    name: str
    parent: str
    child: str
    xyz: tuple[float, float, float]
    quaternion: tuple[float, float, float, float]


def fixed_joints(text: str, path: Path | str = "robot.urdf") -> tuple[str, tuple[FixedJoint, ...]]:
    """The root link of the expanded URDF ``text`` and its fixed joints, in the file's order: what
    robot_state_publisher publishes on /tf_static. ``path`` names the file in errors (:class:`DescriptionError`)."""
    path = Path(path)
    robot = _parse_urdf(path, text, [], {})
    root = next(iter(_link_frames(path, robot, {})))
    found = []
    for joint in robot.joints:
        if joint.type != "fixed":
            continue
        origin = joint.origin
        xyz = tuple(float(v) for v in (origin.xyz if origin is not None and origin.xyz is not None else (0, 0, 0)))
        rpy = origin.rpy if origin is not None and origin.rpy is not None else (0.0, 0.0, 0.0)
        found.append(FixedJoint(joint.name, joint.parent, joint.child, (xyz[0], xyz[1], xyz[2]),
                                _quaternion(*(float(v) for v in rpy))))
    return root, tuple(found)


def _quaternion(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    """``(x, y, z, w)`` of roll, pitch and yaw about the fixed x, y and z axes (tf's setRPY)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


# --- xacro and URDF -------------------------------------------------------------------------------------------


def _expand(path: Path, args: dict[str, str], warnings: list[str], shown: Path | None = None,
            sources: list[Path] | None = None) -> str:
    """The file after xacro, as XML text; ``shown``: ``path`` as the user wrote it, for its errors (xacro knows it
    resolved, as its includes need); the files xacro included are added to ``sources``."""
    import xacro

    # xacro keeps its state in module globals (file stack, includes): start each file afresh.
    xacro.init_stacks(str(path))
    xacro.all_includes = []
    captured = io.StringIO()
    try:
        with contextlib.redirect_stderr(captured):
            doc = xacro.parse(None, str(path))
            xacro.process_doc(doc, mappings=dict(args))
        included_files = [Path(f) for f in xacro.all_includes]
    except xml.parsers.expat.ExpatError as error:
        where = Path(xacro.filestack[-1]) if xacro.filestack and xacro.filestack[-1] else path
        raise DescriptionError(shown if shown is not None and where == path else where,
                               f"XML does not parse: {xml.parsers.expat.ErrorString(error.code)}",
                               error.lineno, error.offset + 1) from None
    except Exception as error:  # noqa: BLE001 - xacro wraps some errors, not all (an expression's NameError)
        stack = [f for f in (xacro.filestack or []) if f]
        where = Path(stack[-1]) if stack else path
        detail = str(error) or type(error).__name__
        included = f" (included from {', '.join(reversed(stack[:-1]))})" if len(stack) > 1 else ""
        detail = " ".join(detail.split())
        expression = re.search(r"when evaluating expression '(.*)'", detail)
        argument = re.search(r"Undefined substitution argument (\S+)", detail)
        missing = re.match(r"No such file or directory: (\S+)", detail)
        line = None
        if missing:
            # xacro says the path twice (its message and the OSError's); the line is the include's
            detail = f"the included file {missing.group(1)} is not there"
            line = _line_of(where, rf"<xacro:include\s[^>]*{re.escape(Path(missing.group(1)).name)}")
        elif expression:
            # inside its ${...} first: the bare text ('a', 'width') may stand in any name or word before it
            line = _line_of(where, rf"\$\{{\s*{re.escape(expression.group(1))}\s*\}}") or _line_of(
                where, re.escape(expression.group(1)))
        elif argument:
            line = _line_of(where, rf"\$\(arg\s+{re.escape(argument.group(1))}\s*\)")
            detail += f" (give it: --arg {argument.group(1)}:=VALUE)"
        elif "ament_index_python" in detail or "rospkg" in detail:
            # $(find PKG) asks a ROS installation where a package is; REI looks up no ROS packages.
            line = _line_of(where, r"\$\(find\s")
            detail = f"$(find PKG) needs a ROS installation: write the path relative to the file ({detail})"
        raise DescriptionError(shown if shown is not None and where == path else where,
                               f"xacro error: {detail}{included}", line) from None
    finally:
        xacro.init_stacks(None)
    # Declared, or used without a declaration (then an error when not given), by the file or one it includes.
    declared: set[str] = set()
    for source in (path, *included_files):
        with contextlib.suppress(OSError):
            text = source.read_text(encoding="utf-8", errors="replace")
            declared |= set(re.findall(r"<xacro:arg\s[^>]*?name\s*=\s*[\"']([^\"']+)[\"']", text))
            declared |= set(re.findall(r"\$\(arg\s+([^)\s]+)\s*\)", text))
    for name in sorted(set(args) - declared):
        warnings.append(f"xacro argument '{name}' is not declared by the file"
                        + (f" (it declares: {', '.join(sorted(declared))})" if declared else ""))
    warnings.extend(line.strip() for line in captured.getvalue().splitlines() if line.strip())
    if sources is not None:
        sources.extend(f.resolve() for f in included_files)
    return doc.toxml()


def _line_of(path: Path, pattern: str) -> int | None:
    """The first line of ``path`` matching ``pattern``: xacro's and the URDF parser's errors name an expression or
    an element, not a line."""
    try:
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return None
    return next((number for number, text in enumerate(lines, 1) if re.search(pattern, text)), None)


def _line_of_name(path: Path, name: str, args: Mapping[str, str]) -> int | None:
    """The line of the element named ``name``, also when the file writes it with a prefix from a xacro argument
    (``${namespace}base_link``)."""
    candidates = [name, *(name[len(v):] for v in args.values() if v and name.startswith(v))]
    for candidate in candidates:
        line = _line_of(path, rf"name\s*=\s*[\"'](?:[^\"']*\}})?{re.escape(candidate)}[\"']")
        if line is not None:
            return line
    return None


def _parse_urdf(path: Path, text: str, warnings: list[str], args: Mapping[str, str]) -> Any:
    from urdf_parser_py import urdf
    from urdf_parser_py.xml_reflection import core

    # a ROS package.xml or a launch file says only "name not set (at /robot)" to the parser
    root = re.search(r"<([A-Za-z_][\w.:-]*)", re.sub(r"<\?.*?\?>|<!--.*?-->", "", text, flags=re.DOTALL))
    if root is not None and root.group(1) != "robot":
        raise DescriptionError(path, f"not a URDF: its root element is <{root.group(1)}>, a URDF's is <robot>",
                               _line_of(path, rf"<{re.escape(root.group(1))}[\s>/]"))
    # The parser prints unknown elements and attributes (Gazebo tags, ...) to stderr by default: keep them.
    previous = core.on_error
    core.on_error = lambda message: warnings.append(f"URDF: {message}")
    try:
        robot = urdf.URDF.from_xml_string(text.encode("utf-8"))
    except core.ParseError as error:
        names = re.findall(r"\[@name='([^']*)'\]", str(error.path))
        line = _line_of_name(path, names[-1], args) if names else None
        raise DescriptionError(path, f"not a valid URDF: {error.e} (at {error.path})", line) from None
    except Exception as error:  # noqa: BLE001 - the parser raises plain Exception and ValueError for bad values
        raise DescriptionError(path, f"not a valid URDF: {error}") from None
    finally:
        core.on_error = previous
    if not robot.links:
        raise DescriptionError(path, "not a valid URDF: no <link>")
    return robot


def _link_frames(path: Path, robot: Any, args: Mapping[str, str]) -> dict[str, np.ndarray]:
    """Each link's frame relative to the root link, at the zero configuration; the root first."""
    names = {link.name for link in robot.links}
    children: dict[str, list[Any]] = {}
    child_of: dict[str, str] = {}
    for joint in robot.joints:
        for role, link in (("parent", joint.parent), ("child", joint.child)):
            if link not in names:
                raise DescriptionError(path, f"not a valid URDF: joint '{joint.name}' names {role} link '{link}', "
                                             "which does not exist", _line_of_name(path, joint.name, args))
        if joint.child in child_of:
            raise DescriptionError(path, f"not a valid URDF: link '{joint.child}' is the child of two joints",
                                   _line_of_name(path, joint.name, args))
        child_of[joint.child] = joint.name
        children.setdefault(joint.parent, []).append(joint)
    roots = [link.name for link in robot.links if link.name not in child_of]
    if len(roots) != 1:
        raise DescriptionError(path, "not a valid URDF: " + (f"several root links ({', '.join(roots)}): "
                                                             "the links are not one tree" if roots
                                                             else "the joints form a loop"))
    frames = {roots[0]: np.eye(4)}
    pending = [roots[0]]
    while pending:
        parent = pending.pop()
        for joint in children.get(parent, []):
            frames[joint.child] = frames[parent] @ _origin(joint.origin)
            if not np.all(np.isfinite(frames[joint.child])):
                # the parser takes nan and inf: they reached the lidar's pose in world.json
                raise DescriptionError(path, f"not a valid URDF: joint '{joint.name}': its <origin> is not finite",
                                       _line_of_name(path, joint.name, args))
            pending.append(joint.child)
    return frames


def _origin(pose: Any) -> np.ndarray:
    """The 4x4 transform of a URDF <origin> (absent: identity); rpy is roll, pitch, yaw about fixed x, y, z."""
    m = np.eye(4)
    if pose is None:
        return m
    roll, pitch, yaw = pose.rpy if pose.rpy is not None else (0.0, 0.0, 0.0)
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    m[:3, :3] = [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                 [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                 [-sp, cp * sr, cp * cr]]
    m[:3, 3] = pose.xyz if pose.xyz is not None else (0.0, 0.0, 0.0)
    return m


# --- shapes ------------------------------------------------------------------------------------------------------


def _is_mesh(geometry: Any) -> bool:
    return hasattr(geometry, "filename")


class _MeshResolver:
    """Finds mesh files: ``package://NAME/...`` in the folder of a package.xml naming NAME (or a folder named
    NAME) at or above the description's folder, ``file://`` and plain paths as they are (relative: to the
    description's folder). No ROS installation is asked."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.packages: dict[str, Path | None] = {}

    def find(self, uri: str) -> Path | None:
        if uri.startswith("package://"):
            package, _, rest = uri[len("package://"):].partition("/")
            root = self._package(package)
            candidate = None if root is None else root / rest
        elif uri.startswith("file://"):
            candidate = Path(uri[len("file://"):])
        else:
            candidate = self.folder / uri
        return candidate if candidate is not None and candidate.is_file() else None

    def _package(self, name: str) -> Path | None:
        if name not in self.packages:
            found = None
            for folder in (self.folder, *self.folder.parents):
                manifest = folder / "package.xml"
                if manifest.is_file() and re.search(rf"<name>\s*{re.escape(name)}\s*</name>",
                                                    manifest.read_text(encoding="utf-8", errors="replace")):
                    found = folder
                    break
                if (folder / name).is_dir():
                    found = folder / name
                    break
            self.packages[name] = found
        return self.packages[name]


class _ShapeError(Exception):
    """A collision shape that cannot be projected: a size that is not a length, a mesh file that does not read."""


def _lengths(kind: str, **sizes: Any) -> None:
    """Refuse sizes that are not finite and at least 0: the URDF parser takes any float (nan, -0.2), and a nan
    would reach world.json, a negative radius a circle of negative size."""
    for name, value in sizes.items():
        values = [float(v) for v in (value if isinstance(value, (list, tuple)) else [value])]
        if not all(math.isfinite(v) and v >= 0 for v in values):
            raise _ShapeError(f"the collision {kind}'s {name} must be finite and at least 0, not "
                              + " ".join(f"{v:g}" for v in values))


def _project(link: str, pose: np.ndarray, geometry: Any, resolver: _MeshResolver,
             warnings: list[str]) -> Part | None:
    """The projection onto the floor of one collision shape placed at ``pose`` (relative to the root link)."""
    rotation, centre = pose[:3, :3], pose[:3, 3]
    if not np.all(np.isfinite(pose)):
        raise _ShapeError("its pose is not finite (a joint's or the collision's <origin> has nan or inf)")
    kind = type(geometry).__name__.lower()
    if kind == "box":
        _lengths(kind, size=geometry.size)
        hx, hy, hz = (s / 2 for s in geometry.size)
        corners = np.array([[sx * hx, sy * hy, sz * hz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
        return Part(link, kind, _hull(corners @ rotation.T + centre))
    if kind == "sphere":
        _lengths(kind, radius=geometry.radius)
        return Part(link, kind, Circle(float(centre[0]), float(centre[1]), float(geometry.radius)))
    if kind == "cylinder":
        _lengths(kind, radius=geometry.radius, length=geometry.length)
        axis = rotation[:, 2]
        r, h = float(geometry.radius), float(geometry.length) / 2
        if 1 - abs(axis[2]) < VERTICAL_TOLERANCE:
            return Part(link, kind, Circle(float(centre[0]), float(centre[1]), r))
        # The hull of the two end discs; a disc as the circumscribed polygon in its own plane.
        points = np.concatenate([_disc(centre + s * h * axis, axis, r) for s in (-1, 1)])
        return Part(link, kind, _hull(points))
    if _is_mesh(geometry):
        found = resolver.find(geometry.filename)
        if found is None:
            warnings.append(f"link {link}: collision mesh {geometry.filename} not found: this shape is left out")
            return None
        try:
            vertices = _mesh_vertices(found)
        except (ValueError, OSError) as error:
            raise _ShapeError(f"collision mesh {geometry.filename} ({found}) does not read: {error}") from None
        if vertices is None:
            warnings.append(f"link {link}: collision mesh {geometry.filename}: only STL and OBJ meshes are read: "
                            "this shape is left out")
            return None
        if len(vertices) == 0:
            raise _ShapeError(f"collision mesh {geometry.filename} ({found}) has no vertices")
        if geometry.scale is not None:
            _lengths("mesh", scale=geometry.scale)
        scale = np.array(geometry.scale if geometry.scale is not None else (1.0, 1.0, 1.0), dtype=float)
        return Part(link, "mesh", _hull((vertices * scale) @ rotation.T + centre))
    warnings.append(f"link {link}: collision geometry {kind} not read: this shape is left out")
    return None


def _disc(centre: np.ndarray, axis: np.ndarray, radius: float) -> np.ndarray:
    """Vertices of the polygon circumscribing the disc of ``radius`` about ``axis``: its edges touch the circle at
    the horizontal direction perpendicular to the axis, so the disc's projection's extent there is exact."""
    u = np.cross(axis, (0.0, 0.0, 1.0))
    u = u / np.linalg.norm(u)
    v = np.cross(axis, u)
    half = math.pi / CIRCLE_SIDES
    angles = np.arange(CIRCLE_SIDES) * 2 * half + half
    r = radius / math.cos(half)
    return centre + r * (np.outer(np.cos(angles), u) + np.outer(np.sin(angles), v))


def _circle_points(circle: Circle) -> np.ndarray:
    half = math.pi / CIRCLE_SIDES
    angles = np.arange(CIRCLE_SIDES) * 2 * half + half
    r = circle.radius / math.cos(half)
    return np.column_stack([circle.x + r * np.cos(angles), circle.y + r * np.sin(angles)])


def _mesh_vertices(path: Path) -> np.ndarray | None:
    """The vertices of an STL (binary or ASCII) or OBJ mesh; None for other formats. ValueError (with what is
    wrong) for a file that does not read as its format: truncated, a vertex that is not three numbers."""
    suffix = path.suffix.lower()
    data = path.read_bytes()
    if suffix == ".stl":
        if data[:5].lower() == b"solid" and b"facet" in data[:1024]:
            numbers = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
            try:
                vertices = np.array(numbers, dtype=float).reshape(-1, 3)
            except ValueError:
                raise ValueError("an ASCII STL vertex that is not three numbers") from None
            return _finite(vertices)
        if len(data) < 84:
            raise ValueError(f"{len(data)} bytes, less than a binary STL's 84-byte header")
        count = int.from_bytes(data[80:84], "little")
        # Each triangle: normal, three vertices (float32 each), two attribute bytes.
        if len(data) < 84 + 50 * count:
            raise ValueError(f"a binary STL of {count} triangles needs {84 + 50 * count} bytes, the file has "
                             f"{len(data)}")
        records = np.frombuffer(data, dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]),
                                count=count, offset=84)
        return _finite(records["v"].reshape(-1, 3).astype(float))
    if suffix == ".obj":
        rows = []
        for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
            if line.startswith("v "):
                try:
                    rows.append([float(v) for v in line.split()[1:4]])
                except ValueError:
                    rows.append([])
                if len(rows[-1]) != 3:
                    raise ValueError(f"line {number}: a vertex is 'v X Y Z', not {line.strip()!r}")
        return _finite(np.array(rows, dtype=float).reshape(-1, 3))
    return None


def _finite(vertices: np.ndarray) -> np.ndarray:
    if not np.all(np.isfinite(vertices)):
        raise ValueError("a vertex that is nan or inf")
    return vertices


def _hull(points: np.ndarray) -> Polygon:
    """Convex hull of the points' x and y (Andrew's monotone chain), counter-clockwise."""
    pts = sorted({(round(float(x), 12), round(float(y), 12)) for x, y in np.asarray(points)[:, :2]})
    if len(pts) < 3:
        return Polygon(tuple(pts))

    def half(seq: list[tuple[float, float]]) -> list[tuple[float, float]]:
        chain: list[tuple[float, float]] = []
        for p in seq:
            while len(chain) >= 2 and _cross(chain[-2], chain[-1], p) <= 1e-15:
                chain.pop()
            chain.append(p)
        return chain[:-1]

    return Polygon(_simplify(half(pts) + half(pts[::-1])))


def _simplify(ring: list[tuple[float, float]]) -> tuple[tuple[float, float], ...]:
    """The convex ring without the vertices whose removal moves no original vertex more than ``SIMPLIFY``
    inside it: a wheel mounted at rpy 1.57 rather than pi/2 gives a 64-gon's worth of vertices on a 25 um arc."""
    points = list(ring)
    # under[i]: the original vertices removed between points[i] and points[i + 1].
    under: list[list[tuple[float, float]]] = [[] for _ in points]
    changed = True
    while changed and len(points) > 3:
        changed = False
        for i in range(len(points)):
            a, b, c = points[i - 1], points[i], points[(i + 1) % len(points)]
            length = math.hypot(c[0] - a[0], c[1] - a[1])
            dropped = [*under[i - 1], b, *under[i]]
            if length > 0 and all(_cross(a, c, q) / length >= -SIMPLIFY for q in dropped):
                under[i - 1] = dropped
                del points[i], under[i]
                changed = True
                break
    return tuple(points)


def _cross(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _footprint(parts: list[Part]) -> Outline:
    """A circle when one part is a circle holding every other part; else the convex hull of all parts."""
    for part in sorted(parts, key=lambda p: -p.outline.radius if isinstance(p.outline, Circle) else 0.0):
        disc = part.outline
        if isinstance(disc, Circle) and all(_inside(other.outline, disc) for other in parts):
            return disc
    points = np.concatenate([_circle_points(p.outline) if isinstance(p.outline, Circle)
                             else np.array(p.outline.points, dtype=float).reshape(-1, 2) for p in parts])
    return _hull(points)


def _flat(outline: Outline) -> bool:
    """No area: a circle of radius 0, a polygon of fewer than three vertices (the hull of collinear points)."""
    if isinstance(outline, Circle):
        return outline.radius <= 0
    return len(outline.points) < 3 or outline.area <= 0


def _inside(outline: Outline, disc: Circle) -> bool:
    if isinstance(outline, Circle):
        return math.hypot(outline.x - disc.x, outline.y - disc.y) + outline.radius <= disc.radius + CONTAINS_TOLERANCE
    return all(math.hypot(x - disc.x, y - disc.y) <= disc.radius + CONTAINS_TOLERANCE for x, y in outline.points)


# --- lidar and drive ---------------------------------------------------------------------------------------------


def _lidar_pose(link: str, frame: np.ndarray) -> LidarPose:
    r = frame[:3, :3]
    pitch = math.asin(max(-1.0, min(1.0, -r[2, 0])))
    return LidarPose(link=link, x=float(frame[0, 3]), y=float(frame[1, 3]), z=float(frame[2, 3]),
                     yaw=math.atan2(r[1, 0], r[0, 0]), roll=math.atan2(r[2, 1], r[2, 2]), pitch=pitch)


def _drive(robot: Any, frames: dict[str, np.ndarray], links: dict[str, Any]) -> tuple[Drive | None, str]:
    """Two continuous joints about one horizontal axle whose child links have a cylinder collision shape about
    that axle; the separation is the distance between the joints along the axle."""
    wheels = []
    for joint in robot.joints:
        if joint.type != "continuous":
            continue
        frame = frames[joint.child]
        axis = frame[:3, :3] @ np.array(joint.axis if joint.axis is not None else (1.0, 0.0, 0.0), dtype=float)
        length = float(np.linalg.norm(axis))
        if not math.isfinite(length) or length == 0:
            continue  # an axis of "0 0 0" turns about nothing: not a wheel (and no division by 0)
        axis = axis / length
        if abs(axis[2]) > AXLE_TOLERANCE:
            continue  # not a wheel on the floor (a turret, a steering joint)
        radii = [float(c.geometry.radius) for c in links[joint.child].collisions
                 if type(c.geometry).__name__ == "Cylinder"
                 and 1 - abs(float(axis @ (frame @ _origin(c.origin))[:3, 2])) < AXLE_TOLERANCE]
        if radii:
            wheels.append((joint.name, frame[:3, 3], axis, max(radii)))
    if len(wheels) != 2:
        found = f"{len(wheels)} wheel joints" if wheels else "no wheel joint"
        return None, (f"{found} (a continuous joint with a horizontal axis whose child link has a cylinder "
                      "collision shape about it); a differential drive needs two")
    (name_a, pos_a, axis_a, r_a), (name_b, pos_b, axis_b, r_b) = wheels
    if 1 - abs(float(axis_a @ axis_b)) > AXLE_TOLERANCE:
        return None, f"wheel joints {name_a} and {name_b} do not share an axle"
    if abs(r_a - r_b) > 1e-6:
        return None, f"wheels {name_a} and {name_b} differ in radius ({r_a} and {r_b} m)"
    # Left is the wheel further along +y (the robot faces +x).
    left, right = (name_a, name_b) if pos_a[1] >= pos_b[1] else (name_b, name_a)
    lateral = np.array([axis_a[0], axis_a[1], 0.0]) / math.hypot(axis_a[0], axis_a[1])
    separation = abs(float((pos_a - pos_b) @ lateral))
    return Drive(left_joint=left, right_joint=right, wheel_separation=separation, wheel_radius=r_a), ""
