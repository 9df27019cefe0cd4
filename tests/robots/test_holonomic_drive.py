# SPDX-License-Identifier: EPL-2.0
"""A holonomic robot (#41, item 3: catalogue 'drive holonomic'): it strafes sideways to a goal on a script that
commands the sideways speed vy alone, its heading unchanged, where a differential robot given the same script does
not move (its vy is limited to 0, docs/robots.md#drives); the reference navigation strafes it to that goal too. Real processes: the Java generator and the simulator."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from rei.artifacts import ArtifactError
from rei.artifacts.world import read_world
from rei.wamp.recording import read_recording

CATALOGUE = """catalogue Bases {
  robot type Omni : box 0.4 x 0.4 x 0.3 mass 12 speed 0.3 turn 1.5 drive holonomic
  robot type Diff : box 0.4 x 0.4 x 0.3 mass 12 speed 0.3 turn 1.5
}
"""
# facing +x (yaw 0) in a 1 x 4 m lane: the goal, 2 m away, is straight to the robot's left
CASE = """import "bases.rei"
testcase Strafe {
  room Lane size 1 x 4 {
    robot base : TYPE on F_0_0
  }
  mission M { tolerance 0.15 goto F_0_2 within 30s goto F_0_2 }
  monitor { close 0.25 collision 0.01 }
}
"""
SCRIPT = "# duration (s)  v  w  vy: sideways only, 6.6 s at 0.3 m/s, then stand\n6.6  0 0 0.3\n1.0  0 0 0\n"


def strafe(run_cli, folder: Path, robot_type: str, script_text: str = SCRIPT):
    (folder / "bases.rei").write_text(CATALOGUE, encoding="utf-8")
    case = folder / "strafe.rei"
    case.write_text(CASE.replace("TYPE", robot_type), encoding="utf-8")
    script = folder / "left.script"
    script.write_text(script_text, encoding="utf-8")
    out = folder / "out"
    result = run_cli("sim", case, "-o", out, "--no-router", "--controller", f"script:{script}")
    states = read_recording(out / "streams" / "state.msgpack")
    poses = np.array([[m["t"], m["robot"]["pose"][0], m["robot"]["pose"][1], m["robot"]["pose"][-1]]
                      for m in states])
    return result, out, poses


def test_a_holonomic_robot_strafes_sideways_to_its_goal(run_cli, tmp_path: Path) -> None:
    result, out, poses = strafe(run_cli, tmp_path, "Omni")
    assert result.returncode == 0 and "mission succeeded" in result.stdout, result.stdout + result.stderr
    assert json.loads((out / "case" / "world.json").read_text())["robot"]["drive"]["kind"] == "holonomic"
    assert read_world(out / "case" / "world.json").robot.drive.holonomic
    t, x, y, yaw = poses.T
    # y moves the 2 m to the goal (6.6 s at 0.3 m/s, less the ramps of its 2.5 m/s^2), x and the heading stay
    assert y[0] == pytest.approx(0.5, abs=1e-3) and y[-1] == pytest.approx(2.48, abs=0.02)
    assert np.all(np.diff(y[t < 6.6]) > -1e-4)  # never back
    assert np.max(np.abs(x - 0.5)) < 0.005
    assert np.max(np.abs(yaw)) < 0.005  # rad: 0.3 degrees over 2 m sideways
    cruise = (t > 1.0) & (t < 6.5)
    speed = np.diff(y)[cruise[1:]] / np.diff(t)[cruise[1:]]
    # the command's speed, but for a few state samples where the wheels cross a seam between two floor blocks
    assert float(np.mean(speed)) == pytest.approx(0.3, abs=0.003) and speed == pytest.approx(0.3, abs=0.03)


def test_a_differential_robot_ignores_vy(run_cli, tmp_path: Path) -> None:
    (tmp_path / "vy").mkdir()
    (tmp_path / "still").mkdir()
    result, out, poses = strafe(run_cli, tmp_path / "vy", "Diff")
    assert result.returncode == 1 and "mission failed" in result.stdout, result.stdout + result.stderr
    # a box robot's world.json is as it always was: no drive kind
    assert "kind" not in json.loads((out / "case" / "world.json").read_text())["robot"]["drive"]
    # exactly what the robot does when told to stand still for as long (it settles a few mm on its casters)
    _, _, still = strafe(run_cli, tmp_path / "still", "Diff", "7.6  0 0 0\n")
    assert np.array_equal(poses, still)
    assert np.max(np.abs(poses[:, 2] - poses[0, 2])) < 0.005


def test_the_reference_navigation_strafes_a_holonomic_robot_to_a_goal_at_its_side(run_cli, tmp_path: Path) -> None:
    """The reference navigation (rei.sut.nav) drives the holonomic robot to the goal 2 m to its left by its sideways
    speed, its heading kept (0.03 degrees measured, at most 0.01 rad allowed) and its x within 5 mm; the
    differential robot on the same goal must turn a quarter round first."""
    (tmp_path / "bases.rei").write_text(CATALOGUE, encoding="utf-8")
    turned = {}
    for robot_type in ("Omni", "Diff"):
        case = tmp_path / f"{robot_type}.rei"
        case.write_text(CASE.replace("TYPE", robot_type), encoding="utf-8")
        out = tmp_path / robot_type
        result = run_cli("sim", case, "-o", out, "--no-router", "--controller", "nav")
        assert result.returncode == 0 and "mission succeeded" in result.stdout, result.stdout + result.stderr
        poses = np.array([[m["robot"]["pose"][0], m["robot"]["pose"][1], m["robot"]["pose"][-1]]
                          for m in read_recording(out / "streams" / "state.msgpack")])
        turned[robot_type] = float(np.max(np.abs(poses[:, 2])))
        if robot_type == "Omni":
            assert poses[-1, 1] - poses[0, 1] > 1.8 and np.max(np.abs(poses[:, 0] - 0.5)) < 0.005
    assert turned["Omni"] < 0.01 and turned["Diff"] > 1.0, turned


def test_a_stuck_wheel_is_refused_for_a_holonomic_robot_and_an_unknown_drive_in_world_json(run_cli,
                                                                                          tmp_path: Path) -> None:
    (tmp_path / "bases.rei").write_text(CATALOGUE, encoding="utf-8")
    case = tmp_path / "strafe.rei"
    case.write_text(CASE.replace("TYPE", "Omni"), encoding="utf-8")
    result = run_cli("sim", case, "-o", tmp_path / "out", "--no-router", "--fault", "drive:stuck,wheel=left,from=1")
    assert result.returncode == 2
    assert "robot: base is holonomic, and a stuck wheel is a fault of a differential drive" in result.stderr
    world = tmp_path / "out" / "case" / "world.json"
    data = json.loads(world.read_text())
    data["robot"]["drive"]["kind"] = "tracked"
    world.write_text(json.dumps(data))
    with pytest.raises(ArtifactError, match=r"robot\.drive\.kind.*unknown value 'tracked', expected one of "
                                            r"differential, holonomic"):
        read_world(world)


def test_a_holonomic_robot_s_slip_moves_it_half_and_its_odometry_counts_the_command(run_cli, tmp_path: Path) -> None:
    (tmp_path / "bases.rei").write_text(CATALOGUE, encoding="utf-8")
    case = tmp_path / "strafe.rei"
    case.write_text(CASE.replace("TYPE", "Omni"), encoding="utf-8")
    script = tmp_path / "left.script"
    script.write_text(SCRIPT, encoding="utf-8")
    result = run_cli("sim", case, "-o", tmp_path / "out", "--no-router", "--controller", f"script:{script}",
                     "--fault", "drive:slip,fraction=0.5")
    assert result.returncode == 1, result.stdout + result.stderr  # the goal is not reached: the ground gave half
    last = read_recording(tmp_path / "out" / "streams" / "state.msgpack")[-1]["robot"]
    # the body goes half of the strafe's 1.98 m, the odometry counts the whole (as a slipping wheel's does)
    assert last["pose"][1] - 0.5 == pytest.approx(0.99, abs=0.02)
    assert last["odom"][1] - 0.5 == pytest.approx(1.98, abs=0.02)
    assert abs(last["pose"][-1]) < 0.005 and abs(last["odom"][-1]) < 0.005
