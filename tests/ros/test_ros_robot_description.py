# SPDX-License-Identifier: EPL-2.0
"""Both ROS bridges give the stack the robot's description and fixed frames, as robot_state_publisher would
(docs/ros.md): /robot_description is the URDF REI read (a described robot's expanded description, a box robot's
the URDF REI's simulator builds), /tf_static holds every fixed joint of a description (a box robot's: base_link ->
base_scan at world.json's lidar pose), and /scan and /odom are in the robot's own frames (a description's lidar
link and root link). The described robot is ROBOTIS's TurtleBot3 Burger as published (the shared data folder,
never copied into the repository) with the namespace argument "tb3/", so that every frame is renamed, on a
holonomic drive. The reader is a node that joins at t = 1 s, long after the bridge published both before starting
the stack: it still gets them (ROS 1: the parameter and a latched topic; ROS 2: transient-local). Real processes,
as the other tests here: a private ROS master and rospy nodes, or DDS in the run's own domain; the stack plays a
strafing script."""

from __future__ import annotations

import json
import math
import shlex
from pathlib import Path
from xml.etree import ElementTree

import pytest

from rei.artifacts.world import read_world
from rei.sim.robot_model import render_urdf

NODES = {"ros1": ("examples/sut/ros1/ram_node.py", "_script:={script}"),
         "ros2": ("examples/sut/ros2/reference_nav_node.py", "--script {script}")}
BURGER = (Path(__file__).resolve().parents[2].parent / "shared" / "data" / "robots" / "turtlebot3"
          / "turtlebot3_burger.urdf")
RECORDERS = {"ros1": "tests/ros/programs/description_recorder.py",
             "ros2": "tests/ros/programs/description_recorder_dds.py"}


def _burger_case(repo_root: Path, folder: Path) -> Path:
    """examples/robots/strafe.rei with the TurtleBot3 Burger, its frames prefixed "tb3/", on a holonomic drive."""
    assert BURGER.is_file(), f"the TurtleBot3 descriptions are expected in {BURGER.parent}"
    folder.mkdir()
    (folder / "catalogue.rei").write_text(f"""catalogue Burgers {{
  robot type OmniBurger : urdf "{BURGER}" arg namespace "tb3/" mass 1.0 speed 0.3 turn 2.0 drive holonomic
    lidar link "tb3/base_scan" beams 360 range 0.12 to 3.5 rate 10
}}
""")
    strafe = (repo_root / "examples/robots/strafe.rei").read_text()
    (folder / "strafe.rei").write_text(strafe.replace('import "omni_base.rei"', 'import "catalogue.rei"')
                                       .replace("omni : OmniBase", "omni : OmniBurger"))
    return folder / "strafe.rei"


def _fixed_joints(urdf: str) -> list[dict]:
    """Every fixed joint of ``urdf`` as /tf_static should carry it, read with the standard library's XML parser:
    the rotation is the product of the rotations about z, y and x by yaw, pitch and roll."""
    def about(axis: int, angle: float) -> list[float]:
        q = [0.0, 0.0, 0.0, math.cos(angle / 2)]
        q[axis] = math.sin(angle / 2)
        return q

    def product(a: list[float], b: list[float]) -> list[float]:
        (ax, ay, az, aw), (bx, by, bz, bw) = a, b
        return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
                aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]

    joints = []
    for joint in ElementTree.fromstring(urdf).iter("joint"):
        if joint.get("type") != "fixed":
            continue
        origin = joint.find("origin")
        xyz = [float(v) for v in (origin.get("xyz", "0 0 0") if origin is not None else "0 0 0").split()]
        roll, pitch, yaw = [float(v) for v in (origin.get("rpy", "0 0 0") if origin is not None else "0 0 0").split()]
        joints.append({"parent": joint.find("parent").get("link"), "child": joint.find("child").get("link"),
                       "translation": xyz, "rotation": product(product(about(2, yaw), about(1, pitch)), about(0, roll))})
    return joints


@pytest.mark.parametrize("robot", ["turtlebot3", "box"])
@pytest.mark.parametrize("bridge", ["ros1", "ros2"])
def test_a_late_node_gets_the_robot_s_description_and_its_fixed_frames(
    bridge: str, robot: str, run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    case = (_burger_case(repo_root, tmp_path / "case") if robot == "turtlebot3"
            else repo_root / "examples/robots/strafe.rei")
    out, recorded = tmp_path / "out", tmp_path / "description.json"
    script = repo_root / "examples/robots/strafe.script"
    program, argument = NODES[bridge]
    node = f"python3 {repo_root / program} {argument.format(script=script)} {out}"
    recorder = shlex.join(["python3", str(repo_root / RECORDERS[bridge]), str(recorded)])
    result = run_cli("sim", case, "-o", out, "--progress", "none",
                     "--sut", f"{bridge}:sh -c {shlex.quote(f'{recorder} & exec {node}')}", timeout=400)
    assert result.returncode == 0 and "mission succeeded" in result.stdout, \
        result.stdout + result.stderr + (out / "sut.log").read_text()
    assert processes_mentioning(out) == []

    world = json.loads((out / "case" / "world.json").read_text())["robot"]
    got = json.loads(recorded.read_text())
    assert got["joined"] >= 1001.0  # it joined at t >= 1 s, after the bridge had published
    if robot == "turtlebot3":
        assert world["description"] == "robot.urdf" and world["lidarLink"] == "tb3/base_scan"
        assert got["urdf"] == (out / "case" / "robot.urdf").read_text()  # the expanded description REI read
        expected = _fixed_joints(got["urdf"])
        # turtlebot3_burger.urdf's fixed joints: base_joint, caster_back_joint, imu_joint, scan_joint
        assert [(e["parent"], e["child"]) for e in expected] == [
            ("tb3/base_footprint", "tb3/base_link"), ("tb3/base_link", "tb3/caster_back_link"),
            ("tb3/base_link", "tb3/imu_link"), ("tb3/base_link", "tb3/base_scan")]
        assert expected[3]["translation"] == [-0.032, 0.0, 0.172]
        assert (got["scan_frame"], got["odom_frames"]) == ("tb3/base_scan", ["odom", "tb3/base_footprint"])
    else:
        assert "description" not in world and "lidarLink" not in world
        assert got["urdf"] == render_urdf(read_world(out / "case" / "world.json").robot)  # the simulator's URDF
        assert '<robot name="omni">' in got["urdf"] and "<box " in got["urdf"]
        assert world["lidar"]["mountHeight"] == 0.25  # omni_base.rei's lidar height
        expected = [{"parent": "base_link", "child": "base_scan", "translation": [0.0, 0.0, 0.25],
                     "rotation": [0.0, 0.0, 0.0, 1.0]}]
        assert (got["scan_frame"], got["odom_frames"]) == ("base_scan", ["odom", "base_link"])
    assert [(e["parent"], e["child"]) for e in got["tf_static"]] == [(e["parent"], e["child"]) for e in expected]
    for edge, want in zip(got["tf_static"], expected, strict=True):
        assert edge["translation"] == pytest.approx(want["translation"], abs=1e-12), edge
        assert edge["rotation"] == pytest.approx(want["rotation"], abs=1e-12), edge
