# SPDX-License-Identifier: EPL-2.0
"""The readers accept the hand-written fixture and turn it into the values docs/artifacts.md describes."""

from __future__ import annotations

from pathlib import Path

from rei.artifacts import Category, Shape, read_case


def test_world_json_fields(room: Path) -> None:
    world = read_case(room).world
    assert world.testcase == "RoomSixByFour"
    assert world.floor_size == 2.0
    assert world.bounds == (0.0, 0.0, 6.0, 4.0)
    assert [f.name for f in world.floors] == ["F_0_0", "F_1_0", "F_2_0", "F_0_1", "F_1_1", "F_2_1"]
    f01 = world.floors[3]
    assert (f01.cell, f01.center, f01.top, f01.bottom) == ((0, 1), (1.0, 3.0), "W_0_1_top", "F_0_0")
    counts = {c: sum(o.category is c for o in world.objects) for c in Category if c is not Category.ROBOT}
    assert counts == {
        Category.FLOOR: 6,
        Category.WALL: 10,
        Category.STATIC: 1,
        Category.DYNAMIC: 0,
        Category.HUMAN: 1,
    }
    human = world.object("h1")
    assert human.shape is Shape.CYLINDER and human.size == (0.5, 0.5, 1.7) and human.mass == 70.0
    assert human.pose == (1.5, 2.7, 0.85, 0.0) and human.floor == "F_0_1"


def test_robot_spec(room: Path) -> None:
    robot = read_case(room).world.robot
    assert (robot.name, robot.type, robot.size, robot.mass) == ("tb3", "Waffle", (0.281, 0.306, 0.141), 1.8)
    assert robot.pose == (1.0, 1.0, 0.0, 0.0)
    assert robot.drive.wheel_radius == 0.033 and robot.drive.wheel_separation == 0.287
    assert robot.drive.max_linear_velocity == 0.26 and robot.drive.max_angular_velocity == 1.82
    assert (robot.lidar.beams, robot.lidar.range_min, robot.lidar.range_max) == (360, 0.12, 3.5)
    assert (robot.lidar.rate, robot.lidar.mount_height) == (10.0, 0.17)


def test_sdf_models_follow_world_order(room: Path) -> None:
    case = read_case(room)
    assert case.sdf.names == tuple(o.name for o in case.world.objects)
    table = case.sdf.models[case.sdf.names.index("table1")]
    assert table.static and table.mass == 0.0 and table.pose[:3] == (4.8, 3.2, 0.375)
    assert case.sdf.models[-1].mass == 70.0 and not case.sdf.models[-1].static


def test_mission_goals_in_order(room: Path) -> None:
    mission = read_case(room).mission
    assert (mission.name, mission.robot, mission.frame) == ("AcrossAndBack", "tb3", "world")
    assert (mission.start.x, mission.start.y, mission.start.yaw) == (1.0, 1.0, 0.0)
    assert [g.index for g in mission.goals] == [0, 1]
    assert (mission.goals[0].pose.x, mission.goals[0].pose.y) == (5.0, 1.0)
    assert mission.goals[0].tolerance == 0.25 and mission.goals[1].timeout == 60.0


def test_animation_points(room: Path) -> None:
    animation = read_case(room).animation
    (h1,) = animation.objects
    assert h1.name == "h1" and h1.category is Category.HUMAN and h1.loop
    assert [(p.t, p.x, p.y) for p in h1.points] == [
        (0.0, 1.5, 2.7),
        (4.0, 3.5, 2.7),
        (6.0, 3.5, 1.9),
        (10.0, 1.5, 1.9),
    ]


def test_monitor_topics_and_catalogue(room: Path) -> None:
    monitor = read_case(room).monitor
    assert (monitor.close_threshold, monitor.collision_threshold, monitor.max_human_collisions) == (
        0.25,
        0.01,
        1,
    )
    assert monitor.topic("state", "run7") == "rei.run.run7.state"
    assert monitor.topic("missionInfo", "x") == "rei.run.x.mission_info"
    assert monitor.files["animation"] == "animation.json"
    assert [c.name for c in monitor.catalogue] == ["Floor", "Wall", "Table", "Human"]
    assert monitor.catalogue[2].category is Category.STATIC and monitor.catalogue[2].mass == 20.0
