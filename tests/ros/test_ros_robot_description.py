# SPDX-License-Identifier: EPL-2.0
"""Both ROS bridges give the stack the robot's description and fixed frames, as robot_state_publisher would
(docs/ros.md): /robot_description is the URDF REI read (a described robot's expanded description, a box robot's
the URDF REI's simulator builds) and /tf_static holds base_link -> base_scan at world.json's lidar pose. The reader
is a node that joins at t = 1 s, long after the bridge published both before starting the stack: it still gets
them (ROS 1: the parameter and a latched topic; ROS 2: transient-local). Real processes, as the other tests here:
a private ROS master and rospy nodes, or DDS in the run's own domain; the stack plays a strafing script."""

from __future__ import annotations

import json
import math
import shlex
from pathlib import Path

import pytest

from rei.artifacts.world import read_world
from rei.sim.robot_model import render_urdf

NODES = {"ros1": ("examples/sut/ros1/ram_node.py", "_script:={script}"),
         "ros2": ("examples/sut/ros2/reference_nav_node.py", "--script {script}")}
RECORDERS = {"ros1": "tests/ros/programs/description_recorder.py",
             "ros2": "tests/ros/programs/description_recorder_dds.py"}


def _round_robot_case(repo_root: Path, folder: Path) -> Path:
    """examples/robots/strafe.rei with the round robot of examples/robots/round_bot.urdf on a holonomic drive."""
    folder.mkdir()
    (folder / "round_bot.urdf").write_text((repo_root / "examples/robots/round_bot.urdf").read_text())
    (folder / "catalogue.rei").write_text("""catalogue OmniRound {
  robot type OmniRoundBot : urdf "round_bot.urdf" mass 2.5 speed 0.3 turn 2.0 drive holonomic
    lidar link "laser" beams 360 range 0.12 to 3.5 rate 10
}
""")
    strafe = (repo_root / "examples/robots/strafe.rei").read_text()
    (folder / "strafe.rei").write_text(strafe.replace('import "omni_base.rei"', 'import "catalogue.rei"')
                                       .replace("omni : OmniBase", "omni : OmniRoundBot"))
    return folder / "strafe.rei"


@pytest.mark.parametrize("robot", ["urdf", "box"])
@pytest.mark.parametrize("bridge", ["ros1", "ros2"])
def test_a_late_node_gets_the_robot_s_description_and_its_lidar_frame(
    bridge: str, robot: str, run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    case = (_round_robot_case(repo_root, tmp_path / "case") if robot == "urdf"
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
    if robot == "urdf":
        assert world["description"] == "robot.urdf"
        assert got["urdf"] == (out / "case" / "robot.urdf").read_text()  # the expanded description REI read
        assert '<joint name="laser_joint" type="fixed">' in got["urdf"]
        lidar = world["lidarPose"]
        assert lidar == pytest.approx([0.05, 0.0, 0.18, 0.0])  # round_bot.urdf's laser_joint
    else:
        assert "description" not in world
        assert got["urdf"] == render_urdf(read_world(out / "case" / "world.json").robot)  # the simulator's URDF
        assert '<robot name="omni">' in got["urdf"] and "<box " in got["urdf"]
        lidar = [0.0, 0.0, world["lidar"]["mountHeight"], 0.0]
        assert lidar[2] == 0.25  # omni_base.rei's lidar height
    [edge] = got["tf_static"]
    assert (edge["parent"], edge["child"]) == ("base_link", "base_scan")  # the scans' frame
    assert edge["translation"] == pytest.approx(lidar[:3], abs=1e-12)
    assert edge["rotation"] == pytest.approx([0.0, 0.0, math.sin(lidar[3] / 2), math.cos(lidar[3] / 2)], abs=1e-12)
