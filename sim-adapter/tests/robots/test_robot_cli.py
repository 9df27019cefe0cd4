# SPDX-License-Identifier: EPL-2.0
"""`rei robot FILE`: the text and JSON a user reads, and exit 1 with the file named for bad input."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from rei.cli import main

TURTLEBOT3 = Path(__file__).resolve().parents[3].parent / "shared" / "data" / "robots" / "turtlebot3"
BURGER = TURTLEBOT3 / "turtlebot3_burger.urdf"


def test_text_shows_footprint_bounds_lidar_and_drive(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["robot", str(BURGER), "--arg", "namespace:=tb3/", "--lidar", "tb3/base_scan"]) == 0
    out, err = capsys.readouterr()
    assert "poses relative to tb3/base_footprint" in out
    assert "footprint: convex polygon of " in out
    assert "bounding box: x -0.1020 .. 0.0380, y -0.0890 .. 0.0890" in out
    assert "lidar: tb3/base_scan at x -0.0320, y 0.0000, z 0.1820 m, yaw 0.0 deg" in out
    assert "drive: differential, wheel separation 0.1600 m, wheel radius 0.0330 m" in out
    assert "not in the description: lidar beams, range and rate" in out
    assert "rei: warning: link tb3/base_link: visual mesh package://turtlebot3_description/meshes/bases/" in err


def test_json(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["robot", str(BURGER), "--arg", "namespace:=", "--lidar", "base_scan", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["footprint"]["type"] == "polygon"
    assert data["bounds"]["xmin"] == pytest.approx(-0.102)
    assert data["lidar"]["z"] == pytest.approx(0.182)
    assert data["drive"] == {"type": "differential", "left_joint": "wheel_left_joint",
                             "right_joint": "wheel_right_joint", "wheel_separation": pytest.approx(0.16),
                             "wheel_radius": 0.033}
    assert len(data["parts"]) == 5


def test_undeclared_xacro_argument_is_warned_about(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["robot", str(BURGER), "--arg", "namespce:=tb3/"]) == 0
    err = capsys.readouterr().err
    assert "rei: warning: xacro argument 'namespce' is not declared by the file (it declares: namespace)" in err


def test_bad_argument_syntax_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as caught:
        main(["robot", str(BURGER), "--arg", "namespace=tb3/"])
    assert caught.value.code == 2
    assert "'namespace=tb3/': write NAME:=VALUE" in capsys.readouterr().err


def test_bad_input_exits_1_naming_the_file(tmp_path: Path) -> None:
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r">\n  <link name="a">\n</robot>\n', encoding="utf-8")
    rei = Path(sys.executable).parent / "rei"
    done = subprocess.run([str(rei), "robot", str(bad)], capture_output=True, text=True, check=False)
    assert done.returncode == 1
    # expat points at the closing tag's name: line 3, column 3.
    assert done.stderr == f"rei: error: {bad}:3:3: XML does not parse: mismatched tag\n"
    done = subprocess.run([str(rei), "robot", str(BURGER), "--lidar", "base_scn"], capture_output=True, text=True,
                          check=False)
    assert done.returncode == 1
    assert done.stderr.endswith(f"rei: error: {BURGER}: no link named 'base_scn' for the lidar; did you mean "
                                "'base_scan'?\n")


def test_a_reader_that_goes_away_ends_the_command_without_a_traceback() -> None:
    """`rei robot X --json | head -c 1`: the pipe closes before the output is written."""
    import subprocess
    import sys

    process = subprocess.Popen([sys.executable, "-m", "rei.cli", "robot", str(TURTLEBOT3 / "turtlebot3_burger.urdf"),
                                "--json"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert process.stdout is not None and process.stderr is not None
    process.stdout.close()  # before the interpreter has even started: the first write meets a closed pipe
    err = process.stderr.read().decode()
    assert process.wait(timeout=60) == 141, err
    assert "Traceback" not in err, err


def test_a_broken_pipe_that_is_not_the_output_keeps_its_traceback(monkeypatch: pytest.MonkeyPatch) -> None:
    """A socket or a process's pipe that broke is a failure to see, not a reader that went away: not exit 141."""
    import rei.cli.robot

    def broken(args: object) -> int:
        raise BrokenPipeError(32, "Broken pipe")  # as a send to a process that died raises it

    monkeypatch.setattr(rei.cli.robot, "run", broken)
    with pytest.raises(BrokenPipeError):
        main(["robot", str(BURGER)])


