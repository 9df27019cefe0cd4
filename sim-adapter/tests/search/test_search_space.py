# SPDX-License-Identifier: EPL-2.0
"""The search space over a base case's room editor diagram: the spec's parameters checked against the case,
Optuna distributions, the base case as a point, and a point as the room editor's operations, seed and fault."""

from __future__ import annotations

from typing import Any

import pytest
from optuna.distributions import CategoricalDistribution, FloatDistribution, IntDistribution

from rei.campaign.spec import SpecError
from rei.search.space import Space
from rei.search.spec import Parameter, Range


def floor(name: str, x: int, y: int) -> dict[str, Any]:
    return {"name": name, "x": x, "y": y, "centreX": x + 0.5, "centreY": y + 0.5}


DIAGRAM: dict[str, Any] = {
    "room": {"floorSize": 1.0, "floors": [floor(f"F_{x}_0", x, 0) for x in range(4)] + [floor("F_1_1", 1, 1)],
             "walls": []},
    "objects": [{"name": "bin1", "kind": "object", "floor": "F_3_0", "yaw": 0.0}],
    "robot": {"name": "tb3", "kind": "robot", "floor": "F_0_0", "yaw": 0.0},
    "movers": [{"name": "walker", "kind": "human", "loop": True,
                "points": [{"floor": "F_1_1", "seconds": 2.0, "x": 1.5, "y": 1.5},
                           {"floor": "F_1_0", "seconds": 4.0, "x": 1.5, "y": 0.5}]}],
    "mission": {"goals": [{"index": 0, "floor": "F_2_0", "timeout": None},
                          {"index": 1, "floor": "F_3_0", "timeout": 30.0}]},
}


def p(target: str, name: str, prop: str, domain: Any, base: str | None = None) -> Parameter:
    return Parameter(target, name, prop, domain, "s.yaml:1:1", base)


def test_distributions_and_the_base_case_as_a_point() -> None:
    space = Space([p("object", "bin1", "floor", None), p("object", "bin1", "yaw", Range(0, 90)),
                   p("human", "walker", "points", (None, ("F_1_0", "F_2_0"))), p("human", "walker", "speed",
                                                                                  Range(0.5, 2)),
                   p("goal", "1", "floor", ("F_2_0", "F_3_0")), p("seed", "", "value", Range(0, 9, True)),
                   p("fault", "", "rate", Range(0, 0.1), base="laser:1%")], DIAGRAM)
    d = space.distributions
    # any free floor: not the robot's; bin1's own floor is among them
    assert d["bin1.floor"] == CategoricalDistribution(["F_1_0", "F_2_0", "F_3_0", "F_1_1"])
    assert d["walker.points.0"] == CategoricalDistribution(["F_0_0", "F_1_0", "F_2_0", "F_3_0", "F_1_1"])
    assert d["walker.points.1"] == CategoricalDistribution(["F_1_0", "F_2_0"])
    assert d["bin1.yaw"] == FloatDistribution(0, 90) and d["seed"] == IntDistribution(0, 9)
    assert space.base_values() == {"bin1.floor": "F_3_0", "bin1.yaw": 0.0, "walker.points.0": "F_1_1",
                                   "walker.points.1": "F_1_0", "walker.speed": 0.5, "goal1.floor": "F_3_0",
                                   "seed": 0, "fault.rate": None}
    assert space.edit(space.base_values()).fault is None
    assert space.removable() == ["bin1", "walker"]
    assert space.floor_at(2.4, 0.7) == "F_2_0"


def test_a_point_as_operations_seed_and_fault() -> None:
    space = Space([p("object", "bin1", "floor", None), p("human", "walker", "points", (None, None)),
                   p("human", "walker", "start", Range(0, 10)), p("human", "walker", "speed", Range(0.5, 2)),
                   p("human", "walker", "loop", (True, False)), p("robot", "tb3", "floor", ("F_0_0", "F_1_0")),
                   p("goal", "0", "floor", None), p("seed", "", "value", Range(0, 9, True)),
                   p("fault", "", "rate", Range(0, 0.1), base="laser:1%"),
                   p("fault", "", "width", Range(1, 4, True), base="laser:1%")], DIAGRAM)
    edit = space.edit({"bin1.floor": "F_2_0", "walker.points.0": "F_0_0", "walker.points.1": "F_3_0",
                       "walker.start": 1.5, "walker.speed": 2.0, "walker.loop": False, "tb3.floor": "F_1_0",
                       "goal0.floor": "F_1_1", "seed": 7, "fault.rate": 0.0123456789, "fault.width": 3})
    assert edit.operations == (
        {"op": "moveObject", "name": "bin1", "floor": "F_2_0"},
        {"op": "moveObject", "name": "tb3", "floor": "F_1_0"},
        # 3 m at 2 m/s after 1.5 s
        {"op": "setTrajectory", "name": "walker", "loop": False,
         "points": [{"floor": "F_0_0", "seconds": 1.5}, {"floor": "F_3_0", "seconds": 3.0}]},
        {"op": "removeGoal", "index": 0}, {"op": "addGoal", "floor": "F_1_1", "index": 0, "timeoutSeconds": None})
    assert edit.seed == 7 and edit.fault == "laser:1%,rate=0.012346,width=3"


