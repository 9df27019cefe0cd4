# SPDX-License-Identifier: EPL-2.0
"""Reader for ``animation.json`` (``rei-animation/1``): timed Catmull-Rom control points per moving object."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from rei.artifacts._fields import Fields, load_json
from rei.artifacts.world import Category

ANIMATION_FORMAT = "rei-animation/1"


@dataclass(frozen=True, slots=True)
class ControlPoint:
    t: float
    x: float
    y: float
    floor: str | None


@dataclass(frozen=True, slots=True)
class AnimatedObject:
    """A human or dynamic object and its trajectory; ``loop`` repeats it forever, otherwise it stops at the end."""

    name: str
    category: Category
    loop: bool
    points: tuple[ControlPoint, ...]


@dataclass(frozen=True, slots=True)
class AnimationSpec:
    path: Path
    objects: tuple[AnimatedObject, ...]


def read_animation(path: Path | str) -> AnimationSpec:
    """Read ``animation.json``; control-point times must be strictly increasing."""
    path = Path(path)
    root = load_json(path, ANIMATION_FORMAT)
    objects = tuple(_animated(o) for o in root.items("objects"))
    seen: set[str] = set()
    for obj in objects:
        if obj.name in seen:
            raise root.error(f"object {obj.name!r} is animated twice", "objects")
        seen.add(obj.name)
    return AnimationSpec(path=path, objects=objects)


def _animated(o: Fields) -> AnimatedObject:
    text = o.text("category")
    if text not in (Category.HUMAN.value, Category.DYNAMIC.value):
        raise o.error(f"only HUMAN or DYNAMIC objects are animated, got {text!r}", "category")
    points = tuple(
        ControlPoint(t=p.number("t"), x=p.number("x"), y=p.number("y"), floor=p.optional_text("floor"))
        for p in o.items("points")
    )
    if not points:
        raise o.error("needs at least one control point", "points")
    for i in range(1, len(points)):
        if points[i].t <= points[i - 1].t:
            raise o.error(
                f"times must be strictly increasing, got {points[i - 1].t} then {points[i].t}",
                f"points[{i}].t",
            )
    return AnimatedObject(name=o.text("name"), category=Category(text), loop=o.flag("loop"), points=points)
