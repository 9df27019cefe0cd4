# SPDX-License-Identifier: EPL-2.0
"""A robot type read from its URDF description (#41): the TurtleBot3 Burger as published (the shared data folder,
never copied into the repository; its absolute path is written into a temporary catalogue) generates a world.json
with its collision shapes' outline, a description that does not read is an error at the catalogue entry with
nothing generated, and a scripted drive into a table gives the monitor's FAR->CLOSE and CLOSE->COLLISION at the
state samples an independent computation on that outline predicts. Real processes: the Java generator calling
the Python reader, the simulator and the monitor jar."""

from __future__ import annotations

import json
import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from rei.artifacts.world import CircleFootprint, PolygonFootprint, read_world
from rei.run.jvm import JarServer, run_jar
from rei.wamp.recording import read_recording

REPO = Path(__file__).resolve().parents[2]
BURGER = REPO.parent / "shared" / "data" / "robots" / "turtlebot3" / "turtlebot3_burger.urdf"
LINE = re.compile(r"^\s*\d+\s+(\S+)\s+(SIG_\S+)\s+(\S+)\s+(\S*)\s+\S+\s*$")


def catalogue(folder: Path, lidar: str = "base_scan") -> Path:
    assert BURGER.is_file(), f"the TurtleBot3 descriptions are expected in {BURGER.parent}"
    path = folder / "robots.rei"
    path.write_text(f'catalogue Robots {{\n  robot type Burger : urdf "{BURGER}" arg namespace ""\n'
                    f'    mass 1.0 speed 0.22 turn 2.84 lidar link "{lidar}" rate 5\n}}\n', encoding="utf-8")
    return path


def case(folder: Path, lidar: str = "base_scan") -> Path:
    catalogue(folder, lidar)
    path = folder / "burger.rei"
    path.write_text('import "robots.rei"\ntestcase BurgerIntoTable {\n  room Lane size 4 x 1 {\n'
                    '    object table : Table on F_2_0\n    robot burger : Burger on F_0_0\n  }\n'
                    '  mission M { tolerance 0.5 goto F_1_0 within 60s goto F_1_0 }\n  monitor { close 0.25 collision 0.01 }\n}\n',
                    encoding="utf-8")
    return path


def test_the_burger_generates_with_its_collision_outline(run_cli, tmp_path: Path) -> None:
    result = run_cli("generate", case(tmp_path), "-o", tmp_path / "out", "--quiet")
    assert result.returncode == 0, result.stderr
    # its visuals are meshes of a ROS package that is not here: said at the catalogue entry, the body is collisions
    warned = re.findall(r"^(.*robots\.rei):2:3: warning: The robot's description: link (\w+): visual mesh "
                        r"package://\S+ not found: visual skipped \[org\.rei\.dsl\.robotDescription\]$",
                        result.stderr, flags=re.MULTILINE)
    assert [link for _, link in warned] == ["base_link", "wheel_left_link", "wheel_right_link", "base_scan"]
    raw = json.loads((tmp_path / "out" / "world.json").read_text())["robot"]
    world = read_world(tmp_path / "out" / "world.json").robot
    assert isinstance(world.footprint, PolygonFootprint)
    points = np.array(world.footprint.points)
    # the URDF's numbers: the caster's box reaches back to x = -0.081 - 0.042/2 = -0.102 (its collision box is
    # 0.030 x 0.009 x 0.020 at x -0.081: the hull's back is the base box's -0.032 - 0.140/2 = -0.102), the base box
    # forward to -0.032 + 0.070 = 0.038, the wheels (radius 0.033, 0.018 wide, at y +-0.08) out to y +-0.089
    assert points[:, 0].min() == pytest.approx(-0.102, abs=1e-6)
    assert points[:, 0].max() == pytest.approx(0.038, abs=1e-6)
    assert points[:, 1].max() == pytest.approx(0.089, abs=1e-4) and points[:, 1].min() == pytest.approx(-0.089, abs=1e-4)
    assert raw["size"][:2] == pytest.approx([0.14, 0.178052551856], abs=1e-6)
    assert world.lidar_pose == pytest.approx((-0.032, 0.0, 0.182, 0.0))
    assert (world.lidar.x, world.lidar.mount_height) == pytest.approx((-0.032, 0.182))
    assert (world.drive.wheel_separation, world.drive.wheel_radius) == pytest.approx((0.16, 0.033))
    assert world.drive.max_linear_velocity == 0.22 and world.lidar.rate == 5  # the catalogue's, not in a URDF
    assert world.description is not None and "<robot" in world.description.read_text()


