# SPDX-License-Identifier: EPL-2.0
"""Broken files are refused with a message naming the file, the place inside it and what is wrong."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rei.artifacts import (
    ArtifactError,
    check_sdf_matches_world,
    read_animation,
    read_case,
    read_mission,
    read_monitor,
    read_sdf,
    read_world,
)

Edit = Callable[[Path, Callable[[Any], None]], None]


def _error(call: Callable[[], object]) -> str:
    with pytest.raises(ArtifactError) as info:
        call()
    return str(info.value)


def test_missing_file_is_named(room_copy: Path) -> None:
    (room_copy / "world.json").unlink()
    message = _error(lambda: read_case(room_copy))
    assert message.endswith("world.json: file is missing")
    assert _error(lambda: read_case(room_copy / "nowhere")).endswith("nowhere: case folder is missing")


def test_unknown_format_rejected(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d.update(format="rei-world/2"))
    message = _error(lambda: read_world(room_copy / "world.json"))
    assert "world.json: format: unknown format 'rei-world/2'" in message and "rei-world/1" in message
    edit_json(room_copy / "animation.json", lambda d: d.pop("format"))
    assert "animation.json: format: required field is missing" in _error(
        lambda: read_animation(room_copy / "animation.json")
    )
    edit_json(room_copy / "monitor.json", lambda d: d.update(format="rei-world/1"))
    assert "unknown format 'rei-world/1'" in _error(lambda: read_monitor(room_copy / "monitor.json"))


def test_invalid_json_reports_line(room_copy: Path) -> None:
    path = room_copy / "animation.json"
    path.write_text('{"format": "rei-animation/1",\n "objects": [}', encoding="utf-8")
    assert re.search(r"animation\.json: not valid JSON: .* at line 2", _error(lambda: read_animation(path)))


def test_missing_nested_field_named_by_path(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d["robot"]["drive"].pop("wheelRadius"))
    message = _error(lambda: read_world(room_copy / "world.json"))
    assert message.endswith("world.json: robot.drive.wheelRadius: required field is missing")


def test_wrong_vector_length(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d["objects"][16].update(size=[1.2, 0.8]))
    message = _error(lambda: read_world(room_copy / "world.json"))
    assert "objects[16].size: expected a list of 3 numbers, got a list of 2" in message


def test_unknown_category(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d["objects"][17].update(category="ROBOTIC"))
    message = _error(lambda: read_world(room_copy / "world.json"))
    assert "objects[17].category: unknown value 'ROBOTIC'" in message and "HUMAN" in message


def test_robot_among_the_objects(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d["objects"][17].update(category="ROBOT"))
    message = _error(lambda: read_world(room_copy / "world.json"))
    assert 'objects[17].category: the robot belongs in "robot", not in objects' in message


def test_fixed_object_with_mass(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d["objects"][6].update(mass=5.0))
    assert "objects[6].mass: a WALL object must have mass 0, got 5.0" in _error(
        lambda: read_world(room_copy / "world.json")
    )


def test_duplicate_object_name(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d["objects"][16].update(name="h1"))
    assert "objects: name 'h1' is used twice" in _error(lambda: read_world(room_copy / "world.json"))


def test_animation_times_must_increase(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "animation.json", lambda d: d["objects"][0]["points"][2].update(t=4.0))
    message = _error(lambda: read_animation(room_copy / "animation.json"))
    assert "objects[0].points[2].t: times must be strictly increasing, got 4.0 then 4.0" in message


def test_animation_of_unknown_object(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "animation.json", lambda d: d["objects"][0].update(name="ghost"))
    assert "animation.json: object 'ghost' is not in world.json" in _error(lambda: read_case(room_copy))


def test_mission_errors(room_copy: Path) -> None:
    path = room_copy / "mission.xml"
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace('x="5.0"', 'x="five"'), encoding="utf-8")
    assert "mission.xml: goal #0: attribute 'x' must be a number, got 'five'" in _error(
        lambda: read_mission(path)
    )
    path.write_text(text.replace('index="1"', 'index="3"'), encoding="utf-8")
    assert "goal #1: index must be 1" in _error(lambda: read_mission(path))
    path.write_text(text.replace("</mission>", ""), encoding="utf-8")
    assert "mission.xml: not well-formed XML at line" in _error(lambda: read_mission(path))
    path.write_text(text.replace('robot="tb3"', 'robot="other"'), encoding="utf-8")
    assert "mission.xml: robot 'other' is not the world's robot 'tb3'" in _error(lambda: read_case(room_copy))


def test_mission_faults_are_read_and_a_bad_one_is_named(room_copy: Path) -> None:
    path = room_copy / "mission.xml"
    text = path.read_text(encoding="utf-8")
    faults = ('<faults><fault sensor="laser" kind="blackout" from="5.0" to="7.0"/>'
              '<fault sensor="laser" kind="impulse" period="10.0" duty="10.0%" gain="0.2@0.0/0.8@30.0"/></faults>')
    path.write_text(text.replace("</mission>", faults + "</mission>"), encoding="utf-8")
    blackout, impulse = read_mission(path).faults
    assert blackout.describe() == "laser blackout, from 5 s to 7 s"
    assert impulse.timing.pulse == 1.0 and impulse.effect.gain.value(15.0) == pytest.approx(0.5)
    path.write_text(text.replace("</mission>", faults.replace('to="7.0"', 'to="4.0"') + "</mission>"),
                    encoding="utf-8")
    assert "mission.xml: fault #0: 'to' (4 s) must be after 'from' (5 s)" in _error(lambda: read_mission(path))
    path.write_text(text.replace("</mission>", '<faults><fault sensor="laser" kind="smoke"/></faults></mission>'),
                    encoding="utf-8")
    assert "fault #0: unknown fault laser smoke" in _error(lambda: read_mission(path))


def test_monitor_topic_needs_run_id(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "monitor.json", lambda d: d["topics"].update(state="rei.run.state"))
    assert "topics.state: must contain {run_id}" in _error(lambda: read_monitor(room_copy / "monitor.json"))


def test_sdf_structure_errors(room_copy: Path) -> None:
    path = room_copy / "world.sdf"
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace('<model name="h1">', '<model name="h1"><bad>'), encoding="utf-8")
    assert "world.sdf: not well-formed XML" in _error(lambda: read_sdf(path))
    path.write_text(text.replace("<mass>70.0</mass>", "<mass>heavy</mass>"), encoding="utf-8")
    assert "model 'h1': <inertial/mass> must be 1 numbers, got 'heavy'" in _error(lambda: read_sdf(path))


def test_sdf_and_world_must_list_the_same_bodies(room_copy: Path, edit_json: Edit) -> None:
    edit_json(room_copy / "world.json", lambda d: d["objects"].pop(16))
    world = read_world(room_copy / "world.json")
    sdf = read_sdf(room_copy / "world.sdf")
    message = _error(lambda: check_sdf_matches_world(sdf, world))
    assert "world.sdf: 18 models but world.json lists 17 objects; not in world.json: table1" in message


def _person(**change: Any) -> dict:
    person = {"name": "h1", "behaviour": "avoids", "speed": 1.2, "start": 0.0, "loop": False,
              "route": [{"floor": "F_0_0", "x": 0.5, "y": 0.5, "wait": 0.0}]}
    person.update(change)
    return person


def test_people_are_read_and_checked(room_copy: Path, edit_json: Edit) -> None:
    def people(*persons: dict) -> Callable[[Any], None]:
        def change(data: Any) -> None:
            data["objects"] = [o for o in data["objects"] if o["name"] != "h1"]
            data["people"] = list(persons)
        return change

    edit_json(room_copy / "animation.json", people(_person(speedTo=1.5, group="g")))
    (ann,) = read_animation(room_copy / "animation.json").people
    assert (ann.name, ann.speed, ann.speed_to, ann.group, ann.route[0].x) == ("h1", 1.2, 1.5, "g", 0.5)
    for change, expected in (
        ({"behaviour": "shy"}, "people[0].behaviour: unknown behaviour 'shy', expected one of avoids, ignores"),
        ({"speedTo": 1.0}, "people[0].speedTo: must be at least speed (1.2) and at most 3 m/s, got 1.0"),
        ({"speed": 0}, "people[0].speed: must be > 0 and <= 3 m/s, got 0"),
        ({"route": []}, "people[0].route: needs at least one stop"),
    ):
        edit_json(room_copy / "animation.json", people(_person(**change)))
        assert expected in _error(lambda: read_animation(room_copy / "animation.json"))
    edit_json(room_copy / "animation.json", people(_person(name="ghost")))
    assert "person 'ghost' is not in world.json" in _error(lambda: read_case(room_copy))
