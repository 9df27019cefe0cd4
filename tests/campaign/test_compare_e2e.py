# SPDX-License-Identifier: EPL-2.0
"""`rei compare` and `rei campaign --compare` end to end, on the example comparison campaign (two small rooms,
two seeds) with the real simulation, monitor and evaluator: the reference navigation against itself reports no
regression; against a variant with a thinner safety margin the minimum clearance regresses, with the right sign,
exit code 1 and a JUnit failure. One campaign pair serves every assertion."""

from __future__ import annotations

import csv
import json
import shutil
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]
SPEC = REPO_ROOT / "examples" / "campaigns" / "compare.yaml"
THRESHOLDS = REPO_ROOT / "examples" / "campaigns" / "compare-thresholds.yaml"
#: The reference navigation with a thinner safety margin: no inflation margin, almost no cost gradient.
THIN = "nav:inflation_margin=0,cost_decay=0.05,preferred_clearance=0.05,min_clearance=0"


@dataclass
class Campaigns:
    base: Path
    again: Any  # the CliResult of the same SUT's second campaign with --compare
    again_out: Path
    thin: Path


@pytest.fixture(scope="module")
def campaigns(run_cli: Any, tmp_path_factory: pytest.TempPathFactory) -> Campaigns:
    root = tmp_path_factory.mktemp("compare")
    base = run_cli("campaign", SPEC, "-o", root / "base", "--workers", "2", timeout=600)
    assert base.returncode == 0, base.stdout + base.stderr
    again = run_cli("campaign", SPEC, "-o", root / "again", "--workers", "2", "--compare", root / "base",
                    "--thresholds", THRESHOLDS, timeout=600)
    thin = run_cli("campaign", SPEC, "-o", root / "thin", "--workers", "2", "--controller", THIN, timeout=600)
    assert thin.returncode == 0, thin.stdout + thin.stderr
    return Campaigns(root / "base", again, root / "again", root / "thin")


def junit(path: Path) -> dict[str, ET.Element]:
    return {case.get("name"): case for case in ET.parse(path).getroot().iter("testcase")}


def test_the_same_navigation_against_itself_has_no_regression(campaigns: Campaigns) -> None:
    result = campaigns.again
    assert result.returncode == 0, result.stdout + result.stderr
    assert "4 pair(s)" in result.stdout and "regressions: none" in result.stdout
    out = campaigns.again_out / "compare"
    document = json.loads((out / "compare.json").read_text())
    assert document["regressions"] == [] and len(document["pairs"]) == 4
    # the same seed gives the same run: every paired difference is zero, every test says so
    clearance = document["metrics"]["clearance_static_min"]
    assert clearance["difference"] == 0 and clearance["p"] == 1 and clearance["verdict"] == "pass"
    cases = junit(out / "verdicts.xml")
    assert {"success", "clearance_static_min", "time"} <= set(cases)
    assert not any(c.find("failure") is not None for c in cases.values())


def test_a_thinner_safety_margin_regresses_the_clearance(campaigns: Campaigns, run_cli: Any, tmp_path: Path) -> None:
    out = tmp_path / "cmp"
    result = run_cli("compare", campaigns.base, campaigns.thin, "-o", out, "--thresholds", THRESHOLDS)
    assert result.returncode == 1, result.stdout + result.stderr
    document = json.loads((out / "compare.json").read_text())
    assert "clearance_static_min" in document["regressions"]
    clearance = document["metrics"]["clearance_static_min"]
    assert clearance["difference"] < -0.05 and clearance["ci_high"] < 0  # closer to the furniture: negative
    assert clearance["candidate_mean"] < clearance["baseline_mean"]
    # the independent record: each pair's difference from the two campaigns' runs.csv
    base, thin = (_column(c / "runs.csv", "clearance_static_min") for c in (campaigns.base, campaigns.thin))
    assert sorted(base) == sorted(thin)  # the same runs (keys), run by run
    mean = sum(thin[k] - base[k] for k in base) / len(base)
    assert clearance["difference"] == pytest.approx(mean, abs=1e-3)  # runs.csv rounds to 4 digits
    failure = junit(out / "verdicts.xml")["clearance_static_min"].find("failure")
    assert failure is not None and "regression" in failure.get("message")
    assert junit(out / "verdicts.xml")["success"].find("failure") is None  # still reaches every goal
    html = (out / "compare.html").read_text()
    assert html.count("<svg class=\"paired\"") >= 10 and html.count("class=\"room\"") >= 20  # 2 rooms per plot
    # the runs that changed most link to both runs' reports
    links = [line for line in html.split("<tr") if "class='changed' data-metric='clearance_static_min'" in line]
    assert links and "report.html" in links[0]
    target = (out / links[0].split("href='")[1].split("'")[0]).resolve()
    assert target.is_file() and target.name == "report.html"


def test_unpaired_runs_are_listed_not_dropped(campaigns: Campaigns, run_cli: Any, tmp_path: Path) -> None:
    partial = tmp_path / "partial"
    shutil.copytree(campaigns.thin / "runs", partial / "runs")
    gone = min((partial / "runs").glob("*/result.json"))
    gone.unlink()
    result = run_cli("compare", campaigns.base, partial, "-o", tmp_path / "cmp", "--thresholds", THRESHOLDS)
    assert "3 pair(s); 1 run(s) only in the baseline" in result.stdout, result.stdout + result.stderr
    document = json.loads((tmp_path / "cmp" / "compare.json").read_text())
    assert [r["key"] for r in document["only_baseline"]] == [gone.parent.name]
    assert gone.parent.name in (tmp_path / "cmp" / "compare.html").read_text()


def test_bad_thresholds_stop_with_their_place(campaigns: Campaigns, run_cli: Any, tmp_path: Path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("metrics:\n  success: {p: 0.05}\n  clearance: {worse_by: 0.05}\n")
    result = run_cli("compare", campaigns.base, campaigns.thin, "-o", tmp_path / "cmp", "--thresholds", bad)
    assert result.returncode == 2 and f"{bad}:3:3: unknown metric 'clearance'" in result.stderr
    assert not (tmp_path / "cmp").exists()


def _column(runs_csv: Path, name: str) -> dict[str, float]:
    with open(runs_csv, newline="", encoding="utf-8") as f:
        return {row["key"]: float(row[name]) for row in csv.DictReader(f)}
