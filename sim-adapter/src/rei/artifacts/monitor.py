# SPDX-License-Identifier: EPL-2.0
"""Reader for ``monitor.json`` (``rei-monitor/1``): thresholds, topic templates and the catalogue of types."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

from rei.artifacts._fields import load_json
from rei.artifacts.world import Category, Shape

MONITOR_FORMAT = "rei-monitor/1"
TOPIC_KEYS = ("state", "mission", "signal", "config", "missionInfo", "snapshot")
FILE_KEYS = ("world", "mission", "animation")


@dataclass(frozen=True, slots=True)
class CatalogueEntry:
    name: str
    category: Category
    shape: Shape
    size: tuple[float, float, float]
    mass: float
    colour: tuple[float, float, float, float]


@dataclass(frozen=True, slots=True)
class MonitorSpec:
    """``topics`` maps a key of :data:`TOPIC_KEYS` to a URI template containing ``{run_id}``."""

    path: Path
    testcase: str
    robot: str
    close_threshold: float
    collision_threshold: float
    max_human_collisions: int
    topics: Mapping[str, str]
    files: Mapping[str, str]
    catalogue: tuple[CatalogueEntry, ...]

    def topic(self, key: str, run_id: str) -> str:
        """The concrete URI of a topic for one run."""
        return self.topics[key].replace("{run_id}", run_id)


def read_monitor(path: Path | str) -> MonitorSpec:
    path = Path(path)
    root = load_json(path, MONITOR_FORMAT)
    thresholds = root.child("thresholds")
    close = thresholds.number("close", positive=True)
    collision = thresholds.number("collision", positive=True)  # 0 < collision < close, as the DSL requires
    if collision >= close:
        raise thresholds.error(f"must be below close ({close}), got {collision}", "collision")
    requirements = root.child("requirements")
    max_collisions = requirements.integer("maxHumanCollisions")
    topics_f = root.child("topics")
    topics = {key: topics_f.text(key) for key in TOPIC_KEYS}
    for key, uri in topics.items():
        if "{run_id}" not in uri:
            raise topics_f.error(f"must contain {{run_id}}, got {uri!r}", key)
    files_f = root.child("files")
    files = {key: files_f.text(key) for key in FILE_KEYS}
    catalogue = []
    for c in root.items("catalogue"):
        category = c.text("category")
        shape = c.text("shape")
        if category not in Category.__members__:
            raise c.error(f"unknown category {category!r}", "category")
        if shape not in Shape.__members__:
            raise c.error(f"unknown shape {shape!r}", "shape")
        size = c.vector("size", 3)
        colour = c.vector("colour", 4)
        catalogue.append(
            CatalogueEntry(
                name=c.text("name"),
                category=Category(category),
                shape=Shape(shape),
                size=(size[0], size[1], size[2]),
                mass=c.number("mass", non_negative=True),
                colour=(colour[0], colour[1], colour[2], colour[3]),
            )
        )
    return MonitorSpec(
        path=path,
        testcase=root.text("testcase"),
        robot=root.text("robot"),
        close_threshold=close,
        collision_threshold=collision,
        max_human_collisions=max_collisions,
        topics=MappingProxyType(topics),
        files=MappingProxyType(files),
        catalogue=tuple(catalogue),
    )
