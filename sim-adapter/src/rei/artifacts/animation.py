# SPDX-License-Identifier: EPL-2.0
"""Reader for ``animation.json`` (``rei-animation/1``): timed Catmull-Rom control points per moving object on
rails (``objects``), and the routes of the people who see the robot (``people``, docs/people.md)."""

from __future__ import annotations

import enum
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


class Behaviour(enum.StrEnum):
    """How a reactive person treats the robot (docs/people.md)."""

    AVOIDS = "avoids"
    IGNORES = "ignores"
    CURIOUS = "curious"
    SCARED = "scared"
    BLOCKS = "blocks"


@dataclass(frozen=True, slots=True)
class RouteStop:
    floor: str
    x: float
    y: float
    wait: float
    #: A crowd's queue here: seconds between two people passing (docs/people.md); None: not a queue.
    queue: float | None = None


@dataclass(frozen=True, slots=True)
class PersonSpec:
    """A reactive person: walks ``route`` from its first stop at ``speed`` from ``start`` on, round again when
    ``loop``; a pedestrian-dynamics model finds the way between stops and keeps the person clear of others."""

    name: str
    behaviour: Behaviour
    speed: float
    start: float
    loop: bool
    route: tuple[RouteStop, ...]
    speed_to: float | None = None  # the desired speed is drawn from [speed, speed_to] with the run's seed
    group: str | None = None  # walks with the people of the same group; the first of them listed leads


@dataclass(frozen=True, slots=True)
class AnimationSpec:
    path: Path
    objects: tuple[AnimatedObject, ...]
    people: tuple[PersonSpec, ...] = ()


def read_animation(path: Path | str) -> AnimationSpec:
    """Read ``animation.json``; control-point times must be strictly increasing."""
    path = Path(path)
    root = load_json(path, ANIMATION_FORMAT)
    objects = tuple(_animated(o) for o in root.items("objects"))
    people = tuple(_person(p) for p in root.items("people")) if root.has("people") else ()
    seen: set[str] = set()
    for name, key in [*((o.name, "objects") for o in objects), *((p.name, "people") for p in people)]:
        if name in seen:
            raise root.error(f"object {name!r} is animated twice", key)
        seen.add(name)
    return AnimationSpec(path=path, objects=objects, people=people)


def _person(p: Fields) -> PersonSpec:
    text = p.text("behaviour")
    try:
        behaviour = Behaviour(text)
    except ValueError:
        known = ", ".join(b.value for b in Behaviour)
        raise p.error(f"unknown behaviour {text!r}, expected one of {known}", "behaviour") from None
    speed = p.number("speed")
    if not 0 < speed <= 3.0:
        raise p.error(f"must be > 0 and <= 3 m/s, got {speed}", "speed")
    speed_to = p.number("speedTo") if p.has("speedTo") else None
    if speed_to is not None and not speed <= speed_to <= 3.0:
        raise p.error(f"must be at least speed ({speed}) and at most 3 m/s, got {speed_to}", "speedTo")
    start = p.number("start")
    if start < 0:
        raise p.error(f"must be >= 0 s, got {start}", "start")
    route = tuple(RouteStop(floor=s.text("floor"), x=s.number("x"), y=s.number("y"), wait=s.number("wait"),
                            queue=s.number("queue") if s.has("queue") else None)
                  for s in p.items("route"))
    if not route:
        raise p.error("needs at least one stop", "route")
    for i, stop in enumerate(route):
        if stop.wait < 0:
            raise p.error(f"must be >= 0 s, got {stop.wait}", f"route[{i}].wait")
        if stop.queue is not None and not stop.queue > 0:
            raise p.error(f"must be > 0 s, got {stop.queue}", f"route[{i}].queue")
    return PersonSpec(name=p.text("name"), behaviour=behaviour, speed=speed, start=start, loop=p.flag("loop"),
                      route=route, speed_to=speed_to, group=p.optional_text("group"))


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
