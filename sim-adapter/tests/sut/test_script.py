# SPDX-License-Identifier: EPL-2.0
"""The script controller: the thesis's translation and circle scenarios (7.2) and its file format."""

from __future__ import annotations

import math

import pytest

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import NavGoal, NavStatus
from rei.sut.script import ScriptController, ScriptError, Segment, load_script, parse_script

from .kinematic import KinematicWorld, rect_room

TRANSLATION_THEN_CIRCLE = """\
# straight ahead, then one full circle of radius 0.2 m
2.0 0.2 0.0
6.283185307 0.2 1.0   # 2 pi seconds at 1 rad/s
"""


def play(script: ScriptController, world: KinematicWorld, until: float) -> list[tuple[float, Pose2D]]:
    """Step until ``until``; the poses with the time they were reached."""
    timed = []
    while world.t < until - 1e-9:
        world.apply(script.step(world.observation()))
        timed.append((world.t, world.pose))
    return timed


def test_translation_then_circle():
    script = ScriptController(parse_script(TRANSLATION_THEN_CIRCLE))
    world = KinematicWorld(rect_room(4, 4), Pose2D(1.0, 1.0, 0.0), control_period=0.05, physics_dt=0.005)
    script.reset(world.static_map, world.pose)
    _, after_translation = play(script, world, 2.0)[-1]
    assert script.status is NavStatus.ACTIVE
    assert (after_translation.x, after_translation.y) == pytest.approx((1.4, 1.0), abs=1e-6)
    timed = play(script, world, 2.0 + 2 * math.pi + 1.0)
    circle = [p for t, p in timed if t <= 2.0 + 2 * math.pi]
    assert all(math.hypot(p.x - 1.4, p.y - 1.2) == pytest.approx(0.2, abs=0.01) for p in circle)
    assert max(p.y for p in circle) == pytest.approx(1.4, abs=0.01)
    end = timed[-1][1]
    assert (end.x, end.y) == pytest.approx((1.4, 1.0), abs=0.02)
    assert script.status is NavStatus.SUCCEEDED
    assert script.step(world.observation()) == Twist2D()


def test_goals_are_ignored_and_cancel_stops_the_script():
    script = ScriptController([Segment(5.0, 0.1, 0.0)])
    world = KinematicWorld(rect_room(3, 3), Pose2D(0.5, 1.5, 0.0))
    script.reset(world.static_map, world.pose)
    script.set_goal(NavGoal(0, Pose2D(2.5, 2.5), 0.2))
    assert script.step(world.observation()) == Twist2D(0.1, 0.0)
    script.cancel()
    assert script.status is NavStatus.CANCELLED
    assert script.step(world.observation()) == Twist2D()


def test_timeline_starts_at_the_first_step_not_at_time_zero():
    script = ScriptController([Segment(1.0, 0.2, 0.0), Segment(1.0, 0.0, 0.5)])
    world = KinematicWorld(rect_room(3, 3), Pose2D(0.5, 1.5, 0.0))
    world.t = 10.0
    script.reset(world.static_map, world.pose)
    assert script.step(world.observation()) == Twist2D(0.2, 0.0)
    world.t = 11.5
    assert script.step(world.observation()) == Twist2D(0.0, 0.5)
    world.t = 12.0
    assert script.step(world.observation()) == Twist2D()
    assert script.status is NavStatus.SUCCEEDED
    assert "2 s" in script.status_text


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("1.0 0.2 0.0\n2.0 0.1\n", "<script>:2: expected 'duration v w [vy]', got 2 field"),
        ("1.0 0.2 0.0 0.1 0.5\n", "<script>:1: expected 'duration v w [vy]', got 5 field"),
        ("1.0 0.2 0.0 inf\n", "<script>:1: values must be finite"),
        ("# header\n\n1.0 fast 0.0\n", "<script>:3: not a number"),
        ("0 0.2 0.0\n", "<script>:1: duration must be > 0"),
        ("1.0 nan 0.0\n", "<script>:1: values must be finite"),
        ("# nothing\n", "the script has no commands"),
    ],
)
def test_bad_scripts_name_the_line(text, message):
    with pytest.raises(ScriptError) as info:
        parse_script(text)
    assert message in str(info.value)


def test_a_fourth_field_is_the_sideways_speed_of_a_holonomic_robot():
    assert parse_script("1.0 0 0 0.3\n2.0 0.1 0.2\n") == (Segment(1.0, 0.0, 0.0, 0.3), Segment(2.0, 0.1, 0.2, 0.0))


def test_load_script_names_the_file(tmp_path):
    path = tmp_path / "moves.txt"
    path.write_text("1 0.1 0\n1 0.1 x\n")
    with pytest.raises(ScriptError, match=f"{path}:2: not a number"):
        load_script(path)
    with pytest.raises(ScriptError, match="missing.txt: cannot read the script"):
        load_script(tmp_path / "missing.txt")
    path.write_text("1 0.1 0  # ok\n")
    assert ScriptController.from_file(path).duration == 1.0
