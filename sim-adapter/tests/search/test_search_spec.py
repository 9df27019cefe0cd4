# SPDX-License-Identifier: EPL-2.0
"""The search spec: a good spec parses to what it says; every mistake is placed at FILE:LINE:COLUMN of the value
(or key) it is about, with what was expected."""

from __future__ import annotations

from pathlib import Path

import pytest
from spec_helpers import error_of, parse

from rei.search.spec import Range

GOOD = """\
name: crossing
case: case.rei
seed: 3
budget: 12
sampler: nsga2
parameters:
  - {human: walker, start: [4, 12], speed: [0.5, 1.5], loop: [true, false]}
  - {human: walker, points: [[F_2_0, F_1_0], any]}
  - {object: bin1, floor: any}
  - {object: bin1, yaw: [0, 90]}
  - {robot: tb3, floor: [F_0_1, F_1_1]}
  - {goal: 1, floor: any}
  - {seed: [0, 100]}
  - {fault: "laser:1%", rate: [0.0, 0.05], width: [1, 4]}
  - {furniture: [Chair, Box], count: [0, 2], floor: [F_1_0, F_2_0]}
objectives:
  - utility
  - {metric: clearance_humans_min}
  - {verdict: MISSION_WITH_HUMAN_TRAJECTORY}
  - {signal: SIG_OBJECT_COLLISION_BEGIN, of: first}
shrink: {budget: 3}
"""


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")  # only its existence is checked here
    return tmp_path


def test_a_good_spec_parses_to_what_it_says(folder: Path) -> None:
    spec = parse(GOOD, folder)
    assert (spec.name, spec.seed, spec.budget, spec.sampler, spec.shrink_budget) == ("crossing", 3, 12, "nsga2", 3)
    assert spec.diversity and not parse(GOOD + "diversity: false\n", folder).diversity
    assert spec.case == folder / "case.rei" and spec.controller == "nav" and spec.sut is None
    keys = [p.key for p in spec.parameters]
    assert keys == ["walker.start", "walker.speed", "walker.loop", "walker.points", "bin1.floor", "bin1.yaw",
                    "tb3.floor", "goal1.floor", "seed", "fault.rate", "fault.width", "furniture.count"]
    by_key = {p.key: p for p in spec.parameters}
    assert by_key["walker.start"].domain == Range(4.0, 12.0)
    assert by_key["walker.points"].domain == (("F_2_0", "F_1_0"), None)
    assert by_key["bin1.floor"].domain is None and by_key["tb3.floor"].domain == ("F_0_1", "F_1_1")
    assert by_key["seed"].domain == Range(0, 100, integer=True) and by_key["fault.width"].domain.integer
    assert by_key["fault.rate"].base == "laser:1%"
    assert by_key["furniture.count"].domain == (("Chair", "Box"), Range(0, 2, True), ("F_1_0", "F_2_0"))
    assert by_key["bin1.floor"].where == "s.yaml:9:27"
    assert [(o.label, o.direction) for o in spec.objectives] == [
        ("utility", "minimize"), ("metric:clearance_humans_min", "minimize"),
        ("verdict:MISSION_WITH_HUMAN_TRAJECTORY", "minimize"),
        ("signal:SIG_OBJECT_COLLISION_BEGIN:first", "minimize")]


