# SPDX-License-Identifier: EPL-2.0
"""The run report shows the navigation metrics of summary.json, and says why when there are none."""

from __future__ import annotations

import json
from pathlib import Path

from rei.evaluation.metrics import NAMES
from rei.report.html import render_report
from rei.report.run_data import load_run


def test_metrics_section(tmp_path: Path) -> None:
    metrics = dict.fromkeys(NAMES) | {"success": True, "clearance_static_min": 0.123456, "oscillations": 2,
                                      "task_times": [10.5, None]}
    (tmp_path / "summary.json").write_text(json.dumps({"status": "COMPLETED", "metrics": metrics}))
    html = render_report(load_run(tmp_path))
    assert '<section id="metrics-section">' in html
    assert 'data-metric="success"><td><code>success</code></td><td class="num">true' in html
    assert 'data-metric="clearance_static_min"><td><code>clearance_static_min</code></td><td class="num">0.1235' in html
    assert 'data-metric="clearance_humans_min"><td><code>clearance_humans_min</code></td><td class="num">-' in html
    assert 'data-metric="task_times"><td><code>task_times</code></td><td class="num">10.5, -' in html
    (tmp_path / "summary.json").write_text(json.dumps({"status": "COMPLETED"}))
    assert 'id="metrics-missing">summary.json has no navigation metrics' in render_report(load_run(tmp_path))