def test_a_description_that_does_not_read_is_an_error_at_the_catalogue_entry(run_cli, tmp_path: Path) -> None:
    result = run_cli("generate", case(tmp_path, lidar="base_scn"), "-o", tmp_path / "out", "--quiet")
    assert result.returncode == 1
    assert f"{tmp_path / 'robots.rei'}:2:" in result.stderr, result.stderr
    assert "no link named 'base_scn' for the lidar; did you mean 'base_scan'?" in result.stderr, result.stderr
    assert not (tmp_path / "out" / "world.json").exists()


def test_a_missing_description_fails_validation_at_the_catalogue_entry(run_cli, tmp_path: Path) -> None:
    path = case(tmp_path)
    (tmp_path / "robots.rei").write_text((tmp_path / "robots.rei").read_text().replace(str(BURGER), "gone.urdf"))
    result = run_cli("validate", path)
    assert result.returncode == 1
    assert f"{tmp_path / 'robots.rei'}:2:28: error: Cannot read the robot's description 'gone.urdf'" \
        in result.stdout + result.stderr, result.stdout + result.stderr


def _distance(a: np.ndarray, b: np.ndarray) -> float:
    """Distance between two convex polygons ((N, 2) arrays, any orientation): 0 when they overlap (no axis of
    their edges separates them), else the shortest vertex-to-edge distance either way."""
    for poly in (a, b):
        for i in range(len(poly)):
            edge = poly[(i + 1) % len(poly)] - poly[i]
            axis = np.array([-edge[1], edge[0]])
            pa, pb = a @ axis, b @ axis
            if pa.max() < pb.min() or pb.max() < pa.min():
                break
        else:
            continue
        break
    else:
        return 0.0

    def point_edges(points: np.ndarray, poly: np.ndarray) -> float:
        best = math.inf
        for i in range(len(poly)):
            p, q = poly[i], poly[(i + 1) % len(poly)]
            d = q - p
            t = np.clip(((points - p) @ d) / (d @ d), 0.0, 1.0)
            best = min(best, float(np.min(np.hypot(*(points - (p + t[:, None] * d)).T))))
        return best

    return min(point_edges(a, b), point_edges(b, a))


def test_driving_the_burger_into_a_table_signals_when_its_outline_gets_close(run_cli, tmp_path: Path) -> None:
    script = tmp_path / "ahead.script"
    script.write_text("# duration (s)  v (m/s)  w (rad/s)\n9.0  0.2  0.0\n1.0  0.0  0.0\n")
    out = tmp_path / "out"
    result = run_cli("sim", case(tmp_path), "-o", out, "--no-router", "--controller", f"script:{script}")
    assert result.returncode == 0, result.stderr
    states = read_recording(out / "streams" / "state.msgpack")
    world = read_world(next(out.rglob("world.json")))
    outline = np.array(world.robot.footprint.points)
    table = world.object("table")
    tx, ty, _, _ = table.pose
    hx, hy = table.size[0] / 2, table.size[1] / 2
    box = np.array([[tx - hx, ty - hy], [tx + hx, ty - hy], [tx + hx, ty + hy], [tx - hx, ty + hy]])

    def gap(state: dict) -> float:
        x, y, yaw = state["robot"]["pose"][0], state["robot"]["pose"][1], state["robot"]["pose"][-1]
        c, s = math.cos(yaw), math.sin(yaw)
        placed = outline @ np.array([[c, s], [-s, c]]) + np.array([x, y])
        return _distance(placed, box)

    times = [m["t"] for m in states]
    gaps = [gap(m) for m in states]
    # the simulator's body is the outline extruded: pushed against the table it stops with the outline touching
    # it (a body of another shape would stop short of it or let the outline sink in)
    assert 0.0 <= gaps[-1] < 0.004, gaps[-1]
    predicted = {}
    for signal, threshold in (("SIG_GEOM_FAR_TRANSIT_CLOSE", 0.25), ("SIG_GEOM_CLOSE_TRANSIT_COLLISION", 0.01)):
        predicted[signal] = next(t for t, g in zip(times, gaps, strict=True) if g <= threshold)
    replay = run_cli("monitor", "--replay", out)
    assert replay.returncode == 0, replay.stderr
    rows = [LINE.match(line) for line in replay.stdout.splitlines()]
    signalled = {}
    for m in rows:
        if m is not None and m[2] in predicted and m[4] == "table":
            signalled.setdefault(m[2], float(m[1]))
    period = float(np.median(np.diff(times)))
    for signal, t in predicted.items():
        assert signal in signalled, (signal, replay.stdout)
        assert abs(signalled[signal] - t) <= period + 1e-9, (signal, signalled[signal], t, period)
    # the outline, not its bounding box centred on the robot (what a box robot of the Burger's size would be): that
    # box reaches 32 mm further forward and would have been CLOSE more than a state sample earlier
    hx, hy = world.robot.size[0] / 2, world.robot.size[1] / 2
    outline = np.array([[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]])
    boxed = next(t for t, m in zip(times, states, strict=True) if gap(m) <= 0.25)
    assert signalled["SIG_GEOM_FAR_TRANSIT_CLOSE"] - boxed > period + 1e-9, (boxed, signalled)


