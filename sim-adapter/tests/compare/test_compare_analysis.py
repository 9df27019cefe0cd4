# SPDX-License-Identifier: EPL-2.0
"""rei compare on campaign folders written here: pairing, the paired statistics and the verdicts, the files."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rei.compare import CompareError, compare, write_comparison
from rei.compare.thresholds import parse_thresholds
from rei.evaluation.metrics import NAMES


def campaign(root: Path, runs: dict[tuple[str, int], dict[str, object]], status: str = "COMPLETED") -> Path:
    for (case, seed), metrics in runs.items():
        key = f"g__{case}__base__r{seed}"
        folder = root / "runs" / key
        folder.mkdir(parents=True)
        (folder / "result.json").write_text(json.dumps({
            "format": "rei-campaign-run/1", "key": key, "group": "g", "case": case, "variant": "base",
            "seed": seed, "status": status if metrics else "ERROR", "error": None if metrics else "crashed",
            "metrics": dict.fromkeys(NAMES) | metrics}))
    return root


def test_paired_differences_tests_and_verdicts(tmp_path: Path) -> None:
    cases = [(f"room{i}", seed) for i in range(4) for seed in (0, 1)]
    base = campaign(tmp_path / "a", {k: {"success": True, "clearance_static_min": 0.25, "time": 30.0} for k in cases})
    worse = {k: {"success": k[1] == 0, "clearance_static_min": 0.25 - 0.1 - 0.01 * n, "time": 30.0}
             for n, k in enumerate(cases)}
    cand = campaign(tmp_path / "b", worse)
    c = compare(base, cand)
    by = {m.metric.name: m for m in c.metrics}
    clearance = by["clearance_static_min"]
    assert clearance.paired.n == 8 and clearance.paired.mean == pytest.approx(-0.135)
    assert clearance.paired.high < 0 and clearance.paired.p == pytest.approx(2 / 2**8)  # exact, all negative
    assert clearance.regressed and clearance.worst(2)[0].candidate.key == "g__room3__base__r1"
    success = by["success"]  # 4 lost, none gained: McNemar's exact p = 2 / 2**4 = 0.125, not below 0.05
    assert success.paired.mean == -0.5 and success.paired.p == pytest.approx(0.125) and not success.regressed
    assert [d.value for d in success.worst(10)] == [-1.0] * 4  # only the pairs that got worse are "changed most"
    assert by["time"].status is None and by["time"].paired.mean == 0  # reported, not judged by the defaults
    assert by["clearance_humans_min"].status == "not-applicable"
    assert c.exit_code == 1 and [m.metric.name for m in c.regressions] == ["clearance_static_min"]
    lenient = parse_thresholds("metrics:\n  clearance_static_min: {worse_by: 0.2}\n")
    assert compare(base, cand, lenient).exit_code == 0  # 0.135 m closer is not more than 0.2 m


def test_files_unpaired_and_errors(tmp_path: Path) -> None:
    base = campaign(tmp_path / "a", {("r1", 0): {"clearance_static_min": 0.2}, ("r2", 0): {"clearance_static_min": 0.2},
                                     ("r3", 0): {"clearance_static_min": 0.2}})
    cand = campaign(tmp_path / "b", {("r1", 0): {"clearance_static_min": 0.2}, ("r2", 0): {},
                                     ("r4", 0): {"clearance_static_min": 0.1}})
    c = compare(base, cand)
    assert [(b.key, k.key) for b, k in c.pairing.pairs] == [("g__r1__base__r0", "g__r1__base__r0")]
    assert [r.key for r in c.pairing.only_baseline] == ["g__r3__base__r0"]
    assert [r.key for r in c.pairing.only_candidate] == ["g__r4__base__r0"]
    # r2 is in ERROR in the candidate: its COMPLETED baseline partner is listed with it, not dropped
    assert [(b.key, b.status, k.key, k.status) for b, k in c.pairing.errors] == [
        ("g__r2__base__r0", "COMPLETED", "g__r2__base__r0", "ERROR")]
    (base / "runs" / "g__r3__base__r0" / "report.html").write_text("<html></html>")  # a run with a report
    files = write_comparison(c, tmp_path / "out")
    suite = ET.parse(files["junit"]).getroot()
    assert suite.get("failures") == "0" and {t.get("classname") for t in suite.iter("testcase")} == {"rei.metrics"}
    html = files["html"].read_text()
    assert "g__r3__base__r0" in html and "g__r4__base__r0" in html and "crashed" in html
    assert "href='../a/runs/g__r3__base__r0/report.html'" in html  # its report, the others' folders
    assert "ERROR (candidate)" in html and "partner of a run in ERROR (baseline)" in html
    assert html.count("href='../a/runs/g__r2__base__r0/'") == 1 and html.count("href='../b/runs/g__r2__base__r0/'") == 1
    errors = json.loads(files["json"].read_text())["errors"]
    assert [(e["baseline"]["status"], e["candidate"]["status"], e["candidate"]["error"]) for e in errors] == [
        ("COMPLETED", "ERROR", "crashed")]
    with pytest.raises(CompareError, match="no run of .* pairs"):
        compare(base, campaign(tmp_path / "c", {("other", 0): {"success": True}}))
    with pytest.raises(CompareError, match="neither a campaign folder"):
        compare(base, tmp_path)


def test_one_pair_compares_without_an_interval(tmp_path: Path) -> None:
    """The smallest comparison: one pair. No bootstrap interval from one difference, every paired test p = 1
    (Wilcoxon and McNemar can say nothing of one pair), and all files written."""
    base = campaign(tmp_path / "a", {("r1", 0): {"success": True, "clearance_static_min": 0.3, "time": 20.0}})
    cand = campaign(tmp_path / "b", {("r1", 0): {"success": False, "clearance_static_min": 0.2, "time": 25.0}})
    c = compare(base, cand)
    by = {m.metric.name: m for m in c.metrics}
    for name in ("success", "clearance_static_min", "time"):
        assert by[name].paired.n == 1 and by[name].paired.low is None and by[name].paired.high is None
        assert by[name].paired.p == 1.0
    assert by["clearance_static_min"].paired.mean == pytest.approx(-0.1) and by["success"].paired.mean == -1.0
    # the size threshold catches it; the p thresholds can not with one pair
    assert [m.metric.name for m in c.regressions] == ["clearance_static_min"] and not by["success"].regressed
    files = write_comparison(c, tmp_path / "out")
    suite = ET.parse(files["junit"]).getroot()
    assert suite.get("failures") == "1" and suite.get("tests") == str(sum(m.status is not None for m in c.metrics))
    data = json.loads(files["json"].read_text())
    assert data["pairs"] == [["g__r1__base__r0", "g__r1__base__r0"]] and data["metrics"]["time"]["ci_low"] is None
    assert "regression(s): clearance_static_min" in files["html"].read_text()


def test_the_social_metrics_are_compared_in_their_better_direction(tmp_path: Path) -> None:
    """A candidate that drives into people more often and nearer to a collision course: more at-fault collisions
    (lower is better) and a shorter time to collision (higher is better) are both worse; the time in the social
    zone has no direction of its own and is reported only."""
    cases = [(f"room{i}", 0) for i in range(4)]
    base = campaign(tmp_path / "a", {k: {"collisions_robot_at_fault": 0, "ttc_humans_min": 3.0,
                                         "social_time": 10.0} for k in cases})
    cand = campaign(tmp_path / "b", {k: {"collisions_robot_at_fault": 1, "ttc_humans_min": 1.0 + 0.1 * n,
                                         "social_time": 12.0} for n, k in enumerate(cases)})
    thresholds = parse_thresholds("metrics:\n  collisions_robot_at_fault: {worse_by: 0.5}\n"
                                  "  ttc_humans_min: {worse_by: 1}\n")
    c = compare(base, cand, thresholds)
    by = {m.metric.name: m for m in c.metrics}
    assert by["collisions_robot_at_fault"].paired.mean == 1.0 and by["collisions_robot_at_fault"].regressed
    assert by["ttc_humans_min"].paired.mean == pytest.approx(-1.85) and by["ttc_humans_min"].regressed
    assert by["social_time"].status is None and by["social_time"].paired.mean == 2.0
    assert by["path_irregularity_humans"].status is None  # no pair has it
    assert c.exit_code == 1


def test_a_campaign_s_runs_are_those_it_planned_not_folders_an_edited_spec_left(tmp_path: Path) -> None:
    """A resume whose spec dropped a repetition keeps the old run's folder; the campaign's runs.csv and summaries
    leave it out, and so must a comparison (it was paired, and its change counted, before)."""
    runs = {("r1", 0): {"clearance_static_min": 0.2}, ("r1", 1): {"clearance_static_min": 0.2}}
    base = campaign(tmp_path / "a", runs)
    cand = campaign(tmp_path / "b", {("r1", 0): {"clearance_static_min": 0.2},
                                     ("r1", 1): {"clearance_static_min": 0.05}})
    (cand / "campaign.json").write_text(json.dumps({"format": "rei-campaign/1", "runs": ["g__r1__base__r0"]}))
    c = compare(base, cand)
    assert [(b.key, k.key) for b, k in c.pairing.pairs] == [("g__r1__base__r0", "g__r1__base__r0")]
    assert [r.key for r in c.pairing.only_baseline] == ["g__r1__base__r1"] and not c.pairing.only_candidate
    assert c.exit_code == 0, "the left-over run's 0.15 m closer is no change of this campaign"
    (cand / "campaign.json").write_text(json.dumps({"format": "rei-campaign/1", "runs": []}))
    with pytest.raises(CompareError, match="0 only in the candidate"):
        compare(base, cand)
