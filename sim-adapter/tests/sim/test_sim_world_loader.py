# SPDX-License-Identifier: EPL-2.0
"""world.sdf in pybullet: bodies by name, fixed bodies fixed, mismatches and missing files refused."""

from __future__ import annotations

import json
from pathlib import Path

import pybullet as p
import pytest

from rei.artifacts import ArtifactError, Category, read_world
from rei.geometry import Twist2D
from rei.sim.simulation import Simulation
from rei.sim.world_loader import load_world


def test_bodies_by_name_and_gravity(room: Path) -> None:
    world = read_world(room / "world.json")
    client = p.connect(p.DIRECT)
    try:
        loaded = load_world(client, room / "world.sdf", world)
        assert list(loaded.body_of) == [o.name for o in world.objects]
        for name, body in loaded.body_of.items():
            assert loaded.name_of[body] == name
            mass = p.getDynamicsInfo(body, -1, physicsClientId=client)[0]
            assert mass == loaded.spec_of[name].mass
        table = loaded.body_of["table1"]
        assert p.getBasePositionAndOrientation(table, physicsClientId=client)[0] == pytest.approx(
            (4.8, 3.2, 0.375)
        )
        assert p.getPhysicsEngineParameters(physicsClientId=client)["gravityAccelerationZ"] == pytest.approx(
            -9.81
        )
        for _ in range(240):  # fixed bodies do not fall, the human stands on the floor
            p.stepSimulation(physicsClientId=client)
        assert p.getBasePositionAndOrientation(table, physicsClientId=client)[0][2] == pytest.approx(0.375)
        human_z = p.getBasePositionAndOrientation(loaded.body_of["h1"], physicsClientId=client)[0][2]
        assert human_z == pytest.approx(0.85, abs=0.005)
    finally:
        p.disconnect(client)


def test_world_json_not_matching_sdf_is_refused(room: Path, tmp_path: Path) -> None:
    data = json.loads((room / "world.json").read_text(encoding="utf-8"))
    data["objects"] = [o for o in data["objects"] if o["name"] != "table1"]
    (tmp_path / "world.json").write_text(json.dumps(data), encoding="utf-8")
    world = read_world(tmp_path / "world.json")
    client = p.connect(p.DIRECT)
    try:
        with pytest.raises(ArtifactError) as info:
            load_world(client, room / "world.sdf", world)
    finally:
        p.disconnect(client)
    message = str(info.value)
    assert message.startswith(str(room / "world.sdf"))
    assert "pybullet loaded 18 bodies but world.json lists 17 objects; not in world.json: table1" in message


def test_renamed_body_is_refused_by_the_simulation(room_copy: Path) -> None:
    path = room_copy / "world.json"
    path.write_text(path.read_text(encoding="utf-8").replace('"h1"', '"human1"'), encoding="utf-8")
    animation = room_copy / "animation.json"
    animation.write_text(animation.read_text(encoding="utf-8").replace('"h1"', '"human1"'), encoding="utf-8")
    with pytest.raises(ArtifactError) as info:
        Simulation(room_copy)
    assert "world.sdf" in str(info.value) and "missing from world.sdf: human1" in str(info.value)


def test_missing_sdf_is_refused(room_copy: Path) -> None:
    (room_copy / "world.sdf").unlink()
    with pytest.raises(ArtifactError, match=r"world\.sdf: file is missing"):
        Simulation(room_copy)
    client = p.connect(p.DIRECT)
    try:
        with pytest.raises(ArtifactError, match=r"world\.sdf: file is missing"):
            load_world(client, room_copy / "world.sdf", read_world(room_copy / "world.json"))
    finally:
        p.disconnect(client)


def test_malformed_world_json_is_refused(room_copy: Path) -> None:
    (room_copy / "world.json").write_text('{"format": "rei-world/1", "floors": []}', encoding="utf-8")
    with pytest.raises(ArtifactError, match=r"world\.json: bounds: required field is missing"):
        Simulation(room_copy)


def test_static_body_with_mass_is_refused(room: Path, tmp_path: Path) -> None:
    sdf = (room / "world.sdf").read_text(encoding="utf-8")
    marker = '<model name="table1">'
    head, tail = sdf.split(marker)
    tail = tail.replace("<static>true</static>", "<static>false</static>", 1).replace(
        "<mass>0</mass>", "<mass>5</mass>", 1
    )
    (tmp_path / "world.sdf").write_text(head + marker + tail, encoding="utf-8")
    client = p.connect(p.DIRECT)
    try:
        with pytest.raises(ArtifactError) as info:
            load_world(client, tmp_path / "world.sdf", read_world(room / "world.json"))
    finally:
        p.disconnect(client)
    assert "model 'table1' is STATIC but has mass 5.0; fixed bodies need mass 0" in str(info.value)


def test_a_map_room_s_floors_are_places_on_the_ground_slab_not_bodies(map_case: Path) -> None:
    world = read_world(map_case / "world.json")
    floors = [o for o in world.objects if o.category is Category.FLOOR]
    with Simulation(map_case) as sim:
        loaded = sim.world
        assert loaded.ground is not None and floors
        assert list(loaded.body_of) == [o.name for o in world.objects]  # every name kept, floors on the slab
        assert {loaded.body_of[o.name] for o in floors} == {loaded.ground}
        others = [o for o in world.objects if o.category is not Category.FLOOR]
        assert p.getNumBodies(physicsClientId=sim.client) == len(others) + 2  # and the ground and the robot
        for floor in floors:  # a point on the slab is named after the floor it lies on
            x, y = floor.pose[0] + 0.3 * floor.size[0], floor.pose[1] - 0.3 * floor.size[1]
            assert loaded.contact_name(loaded.ground, (x, y, 0.0)) == floor.name
        for _ in range(240):  # the robot stands on the slab, which is no contact
            sim.step(Twist2D(0.0, 0.0))
        state = sim.state()
        assert abs(state.robot.pose[2]) < 0.01 and state.contacts == ()
        under = p.getContactPoints(bodyA=sim.robot_body, bodyB=loaded.ground, physicsClientId=sim.client)
        assert {loaded.contact_name(loaded.ground, pt[6]) for pt in under} == {world.robot.floor}