def test_the_reference_navigation_completes_the_simple_navigation_example_with_the_burger(run_cli,
                                                                                          tmp_path: Path) -> None:
    catalogue(tmp_path)
    text = (REPO / "examples" / "simple_navigation.rei").read_text()
    path = tmp_path / "simple_navigation.rei"
    path.write_text('import "robots.rei"\n' + text.replace("robot tb3 : Waffle", "robot tb3 : Burger"))
    result = run_cli("sim", path, "-o", tmp_path / "out", "--no-router")
    assert result.returncode == 0 and "mission succeeded" in result.stdout, result.stdout + result.stderr
    assert read_world(tmp_path / "out" / "case" / "world.json").robot.footprint is not None


def test_the_round_robot_example_is_a_circle_and_completes_its_mission(run_cli, tmp_path: Path) -> None:
    example = REPO / "examples" / "robots" / "round_bot.rei"
    result = run_cli("sim", example, "-o", tmp_path / "out", "--no-router")
    assert result.returncode == 0 and "mission succeeded" in result.stdout, result.stdout + result.stderr
    robot = read_world(tmp_path / "out" / "case" / "world.json").robot
    assert robot.footprint == CircleFootprint(0.0, 0.0, 0.17)  # round_bot.urdf's body; its wheels are inside it
    assert robot.lidar_pose == pytest.approx((0.05, 0.0, 0.18, 0.0))
    assert (robot.drive.wheel_separation, robot.drive.wheel_radius) == pytest.approx((0.23, 0.035))


BAD = {
    "xml": ('<robot name="r">\n  <link name="a">\n</robot>\n', "XML does not parse"),
    "xacro": ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="${width}"/>\n</robot>\n',
              "xacro error: name 'width' is not defined"),
    "no-collision": (('<robot name="r">\n  <link name="base_footprint"/>\n  <link name="base_scan"/>\n'
                      '  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_scan"/></joint>\n'
                      '</robot>\n'), "the robot has no collision shape"),
    # the URDF parser takes nan: it reached world.json's footprint
    "nan-size": (('<robot name="r">\n  <link name="base_footprint">\n'
                  '    <collision><geometry><box size="nan 0.2 0.1"/></geometry></collision></link>\n'
                  '  <link name="base_scan"/>\n'
                  '  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_scan"/>'
                  '<origin xyz="0 0 0.2"/></joint>\n</robot>\n'),
                 "robot.urdf:2: link base_footprint: the collision box's size must be finite and at least 0, not nan"),
    # a lidar 2 cm up: generated, then the simulation failed (no body between 1 cm and the lidar)
    "low-lidar": (('<robot name="r">\n  <link name="base_footprint">\n'
                   '    <collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision></link>\n'
                   '  <link name="base_scan"/>\n'
                   '  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_scan"/>'
                   '<origin xyz="0 0 0.02"/></joint>\n</robot>\n'),
                  "the lidar's link base_scan is 0.0200 m above base_footprint"),
    # no wheel joints: the default wheels, 0.287 m apart, stuck out of the 0.14 m wide body, and pybullet's
    # contacts with them were collisions 7 cm from the outline
    "wheels-outside": (('<robot name="r">\n  <link name="base_footprint">\n'
                        '    <collision><origin xyz="0 0 0.08"/><geometry><box size="0.3 0.14 0.12"/></geometry>'
                        '</collision></link>\n  <link name="base_scan"/>\n'
                        '  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="base_scan"/>'
                        '<origin xyz="0 0 0.17"/></joint>\n</robot>\n'),
                       "the simulator's wheels (radius 0.033 m, 0.287 m apart"),
    # the catalogue's `arg namespace ""` for a file that declares `prefix`: generated as if not given
    "undeclared-arg": (('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                        '  <xacro:arg name="prefix" default=""/>\n  <link name="$(arg prefix)base_footprint">\n'
                        '    <collision><origin xyz="0 0 0.1"/><geometry><box size="0.4 0.4 0.2"/></geometry>'
                        '</collision></link>\n  <link name="$(arg prefix)base_scan"/>\n'
                        '  <joint name="j" type="fixed"><parent link="$(arg prefix)base_footprint"/>'
                        '<child link="$(arg prefix)base_scan"/><origin xyz="0 0 0.2"/></joint>\n</robot>\n'),
                       "xacro argument 'namespace' is not declared by the file (it declares: prefix)"),
}


