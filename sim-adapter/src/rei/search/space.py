# SPDX-License-Identifier: EPL-2.0
"""The search space: the spec's parameters, checked against the base case, as Optuna distributions, and a
point of it as the room editor's operations (docs/room-editor.md, "Operations") plus the run's seed and fault.

Every value is named as in search.json (``bin1.floor``, ``walker.points.1``, ``walker.start``, ``ann.stops.1``,
``seed``); the base case's own values are a point of the space too (``base_values``), which is where shrinking moves
elements back to.

A human walks a trajectory (on rails: ``points``, and its ``start``, ``speed`` and ``loop`` retime it, the room
editor's ``setTrajectory``) or a route (a person who sees the robot: its ``start``, ``speed``, ``loop``, ``behaviour``
and the floors of its ``stop``s, ``setRoute``). A key of the other kind is refused at the key.

A crowd or a group (``shoppers.count``, ``shoppers.rate``, ``shoppers.behaviour``, ``family.count``) is a line of
the text whose behaviour, and a group's count, no room editor operation sets (setCrowd sets a crowd's count and
rate and areas, not its behaviour): its values are set in the base case's text (rei.edit.gatherings) before
the engine validates it, and a count larger than the line's floors hold is refused when the spec is checked, with
the language's own message.
"""

from __future__ import annotations

import difflib
import itertools
import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from optuna.distributions import BaseDistribution, CategoricalDistribution, FloatDistribution, IntDistribution

from rei import located_yaml
from rei.campaign.spec import SpecError
from rei.edit.gatherings import gatherings, with_values
from rei.search.spec import UNREAD, Parameter, Range
from rei.sim.faults import SENSOR_KIND_KEYS, fault_from_fields, format_fault

Values = Mapping[str, Any]
#: The names of extra pieces of furniture: ``search_extra_0``, ...
EXTRA = "search_extra_"
#: The keys of a person on a route and of a trajectory (a human's or a moving object's).
ROUTE_KEYS = ("start", "speed", "loop", "behaviour", "stop")
TRAJECTORY_KEYS = ("points", "start", "speed", "loop")
#: The fastest a person on a route walks (the language's RouteValidator.MAX_SPEED), m/s.
MAX_ROUTE_SPEED = 3.0


@dataclass(frozen=True, slots=True)
class Edit:
    """A point of the space as what to do to the base case: edit operations, the run's seed and fault, and the
    crowds' and groups' values to set in the base case's text first (rei.edit.gatherings.with_values)."""

    operations: tuple[dict[str, Any], ...]
    seed: int
    fault: str | None
    people: tuple[dict[str, Any], ...] = field(default=())

    def text(self, base: str) -> str:
        """The base case's text with the crowds' and groups' values (the text itself when it has none)."""
        return with_values(base, self.people) if self.people else base


