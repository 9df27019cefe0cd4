# SPDX-License-Identifier: EPL-2.0
"""search.html as a page: every id in it is unique though each failure brings the run report's map, and the
Pareto front is shown for any number of objectives."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path
from typing import Any

from rei.search.report import render

ROOM = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"


def failure(out: Path, n: int) -> dict[str, Any]:
    """A distinct failure whose run is the fixture room (no recorded streams: the map still draws the room)."""
    run, case = out / "runs" / f"tpe-{n:04d}", out / "cases" / f"tpe-{n:04d}"
    run.mkdir(parents=True)
    shutil.copytree(ROOM, case)
    (run / "task.json").write_text(json.dumps({"case_dir": str(case)}), encoding="utf-8")
    return {"signature": f"COLLISION/walker/F_{n}_0", "kind": "COLLISION", "element": "walker", "place": f"F_{n}_0",
            "requirements": ["MISSION_SIMPLE", "MISSION_WITH_HUMAN_TRAJECTORY"],
            "what": f"collision with walker at t={n}.000 during task 0",
            "message": "MISSION_SIMPLE: 1 collision(s); MISSION_WITH_HUMAN_TRAJECTORY: 1 collision(s) with humans",
            "worst_utility": -10.0,
            "evaluations": [f"tpe-{n:04d}"], "first": f"tpe-{n:04d}", "seed": 0, "run": str(run),
            "report": str(run / "report.html"), "case": str(out / "candidates" / f"tpe-{n:04d}.rei"), "shrunk": None}


def document(objectives: list[str], values: list[list[float]], failures: list[dict[str, Any]]) -> dict[str, Any]:
    evaluations = [{"key": f"tpe-{k:04d}", "status": "COMPLETED", "values": v} for k, v in enumerate(values)]
    return {"name": "n", "sampler": "tpe", "budget": len(values), "failures": failures, "evaluations": evaluations,
            "counts": {"simulated": len(values), "errors": 0, "invalid": 0, "unplannable": 0, "failing": 0,
                       "distinct_failures": len(failures), "first_failure_at": None},
            "objectives": [{"label": label, "direction": "minimize"} for label in objectives]}


def test_each_failure_s_map_has_ids_of_its_own(tmp_path: Path) -> None:
    page = render(tmp_path, document(["utility"], [], [failure(tmp_path, 1), failure(tmp_path, 2)]))
    ids = re.findall(r'\sid="([^"]+)"', page)
    assert len(ids) == len(set(ids)), sorted(i for i in ids if ids.count(i) > 1)
    for n in (1, 2):  # the svg and its layers, each failure's own
        assert f'<svg id="failure-{n}-map"' in page
        assert f'id="failure-{n}-map-robot-path"' in page and f'id="failure-{n}-map-world"' in page
    assert 'id="map"' not in page


def test_each_failure_is_an_event_with_every_requirement_it_violated(tmp_path: Path) -> None:
    page = render(tmp_path, document(["utility"], [], [failure(tmp_path, 1)]))
    section = page[page.index('id="failures"'):]
    assert "<h3>COLLISION/walker/F_1_0</h3>" in section
    assert ('<p class="requirements">fails MISSION_SIMPLE, MISSION_WITH_HUMAN_TRAJECTORY: collision with walker at '
            "t=1.000 during task 0</p>") in section


def front_of(page: str) -> list[list[str]]:
    table = page[page.index('id="pareto"'):]
    table = table[:table.index("</table>")]
    return [re.findall(r"<td>([^<]*)</td>", row) for row in re.findall(r"<tr><td>.*?</tr>", table)]


def test_the_pareto_front_of_three_objectives_lists_the_non_dominated_evaluations(tmp_path: Path) -> None:
    doc = document(["clearance", "utility", "time"], [
        [0.5, 10.0, 30.0],  # tpe-0000: dominated by 0001 (closer, lower utility, longer)
        [0.2, 5.0, 40.0],   # tpe-0001: on the front
        [0.1, 8.0, 35.0],   # tpe-0002: on the front (closest)
        [0.3, 2.0, 20.0],   # tpe-0003: on the front (lowest utility), though the shortest
        [1e6, 1.0, 50.0],   # tpe-0004: a clearance it did not have: left out
        [0.2, 5.0, 40.0],   # tpe-0005: the same point as 0001, which does not dominate it
    ], [])
    doc["objectives"][2]["direction"] = "maximize"  # a longer run is worse for the robot here
    page = render(tmp_path, doc)
    assert front_of(page) == [["tpe-0002", "0.1", "8", "35"], ["tpe-0001", "0.2", "5", "40"],
                              ["tpe-0005", "0.2", "5", "40"], ["tpe-0003", "0.3", "2", "20"]]
    assert "<th>time (maximize)</th>" in page and "4 of 5 evaluations" in page


def test_one_objective_has_no_front(tmp_path: Path) -> None:
    assert 'id="pareto"' not in render(tmp_path, document(["utility"], [[1.0], [2.0]], []))


def test_the_baseline_s_figures_and_the_failures_only_one_side_found(tmp_path: Path) -> None:
    doc = document(["utility"], [[1.0], [2.0]], [failure(tmp_path, 1), failure(tmp_path, 2)])
    doc["counts"].update(failing=2, first_failure_at=1)
    theirs = {**failure(tmp_path, 3), "first": "random-0004", "evaluations": ["random-0004", "random-0007"]}
    both = {**failure(tmp_path, 4), "signature": doc["failures"][1]["signature"]}  # found by both sides
    doc["baseline"] = {"sampler": "random", "budget": 9, "failures": [both, theirs],
        "evaluations": [{"key": "random-0000", "status": "COMPLETED", "values": [3.0]}],
        "counts": {"simulated": 9, "errors": 1, "failing": 2, "distinct_failures": 2, "first_failure_at": None}}
    page = render(tmp_path, doc)
    section = page[page.index('id="baseline"'):page.index('id="objective-0"')]
    rows = [re.findall(r"<td>([^<]*)</td>", row) for row in re.findall(r"<tr><td>.*?</tr>", section)]
    assert rows == [["budget", "2", "9"], ["simulated evaluations", "2", "9"], ["in ERROR", "0", "1"],
                    ["failing evaluations", "2", "2"], ["distinct failures", "2", "2"],
                    ["first failure at evaluation", "1", "-"],
                    ["the search", "COLLISION/walker/F_1_0", "MISSION_SIMPLE, MISSION_WITH_HUMAN_TRAJECTORY", "1",
                     "tpe-0001"],
                    ["the random baseline", "COLLISION/walker/F_3_0", "MISSION_SIMPLE, MISSION_WITH_HUMAN_TRAJECTORY",
                     "2", "random-0004"]]
    assert "#ff7f0e" in page[page.index('id="objective-0"'):]  # the baseline's dots in the chart
