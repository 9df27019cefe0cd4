# SPDX-License-Identifier: EPL-2.0
"""rei.robots: robot descriptions read into footprint, lidar pose and drive, on ROBOTIS's TurtleBot3 descriptions
(read where they are shared, beside the repository: xacro arguments, ``${namespace}`` in every name, visuals on
``package://`` meshes that are not there) and on small descriptions written here; and every bad input's error.

The expected numbers are worked out by hand from the numbers in turtlebot3_burger.urdf (quoted in comments)."""

from __future__ import annotations

import math
import struct
import warnings
from pathlib import Path

import pytest

from rei.robots import Circle, DescriptionError, Polygon, load_description

TURTLEBOT3 = Path(__file__).resolve().parents[3].parent / "shared" / "data" / "robots" / "turtlebot3"
BURGER = TURTLEBOT3 / "turtlebot3_burger.urdf"
NAMESPACES = ("", "tb3/")

# turtlebot3_burger.urdf: base_joint lifts base_link 0.010 above base_footprint; base_link's collision box
# 0.140 x 0.140 centred at x -0.032; wheel joints at y +-0.08 (z 0.023) with rpy -1.57 0 0, wheels cylinders
# radius 0.033 length 0.018; scan_joint at (-0.032, 0, 0.172) on base_link.
BODY_X = (-0.032 - 0.070, -0.032 + 0.070)
BODY_Y = 0.070
WHEEL_Y, WHEEL_R, WHEEL_HALF = 0.08, 0.033, 0.009
# The wheel joint turns the wheel's axis by 1.57 rad, not pi/2: the axis leans cos(1.57) out of the floor, so the
# wheel's outer face reaches a little further out than 0.089, by its radius times that lean.
WHEEL_OUTER = WHEEL_Y + WHEEL_HALF * math.sin(1.57) + WHEEL_R * math.cos(1.57)


def _inside(point: tuple[float, float], polygon: list[tuple[float, float]], slack: float) -> bool:
    """``point`` within ``slack`` m of the convex counter-clockwise ``polygon`` or inside it."""
    for (x0, y0), (x1, y1) in zip(polygon, polygon[1:] + polygon[:1], strict=True):
        length = math.hypot(x1 - x0, y1 - y0)
        if ((x1 - x0) * (point[1] - y0) - (y1 - y0) * (point[0] - x0)) / length < -slack:
            return False
    return True


def _area(points: list[tuple[float, float]]) -> float:
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=True))


@pytest.mark.parametrize("namespace", NAMESPACES)
def test_burger_footprint_is_the_outline_of_its_collision_shapes(namespace: str) -> None:
    robot = load_description(BURGER, {"namespace": namespace}, lidar=f"{namespace}base_scan")
    assert robot.base_link == f"{namespace}base_footprint"
    # The body's box and the two wheels stand out; the caster and the lidar's turret lie inside the body.
    octagon = [(BODY_X[0], -BODY_Y), (-WHEEL_R, -WHEEL_Y - WHEEL_HALF), (WHEEL_R, -WHEEL_Y - WHEEL_HALF),
               (BODY_X[1], -BODY_Y), (BODY_X[1], BODY_Y), (WHEEL_R, WHEEL_Y + WHEEL_HALF),
               (-WHEEL_R, WHEEL_Y + WHEEL_HALF), (BODY_X[0], BODY_Y)]
    footprint = robot.footprint
    assert isinstance(footprint, Polygon)
    points = list(footprint.points)
    # Both ways within 30 um: no corner of the octagon outside the footprint, no footprint vertex outside it but
    # for the wheel's lean (26 um).
    assert all(_inside(corner, points, 1e-9) for corner in octagon)
    assert all(_inside(vertex, octagon, 3e-5) for vertex in points)
    xmin, ymin, xmax, ymax = footprint.bounds
    assert (xmin, xmax) == pytest.approx(BODY_X, abs=1e-9)
    assert (ymin, ymax) == pytest.approx((-WHEEL_OUTER, WHEEL_OUTER), abs=1e-8)
    assert footprint.area == pytest.approx(_area(octagon), abs=1e-5)
    # Not the bounding box: the body's rear corners are 19 mm inside the wheels' outer faces.
    assert footprint.area < (xmax - xmin) * (ymax - ymin) - 1e-3
    kinds = sorted((part.link.removeprefix(namespace), part.kind) for part in robot.parts)
    assert kinds == [("base_link", "box"), ("base_scan", "cylinder"), ("caster_back_link", "box"),
                     ("wheel_left_link", "cylinder"), ("wheel_right_link", "cylinder")]
    # The lidar's turret is a vertical cylinder: a circle, at scan_joint + its collision origin's 0.015.
    turret = next(part.outline for part in robot.parts if part.link == f"{namespace}base_scan")
    assert turret == Circle(pytest.approx(-0.032 + 0.015), pytest.approx(0.0), pytest.approx(0.055))


