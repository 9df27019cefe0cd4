# SPDX-License-Identifier: EPL-2.0
"""search.html from a search.json document: what the charts, the front and the importance are drawn from."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from rei.search.report import render


def document(values: list[list[float]]) -> dict[str, Any]:
    evaluations = [{"key": f"tpe-{k:04d}", "status": "COMPLETED", "values": v} for k, v in enumerate(values)]
    return {"name": "n", "sampler": "tpe", "budget": len(values), "failures": [], "evaluations": evaluations,
            "counts": {"simulated": len(values), "errors": 0, "invalid": 0, "unplannable": 0, "failing": 0,
                       "distinct_failures": 0, "first_failure_at": None},
            "objectives": [{"label": "metric:clearance_humans_min", "direction": "minimize"},
                           {"label": "utility", "direction": "minimize"}]}


def test_absent_values_are_left_out_of_the_chart_scale_and_the_front(tmp_path: Path) -> None:
    page = render(tmp_path, document([[1e6, 40.0], [0.25, 60.0], [0.5, 30.0]]))
    assert "1e+06" not in page and "1000000" not in page
    chart = page[page.index('id="objective-0"'):page.index('id="objective-1"')]
    assert ">0.5</text>" in chart and ">0.25</text>" in chart  # the scale spans the runs' own values
    front = page[page.index('id="pareto"'):]
    assert "tpe-0000" not in front[:front.index("</table>")]
    assert "tpe-0001" in front and "tpe-0002" in front


def test_an_objective_no_run_had(tmp_path: Path) -> None:
    page = render(tmp_path, document([[1e6, 40.0], [-1e6, 60.0]]))
    assert "no completed evaluation with a value" in page
