# SPDX-License-Identifier: EPL-2.0
"""A generated test case: the five files of one output folder, read and checked against each other.

Each reader validates its own file; this module checks what no single file can (the animation names objects of
the world, the mission and the monitor name the world's robot, the SDF holds exactly the world's bodies).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from rei.artifacts.animation import AnimationSpec, read_animation
from rei.artifacts.errors import ArtifactError
from rei.artifacts.mission import MissionSpec, read_mission
from rei.artifacts.monitor import MonitorSpec, read_monitor
from rei.artifacts.sdf import SdfWorld, read_sdf
from rei.artifacts.world import Category, WorldSpec, read_world

WORLD_SDF = "world.sdf"
WORLD_JSON = "world.json"
MISSION_XML = "mission.xml"
ANIMATION_JSON = "animation.json"
MONITOR_JSON = "monitor.json"


def case_of_run(out: Path) -> Path | None:
    """The generated case a run was made from: ``OUT/case`` (rei run, campaigns, rei import), else the folder
    ``OUT/sim.json`` names (rei sim GEN -o OUT simulates a case that lives elsewhere); None when neither exists."""
    if (out / "case" / WORLD_JSON).is_file():
        return out / "case"
    try:
        recorded = json.loads((out / "sim.json").read_text(encoding="utf-8")).get("case")
    except (OSError, ValueError, AttributeError):
        return None
    if isinstance(recorded, str) and (Path(recorded) / WORLD_JSON).is_file():
        return Path(recorded)
    return None


@dataclass(frozen=True, slots=True)
class Case:
    folder: Path
    sdf: SdfWorld
    world: WorldSpec
    mission: MissionSpec
    animation: AnimationSpec
    monitor: MonitorSpec

    @property
    def sdf_path(self) -> Path:
        return self.folder / WORLD_SDF


def read_case(folder: Path | str) -> Case:
    """Read all five files of a generated case folder and cross-check them."""
    folder = Path(folder)
    if not folder.is_dir():
        raise ArtifactError(folder, "case folder is missing")
    world = read_world(folder / WORLD_JSON)
    sdf = read_sdf(folder / WORLD_SDF)
    mission = read_mission(folder / MISSION_XML)
    animation = read_animation(folder / ANIMATION_JSON)
    monitor = read_monitor(folder / MONITOR_JSON)
    check_sdf_matches_world(sdf, world)
    objects = {o.name: o for o in world.objects}
    for animated in animation.objects:
        obj = objects.get(animated.name)
        if obj is None:
            raise ArtifactError(animation.path, f"object {animated.name!r} is not in {world.path.name}")
        if obj.category != animated.category:
            raise ArtifactError(
                animation.path,
                f"object {animated.name!r} is {animated.category.value} here but {obj.category.value} in "
                f"{world.path.name}",
            )
    for person in animation.people:
        obj = objects.get(person.name)
        if obj is None or obj.category is not Category.HUMAN:
            found = "not" if obj is None else f"a {obj.category.value}, not a HUMAN,"
            raise ArtifactError(animation.path, f"person {person.name!r} is {found} in {world.path.name}")
    if mission.robot != world.robot.name:
        raise ArtifactError(
            mission.path, f"robot {mission.robot!r} is not the world's robot {world.robot.name!r}"
        )
    if monitor.robot != world.robot.name:
        raise ArtifactError(
            monitor.path, f"robot {monitor.robot!r} is not the world's robot {world.robot.name!r}"
        )
    return Case(folder=folder, sdf=sdf, world=world, mission=mission, animation=animation, monitor=monitor)


def check_sdf_matches_world(sdf: SdfWorld, world: WorldSpec) -> None:
    """world.sdf holds one model per world.json object, same names, same order, mass 0 exactly for fixed ones."""
    expected = [o.name for o in world.objects]
    found = list(sdf.names)
    if found != expected:
        missing = [n for n in expected if n not in found]
        extra = [n for n in found if n not in expected]
        detail = f"{len(found)} models but {world.path.name} lists {len(expected)} objects"
        if missing:
            detail += f"; missing from {sdf.path.name}: {', '.join(missing)}"
        if extra:
            detail += f"; not in {world.path.name}: {', '.join(extra)}"
        if not missing and not extra:
            detail = f"models are not in the order of {world.path.name}'s objects"
        raise ArtifactError(sdf.path, detail)
    for model, obj in zip(sdf.models, world.objects, strict=True):
        if (model.mass == 0.0) != obj.category.fixed:
            raise ArtifactError(
                sdf.path,
                f"model {model.name!r}: mass {model.mass} does not fit category {obj.category.value}",
            )