@pytest.mark.parametrize("namespace", NAMESPACES)
def test_burger_lidar_pose_and_drive(namespace: str) -> None:
    robot = load_description(BURGER, {"namespace": namespace}, lidar=f"{namespace}base_scan")
    lidar = robot.lidar
    assert lidar is not None and lidar.link == f"{namespace}base_scan"
    assert (lidar.x, lidar.y, lidar.z, lidar.yaw) == pytest.approx((-0.032, 0.0, 0.010 + 0.172, 0.0), abs=1e-12)
    drive = robot.drive
    assert drive is not None
    assert drive.wheel_separation == pytest.approx(2 * WHEEL_Y, abs=1e-12)
    assert drive.wheel_radius == WHEEL_R
    assert (drive.left_joint, drive.right_joint) == (f"{namespace}wheel_left_joint", f"{namespace}wheel_right_joint")
    # What a URDF does not say is listed for the catalogue to supply; the lidar and the drive are not in it.
    assert not any(m.startswith(("lidar:", "drive:")) for m in robot.missing)
    assert any("beams" in m for m in robot.missing)
    # The visuals' meshes are not shipped with the descriptions: warned about and skipped, not an error.
    assert any("burger_base.stl not found" in w for w in robot.warnings)


# turtlebot3_waffle.urdf and _waffle_pi.urdf: base box 0.266 wide centred at x -0.064; wheels at y +-0.144;
# scan_joint at (-0.064, 0, 0.122); the Waffle's camera box (0.012 deep) at 0.064 + 0.003, the Waffle Pi's
# (0.015 deep) at 0.073 + 0.005.
@pytest.mark.parametrize("namespace", NAMESPACES)
@pytest.mark.parametrize(("model", "front"), [("waffle", 0.064 + 0.003 + 0.006), ("waffle_pi", 0.073 + 0.005 + 0.0075)])
def test_waffles_load(model: str, front: float, namespace: str) -> None:
    robot = load_description(TURTLEBOT3 / f"turtlebot3_{model}.urdf", {"namespace": namespace},
                             lidar=f"{namespace}base_scan")
    assert all(link.startswith(namespace) for link in robot.links)
    xmin, _, xmax, ymax = robot.footprint.bounds
    assert (xmin, xmax) == pytest.approx((-0.064 - 0.133, front), abs=1e-9)
    assert ymax == pytest.approx(0.144 + WHEEL_HALF * math.sin(1.57) + WHEEL_R * math.cos(1.57), abs=1e-8)
    assert robot.lidar is not None
    assert (robot.lidar.x, robot.lidar.z) == pytest.approx((-0.064, 0.010 + 0.122), abs=1e-12)
    assert robot.drive is not None and robot.drive.wheel_separation == pytest.approx(0.288, abs=1e-12)