def test_a_start_alone_shifts_the_base_times_and_removal_drops_the_element() -> None:
    space = Space([p("human", "walker", "start", Range(0, 10)), p("object", "bin1", "yaw", Range(0, 90))], DIAGRAM)
    edit = space.edit({"walker.start": 5.0, "bin1.yaw": 45.0}, removed=["bin1"])
    assert edit.operations == (
        {"op": "setTrajectory", "name": "walker", "loop": True,
         "points": [{"floor": "F_1_1", "seconds": 5.0}, {"floor": "F_1_0", "seconds": 7.0}]},
        {"op": "deleteObject", "name": "bin1"})


@pytest.mark.parametrize(("parameter", "message"), [
    (p("object", "bin2", "floor", None), "s.yaml:1:1: the base case has no object named 'bin2'; it has bin1"),
    (p("robot", "r2", "floor", None), "s.yaml:1:1: the base case's robot is tb3, not 'r2'"),
    (p("human", "ghost", "start", Range(0, 1)), "s.yaml:1:1: the base case has no human or moving object named"),
    (p("goal", "2", "floor", None), "s.yaml:1:1: the mission has 2 goal(s): index 2 is not one"),
    (p("object", "bin1", "floor", ("F_9_9",)), "s.yaml:1:1: the base case's room has no floor 'F_9_9'"),
    (p("human", "walker", "points", (None,)), ("s.yaml:1:1: walker has 2 control points in the base case, the spec "
                                             "gives floors for 1")),
])
def test_parameters_are_checked_against_the_base_case(parameter: Parameter, message: str) -> None:
    with pytest.raises(SpecError) as raised:
        Space([parameter], DIAGRAM)
    assert str(raised.value).startswith(message)


def test_a_missing_element_is_reported_at_its_name() -> None:
    parameter = Parameter("object", "bin2", "floor", None, "s.yaml:3:27", name_at="s.yaml:3:14")
    with pytest.raises(SpecError, match=r"^s\.yaml:3:14: the base case has no object named 'bin2'"):
        Space([parameter], DIAGRAM)


def test_extra_furniture_adds_the_first_count_pieces() -> None:
    palette = [{"name": "Chair", "category": "object"}, {"name": "Box", "category": "object"},
               {"name": "Human", "category": "human"}]
    parameter = Parameter("furniture", "", "count", (("Chair", "Box"), Range(0, 2, True), None), "s.yaml:2:3")
    space = Space([parameter], DIAGRAM, palette)
    assert space.distributions["furniture.count"] == IntDistribution(0, 2)
    # free floors: not the robot's nor bin1's
    assert space.distributions["furniture.1.floor"] == CategoricalDistribution(["F_1_0", "F_2_0", "F_1_1"])
    values = {"furniture.count": 1, "furniture.0.type": "Box", "furniture.0.floor": "F_2_0",
              "furniture.1.type": "Chair", "furniture.1.floor": "F_1_0"}
    assert space.edit(values).operations == (
        {"op": "addObject", "name": "search_extra_0", "type": "Box", "floor": "F_2_0"},)
    assert space.edit({**values, "furniture.count": 0}).operations == ()
    with pytest.raises(SpecError, match="'Human' is not a furniture type of the base case's catalogues"):
        Space([Parameter("furniture", "", "count", (("Human",), Range(0, 1, True), None), "s.yaml:2:3")], DIAGRAM,
              palette)


def test_every_parameter_the_base_case_lacks_is_reported_at_once() -> None:
    # an unknown human's parameters are not checked further (its floors, its points): its name is reported once
    parameters = [Parameter("human", "ghost", "start", Range(0, 1), "s.yaml:4:30", name_at="s.yaml:4:13"),
                  Parameter("human", "ghost", "points", (("F_9_9",), None), "s.yaml:4:50", name_at="s.yaml:4:13"),
                  Parameter("object", "bin1", "floor", ("F_9_9",), "s.yaml:5:27", name_at="s.yaml:5:14"),
                  Parameter("object", "bin2", "yaw", Range(0, 90), "s.yaml:6:25", name_at="s.yaml:6:14")]
    with pytest.raises(SpecError) as raised:
        Space(parameters, DIAGRAM)
    assert str(raised.value).splitlines() == [
        "s.yaml:4:13: the base case has no human or moving object named 'ghost'; it has walker",
        "s.yaml:5:27: the base case's room has no floor 'F_9_9'",
        "s.yaml:6:14: the base case has no object named 'bin2'; it has bin1"]
