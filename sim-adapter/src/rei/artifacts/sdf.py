# SPDX-License-Identifier: EPL-2.0
"""Reader for the parts of ``world.sdf`` the adapter checks before handing it to pybullet.

pybullet's ``loadSDF`` fails with an unhelpful message (or silently loads fewer bodies) on a broken file, and it
ignores ``<static>``; reading the models first lets us name the file, the model and the problem.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

from rei.artifacts._xml import read_root
from rei.artifacts.errors import ArtifactError


@dataclass(frozen=True, slots=True)
class SdfModel:
    """One ``<model>``: its name, ``<static>`` flag, ``<pose>`` (x y z roll pitch yaw) and its link's mass."""

    name: str
    static: bool
    pose: tuple[float, float, float, float, float, float]
    mass: float


@dataclass(frozen=True, slots=True)
class SdfWorld:
    path: Path
    models: tuple[SdfModel, ...]

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(m.name for m in self.models)


def read_sdf(path: Path | str) -> SdfWorld:
    """Parse ``world.sdf`` and check the subset of SDF 1.6 described in docs/artifacts.md."""
    path = Path(path)
    root = read_root(path, "sdf")
    world = root.find("world")
    holder = world if world is not None else root
    models = tuple(_model(path, i, m) for i, m in enumerate(holder.findall("model")))
    if not models:
        raise ArtifactError(path, "no <model> elements")
    seen: set[str] = set()
    for m in models:
        if m.name in seen:
            raise ArtifactError(path, f"model name {m.name!r} is used twice")
        seen.add(m.name)
    return SdfWorld(path=path, models=models)


def _model(path: Path, index: int, model: ET.Element) -> SdfModel:
    name = model.get("name")
    if not name:
        raise ArtifactError(path, f"model #{index}: missing name attribute")
    where = f"model {name!r}"
    pose = _floats(path, where, "pose", model.findtext("pose", "0 0 0 0 0 0"), 6)
    link = model.find("link")
    if link is None:
        raise ArtifactError(path, f"{where}: no <link>")
    inertial = link.find("inertial")
    if inertial is None or inertial.find("inertia") is None:
        raise ArtifactError(
            path, f"{where}: the link needs an <inertial> with an <inertia> (pybullet requires it)"
        )
    mass = _floats(path, where, "inertial/mass", inertial.findtext("mass", "0"), 1)[0]
    if link.find("collision") is None:
        raise ArtifactError(path, f"{where}: the link has no <collision>")
    static = (model.findtext("static") or "false").strip().lower() in ("true", "1")
    if static and mass != 0.0:
        raise ArtifactError(path, f"{where}: static but mass {mass} (pybullet ignores <static>; use mass 0)")
    return SdfModel(
        name=name, static=static, pose=(pose[0], pose[1], pose[2], pose[3], pose[4], pose[5]), mass=mass
    )


def _floats(path: Path, where: str, what: str, text: str, count: int) -> tuple[float, ...]:
    parts = text.split()
    try:
        values = tuple(float(p) for p in parts)
    except ValueError:
        raise ArtifactError(path, f"{where}: <{what}> must be {count} numbers, got {text!r}") from None
    if len(values) != count:
        raise ArtifactError(path, f"{where}: <{what}> must be {count} numbers, got {text!r}")
    return values