ROUND = """<?xml version="1.0"?>
<robot name="round">
  <link name="base_footprint"/>
  <link name="base_link"><collision><origin xyz="0.01 0 0.1"/>
    <geometry><cylinder radius="0.2" length="0.15"/></geometry></collision></link>
  <joint name="base_joint" type="fixed"><parent link="base_footprint"/><child link="base_link"/></joint>
  <link name="laser"/>
  <joint name="laser_joint" type="fixed"><parent link="base_link"/><child link="laser"/>
    <origin xyz="0.05 0 0.2" rpy="0 0 1.5707963267948966"/></joint>
  {wheels}
</robot>
"""
WHEEL = """<link name="w{side}"><collision><origin rpy="1.5707963267948966 0 0"/>
    <geometry><cylinder radius="0.035" length="0.02"/></geometry></collision></link>
  <joint name="j{side}" type="continuous"><parent link="base_footprint"/><child link="w{side}"/>
    <origin xyz="0 {y} 0.035"/><axis xyz="0 1 0"/></joint>"""


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def test_round_robot_has_a_circle_footprint(tmp_path: Path) -> None:
    wheels = WHEEL.format(side="l", y=0.115) + WHEEL.format(side="r", y=-0.115)
    robot = load_description(_write(tmp_path, "round.urdf", ROUND.format(wheels=wheels)), lidar="laser")
    # The wheels lie within the body's disc, so the footprint is that disc.
    assert robot.footprint == Circle(pytest.approx(0.01), 0.0, 0.2)
    assert robot.lidar is not None
    assert (robot.lidar.x, robot.lidar.z, robot.lidar.yaw) == pytest.approx((0.05, 0.2, math.pi / 2))
    assert robot.drive is not None
    assert (robot.drive.wheel_separation, robot.drive.wheel_radius) == pytest.approx((0.23, 0.035))
    # A wheel reaching out of the disc makes the footprint a polygon around both.
    wheels = WHEEL.format(side="l", y=0.2) + WHEEL.format(side="r", y=-0.115)
    robot = load_description(_write(tmp_path, "wide.urdf", ROUND.format(wheels=wheels)))
    assert isinstance(robot.footprint, Polygon)
    assert robot.footprint.bounds[3] == pytest.approx(0.2 + 0.01)


def test_without_wheels_or_lidar_they_are_reported_missing(tmp_path: Path) -> None:
    robot = load_description(_write(tmp_path, "bare.urdf", ROUND.format(wheels="")))
    assert robot.drive is None and robot.lidar is None
    assert any(m.startswith("drive: no wheel joint") for m in robot.missing)
    assert any(m.startswith("lidar:") and "laser" in m for m in robot.missing)


def test_collision_mesh_that_is_there_is_read(tmp_path: Path) -> None:
    # A binary STL: one triangle with corners (0, 0, 0), (0.4, 0, 0), (0, 0.3, 0.2), scaled by 0.5 in the URDF.
    triangle = [(0.0, 0.0, 0.0), (0.4, 0.0, 0.0), (0.0, 0.3, 0.2)]
    body = struct.pack("<12f", 0, 0, 1, *(c for v in triangle for c in v)) + b"\0\0"
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "body.stl").write_bytes(b"\0" * 80 + struct.pack("<I", 1) + body)
    _write(tmp_path, "package.xml", "<package><name>my_robot</name></package>")
    robot = load_description(_write(tmp_path, "mesh.urdf", """<robot name="m"><link name="base_link">
      <collision><origin xyz="1 0 0"/><geometry><mesh filename="package://my_robot/meshes/body.stl"
        scale="0.5 0.5 0.5"/></geometry></collision></link></robot>"""))
    assert isinstance(robot.footprint, Polygon)
    # float32 in the file: equal to 1e-7.
    flat = [c for point in robot.footprint.points for c in point]
    assert flat == pytest.approx([1.0, 0.0, 1.2, 0.0, 1.0, 0.15], abs=1e-7)
    assert [part.kind for part in robot.parts] == ["mesh"]


# --- bad input -----------------------------------------------------------------------------------------------


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(DescriptionError, match=r"nope\.urdf: no such file"):
        load_description(tmp_path / "nope.urdf")


def test_xml_that_does_not_parse_names_line_and_column(tmp_path: Path) -> None:
    path = _write(tmp_path, "bad.urdf", '<?xml version="1.0"?>\n<robot name="r">\n  <link name="a">\n  </lnk>\n'
                                        "</robot>\n")
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value) == f"{path}:4:5: XML does not parse: mismatched tag"


