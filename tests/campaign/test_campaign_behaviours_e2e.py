# SPDX-License-Identifier: EPL-2.0
"""A campaign whose variants are the people's behaviour (issue #38), end to end with the real generator, people
server, simulation, monitor and evaluator: one generated room with two people who see the robot, run once as they
avoid it and once as they ignore it. Both runs are the same room (runs.csv's case), each generated case's people
behave as its variant says, the summaries and metrics have a line per behaviour, and `rei compare` of the campaign
against itself pairs the runs by room and behaviour."""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

SPEC = """\
name: behaviours
timeout: 300
variants: [{name: avoids, behaviour: avoids}, {name: ignores, behaviour: ignores}]
groups:
  - name: small
    rooms: {size: small, density: sparse, humans: 2, people: reactive, count: 1, seed: 4}
"""


def test_each_room_runs_once_per_behaviour_and_reports_group_by_it(tmp_path: Path, run_cli: Any) -> None:
    spec = tmp_path / "behaviours.yaml"
    spec.write_text(SPEC, encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("campaign", spec, "-o", out, "--workers", "2", timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    rows = list(csv.DictReader((out / "runs.csv").open(encoding="utf-8")))
    assert [(r["case"], r["variant"], r["status"]) for r in rows] == [
        ("small_sparse_p2_s4_01", "avoids", "COMPLETED"), ("small_sparse_p2_s4_01", "ignores", "COMPLETED")], rows
    for row in rows:
        task = json.loads((out / "runs" / row["key"] / "task.json").read_text(encoding="utf-8"))
        people = json.loads((Path(task["case_dir"]) / "animation.json").read_text(encoding="utf-8"))["people"]
        assert len(people) == 2 and {p["behaviour"] for p in people} == {row["variant"]}, people
    # the two cases are the same room: the same people on the same routes
    routes = [[p["route"] for p in json.loads((out / "cases" / case / "animation.json").read_text())["people"]]
              for case in ("small_sparse_p2_s4_01", "small_sparse_p2-ignores_s4_01")]
    assert routes[0] == routes[1]
    summary = list(csv.DictReader((out / "summary.csv").open(encoding="utf-8")))
    assert [(r["room"], r["variant"]) for r in summary] == [
        ("small_sparse_p2_s4_01", "*"), ("Total", "*"), ("*", "avoids"), ("*", "ignores")], summary
    metrics = {(r["variant"], r["metric"]) for r in csv.DictReader((out / "metrics.csv").open(encoding="utf-8"))}
    assert {("avoids", "collisions_robot_at_fault"), ("ignores", "collisions_robot_at_fault")} <= metrics

    compared = run_cli("compare", out, out, "-o", tmp_path / "compare", timeout=300)
    assert compared.returncode == 0, compared.stdout + compared.stderr
    document = json.loads((tmp_path / "compare" / "compare.json").read_text(encoding="utf-8"))
    # runs pair by group, room, variant and seed: each behaviour with itself
    keys = [row["key"] for row in rows]
    assert sorted(tuple(pair) for pair in document["pairs"]) == [(key, key) for key in keys], document["pairs"]
