# SPDX-License-Identifier: EPL-2.0
"""What the ROS 1 and ROS 2 bridges share (rei.sut.ros_bridge), without a ROS: the lockstep tick's watch on /cmd_vel."""

from __future__ import annotations

import pytest

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import Observation
from rei.sut.client import Tick
from rei.sut.ros_bridge import SILENT_TICKS, RosBridge


class _Bridge(RosBridge):
    def __init__(self, elsewhere: list[tuple[str, str]] | None, answers: bool = False) -> None:
        super().__init__(cmd_wait=0.0)
        self.elsewhere, self.answers = elsewhere, answers

    def publish_sensors(self, tick: Tick) -> None:
        pass

    def publish_clock(self, t: float) -> None:
        if self.answers:
            self.command_received(Twist2D(0.1, 0.0))

    def velocity_publishers(self) -> list[tuple[str, str]] | None:
        return self.elsewhere


def _ticks(bridge: RosBridge, n: int) -> None:
    for k in range(n):
        bridge.on_tick(Tick(k, Observation(k / 10, Pose2D(0.5, 0.5), Twist2D(), None), False))


def test_a_stack_that_publishes_its_commands_elsewhere_is_told_where_once(capsys: pytest.CaptureFixture[str]) -> None:
    """A stack publishing on /mobile_base/cmd_vel left the robot standing, each tick waiting cmd_wait (a simple
    navigation run took ten minutes of wall time) and said nothing anywhere."""
    bridge = _Bridge([("/cmd_vel", "geometry_msgs/Twist"), ("/mobile_base/cmd_vel", "geometry_msgs/Twist")])
    _ticks(bridge, SILENT_TICKS - 1)
    assert capsys.readouterr().err == ""
    _ticks(bridge, 3 * SILENT_TICKS)
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert (f"rei ros1-bridge: no /cmd_vel from the ROS stack in the first {SILENT_TICKS} control periods "
            f"(tick {SILENT_TICKS - 1}, t=1.900 s)") in err
    assert "it publishes geometry_msgs/Twist on /mobile_base/cmd_vel: REI reads geometry_msgs/Twist on /cmd_vel" in err


def test_a_stack_that_publishes_twist_stamped_is_told_its_type(capsys: pytest.CaptureFixture[str]) -> None:
    """Nav2's enable_stamped_cmd_vel: TwistStamped on /cmd_vel, which a Twist reader never matches."""
    _ticks(_Bridge([("/cmd_vel", "geometry_msgs/TwistStamped")]), SILENT_TICKS)
    assert "it publishes geometry_msgs/TwistStamped on /cmd_vel: REI reads geometry_msgs/Twist" in \
        capsys.readouterr().err


def test_a_silent_stack_without_another_twist_topic_is_told_so(capsys: pytest.CaptureFixture[str]) -> None:
    _ticks(_Bridge([]), SILENT_TICKS)
    assert "nothing publishes geometry_msgs/Twist on /cmd_vel" in capsys.readouterr().err


def test_a_bridge_that_cannot_list_topics_asks(capsys: pytest.CaptureFixture[str]) -> None:
    _ticks(_Bridge(None), SILENT_TICKS)
    assert "does it publish geometry_msgs/Twist (not TwistStamped) on /cmd_vel?" in capsys.readouterr().err


def test_a_stack_that_answers_hears_nothing(capsys: pytest.CaptureFixture[str]) -> None:
    _ticks(_Bridge([], answers=True), 2 * SILENT_TICKS)
    assert capsys.readouterr().err == ""


def test_a_stack_started_by_a_bridge_started_by_hand_finds_rei_s_python_first(tmp_path) -> None:
    """`rei ros1-bridge --ros-master URI -- python3 examples/sut/ros1/reference_nav_node.py`, started by hand with
    --sut-attach as docs/ros.md says, ran the node with the shell's python3: "No module named 'numpy'"; the same
    command through --sut "ros1:..." got REI's Python first on PATH."""
    import sys
    from pathlib import Path

    from rei.sut.ros1.environment import ros_environment
    from rei.sut.ros2.environment import ros2_environment

    own = str(Path(sys.executable).parent)
    for env in (ros_environment("http://127.0.0.1:11311", tmp_path, {"PATH": "/usr/bin:/bin"}),
                ros2_environment(7, "<CycloneDDS/>", tmp_path, {"PATH": "/usr/bin:/bin"})):
        assert env["PATH"] == f"{own}:/usr/bin:/bin"