@pytest.mark.parametrize(("change", "expected"), [
    (("seed: 3", "seed: -1"), "s.yaml:3:7: 'seed' must be >= 0, got -1"),
    (("budget: 12", "budget: many"), "s.yaml:4:9: 'budget' must be an integer, got 'many'"),
    (("sampler: nsga2", "sampler: grid"), "s.yaml:5:10: 'sampler' must be one of tpe, cmaes, nsga2, qmc, random"),
    (("start: [4, 12]", "start: [12, 4]"),
     "s.yaml:7:28: the range's low end must be below its high end, got [12, 4]"),
    (("speed: [0.5, 1.5]", "speed: [0, 1.5]"), "s.yaml:7:44: a speed (m/s) must be positive, got 0"),
    (("{object: bin1, yaw: [0, 90]}", "{object: bin1, yew: [0, 90]}"),
     "s.yaml:10:20: 'yew' is not a property of an object; expected floor, yaw"),
    (("{goal: 1, floor: any}", "{goal: -1, floor: any}"),
     "s.yaml:12:12: 'goal' is the goal's index in the mission (0 is the first), got -1"),
    (("{robot: tb3, floor: [F_0_1, F_1_1]}", "{robot: tb3, floor: somewhere}"),
     "s.yaml:11:25: expected 'any' or a list of floor names, got 'somewhere'"),
    (('"laser:1%"', '"laser:lots"'), "s.yaml:14:13: bad fault spec 'laser:lots': unknown preset 'lots'"),
    (("{metric: clearance_humans_min}", "{metric: clearance}"), "s.yaml:18:14: unknown metric 'clearance'"),
    (("{verdict: MISSION_WITH_HUMAN_TRAJECTORY}", "{verdict: NEVER_FAIL}"),
     "s.yaml:19:15: unknown requirement 'NEVER_FAIL'"),
    (("of: first", "of: last"), "s.yaml:20:46: 'of' is count or first, got 'last'"),
    (("  - utility\n", "  - {utility: minimize, direction: maximize}\n"),
     "s.yaml:17:25: 'utility' takes its direction as its value: {utility: minimize} or {utility: maximize}"),
    (("{metric: clearance_humans_min}", "{metric: clearance_humans_min, of: first}"),
     "s.yaml:18:36: unknown key 'of'; known: metric, direction"),
    (("{verdict: MISSION_WITH_HUMAN_TRAJECTORY}", "{verdict: MISSION_WITH_HUMAN_TRAJECTORY, of: count}"),
     "s.yaml:19:46: unknown key 'of'; known: verdict, direction"),
    (("  - utility\n", "  - {time: maximize, of: count}\n"), "s.yaml:17:22: unknown key 'of'; known: time"),
    (("shrink: {budget: 3}", "shrink: {budget: 3, depth: 2}"), "s.yaml:21:21: unknown key 'depth'; known: budget"),
    (("name: crossing", "nmae: crossing"), "s.yaml:1:1: unknown key 'nmae'"),
    (("count: [0, 2]", "count: [0, 20]"), "s.yaml:15:38: 'count' is between 0 and 10 pieces, got [0, 20]"),
    (("shrink: {budget: 3}", "shrink: {budget: 3}\ndiversity: maybe"),
     "s.yaml:22:12: 'diversity' must be true or false, got 'maybe'"),
    (("name: crossing", "controller: autopilot"), "s.yaml:1:13: unknown controller 'autopilot'"),
    (("name: crossing", 'controller: "nav:inflaton_margin=0"'),
     "s.yaml:1:13: nav parameter 'inflaton_margin=0': expected key=value with key one of acc_angular, "),
    (("name: crossing", "sut: {cmd: x}"), "s.yaml:1:6: unknown key 'cmd'; known: command, clock"),
    (("case: case.rei", "case: other.rei"), "s.yaml:2:7: the base case "),
    (("  - {seed: [0, 100]}\n", "  - {seed: [0, 100]}\n  - {seed: [0, 9]}\n"), "s.yaml:14:5: seed is searched twice"),
    (("budget: 12", "budget: [12"), "s.yaml:5:8: not YAML"),
])
def test_every_mistake_is_placed_at_its_line_and_column(folder: Path, change: tuple[str, str], expected: str) -> None:
    old, new = change
    assert old in GOOD
    assert error_of(GOOD.replace(old, new, 1), folder).startswith(expected)


def test_required_keys_and_lists(folder: Path) -> None:
    assert error_of("case: case.rei\nobjectives: [utility]\n", folder) == "s.yaml:1:1: 'parameters' is required"
    assert error_of("case: case.rei\nparameters: []\nobjectives: [utility]\n", folder) == \
        "s.yaml:2:13: 'parameters' must be a non-empty list"
    assert error_of("", folder).startswith("s.yaml:1:1: the spec is empty")
    assert error_of("case: case.rei\nparameters: [{seed: [0, 9]}]\nobjectives: [speed]\n", folder).startswith(
        "s.yaml:3:14: unknown objective 'speed'")


def test_zero_workers_is_refused_not_read_as_every_core(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from rei.cli import main

    assert main(["search", str(tmp_path / "s.yaml"), "-o", str(tmp_path / "out"), "--workers", "0"]) == 2
    assert "--workers must be at least 1, got 0" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()