class Space:
    """The parameters of a spec over one base case (its room editor diagram)."""

    def __init__(self, parameters: Sequence[Parameter], diagram: Mapping[str, Any],
                 palette: Sequence[Mapping[str, Any]] = (), *, humans: bool = True, text: str = "",
                 validate: Callable[[str], list[dict[str, Any]]] | None = None) -> None:
        """``humans``: whether the runs have the humans (a spec's ``humans: false`` leaves them out); ``text``: the
        base case's text (its crowds and groups); ``validate``: the language's issues of a text (the room editor's
        engine), to check a crowd's or a group's largest count. Every parameter the base case does not have is a
        problem of one ``SpecError``."""
        self.parameters = tuple(parameters)
        self._with_humans = humans
        self._text = text
        self._validate = validate
        self._gatherings = gatherings(text)
        self._diagram = diagram
        self._floors = {f["name"]: (float(f["centreX"]), float(f["centreY"])) for f in diagram["room"]["floors"]}
        objects = {o["name"]: o for o in diagram.get("objects") or []}
        robot = diagram.get("robot")
        self._humans = {m["name"]: m for m in diagram.get("movers") or []}
        self._goals = list((diagram.get("mission") or {}).get("goals") or [])
        self._items = {**objects, **({robot["name"]: robot} if robot else {})}
        taken = {item["floor"]: name for name, item in self._items.items()}
        self.distributions: dict[str, BaseDistribution] = {}
        self._base: dict[str, Any] = {}
        self._furniture_types = [t["name"] for t in palette if t.get("category") == "object"]
        self._extras = 0  # the most extra pieces of furniture a point may have
        # every parameter the base case does not have is reported at once, each at its name or value (a parameter
        # whose element is missing is not checked further)
        problems = located_yaml.Collector()
        self._walks_refused: set[str] = set()
        for p in self.parameters:
            with problems.check():
                self._add(p, objects, robot, taken)
        problems.raise_if_any(SpecError)

    # -- the spec against the base case -------------------------------------------------------------------------

    def _add(self, p: Parameter, objects: Mapping[str, Any], robot: Mapping[str, Any] | None,
             taken: Mapping[str, str]) -> None:
        at = p.name_at or p.where
        if p.target == "object" and p.name not in objects:
            raise SpecError(f"{at}: the base case has no object named {p.name!r}; it has "
                            f"{', '.join(objects) or 'none'}")
        if p.target == "robot" and (robot is None or robot["name"] != p.name):
            raise SpecError(f"{at}: the base case's robot is {robot['name'] if robot else 'missing'}, "
                            f"not {p.name!r}")
        if p.target == "human" and p.name not in self._humans:
            raise SpecError(f"{at}: the base case has no human or moving object named {p.name!r}; it has "
                            f"{', '.join(self._humans) or 'none'}")
        if p.target in ("crowd", "group"):
            self._add_gathering(p)
            return
        if p.target == "goal" and int(p.name) >= len(self._goals):
            raise SpecError(f"{at}: the mission has {len(self._goals)} goal(s): index {p.name} is not one")
        if p.target == "human" and p.prop in ROUTE_KEYS + TRAJECTORY_KEYS:
            self._check_kind(p)
        if p.domain is UNREAD:  # its values did not read (the spec's own mistake): only its element is checked
            return
        if p.target == "human" and not self._with_humans and self._humans[p.name].get("kind") == "human":
            # the runs leave the humans out (a moving object stays): searching one's walk would change nothing (said
            # once per human, of its first parameter)
            if p.name in self._walks_refused:
                return
            self._walks_refused.add(p.name)
            raise SpecError(f"{at}: {p.name} is a human and the spec runs without humans (humans: false): its "
                            f"{p.prop} would change nothing; remove its parameters or set humans: true")
        if p.target == "furniture":
            self._add_furniture(p, taken)
            return
        if p.target == "fault" and p.prop in ("kind", "wheel"):
            self._categorical(p.key, list(p.domain), None, p.where)  # base None: the base case runs no such fault
            return
        if p.target == "fault":  # a fault's values (its start and speed are no person's)
            self._float(p.key, p.domain, None)
            return
        route = self._route(p.name) if p.target == "human" else None
        if route is not None:
            self._add_route(p, route, taken)
        elif p.prop == "floor":
            own = self._items[p.name]["floor"] if p.target in ("object", "robot") else None
            base = own if own is not None else self._goals[int(p.name)]["floor"]
            free = [f for f in self._floors if f not in taken or taken[f] == p.name] if p.target != "goal" \
                else list(self._floors)
            self._categorical(p.key, self._checked_floors(p, p.domain, free), base, p.where)
        elif p.prop == "yaw":
            self._float(p.key, p.domain, float(self._items[p.name]["yaw"]))
        elif p.prop == "points":
            points = self._humans[p.name]["points"]
            if len(p.domain) != len(points):
                raise SpecError(f"{p.where}: {p.name} has {len(points)} control points in the base case, the spec "
                                f"gives floors for {len(p.domain)}")
            for i, floors in enumerate(p.domain):
                self._categorical(f"{p.key}.{i}", self._checked_floors(p, floors, list(self._floors)),
                                  points[i]["floor"], p.where)
        elif p.prop == "start":
            self._float(p.key, p.domain, float(self._humans[p.name]["points"][0]["seconds"]))
        elif p.prop == "speed":
            self._float(p.key, p.domain, self._base_speed(p.name))
        elif p.prop == "loop":
            self._categorical(p.key, list(p.domain), bool(self._humans[p.name]["loop"]), p.where)
        elif p.target == "seed":
            self._float(p.key, p.domain, 0)
        elif p.target == "fault":
            self._float(p.key, p.domain, None)
        else:
            raise AssertionError(p)

    def _add_gathering(self, p: Parameter) -> None:
        """A crowd's or a group's count, rate or behaviour: the line exists and is of that kind, the runs have the
        humans, the largest count fits its floors."""
        at = p.name_at or p.where
        g = self._gatherings.get(p.name)
        if g is None or g.kind != p.target:
            same = [name for name, other in self._gatherings.items() if other.kind == p.target]
            if g is not None:
                hint = f": {p.name} is a {g.kind}, searched as {{{g.kind}: {p.name}, ...}}"
            else:
                close = difflib.get_close_matches(p.name, same, n=1)
                hint = f" (did you mean {close[0]}?)" if close else ""
            raise SpecError(f"{at}: the base case has no {p.target} named {p.name!r}{hint}; its {p.target}s: "
                            f"{', '.join(same) or 'none'}")
        if p.domain is UNREAD:
            return
        if not self._with_humans:
            raise SpecError(f"{at}: {p.name} is a {p.target} of people and the spec runs without humans (humans: "
                            f"false): its {p.prop} would change nothing; remove its parameters or set humans: true")
        if p.prop == "count":
            self._check_count(p)
            self._float(p.key, p.domain, g.count)
        elif p.prop == "rate":
            self._float(p.key, p.domain, g.rate)  # None: unwritten, every person sets off at the start
        elif p.prop == "behaviour":
            self._categorical(p.key, list(p.domain), g.behaviour, p.where)
        else:
            raise AssertionError(p)

    def _check_count(self, p: Parameter) -> None:
        """The most people the range reaches must fit the line's floors: the language's own check of the base case
        with that count (its message said at the range), so that no candidate is refused for it."""
        if self._validate is None:
            return
        high = int(p.domain.high)
        text = with_values(self._text, [{"name": p.name, "count": high}])
        own = [i for i in self._validate(text) if i.get("severity") == "error" and i.get("element") == p.name]
        if own:
            raise SpecError(f"{p.where}: {p.name} of {high} people is more than the base case's room takes: "
                            f"{own[0]['message']}")

    def _route(self, name: str) -> Mapping[str, Any] | None:
        """The route of a person who sees the robot; None for a trajectory."""
        route: Mapping[str, Any] | None = self._humans[name].get("route")
        return route

    def _check_kind(self, p: Parameter) -> None:
        """A key of a route on a trajectory, or the other way round, is refused at the key."""
        mover = self._humans[p.name]
        at = p.prop_at or p.where
        if self._route(p.name) is not None and p.prop not in ROUTE_KEYS:
            raise SpecError(f"{at}: {p.name} walks a route (a person who sees the robot): '{p.prop}' is a "
                            f"trajectory's; a route's keys are {', '.join(ROUTE_KEYS)} (a stop's floors: "
                            f"{{human: {p.name}, stop: INDEX, floor: [...]}})")
        if self._route(p.name) is None and p.prop not in TRAJECTORY_KEYS:
            what = "a moving object on a trajectory" if mover.get("kind") == "dynamic" else \
                "a human on a trajectory"
            raise SpecError(f"{at}: {p.name} is {what}: '{p.prop}' is a route's (a person who sees the robot); a "
                            f"trajectory's keys are {', '.join(TRAJECTORY_KEYS)}")

    def _add_route(self, p: Parameter, route: Mapping[str, Any], taken: Mapping[str, str]) -> None:
        """A person on a route: its start, speed, loop and behaviour, and the floor of a stop."""
        if p.prop == "start":
            self._float(p.key, p.domain, float(route["start"]))
        elif p.prop == "speed":
            if p.domain.high > MAX_ROUTE_SPEED:
                raise SpecError(f"{p.where}: {p.name} walks a route, at most {MAX_ROUTE_SPEED:g} m/s (the language's "
                                f"limit), got [{p.domain.low:g}, {p.domain.high:g}]")
            self._float(p.key, p.domain, float(route["speed"]))
        elif p.prop == "loop":
            self._categorical(p.key, list(p.domain), bool(self._humans[p.name]["loop"]), p.where)
        elif p.prop == "behaviour":
            self._categorical(p.key, list(p.domain), route["behaviour"], p.where)
        elif p.prop == "stop":
            stops = route["stops"]
            assert p.index is not None
            if p.index >= len(stops):
                raise SpecError(f"{p.prop_at or p.where}: {p.name}'s route has {len(stops)} stop(s), counted from 0: "
                                f"stop {p.index} is not one")
            # the first stop is where the person stands at the start: free of furniture and the robot, as every
            # start; a later one only of furniture
            blocked = {f for f, name in taken.items() if p.index == 0 or self._items[name]["kind"] == "object"}
            free = [f for f in self._floors if f not in blocked]
            self._categorical(p.key, self._checked_floors(p, p.domain, free), stops[p.index]["floor"], p.where)
        else:
            raise AssertionError(p)

    def _add_furniture(self, p: Parameter, taken: Mapping[str, str]) -> None:
        types, count, floors = p.domain
        unknown = [t for t in types if t not in self._furniture_types]
        if unknown:
            raise SpecError(f"{p.name_at or p.where}: {unknown[0]!r} is not a furniture type of the base case's "
                            f"catalogues; they have {', '.join(self._furniture_types)}")
        free = [f for f in self._floors if f not in taken]
        choices = self._checked_floors(p, floors, free)
        self._float(p.key, count, 0)
        self._extras = int(count.high)
        for i in range(self._extras):  # every slot is sampled; a point uses the first ``count`` of them
            self._categorical(f"furniture.{i}.type", list(types), None, p.where)
            self._categorical(f"furniture.{i}.floor", choices, None, p.where)

    def _checked_floors(self, p: Parameter, floors: Sequence[str] | None, default: list[str]) -> list[str]:
        if floors is None:
            return default
        unknown = [f for f in floors if f not in self._floors]
        if unknown:
            raise SpecError(f"{p.where}: the base case's room has no floor {unknown[0]!r}")
        return list(floors)

    def _categorical(self, key: str, choices: list[Any], base: Any, where: str) -> None:
        if not choices:
            raise SpecError(f"{where}: {key} has no floor to choose from")
        self.distributions[key] = CategoricalDistribution(choices)
        self._base[key] = base

    def _float(self, key: str, domain: Range, base: Any) -> None:
        if domain.integer:
            self.distributions[key] = IntDistribution(int(domain.low), int(domain.high))
        else:
            self.distributions[key] = FloatDistribution(domain.low, domain.high)
        self._base[key] = base

    def _base_speed(self, human: str) -> float:
        points = self._humans[human]["points"]
        length = sum(math.dist((a["x"], a["y"]), (b["x"], b["y"])) for a, b in itertools.pairwise(points))
        duration = float(points[-1]["seconds"]) - float(points[0]["seconds"])
        return length / duration if duration > 0 else 1.0

    # -- a point of the space ------------------------------------------------------------------------------------

    def base_values(self) -> dict[str, Any]:
        """The base case's own value of every parameter (None for a fault's value: no fault)."""
        return dict(self._base)

    def edit(self, values: Values, removed: Sequence[str] = ()) -> Edit:
        """The operations that make ``values`` of the base case, with the objects and humans ``removed``
        deleted (a shrunk case)."""
        operations: list[dict[str, Any]] = []
        for p in self.parameters:
            if p.name in removed and p.target in ("object", "human"):
                continue
            if p.target in ("object", "robot") and p.prop == "floor":
                operations.append({"op": "moveObject", "name": p.name, "floor": values[p.key]})
            elif p.prop == "yaw":
                operations.append({"op": "rotateObject", "name": p.name, "yawDegrees": float(values[p.key])})
        for human in dict.fromkeys(p.name for p in self.parameters if p.target == "human" and p.name not in removed):
            operations.append(self._trajectory(human, values) if self._route(human) is None
                              else self._set_route(human, values))
        goals = [p for p in self.parameters if p.target == "goal"]
        for p in sorted(goals, key=lambda p: int(p.name)):
            index = int(p.name)
            operations += [{"op": "removeGoal", "index": index},
                           {"op": "addGoal", "floor": values[p.key], "index": index,
                            "timeoutSeconds": self._goals[index].get("timeout")}]
        count = int(values.get("furniture.count") or 0)
        operations += [{"op": "addObject", "name": f"{EXTRA}{i}", "type": values[f"furniture.{i}.type"],
                        "floor": values[f"furniture.{i}.floor"]} for i in range(min(count, self._extras))]
        operations += [{"op": "deleteObject", "name": name} for name in removed]
        seed = int(values.get("seed", 0) or 0)
        people: dict[str, dict[str, Any]] = {}
        for p in self.parameters:
            if p.target in ("crowd", "group") and p.name not in removed and values.get(p.key) is not None:
                people.setdefault(p.name, {"name": p.name})[p.prop] = values[p.key]
        return Edit(tuple(operations), seed, self._fault(values), tuple(people.values()))

    def _trajectory(self, human: str, values: Values) -> dict[str, Any]:
        base = self._humans[human]
        points = base["points"]
        floors = [values.get(f"{human}.points.{i}", point["floor"]) for i, point in enumerate(points)]
        start = float(values.get(f"{human}.start", points[0]["seconds"]))
        speed = values.get(f"{human}.speed")
        if speed is None:
            times = [start + float(p["seconds"]) - float(points[0]["seconds"]) for p in points]
        else:
            times = [start]
            for a, b in itertools.pairwise(floors):
                times.append(times[-1] + math.dist(self._floors[a], self._floors[b]) / float(speed))
        loop = values.get(f"{human}.loop", base["loop"])
        return {"op": "setTrajectory", "name": human, "loop": bool(loop),
                "points": [{"floor": f, "seconds": round(t, 3)} for f, t in zip(floors, times, strict=True)]}

    def _set_route(self, human: str, values: Values) -> dict[str, Any]:
        """The route with the point's values, the base case's where the point has none (numbers to the millisecond
        and millimetre per second: the text writes what it is given)."""
        route = self._route(human)
        assert route is not None
        stops = [{"floor": values.get(f"{human}.stops.{i}", stop["floor"]), "waitSeconds": float(stop["waitSeconds"])}
                 for i, stop in enumerate(route["stops"])]
        return {"op": "setRoute", "name": human, "stops": stops,
                "speed": round(float(values.get(f"{human}.speed", route["speed"])), 3),
                "start": round(float(values.get(f"{human}.start", route["start"])), 3),
                "loop": bool(values.get(f"{human}.loop", self._humans[human]["loop"])),
                "behaviour": str(values.get(f"{human}.behaviour", route["behaviour"]))}

    def _fault(self, values: Values) -> str | None:
        faults = [p for p in self.parameters if p.target == "fault"]
        if not faults or all(values.get(p.key) is None for p in faults):
            return None
        if faults[0].base is None:  # a fault on a timeline
            return self._scheduled_fault(faults[0].name, values)
        settings = ",".join(f"{p.prop}={int(values[p.key]) if p.prop == 'width' else round(values[p.key], 6)}"
                            for p in faults if values.get(p.key) is not None)
        return f"{faults[0].base},{settings}"

    @staticmethod
    def _scheduled_fault(sensor: str, values: Values) -> str | None:
        """The point's fault on a timeline as its ``--fault`` spec, written by the fault model's own writer
        (rei.sim.faults.format_fault): times to the millisecond, the other values to six digits, only the keys of
        the point's kind; a pulse longer than its period is the whole period (a range of pulses and one of periods
        may cross)."""
        kind = values.get("fault.kind")
        if kind is None:
            return None

        def number(key: str) -> float | None:
            value = values.get(f"fault.{key}")
            return None if value is None else float(value)

        fields: dict[str, str] = {}
        start, duration = number("start"), number("duration")
        if start is not None or duration is not None:
            fields["from"] = repr(round(start or 0.0, 3))
        if duration is not None:
            fields["to"] = repr(round((start or 0.0) + duration, 3))
        for key in SENSOR_KIND_KEYS[sensor][kind]:
            if key == "wheel":  # a choice, not a number
                if values.get("fault.wheel") is not None:
                    fields["wheel"] = str(values["fault.wheel"])
                continue
            value = number(key)
            if value is not None and key == "delay":
                fields[key] = repr(round(_control_periods(value), 6))
            elif value is not None:
                fields[key] = str(int(value)) if key == "width" else repr(round(value, 6))
        period = number("period")
        if period is not None:
            fields["period"] = repr(round(period, 3))
            pulse, duty = number("pulse"), number("duty")
            if pulse is not None:
                fields["pulse"] = repr(round(min(pulse, period), 3))
            elif duty is not None:
                fields["duty"] = repr(round(duty, 6))
        return format_fault(fault_from_fields(sensor, kind, fields))

    def removable(self) -> list[str]:
        """The objects, humans, crowds and groups of the base case: what shrinking may try to remove (never the
        robot)."""
        return [name for name, item in self._items.items() if item["kind"] == "object"] + list(self._humans) + \
            list(self._gatherings)

    def owns(self, name: str, element: str) -> bool:
        """Whether ``element`` (what a failure names) is ``name`` or one of its people, when ``name`` is a crowd or
        a group (``shoppers_3`` of ``shoppers``)."""
        if element == name:
            return True
        return name in self._gatherings and re.fullmatch(rf"{re.escape(name)}_[0-9]+", element) is not None

    def people_counts(self) -> set[str]:
        """The keys of the crowds' and groups' counts (``shoppers.count``)."""
        return {p.key for p in self.parameters if p.target in ("crowd", "group") and p.prop == "count"}

    def smaller(self, key: str, value: Any, element: str) -> list[Any]:
        """The values shrinking tries for ``key``, in order, after ``value`` failed: towards the base case's value,
        but a crowd's or a group's count towards its fewest people (never fewer than the failure's own person,
        ``shoppers_7`` needs 7; then halfway) and a crowd's rate towards its slowest."""
        p = next((p for p in self.parameters if p.key == key), None)
        if p is not None and p.target == "fault" and p.base is None:
            return _shorter_or_later(p, value)
        if p is None or p.target not in ("crowd", "group") or p.prop == "behaviour":
            return [self._base.get(key)]
        if p.prop == "rate":
            return [p.domain.low] if value is None or float(value) > p.domain.low else []
        own = re.fullmatch(rf"{re.escape(p.name)}_([0-9]+)", element)
        least = max(int(p.domain.low), int(own[1]) if own else 0)
        if value is None or int(value) <= least:
            return []
        halfway = (least + int(value)) // 2
        return [least] + ([halfway] if least < halfway < int(value) else [])

    def shrink_order(self, keys: Sequence[str]) -> list[str]:
        """The order in which shrinking moves values: the crowds' and groups' counts first (fewer people is the
        largest reduction), a fault's duration before its start (shorter first, then later), then the rest."""
        counts = self.people_counts()
        return sorted(keys, key=lambda key: (key not in counts, key != "fault.duration"))

    def floor_at(self, x: float, y: float) -> str:
        """The floor whose centre is nearest to (x, y): where something happened, as the test case names it."""
        return min(self._floors, key=lambda name: math.dist(self._floors[name], (x, y)))


