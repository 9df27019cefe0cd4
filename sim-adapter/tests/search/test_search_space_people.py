# SPDX-License-Identifier: EPL-2.0
"""The search space over people who see the robot (a human on a route): the same start, speed and loop keys as a
trajectory's, its behaviour and the floors of its stops, the base case as a point, a point as the room editor's
setRoute; a key of the other kind of human is refused at the key, every one at once."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import pytest
from optuna.distributions import CategoricalDistribution, FloatDistribution
from spec_helpers import error_of, parse

from rei.campaign.spec import SpecError
from rei.search.space import Space
from rei.search.spec import Parameter, Range


def floor(name: str, x: int, y: int) -> dict[str, Any]:
    return {"name": name, "x": x, "y": y, "centreX": x + 0.5, "centreY": y + 0.5}


def stop(name: str, wait: float = 0.0) -> dict[str, Any]:
    return {"floor": name, "waitSeconds": wait, "x": 0.0, "y": 0.0}


#: A row of four floors and one above F_1_0: a bin on F_3_0, the robot on F_0_0, a walker on rails and ann on a route.
DIAGRAM: dict[str, Any] = {
    "room": {"floorSize": 1.0, "floors": [floor(f"F_{x}_0", x, 0) for x in range(4)] + [floor("F_1_1", 1, 1)],
             "walls": []},
    "objects": [{"name": "bin1", "kind": "object", "floor": "F_3_0", "yaw": 0.0}],
    "robot": {"name": "tb3", "kind": "robot", "floor": "F_0_0", "yaw": 0.0},
    "movers": [{"name": "walker", "kind": "human", "loop": True, "route": None,
                "points": [{"floor": "F_1_1", "seconds": 2.0, "x": 1.5, "y": 1.5},
                           {"floor": "F_1_0", "seconds": 4.0, "x": 1.5, "y": 0.5}]},
               {"name": "cart", "kind": "dynamic", "loop": False, "route": None,
                "points": [{"floor": "F_2_0", "seconds": 0.0, "x": 2.5, "y": 0.5}]},
               {"name": "ann", "kind": "human", "loop": True, "points": [],
                "route": {"stops": [stop("F_1_1"), stop("F_2_0", 3.0)], "speed": 1.1, "start": 0.0,
                          "behaviour": "avoids"}}],
    "mission": {"goals": [{"index": 0, "floor": "F_2_0", "timeout": None}]},
}


def p(prop: str, domain: Any, name: str = "ann", index: int | None = None) -> Parameter:
    return Parameter("human", name, prop, domain, "s.yaml:1:30", name_at="s.yaml:1:12", prop_at="s.yaml:1:20",
                     index=index)


def test_a_routed_persons_distributions_and_base_values() -> None:
    space = Space([p("start", Range(0, 20)), p("speed", Range(0.5, 1.8)), p("loop", (True, False)),
                   p("behaviour", ("avoids", "curious", "blocks")), p("stop", None, index=0),
                   p("stop", ("F_2_0", "F_3_0"), index=1)], DIAGRAM)
    d = space.distributions
    assert d["ann.start"] == FloatDistribution(0, 20) and d["ann.speed"] == FloatDistribution(0.5, 1.8)
    assert d["ann.behaviour"] == CategoricalDistribution(["avoids", "curious", "blocks"])
    # any floor for where the person starts: not the robot's, not the bin's
    assert d["ann.stops.0"] == CategoricalDistribution(["F_1_0", "F_2_0", "F_1_1"])
    assert d["ann.stops.1"] == CategoricalDistribution(["F_2_0", "F_3_0"])
    assert space.base_values() == {"ann.start": 0.0, "ann.speed": 1.1, "ann.loop": True, "ann.behaviour": "avoids",
                                   "ann.stops.0": "F_1_1", "ann.stops.1": "F_2_0"}
    assert space.removable() == ["bin1", "walker", "cart", "ann"]


def test_a_later_stop_may_be_where_the_robot_starts_but_not_on_furniture() -> None:
    space = Space([p("stop", None, index=1)], DIAGRAM)
    assert space.distributions["ann.stops.1"] == CategoricalDistribution(["F_0_0", "F_1_0", "F_2_0", "F_1_1"])


def test_a_point_is_one_set_route_with_the_base_case_where_the_point_has_nothing() -> None:
    space = Space([p("start", Range(0, 20)), p("behaviour", ("avoids", "scared")), p("stop", None, index=1),
                   Parameter("human", "walker", "start", Range(0, 10), "s.yaml:2:1")], DIAGRAM)
    edit = space.edit({"ann.start": 7.123456, "ann.behaviour": "scared", "ann.stops.1": "F_1_0",
                       "walker.start": 5.0})
    assert edit.operations == (
        {"op": "setRoute", "name": "ann", "stops": [{"floor": "F_1_1", "waitSeconds": 0.0},
                                                    {"floor": "F_1_0", "waitSeconds": 3.0}],
         "speed": 1.1, "start": 7.123, "loop": True, "behaviour": "scared"},
        {"op": "setTrajectory", "name": "walker", "loop": True,
         "points": [{"floor": "F_1_1", "seconds": 5.0}, {"floor": "F_1_0", "seconds": 7.0}]})
    # the base case's own values are the route as written; a removed person is only deleted
    assert space.edit(space.base_values()).operations[0] == {
        "op": "setRoute", "name": "ann", "stops": [{"floor": "F_1_1", "waitSeconds": 0.0},
                                                   {"floor": "F_2_0", "waitSeconds": 3.0}],
        "speed": 1.1, "start": 0.0, "loop": True, "behaviour": "avoids"}
    assert space.edit(space.base_values(), removed=["ann"]).operations[-1] == {"op": "deleteObject", "name": "ann"}
    assert all(op["op"] != "setRoute" for op in space.edit(space.base_values(), removed=["ann"]).operations)


def test_speed_and_loop_of_a_route() -> None:
    space = Space([p("speed", Range(0.4, 2.5)), p("loop", (False,))], DIAGRAM)
    [operation] = space.edit({"ann.speed": 0.87654, "ann.loop": False}).operations
    assert (operation["speed"], operation["loop"]) == (0.877, False)


def test_keys_of_the_other_kind_are_refused_at_the_key_all_at_once() -> None:
    parameters = [p("points", (None, None)), p("behaviour", ("ignores",), name="walker"),
                  Parameter("human", "cart", "stop", None, "s.yaml:3:40", name_at="s.yaml:3:12", prop_at="s.yaml:3:25",
                            index=0),
                  p("stop", None, index=2), p("speed", Range(1, 3.5))]
    with pytest.raises(SpecError) as raised:
        Space(parameters, DIAGRAM)
    # in the order of the file
    assert list(raised.value.problems) == [
        ("s.yaml:1:20: ann walks a route (a person who sees the robot): 'points' is a trajectory's; a route's keys are "
        "start, speed, loop, behaviour, stop (a stop's floors: {human: ann, stop: INDEX, floor: [...]})"),
        ("s.yaml:1:20: walker is a human on a trajectory: 'behaviour' is a route's (a person who sees the robot); a "
        "trajectory's keys are points, start, speed, loop"),
        "s.yaml:1:20: ann's route has 2 stop(s), counted from 0: stop 2 is not one",
        "s.yaml:1:30: ann walks a route, at most 3 m/s (the language's limit), got [1, 3.5]",
        ("s.yaml:3:25: cart is a moving object on a trajectory: 'stop' is a route's (a person who sees the robot); a "
        "trajectory's keys are points, start, speed, loop")]


def test_a_stop_on_a_floor_the_room_does_not_have() -> None:
    with pytest.raises(SpecError, match=r"^s\.yaml:1:30: the base case's room has no floor 'F_9_9'"):
        Space([p("stop", ("F_2_0", "F_9_9"), index=1)], DIAGRAM)


def test_without_humans_a_routed_persons_keys_are_refused_once() -> None:
    with pytest.raises(SpecError) as raised:
        Space([p("start", Range(0, 1)), p("behaviour", ("blocks",))], DIAGRAM, humans=False)
    assert list(raised.value.problems) == [("s.yaml:1:12: ann is a human and the spec runs without humans (humans: false): "
                                     "its start would change nothing; remove its parameters or set humans: true")]


def test_a_trajectory_only_diagram_is_searched_as_before() -> None:
    diagram = copy.deepcopy(DIAGRAM)
    for mover in diagram["movers"]:
        mover.pop("route")  # a diagram without the field: nobody walks a route
    space = Space([Parameter("human", "walker", "speed", Range(0.5, 2), "s.yaml:2:1")], diagram)
    assert space.edit({"walker.speed": 1.0}).operations[0]["op"] == "setTrajectory"


# -- the spec's keys ----------------------------------------------------------------------------------------------

SPEC = "case: case.rei\nparameters:\n{}objectives: [utility]\n"


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    return tmp_path


def test_a_stop_and_a_behaviour_parse_to_their_parameters(folder: Path) -> None:
    spec = parse(SPEC.format("  - {human: ann, stop: 1, floor: [F_2_0, F_3_0], speed: [0.5, 1.5]}\n"
                             "  - {human: ann, behaviour: [avoids, blocks, avoids], stop: 0, floor: any}\n"), folder)
    assert [(q.key, q.domain, q.where, q.prop_at) for q in spec.parameters] == [
        ("ann.stops.1", ("F_2_0", "F_3_0"), "s.yaml:3:34", "s.yaml:3:18"),
        ("ann.speed", Range(0.5, 1.5), "s.yaml:3:57", "s.yaml:3:50"),
        ("ann.stops.0", None, "s.yaml:4:71", "s.yaml:4:55"),
        ("ann.behaviour", ("avoids", "blocks"), "s.yaml:4:29", "s.yaml:4:18")]


@pytest.mark.parametrize(("item", "message"), [
    ("{human: ann, floor: [F_2_0]}", ("s.yaml:3:18: a person's 'floor' is a floor of its route's stops: give 'stop' "
                                     "too, the stop's index in the route (0 is the first)")),
    ("{human: ann, stop: 1}", "s.yaml:3:18: give 'floor' with 'stop': the floors the stop may be on, a list or 'any'"),
    ("{human: ann, stop: -1, floor: any}", ("s.yaml:3:24: 'stop' is the stop's index in the person's route (0 is the "
                                           "first), got -1")),
    ("{human: ann, stop: 0, floor: F_1_1}", "s.yaml:3:34: expected 'any' or a list of floor names, got 'F_1_1'"),
    ("{human: ann, behaviour: [avoids, angry]}", ("s.yaml:3:29: 'angry' is not a behaviour; expected avoids, ignores, "
                                                 "curious, scared, blocks")),
    ("{human: ann, behaviour: curious}", ("s.yaml:3:29: 'behaviour' lists the choices, such as [avoids, ignores, "
                                         "curious, scared, blocks]")),
])
def test_mistakes_in_a_routed_persons_keys_are_placed(folder: Path, item: str, message: str) -> None:
    assert error_of(SPEC.format(f"  - {item}\n"), folder) == message


def test_the_same_stop_twice_is_refused(folder: Path) -> None:
    text = SPEC.format("  - {human: ann, stop: 1, floor: any}\n  - {human: ann, stop: 1, floor: [F_0_0]}\n")
    assert error_of(text, folder) == "s.yaml:4:34: ann.stops.1 is searched twice"
