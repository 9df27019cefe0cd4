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
    return {"signature": f"R{n}/walker/F_{n}_0", "message": "hit", "worst_utility": -10.0,
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
