# SPDX-License-Identifier: EPL-2.0
"""The social metrics as search objectives: a spec names them like any metric of docs/metrics.md, the search
moves away from each one's better side, and a run scores the value its summary.json has."""

from __future__ import annotations

from pathlib import Path

from spec_helpers import parse

from rei.search.objectives import ABSENT, score

SPEC = """\
name: social
case: case.rei
budget: 4
parameters:
  - {seed: [0, 10]}
objectives:
  - {metric: ttc_humans_min}
  - {metric: collisions_robot_at_fault}
  - {metric: intimate_time}
"""


def test_social_metrics_are_objectives_towards_their_worse_side(tmp_path: Path) -> None:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    spec = parse(SPEC, tmp_path)
    assert [(o.label, o.direction) for o in spec.objectives] == [
        ("metric:ttc_humans_min", "minimize"), ("metric:collisions_robot_at_fault", "maximize"),
        ("metric:intimate_time", "maximize")]
    summary = {"metrics": {"ttc_humans_min": 0.75, "collisions_robot_at_fault": 2, "intimate_time": 4.5}}
    assert score(spec.objectives, summary, tmp_path) == [0.75, 2.0, 4.5]
    # never on a collision course: no time to collision, scored away from the search's side
    assert score(spec.objectives, {"metrics": {}}, tmp_path) == [ABSENT, -ABSENT, -ABSENT]