def test_errors_name_the_file_as_it_was_given(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _write(tmp_path, "bad.urdf", '<robot name="r">\n  <link name="a">\n  </lnk>\n</robot>\n')
    _write(tmp_path, "bad.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                  '  <link name="${wide}"/>\n</robot>\n')
    monkeypatch.chdir(tmp_path)
    for name, message in (("bad.urdf", "bad.urdf:3:5: XML does not parse"), ("bad.xacro", "bad.xacro:2: xacro error")):
        with pytest.raises(DescriptionError) as caught:
            load_description(Path(name))
        assert str(caught.value).startswith(message), caught.value


def test_xacro_error_names_the_line_of_the_expression(tmp_path: Path) -> None:
    path = _write(tmp_path, "bad.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                         '  <link name="a"><collision><geometry>\n'
                                         '    <box size="${width} 1 1"/></geometry></collision></link>\n</robot>\n')
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value).startswith(f"{path}:3: xacro error: name 'width' is not defined")
    # an expression whose text stands earlier in a name or a word: the line of the ${...}
    path = _write(tmp_path, "short.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                           '  <link name="${a}"/>\n</robot>\n')
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value).startswith(f"{path}:2: xacro error: name 'a' is not defined"), caught.value


def test_xacro_argument_not_given_and_find_without_ros(tmp_path: Path) -> None:
    path = _write(tmp_path, "arg.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                         '  <link name="$(arg prefix)a"><collision><geometry><box size="1 1 1"/>'
                                         "</geometry></collision></link>\n</robot>\n")
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value) == (f"{path}:2: xacro error: Undefined substitution argument prefix "
                                 "(give it: --arg prefix:=VALUE)")
    assert load_description(path, {"prefix": "left_"}).base_link == "left_a"
    path = _write(tmp_path, "find.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                          '  <xacro:include filename="$(find my_robot)/urdf/common.xacro"/>\n'
                                          "</robot>\n")
    with pytest.raises(DescriptionError, match=r"find\.xacro:2: xacro error: \$\(find PKG\) needs a ROS installation"):
        load_description(path)


def test_an_argument_declared_by_an_included_file_is_declared(tmp_path: Path) -> None:
    _write(tmp_path, "parts.xacro", '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                    '  <xacro:arg name="w" default="1"/>\n  <link name="a"><collision><geometry>'
                                    '<box size="$(arg w) 1 1"/></geometry></collision></link>\n</robot>\n')
    path = _write(tmp_path, "top.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                         '  <xacro:include filename="parts.xacro"/>\n</robot>\n')
    robot = load_description(path, {"w": "2"})
    assert robot.warnings == () and robot.footprint.bounds == (-1.0, -0.5, 1.0, 0.5)
    warning = "xacro argument 'v' is not declared by the file (it declares: w)"
    assert load_description(path, {"v": "2"}).warnings == (warning,)


def test_xacro_include_that_is_missing(tmp_path: Path) -> None:
    path = _write(tmp_path, "inc.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                         '  <xacro:include filename="parts.xacro"/>\n</robot>\n')
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    # the include's line, the path once (xacro's message said it twice, with no line)
    assert str(caught.value) == f"{path}:2: xacro error: the included file {tmp_path / 'parts.xacro'} is not there"
    middle = _write(tmp_path, "middle.xacro", '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n\n'
                                              '  <xacro:include filename="gone.xacro"/>\n</robot>\n')
    top = _write(tmp_path, "top.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                        '  <xacro:include filename="middle.xacro"/>\n</robot>\n')
    with pytest.raises(DescriptionError) as caught:
        load_description(top)
    assert str(caught.value) == (f"{middle}:3: xacro error: the included file {tmp_path / 'gone.xacro'} is not "
                                 f"there (included from {top})")


def test_xml_error_in_an_included_file_names_that_file(tmp_path: Path) -> None:
    parts = _write(tmp_path, "parts.xacro", '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n<link name="a">\n'
                                            "</robot>\n")
    path = _write(tmp_path, "inc.xacro", '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                         '  <xacro:include filename="parts.xacro"/>\n</robot>\n')
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value) == f"{parts}:3:3: XML does not parse: mismatched tag"


def test_urdf_the_parser_refuses_names_the_line_of_the_element(tmp_path: Path) -> None:
    path = _write(tmp_path, "bad.urdf", '<robot name="r">\n\n  <link name="a"><collision><geometry>'
                                        '<box size="1 1"/></geometry></collision></link>\n</robot>\n')
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value).startswith(f"{path}:3: not a valid URDF: Invalid vector length (at /robot")
    path = _write(tmp_path, "joint.urdf", '<robot name="r">\n  <link name="a"/>\n'
                                          '  <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>\n'
                                          "</robot>\n")
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value) == (f"{path}:3: not a valid URDF: joint 'j' names child link 'b', which does not exist")


def test_an_xml_file_that_is_not_a_urdf_says_its_root_element(tmp_path: Path) -> None:
    path = _write(tmp_path, "package.xml", '<?xml version="1.0"?>\n<!-- a ROS package -->\n'
                                           '<package format="3">\n  <name>r</name>\n</package>\n')
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value) == f"{path}:3: not a URDF: its root element is <package>, a URDF's is <robot>"


