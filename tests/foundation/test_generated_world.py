# SPDX-License-Identifier: EPL-2.0
"""`rei generate` end to end: the generated world.sdf, loaded by pybullet, is the world world.json describes.

pybullet is the consumer the SDF is written for (docs/artifacts.md): if a body is missing, misplaced or movable
when it should be fixed, the simulator would run a different room than the one the monitor reasons about.
"""

from __future__ import annotations

import json
import math
from collections import Counter
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pybullet
import pytest

TOLERANCE = 1e-6

# Compact form: a 6 x 4 grid of floors F_x_y with walls all around.
GRID_CASE = """\
testcase SimpleNavigation {
  room Lab size 6 x 4 {
    object table1 : Table on F_3_1
    human h1 trajectory [F_0_3 @ 0s, F_5_3 @ 10s, F_5_0 @ 20s] loop
    robot tb3 : Waffle on F_0_0
  }
  mission Deliver { goto F_5_3 goto F_0_0 }
  monitor { close 0.25 collision 0.01 }
}
"""

# Explicit floor graph: an L of four floors (A B C along the bottom, D above C) with ten walls, floors of 1.5 m.
GRAPH_CASE = """\
testcase Corner {
  room Hall floorSize 1.5 {
    floor A right B top WA_top bottom WA_bottom left WA_left
    floor B left A right C top WB_top bottom WB_bottom
    floor C left B top D right WC_right bottom WC_bottom
    floor D bottom C top WD_top left WD_left right WD_right
    wall WA_top wall WA_bottom wall WA_left wall WB_top wall WB_bottom
    wall WC_right wall WC_bottom wall WD_top wall WD_left wall WD_right
    object crate : Table on C yaw 1.5
    robot r1 : Waffle on A
  }
  mission Visit { goto D goto A }
}
"""


def generate(run_cli: Callable[..., Any], source: Path, out: Path) -> dict[str, Any]:
    """Run `rei generate` and return world.json, after checking every artifact was written."""
    result = run_cli("generate", source, "-o", out)
    assert result.returncode == 0, f"rei generate failed:\n{result.stderr}"
    for name in ("world.sdf", "world.json", "mission.xml", "animation.json", "monitor.json"):
        assert (out / name).is_file(), f"{name} not written; stdout:\n{result.stdout}"
    world: dict[str, Any] = json.loads((out / "world.json").read_text(encoding="utf-8"))
    assert world["format"] == "rei-world/1"
    return world


@pytest.fixture
def physics() -> Iterator[int]:
    """A headless pybullet client, disconnected after the test."""
    client = pybullet.connect(pybullet.DIRECT)
    try:
        yield client
    finally:
        pybullet.disconnect(client)


def angle_difference(a: float, b: float) -> float:
    return abs(math.remainder(a - b, math.tau))


def assert_sdf_matches_world(sdf: Path, world: dict[str, Any], client: int) -> None:
    """Every object of world.json is one pybullet body, in the same order, with its name, pose and mass."""
    bodies = pybullet.loadSDF(str(sdf), physicsClientId=client)
    objects = world["objects"]
    assert len(bodies) == len(objects), "one body per object of world.json"
    assert pybullet.getNumBodies(physicsClientId=client) == len(objects)
    for body, obj in zip(bodies, objects, strict=True):
        name = pybullet.getBodyInfo(body, physicsClientId=client)[1].decode()
        assert name == obj["name"]
        position, orientation = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
        x, y, z, yaw = obj["pose"]
        for axis, got, want in zip("xyz", position, (x, y, z), strict=True):
            assert got == pytest.approx(want, abs=TOLERANCE), (
                f"{name}: {axis} is {got}, world.json says {want}"
            )
        roll, pitch, body_yaw = pybullet.getEulerFromQuaternion(orientation)
        assert abs(roll) < TOLERANCE and abs(pitch) < TOLERANCE, f"{name} is tilted"
        assert angle_difference(body_yaw, yaw) < TOLERANCE, f"{name}: yaw {body_yaw}, world.json says {yaw}"
        mass = pybullet.getDynamicsInfo(body, -1, physicsClientId=client)[0]
        if obj["category"] in ("FLOOR", "WALL", "STATIC"):
            assert obj["mass"] == 0.0, f"{name} is {obj['category']} and must be fixed"
        assert mass == pytest.approx(obj["mass"], abs=TOLERANCE), f"{name}: mass {mass} != {obj['mass']}"


def test_grid_room_generates_the_world_pybullet_loads(
    run_cli: Callable[..., Any], write_rei: Callable[[str, str], Path], tmp_path: Path, physics: int
) -> None:
    world = generate(run_cli, write_rei("simple.rei", GRID_CASE), tmp_path / "out")
    categories = Counter(obj["category"] for obj in world["objects"])
    assert categories == {"FLOOR": 24, "WALL": 20, "STATIC": 1, "HUMAN": 1}
    assert world["bounds"] == pytest.approx([0.0, 0.0, 6.0, 4.0])
    for obj in world["objects"]:
        if obj["category"] == "FLOOR":  # F_x_y: x from the left, y from the bottom, 1 m floors by default
            _, x, y = obj["name"].split("_")
            assert obj["pose"][:2] == pytest.approx([int(x) + 0.5, int(y) + 0.5]), obj["name"]
    assert world["robot"]["name"] == "tb3"
    assert world["robot"]["pose"][:2] == pytest.approx([0.5, 0.5])
    assert_sdf_matches_world(tmp_path / "out" / "world.sdf", world, physics)


def test_explicit_floor_graph_generates_the_world_pybullet_loads(
    run_cli: Callable[..., Any], write_rei: Callable[[str, str], Path], tmp_path: Path, physics: int
) -> None:
    world = generate(run_cli, write_rei("corner.rei", GRAPH_CASE), tmp_path / "out")
    assert world["floorSize"] == pytest.approx(1.5)
    cells = {floor["name"]: floor["cell"] for floor in world["floors"]}
    assert cells == {"A": [0, 0], "B": [1, 0], "C": [2, 0], "D": [2, 1]}
    assert world["bounds"] == pytest.approx([0.0, 0.0, 4.5, 3.0])
    categories = Counter(obj["category"] for obj in world["objects"])
    assert categories == {"FLOOR": 4, "WALL": 10, "STATIC": 1}
    crate = next(obj for obj in world["objects"] if obj["name"] == "crate")
    assert crate["pose"][:2] == pytest.approx([3.75, 0.75]), "crate stands on the centre of floor C"
    assert_sdf_matches_world(tmp_path / "out" / "world.sdf", world, physics)
