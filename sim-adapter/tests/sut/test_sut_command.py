# SPDX-License-Identifier: EPL-2.0
"""``--sut COMMAND`` checked before anything starts (rei.sut.external.process, docs/sut.md)."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei.sut.external.process import SutLaunchError, bridged, check_command


@pytest.mark.parametrize("command, program", [
    ("ros:python3 my_nav.py", "ros:python3"),
    ("ROS1:roslaunch my_robot nav.launch", "ROS1:roslaunch"),
    ("ros1 :python3 my_nav.py", "ros1"),
    ("ros-2:ros2 launch my_robot nav2.launch.py", "ros-2:ros2"),
])
def test_a_misspelt_bridge_prefix_names_the_bridges(command: str, program: str) -> None:
    """"ros:python3 ..." said only "program 'ros:python3' not found on PATH"."""
    with pytest.raises(SutLaunchError) as raised:
        check_command(command)
    message = str(raised.value)
    assert f"program {program!r} not found on PATH" in message
    assert "--sut 'ros1:COMMAND' or 'ros2:COMMAND'" in message, message


def test_a_plain_missing_program_gets_no_bridge_hint() -> None:
    with pytest.raises(SutLaunchError) as raised:
        check_command("pyhton3 my_nav.py")
    assert str(raised.value) == "--sut: program 'pyhton3' not found on PATH"


def test_a_bridge_prefix_is_taken() -> None:
    assert check_command("ros1:python3 my_nav.py") == ["python3", "my_nav.py"]
    assert bridged("ros2:python3 n.py", ["python3", "n.py"], Path("out"))[:2] == \
        ["rei", "ros2-bridge"]