def test_lidar_link_that_does_not_exist_says_did_you_mean() -> None:
    with pytest.raises(DescriptionError) as caught:
        load_description(BURGER, {"namespace": "tb3/"}, lidar="base_scan")
    assert str(caught.value) == f"{BURGER}: no link named 'base_scan' for the lidar; did you mean 'tb3/base_scan'?"
    with pytest.raises(DescriptionError) as caught:
        load_description(BURGER, lidar="laser")
    assert str(caught.value) == (f"{BURGER}: no link named 'laser' for the lidar (links: base_footprint, base_link, "
                                 "wheel_left_link, wheel_right_link, caster_back_link, imu_link, base_scan)")


def test_no_collision_shape_at_all(tmp_path: Path) -> None:
    # Its only collision shape is a mesh that is not there: as good as none.
    path = _write(tmp_path, "ghost.urdf", '<robot name="g"><link name="base_link">'
                                          '<visual><geometry><box size="1 1 1"/></geometry></visual>'
                                          '<collision><geometry><mesh filename="package://nowhere/body.stl"/>'
                                          "</geometry></collision></link></robot>")
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    message = str(caught.value)
    assert message.startswith(f"{path}: the robot has no collision shape")
    assert "package://nowhere/body.stl not found" in message


# A collision mesh that is there but does not read, sizes that are not lengths, shapes without area: each an error
# naming the file, the link's line and what is wrong (they were tracebacks, or a footprint of nan or of one point).
MESH_URDF = """<?xml version="1.0"?>
<robot name="m">
  <link name="base_link">
    <collision><geometry><mesh filename="{mesh}"/></geometry></collision>
  </link>
</robot>
"""
BAD_MESHES = {
    "truncated.stl": (b"\0" * 80 + struct.pack("<I", 10) + b"\0" * 50,
                      "does not read: a binary STL of 10 triangles needs 584 bytes, the file has 134"),
    "empty.stl": (b"", "does not read: 0 bytes, less than a binary STL's 84-byte header"),
    "no_triangles.stl": (b"\0" * 80 + struct.pack("<I", 0), "has no vertices"),
    "letters.stl": ((b"solid s\n facet normal 0 0 1\n  outer loop\n   vertex 1 2 abc\n   vertex 0 0 0\n"
                     b"   vertex 0 1 0\n  endloop\n endfacet\nendsolid s\n"),
                    "does not read: an ASCII STL vertex that is not three numbers"),
    "flat.obj": (b"# two coordinates\nv 1 2\nv 0 0 0\n", "does not read: line 2: a vertex is 'v X Y Z', not 'v 1 2'"),
    "nothing.obj": (b"# no vertex\n", "has no vertices"),
}


@pytest.mark.parametrize("mesh", sorted(BAD_MESHES))
def test_a_collision_mesh_that_does_not_read_is_an_error_at_its_link(tmp_path: Path, mesh: str) -> None:
    data, what = BAD_MESHES[mesh]
    (tmp_path / mesh).write_bytes(data)
    path = _write(tmp_path, "robot.urdf", MESH_URDF.format(mesh=mesh))
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value) == f"{path}:3: link base_link: collision mesh {mesh} ({tmp_path / mesh}) {what}"


SHAPE_URDF = """<?xml version="1.0"?>
<robot name="s">
  <link name="base_link">
    <collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision>
  </link>
  <link name="arm">
    <collision><geometry>{shape}</geometry></collision>
  </link>
  <joint name="arm_joint" type="fixed"><parent link="base_link"/><child link="arm"/></joint>
</robot>
"""


@pytest.mark.parametrize(("shape", "what"), [
    ('<box size="nan 0.2 0.1"/>', "the collision box's size must be finite and at least 0, not nan 0.2 0.1"),
    ('<cylinder radius="-0.2" length="0.1"/>', "the collision cylinder's radius must be finite and at least 0, not -0.2"),
    ('<cylinder radius="0.2" length="inf"/>', "the collision cylinder's length must be finite and at least 0, not inf"),
    ('<sphere radius="-1"/>', "the collision sphere's radius must be finite and at least 0, not -1"),
])
def test_a_collision_size_that_is_not_a_length_is_an_error_at_its_link(tmp_path: Path, shape: str,
                                                                        what: str) -> None:
    path = _write(tmp_path, "robot.urdf", SHAPE_URDF.format(shape=shape))
    with pytest.raises(DescriptionError) as caught:
        load_description(path)
    assert str(caught.value) == f"{path}:6: link arm: {what}"


