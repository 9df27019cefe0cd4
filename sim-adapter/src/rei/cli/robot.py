# SPDX-License-Identifier: EPL-2.0
"""`rei robot FILE [--arg NAME:=VALUE ...] [--lidar LINK] [--json]`: what REI reads from a robot description.

FILE is a URDF or xacro file (every file goes through xacro, with the arguments given). Prints the footprint (the
collision shapes projected onto the floor: a convex polygon, or a circle for a round robot), its bounding box, the
lidar's pose (of the link --lidar names) and the differential drive from the wheel joints, relative to the root
link; then what the description does not say and what was skipped (meshes that are not there). Exit 0: read;
1: a description that cannot be used (the message names the file, and the line when the parser gives one).
See docs/robots.md.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any

from rei.cli.errors import EXIT_INVALID, EXIT_OK, CommandError

#: The lowest lidar a described robot may have, m: a box robot's least height (the language's outOfRange rule).
MIN_LIDAR_HEIGHT = 0.05
#: The simulator's wheels' width, m: rei.sim.robot_model.WHEEL_WIDTH (not imported here: it imports pybullet).
SIM_WHEEL_WIDTH = 0.018


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `robot` subcommand."""
    parser = subparsers.add_parser("robot", help="inspect a robot description (URDF or xacro): footprint, lidar, "
                                   "drive", description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("file", metavar="FILE", type=Path, help="a .urdf or .xacro file")
    parser.add_argument("--arg", action="append", default=[], metavar="NAME:=VALUE", type=_xacro_arg,
                        help="a xacro argument, as on xacro's command line (repeatable); VALUE may be empty")
    parser.add_argument("--lidar", metavar="LINK", help="the lidar's link (e.g. base_scan)")
    parser.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    parser.add_argument("--wheels", nargs=2, type=float, metavar=("RADIUS", "SEPARATION"),
                        help="with --for-generator: the catalogue entry's wheels (or the defaults), the simulator's "
                        "when the description has no wheel joints; they must lie within the footprint")
    parser.add_argument("--for-generator", metavar="URDF_OUT", type=Path,
                        help="what the generator of world.json reads (lines 'footprint JSON', 'bounds XMIN YMIN XMAX "
                        "YMAX', 'lidar X Y Z YAW', 'drive SEPARATION RADIUS' or 'drive none', then 'source PATH' for "
                        "each file read: the description, its xacro includes, its collision meshes), and the expanded "
                        "URDF written to URDF_OUT (the simulator's body)")
    parser.set_defaults(handler=run)


def _xacro_arg(text: str) -> tuple[str, str]:
    name, sep, value = text.partition(":=")
    if not sep or not name:
        raise argparse.ArgumentTypeError(f"'{text}': write NAME:=VALUE")
    return name, value


def run(args: argparse.Namespace) -> int:
    from rei.robots import Circle, DescriptionError, load_description

    try:
        robot = load_description(args.file, dict(args.arg), lidar=args.lidar)
    except DescriptionError as error:
        raise CommandError(str(error), exit_code=EXIT_INVALID) from None
    if args.json:
        print(json.dumps(robot.to_json(), indent=2))
        return EXIT_OK
    if args.for_generator is not None:
        return _for_generator(robot, args.for_generator, args.wheels)
    for warning in robot.warnings:
        print(f"rei: warning: {warning}", file=sys.stderr)
    footprint = robot.footprint
    print(f"robot {robot.name} ({robot.path}), poses relative to {robot.base_link}")
    if isinstance(footprint, Circle):
        print(f"footprint: circle, centre ({footprint.x:.4f}, {footprint.y:.4f}) m, radius {footprint.radius:.4f} m")
    else:
        print(f"footprint: convex polygon of {len(footprint.points)} vertices, {footprint.area:.5f} m^2:")
        print("  " + " ".join(f"({x:.4f}, {y:.4f})" for x, y in footprint.points))
    xmin, ymin, xmax, ymax = footprint.bounds
    print(f"bounding box: x {xmin:.4f} .. {xmax:.4f}, y {ymin:.4f} .. {ymax:.4f} "
          f"({xmax - xmin:.4f} x {ymax - ymin:.4f} m)")
    print(f"collision shapes: {len(robot.parts)} (" + ", ".join(f"{p.link} {p.kind}" for p in robot.parts) + ")")
    if robot.lidar is not None:
        lidar = robot.lidar
        tilt = (f", tilted roll {math.degrees(lidar.roll):.1f} deg pitch {math.degrees(lidar.pitch):.1f} deg"
                if abs(lidar.roll) > 1e-6 or abs(lidar.pitch) > 1e-6 else "")
        print(f"lidar: {lidar.link} at x {lidar.x:.4f}, y {lidar.y:.4f}, z {lidar.z:.4f} m, "
              f"yaw {math.degrees(lidar.yaw):.1f} deg{tilt}")
    if robot.drive is not None:
        drive = robot.drive
        print(f"drive: differential, wheel separation {drive.wheel_separation:.4f} m, wheel radius "
              f"{drive.wheel_radius:.4f} m ({drive.left_joint} left, {drive.right_joint} right)")
    for missing in robot.missing:
        print(f"not in the description: {missing}")
    return EXIT_OK


def _for_generator(robot: Any, urdf_out: Path, wheels: list[float] | None = None) -> int:
    """Lines of numbers rather than JSON: the Java generator reads them without a JSON library. ``repr`` keeps
    every float exact; the footprint is JSON the generator writes into world.json as it is. ``wheels``: the entry's
    radius and separation, the simulator's wheels when the description's are not read."""
    if robot.lidar is None:
        raise CommandError(f"{robot.path}: the lidar's link is not named", exit_code=EXIT_INVALID)
    if not robot.lidar.z >= MIN_LIDAR_HEIGHT:
        # The simulator's body is the footprint extruded from 1 cm above the floor up to the lidar: a lidar link
        # on the floor (the root link) or just above it gives no body, which only the simulation found out.
        raise CommandError(f"{robot.path}: the lidar's link {robot.lidar.link} is {robot.lidar.z:.4f} m above "
                           f"{robot.base_link}: REI's robot reaches from the floor up to its lidar and is at least "
                           f"{MIN_LIDAR_HEIGHT} m high (is {robot.lidar.link} the lidar's own link?)",
                           exit_code=EXIT_INVALID)
    if robot.drive is None and wheels is not None:
        _wheels_within(robot, *wheels)
    # `rei robot` warns; a catalogue's argument the description never reads is a typo that changes nothing (an
    # `arg namespce` left every frame without its prefix), and a generator's warnings reach nobody
    undeclared = [w for w in robot.warnings if w.startswith("xacro argument '")]
    if undeclared:
        raise CommandError(f"{robot.path}: {undeclared[0]}", exit_code=EXIT_INVALID)
    try:
        urdf_out.write_text(robot.urdf, encoding="utf-8")
    except OSError as error:
        raise CommandError(f"cannot write {urdf_out}: {error.strerror}", exit_code=EXIT_INVALID) from None
    lidar, drive = robot.lidar, robot.drive
    print("footprint " + json.dumps(robot.footprint.to_json(), separators=(", ", ": ")))
    print("bounds " + " ".join(repr(float(v)) for v in robot.footprint.bounds))
    print("lidar " + " ".join(repr(float(v)) for v in (lidar.x, lidar.y, lidar.z, lidar.yaw)))
    print("drive none" if drive is None else f"drive {float(drive.wheel_separation)!r} {float(drive.wheel_radius)!r}")
    for source in robot.sources:
        print(f"source {source}")
    for warning in robot.warnings:
        print(f"rei: warning: {warning}", file=sys.stderr)
    return EXIT_OK


def _wheels_within(robot: Any, radius: float, separation: float) -> None:
    """The simulator puts two wheels on the origin's axle; with the description's wheel joints not read, they are
    the entry's or the defaults (0.287 m apart), and wheels outside the footprint touch furniture the monitor sees
    the outline clear of (a collision 7 cm away) and stop the robot there."""
    from rei.robots import Circle

    footprint = robot.footprint
    outer, inner = separation / 2 + SIM_WHEEL_WIDTH / 2, max(separation / 2 - SIM_WHEEL_WIDTH / 2, 0.0)
    corners = [(x, y) for x in (-radius, radius) for y in (-outer, -inner, inner, outer)]
    slack = 1e-6
    if isinstance(footprint, Circle):
        inside = all(math.hypot(x - footprint.x, y - footprint.y) <= footprint.radius + slack for x, y in corners)
    else:
        ring = list(footprint.points)
        inside = all(((x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)) / math.hypot(x1 - x0, y1 - y0) >= -slack
                     for x, y in corners for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1], strict=True))
    if not inside:
        why = next((m[len("drive: "):] for m in robot.missing if m.startswith("drive: ")), "not read")
        _, ymin, _, ymax = footprint.bounds
        raise CommandError(f"{robot.path}: the simulator's wheels (radius {radius:g} m, {separation:g} m apart: the "
                           "catalogue entry's 'wheels' or the defaults, as the description's wheels were not read: "
                           f"{why}) reach outside the robot's footprint (y {ymin:.4f} .. {ymax:.4f} m), where they "
                           "would touch what the monitor sees the outline clear of: give the entry 'wheels RADIUS "
                           "apart SEPARATION' within it", exit_code=EXIT_INVALID)
