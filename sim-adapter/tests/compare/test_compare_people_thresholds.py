# SPDX-License-Identifier: EPL-2.0
"""rei compare's default thresholds for the people's metrics (issue #38): one more collision in which the robot
drove into a person, in one pair of many, is a regression; more time in people's intimate space and a longer delay
of the people are judged by size; runs without people leave them not applicable."""

from __future__ import annotations

from pathlib import Path

from test_compare_analysis import campaign

from rei.compare import compare, default_thresholds
from rei.evaluation.metrics import BY_NAME, Better

CASES = [(f"room{i}", seed) for i in range(4) for seed in (0, 1)]
PEOPLE = {"collisions_robot_at_fault": 0, "intimate_share": 0.01, "people_delay_mean": 2.0}


def test_the_defaults_judge_the_people_metrics_in_their_better_direction() -> None:
    defaults = {t.metric: t for t in default_thresholds().items}
    for name in ("collisions_robot_at_fault", "intimate_share", "people_delay_mean"):
        assert defaults[name].better == BY_NAME[name].better == Better.LOWER
    assert (defaults["collisions_robot_at_fault"].worse_by, defaults["collisions_robot_at_fault"].p) == (0.0, None)
    assert defaults["collisions_robot_at_fault"].describe() == "collisions_robot_at_fault higher at all"


def test_one_more_robot_at_fault_collision_is_a_regression(tmp_path: Path) -> None:
    base = campaign(tmp_path / "a", {key: PEOPLE for key in CASES})
    # one pair of eight drives into a person; the people wait 0.5 s more each (less than 1 s): not a regression
    cand = campaign(tmp_path / "b", {k: PEOPLE | {"collisions_robot_at_fault": int(n == 3), "people_delay_mean": 2.5}
                                     for n, k in enumerate(CASES)})
    c = compare(base, cand)
    by = {m.metric.name: m for m in c.metrics}
    assert by["collisions_robot_at_fault"].regressed and by["collisions_robot_at_fault"].paired.mean == 1 / 8
    assert by["people_delay_mean"].status == "pass" and by["intimate_share"].status == "pass"
    assert c.exit_code == 1 and [m.metric.name for m in c.regressions] == ["collisions_robot_at_fault"]
    # 3 % more of the mission in intimate space (more than 2 %) and people delayed 1.5 s more: both regress
    closer = campaign(tmp_path / "c", {key: PEOPLE | {"intimate_share": 0.04, "people_delay_mean": 3.5} for key in CASES})
    assert [m.metric.name for m in compare(base, closer).regressions] == ["intimate_share", "people_delay_mean"]


def test_without_people_the_people_metrics_are_not_applicable(tmp_path: Path) -> None:
    base = campaign(tmp_path / "a", {key: {"clearance_static_min": 0.3} for key in CASES})
    cand = campaign(tmp_path / "b", {key: {"clearance_static_min": 0.3} for key in CASES})
    by = {m.metric.name: m for m in compare(base, cand).metrics}
    assert {by[n].status for n in PEOPLE} == {"not-applicable"}