def test_collision_shapes_without_area_are_an_error_and_a_zero_size_part_is_not(tmp_path: Path) -> None:
    # a zero-size box beside a real one adds a point inside the outline: harmless
    robot = load_description(_write(tmp_path, "robot.urdf", SHAPE_URDF.format(shape='<box size="0 0 0"/>')))
    assert isinstance(robot.footprint, Polygon) and robot.footprint.area == pytest.approx(0.06)
    for name, shapes in (("point.urdf", '<box size="0 0 0"/>'), ("segment.urdf", '<box size="0.4 0 0.1"/>'),
                         ("dot.urdf", '<sphere radius="0"/>')):
        path = _write(tmp_path, name, f'<robot name="p"><link name="base_link"><collision><geometry>{shapes}'
                                      "</geometry></collision></link></robot>")
        with pytest.raises(DescriptionError) as caught:
            load_description(path)
        assert str(caught.value).startswith(f"{path}: the robot's collision shapes have no area on the floor "
                                            "(base_link "), caught.value


def test_a_continuous_joint_about_a_zero_axis_is_not_a_wheel(tmp_path: Path) -> None:
    wheels = WHEEL.format(side="l", y=0.115) + WHEEL.format(side="r", y=-0.115).replace('xyz="0 1 0"', 'xyz="0 0 0"')
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy's "invalid value encountered in divide" was printed, then nan
        robot = load_description(_write(tmp_path, "round.urdf", ROUND.format(wheels=wheels)))
    assert robot.drive is None
    assert any(m.startswith("drive: 1 wheel joints") for m in robot.missing), robot.missing


def test_sources_are_the_description_its_xacro_includes_and_its_collision_meshes(tmp_path: Path) -> None:
    # what a reader that keeps reads (the generator's warm JVM) must watch to see an edit
    (tmp_path / "mesh").mkdir()
    triangle = struct.pack("<12f", 0, 0, 1, 0, 0, 0, 0.4, 0, 0, 0, 0.3, 0) + b"\0\0"
    (tmp_path / "mesh" / "body.stl").write_bytes(b"\0" * 80 + struct.pack("<I", 1) + triangle)
    _write(tmp_path, "props.xacro", '<robot xmlns:xacro="http://ros.org/wiki/xacro">'
                                    '<xacro:property name="body" value="mesh/body.stl"/></robot>')
    path = _write(tmp_path, "bot.xacro", '<robot name="b" xmlns:xacro="http://ros.org/wiki/xacro">'
                                         '<xacro:include filename="props.xacro"/><link name="base_link">'
                                         '<visual><geometry><mesh filename="mesh/visual.stl"/></geometry></visual>'
                                         '<collision><geometry><mesh filename="${body}"/></geometry></collision>'
                                         "</link></robot>")
    robot = load_description(path)
    assert robot.sources == (path, tmp_path / "props.xacro", tmp_path / "mesh" / "body.stl")


def test_a_lidar_link_missing_for_a_misspelt_argument_says_so() -> None:
    with pytest.raises(DescriptionError) as caught:
        load_description(BURGER, {"namespce": "tb3/"}, lidar="tb3/base_scan")
    assert str(caught.value) == (f"{BURGER}: no link named 'tb3/base_scan' for the lidar; did you mean 'base_scan'?; "
                                 "xacro argument 'namespce' is not declared by the file (it declares: namespace)")


def test_a_joint_origin_that_is_not_finite_is_an_error_at_the_joint(tmp_path: Path) -> None:
    # the lidar's joint: its pose went into world.json as nan
    text = ROUND.format(wheels="").replace('<origin xyz="0.05 0 0.2"', '<origin xyz="0.05 0 nan"')
    path = _write(tmp_path, "round.urdf", text)
    with pytest.raises(DescriptionError) as caught:
        load_description(path, lidar="laser")
    assert str(caught.value) == f"{path}:8: not a valid URDF: joint 'laser_joint': its <origin> is not finite"