@pytest.mark.parametrize("kind", sorted(BAD))
def test_a_bad_description_is_an_error_at_the_catalogue_entry_and_nothing_is_generated(run_cli, tmp_path: Path,
                                                                                      kind: str) -> None:
    text, message = BAD[kind]
    (tmp_path / "robot.urdf").write_text(text)
    path = case(tmp_path)
    robots = tmp_path / "robots.rei"
    robots.write_text(robots.read_text().replace(str(BURGER), "robot.urdf"))
    assert run_cli("validate", path).returncode == 0  # the entry itself is sound: the file is there
    result = run_cli("generate", path, "-o", tmp_path / "out", "--quiet")
    assert result.returncode == 1
    assert f"{robots}:2:28: error: The robot's description does not read: " in result.stderr, result.stderr
    assert message in result.stderr, result.stderr
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_a_warm_generator_reads_a_description_again_when_a_file_it_includes_changed(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # One JVM for many generations, as a campaign's, a search's and `rei run`'s background service: it kept the
    # first read as long as the top file was unchanged, so an edited xacro include (or mesh) was not seen.
    monkeypatch.setenv("REI_PYTHON", sys.executable)
    body = tmp_path / "body.xacro"
    (tmp_path / "bot.xacro").write_text(
        '<robot name="bot" xmlns:xacro="http://ros.org/wiki/xacro">\n  <xacro:include filename="body.xacro"/>\n'
        '  <link name="base_footprint"><collision><origin xyz="0 0 0.1"/>'
        '<geometry><cylinder radius="${radius}" length="0.2"/></geometry></collision></link>\n'
        '  <link name="laser"/>\n  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="laser"/>'
        '<origin xyz="0 0 0.25"/></joint>\n</robot>\n', encoding="utf-8")
    (tmp_path / "robots.rei").write_text('catalogue Inc { robot type Bot : urdf "bot.xacro" mass 2 lidar link "laser" }\n',
                                         encoding="utf-8")
    case = tmp_path / "bot.rei"
    case.write_text('import "robots.rei"\ntestcase Inc {\n  room Lab size 4 x 2 { robot b : Bot on F_0_0 }\n'
                    '  mission M { goto F_1_0 goto F_3_1 }\n  monitor { close 0.25 collision 0.01 }\n}\n',
                    encoding="utf-8")
    with JarServer("cli", tmp_path / "server.log") as server:
        for i, radius in enumerate(("0.2", "0.25", "0.22")):
            body.write_text('<robot xmlns:xacro="http://ros.org/wiki/xacro">'
                            f'<xacro:property name="radius" value="{radius}"/></robot>\n', encoding="utf-8")
            out = tmp_path / f"out{i}"
            result = run_jar("cli", ["generate", str(case), "-o", str(out), "--quiet"], tmp_path / f"g{i}.log",
                             server=server.socket)
            assert result.code == 0 and result.served, result.log_tail
            footprint = read_world(out / "world.json").robot.footprint
            assert isinstance(footprint, CircleFootprint) and footprint.radius == float(radius), (radius, footprint)
