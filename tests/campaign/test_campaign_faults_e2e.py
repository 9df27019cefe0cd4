# SPDX-License-Identifier: EPL-2.0
"""A campaign whose variants carry different faults, end to end with the real simulation, monitor and evaluator:
its summary, metrics and report group the runs by fault (two variants writing the same gated fault differently
are one fault level), the signal counts per fault are the runs' own signals.jsonl summed, and `rei compare`
pairs the runs by fault and judges each fault's pairs."""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "simple_navigation.rei"
GATED = "laser:impulse,rate=0.03333333333333333,gain=0.5,width=3,from=0.0,period=10.0,pulse=1.0"


def test_a_campaign_and_its_comparison_by_fault(tmp_path: Path, run_cli: Any) -> None:
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"""
name: by-fault
timeout: 240
groups:
  - name: example
    cases: [{EXAMPLE}]
    variants:
      - {{name: none}}
      - {{name: gated10, fault: "laser:gated-10%"}}
      - {{name: spelled, fault: "laser:impulse,rate=0.03333333333333333,width=3,period=10,duty=10%"}}
""", encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("campaign", spec, "-o", out, "--workers", "2", timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    with open(out / "summary.csv", newline="", encoding="utf-8") as f:
        faults = {r["fault"]: r for r in csv.DictReader(f) if r["fault"] != "*"}
    assert sorted(faults) == sorted(["none", GATED]) and faults[GATED]["executions"] == "2"
    assert faults["none"]["executions"] == "1" and faults["none"]["room"] == faults["none"]["variant"] == "*"
    with open(out / "metrics.csv", newline="", encoding="utf-8") as f:
        metrics = {(r["fault"], r["metric"]): r for r in csv.DictReader(f) if r["fault"] != "*"}
    assert metrics[(GATED, "collision_episodes")]["n"] == "2"
    # the report's signals per fault: each run's signals.jsonl, summed over the fault's runs
    counted: dict[str, dict[str, int]] = {"none": {}, GATED: {}}
    for key in ("none", "gated10", "spelled"):
        fault = "none" if key == "none" else GATED
        for line in (out / "runs" / f"example__simple_navigation__{key}__r0" / "signals.jsonl").read_text().splitlines():
            name = json.loads(line)["signal"]
            counted[fault][name] = counted[fault].get(name, 0) + 1
    assert counted[GATED].get("SIG_FAULT_LASER_IMPULSE_BEGIN", 0) > 0 and "SIG_FAULT_LASER_IMPULSE_BEGIN" not in counted["none"]
    html = (out / "report.html").read_text(encoding="utf-8")
    table = html.split("id='faults-example'>")[1].split("</table>")[0]
    assert f"<th>none</th><th>{GATED}</th>" in table
    for name in ("SIG_MISSION_BEGIN", "SIG_FAULT_LASER_IMPULSE_BEGIN", "SIG_LASER_CLOSE_TRANSIT_COLLISION"):
        a, b = counted["none"].get(name, 0), counted[GATED].get(name, 0)
        if a or b:
            assert f"<td>{name}</td><td>{a}</td><td>{b}</td><td>{a + b}</td>" in table, name

    compared = run_cli("compare", out, out, "-o", tmp_path / "cmp", timeout=300)
    assert compared.returncode == 0, compared.stdout + compared.stderr
    assert "3 pair(s)" in compared.stdout and "regressions under a fault: none" in compared.stdout
    document = json.loads((tmp_path / "cmp" / "compare.json").read_text())
    assert {f: d["pairs"] for f, d in document["by_fault"].items()} == {"none": 1, GATED: 2}
    assert document["by_fault"][GATED]["metrics"]["clearance_static_min"]["difference"] == 0