def test_for_the_generator_a_lidar_link_on_the_floor_is_an_error(tmp_path: Path,
                                                                  capsys: pytest.CaptureFixture[str]) -> None:
    # base_link is 0.010 m above base_footprint: the simulator's body (from 1 cm up to the lidar) would be nothing,
    # and the simulation failed with a traceback after generation had succeeded.
    urdf_out = tmp_path / "robot.urdf"
    assert main(["robot", str(BURGER), "--lidar", "base_link", "--for-generator", str(urdf_out)]) == 1
    assert capsys.readouterr().err == (
        f"rei: error: {BURGER}: the lidar's link base_link is 0.0100 m above base_footprint: REI's robot reaches "
        "from the floor up to its lidar and is at least 0.05 m high (is base_link the lidar's own link?)\n")
    assert not urdf_out.exists()
    assert main(["robot", str(BURGER), "--lidar", "base_scan", "--for-generator", str(urdf_out)]) == 0
    assert capsys.readouterr().out.splitlines()[2] == "lidar -0.032 0.0 0.182 0.0"


# A narrow robot whose wheel joints are not read (their collision shapes are meshes that are not there): the
# simulator's wheels are then the entry's or the defaults, 0.287 m apart, 7 cm outside its 0.14 m wide body.
NARROW = """<robot name="narrow">
  <link name="base_footprint"><collision><origin xyz="0 0 0.08"/><geometry><box size="0.3 0.14 0.12"/></geometry>
  </collision></link>
  <link name="wheel_left_link"><collision><geometry><mesh filename="package://gone/wheel.stl"/></geometry>
  </collision></link>
  <joint name="wheel_left_joint" type="continuous"><parent link="base_footprint"/><child link="wheel_left_link"/>
    <origin xyz="0 0.08 0.033" rpy="-1.5708 0 0"/><axis xyz="0 0 1"/></joint>
  <link name="laser"/>
  <joint name="laser_joint" type="fixed"><parent link="base_footprint"/><child link="laser"/>
    <origin xyz="0 0 0.17"/></joint>
</robot>
"""


def test_for_the_generator_wheels_outside_the_footprint_are_an_error(tmp_path: Path,
                                                                     capsys: pytest.CaptureFixture[str]) -> None:
    urdf = tmp_path / "narrow.urdf"
    urdf.write_text(NARROW, encoding="utf-8")
    out = tmp_path / "out.urdf"
    assert main(["robot", str(urdf), "--lidar", "laser", "--wheels", "0.033", "0.287", "--for-generator",
                 str(out)]) == 1
    err = capsys.readouterr().err
    assert err.startswith(f"rei: error: {urdf}: the simulator's wheels (radius 0.033 m, 0.287 m apart: the "
                          "catalogue entry's 'wheels' or the defaults, as the description's wheels were not read: "
                          "no wheel joint"), err
    assert "reach outside the robot's footprint (y -0.0700 .. 0.0700 m)" in err
    # 0.12 apart: the wheels' outer faces at 0.069, inside
    assert main(["robot", str(urdf), "--lidar", "laser", "--wheels", "0.033", "0.12", "--for-generator",
                 str(out)]) == 0
    capsys.readouterr()
    # a description whose wheels are read keeps them, whatever the entry says
    assert main(["robot", str(BURGER), "--lidar", "base_scan", "--wheels", "0.033", "0.287", "--for-generator",
                 str(out)]) == 0
    assert "drive 0.16" in capsys.readouterr().out


def test_the_wheel_width_checked_is_the_simulator_s() -> None:
    from rei.cli.robot import SIM_WHEEL_WIDTH
    from rei.sim.robot_model import WHEEL_WIDTH

    assert SIM_WHEEL_WIDTH == WHEEL_WIDTH


def test_for_the_generator_an_undeclared_xacro_argument_is_an_error(tmp_path: Path,
                                                                    capsys: pytest.CaptureFixture[str]) -> None:
    # `rei robot` warns (above); a catalogue's misspelt argument changed nothing, silently: the frames kept no prefix
    out = tmp_path / "out.urdf"
    assert main(["robot", str(BURGER), "--arg", "namespce:=tb3/", "--lidar", "base_scan", "--for-generator",
                 str(out)]) == 1
    assert capsys.readouterr().err == (f"rei: error: {BURGER}: xacro argument 'namespce' is not declared by the file "
                                       "(it declares: namespace)\n")
