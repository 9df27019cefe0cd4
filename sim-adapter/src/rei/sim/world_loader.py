# SPDX-License-Identifier: EPL-2.0
"""Loads world.sdf into a pybullet client and checks it against world.json.

pybullet's ``loadSDF`` returns bare body ids and ignores ``<static>``; downstream code speaks in model names and
needs fixed bodies to really be fixed. So the loader keeps the name <-> id map and refuses a world whose bodies
(count, names, order, fixedness) differ from world.json, naming the file and the first difference.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

import pybullet as p

from rei.artifacts.errors import ArtifactError
from rei.artifacts.world import ObjectSpec, WorldSpec
from rei.sim.native_output import quiet_native_output

GRAVITY = 9.81


@dataclass(frozen=True, slots=True)
class LoadedWorld:
    """The bodies of world.sdf in one pybullet client, by name and by id."""

    client: int
    body_of: Mapping[str, int]
    name_of: Mapping[int, str]
    spec_of: Mapping[str, ObjectSpec]


def load_world(client: int, sdf_path: Path | str, world: WorldSpec) -> LoadedWorld:
    """Load ``sdf_path``, set gravity, and verify the bodies against ``world``."""
    sdf_path = Path(sdf_path)
    if not sdf_path.is_file():
        raise ArtifactError(sdf_path, "file is missing")
    p.setGravity(0.0, 0.0, -GRAVITY, physicsClientId=client)
    try:
        with quiet_native_output():
            ids = p.loadSDF(str(sdf_path), physicsClientId=client)
    except p.error as exc:
        raise ArtifactError(sdf_path, f"pybullet could not load it: {exc}") from None
    names = [p.getBodyInfo(b, physicsClientId=client)[1].decode("utf-8") for b in ids]
    expected = [o.name for o in world.objects]
    if names != expected:
        raise ArtifactError(sdf_path, _difference(names, expected, world.path.name))
    for body, obj in zip(ids, world.objects, strict=True):
        mass = p.getDynamicsInfo(body, -1, physicsClientId=client)[0]
        if obj.category.fixed and mass != 0.0:
            raise ArtifactError(
                sdf_path,
                f"model {obj.name!r} is {obj.category.value} but has mass {mass}; fixed bodies need mass 0",
            )
        if not obj.category.fixed and mass == 0.0:
            raise ArtifactError(
                sdf_path, f"model {obj.name!r} is {obj.category.value} but has mass 0 (fixed)"
            )
    return LoadedWorld(
        client=client,
        body_of=MappingProxyType(dict(zip(names, ids, strict=True))),
        name_of=MappingProxyType(dict(zip(ids, names, strict=True))),
        spec_of=MappingProxyType({o.name: o for o in world.objects}),
    )


def _difference(loaded: list[str], expected: list[str], world_name: str) -> str:
    head = f"pybullet loaded {len(loaded)} bodies but {world_name} lists {len(expected)} objects"
    missing = [n for n in expected if n not in loaded]
    extra = [n for n in loaded if n not in expected]
    if missing:
        head += f"; not loaded: {', '.join(missing[:10])}"
    if extra:
        head += f"; not in {world_name}: {', '.join(extra[:10])}"
    if not missing and not extra:
        first = next(i for i, (a, b) in enumerate(zip(loaded, expected, strict=True)) if a != b)
        head = f"bodies are not in {world_name}'s order: body #{first} is {loaded[first]!r}, expected {expected[first]!r}"
    return head