#: The shares of the way to a fault's shortest duration (or latest start) shrinking tries, boldest first.
SHRINK_STEPS = (1.0, 0.75, 0.5, 0.25)


def _control_periods(delay: float) -> float:
    """A command latency's ``delay`` as the whole number of the runs' control periods nearest to it, one at least:
    the mission loop applies a command a whole number of ticks later (rei.sim.faults.motion.Latency)."""
    from rei.run.mission_run import MissionRunOptions  # the rate every run of a search has (rei run's own)

    rate = MissionRunOptions().control_rate
    return max(1, round(delay * rate)) / rate


def _shorter_or_later(p: Parameter, value: Any) -> list[Any]:
    """A fault on a timeline shrinks towards a shorter fault and a later start, within the spec's ranges: its
    duration towards the range's low end, its start towards the high end, each by the shares ``SHRINK_STEPS`` of the
    way (the first that still fails is kept); its kind and other values stay (a fault the failure needs is not
    removed: shrinking says how little of it does)."""
    if value is None or p.prop not in ("duration", "start"):
        return []
    value = float(value)
    target = p.domain.low if p.prop == "duration" else p.domain.high
    if abs(target - value) < 1e-3:  # the times are written to the millisecond
        return []
    return [value + share * (target - value) for share in SHRINK_STEPS]
