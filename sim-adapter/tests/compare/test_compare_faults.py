# SPDX-License-Identifier: EPL-2.0
"""rei compare by fault: runs pair only under the same fault (its canonical text), and a comparison whose pairs
carry several faults judges every metric per fault too, so a regression under one fault is not averaged away."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rei.cli import main
from rei.compare import CompareError, compare, write_comparison
from rei.compare.thresholds import parse_thresholds
from rei.evaluation.metrics import NAMES

GATED = "laser:impulse,rate=0.03333333333333333,gain=0.5,width=3,from=0.0,period=10.0,pulse=1.0"
THRESHOLDS = parse_thresholds("metrics:\n  clearance_static_min: {worse_by: 0.05}\n")


def campaign(root: Path, runs: dict[tuple[str, str | None, int], float]) -> Path:
    """Runs (variant, fault, seed) -> clearance, in two rooms each."""
    for (variant, fault, seed), clearance in runs.items():
        for case in ("r1", "r2"):
            key = f"g__{case}__{variant}__r{seed}"
            (root / "runs" / key).mkdir(parents=True)
            (root / "runs" / key / "result.json").write_text(json.dumps({
                "key": key, "group": "g", "case": case, "variant": variant, "seed": seed, "fault": fault,
                "status": "COMPLETED", "metrics": dict.fromkeys(NAMES) | {"clearance_static_min": clearance}}))
    return root


def test_a_regression_under_one_fault_is_judged_per_fault(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    runs = {("none", None, s): 0.3 for s in (0, 1)} | {("g10", "laser:gated-10%", s): 0.3 for s in (0, 1)}
    base = campaign(tmp_path / "a", runs | {("g1", "laser:gated-1%", s): 0.3 for s in (0, 1)})
    # worse by 0.08 m under the 10 % fault only: 0.08 / 3 overall, below the 0.05 m threshold
    cand = campaign(tmp_path / "b", runs | {("g10", "laser:gated-10%", s): 0.22 for s in (0, 1)}
                    | {("g1", "laser:gated-1%", s): 0.3 for s in (0, 1)})
    c = compare(base, cand, THRESHOLDS)
    assert len(c.pairing.pairs) == 12 and not c.regressions
    assert sorted(fault for fault, _ in c.by_fault) == sorted(["none", GATED, GATED.replace("pulse=1.0", "pulse=0.1")])
    assert [(f, m.metric.name) for f, m in c.fault_regressions] == [(GATED, "clearance_static_min")]
    assert c.exit_code == 1
    per = {f: {m.metric.name: m for m in ms} for f, ms in c.by_fault}
    assert per[GATED]["clearance_static_min"].paired.n == 4
    assert per[GATED]["clearance_static_min"].paired.mean == pytest.approx(-0.08)
    assert per["none"]["clearance_static_min"].status == "pass"
    files = write_comparison(c, tmp_path / "out")
    document = json.loads(files["json"].read_text())
    assert document["regressions"] == [] and document["fault_regressions"] == [
        {"fault": GATED, "metric": "clearance_static_min"}]
    assert document["by_fault"][GATED]["pairs"] == 4 and document["by_fault"]["none"]["regressions"] == []
    assert document["only_baseline"] == []
    cases = {t.get("name"): t for t in ET.parse(files["junit"]).getroot().iter("testcase")}
    assert cases[f"clearance_static_min under {GATED}"].find("failure") is not None
    assert cases["clearance_static_min"].find("failure") is None
    assert "1 regression(s) under a fault" in files["html"].read_text()
    assert main(["compare", str(base), str(cand), "-o", str(tmp_path / "cli")]) == 1  # default thresholds: 5 cm
    out = capsys.readouterr().out
    assert "regressions: none" in out and f"regressions under a fault: clearance_static_min under {GATED}" in out


def test_runs_pair_only_under_the_same_fault(tmp_path: Path) -> None:
    base = campaign(tmp_path / "a", {("f", "laser:gated-1%", 0): 0.3, ("none", None, 0): 0.3})
    # the same variant names, f now with another fault, written differently for "none"
    cand = campaign(tmp_path / "b", {("f", "laser:gated-10%", 0): 0.3, ("none", "none", 0): 0.3})
    c = compare(base, cand)
    assert sorted(b.key for b, _ in c.pairing.pairs) == ["g__r1__none__r0", "g__r2__none__r0"]
    assert sorted(r.key for r in c.pairing.only_baseline) == sorted(r.key for r in c.pairing.only_candidate) == [
        "g__r1__f__r0", "g__r2__f__r0"]
    assert c.by_fault == ()  # the pairs share one fault: no verdicts per fault
    document = json.loads(write_comparison(c, tmp_path / "out")["json"].read_text())
    assert document["by_fault"] == {} and document["only_candidate"][0]["fault"] == GATED


def test_run_folders_pair_by_their_fault(tmp_path: Path) -> None:
    """Two `rei run` folders: the fault is sim.json's --fault, so a run under another fault does not pair."""
    def run(name: str, fault: str | None) -> Path:
        folder = tmp_path / name
        folder.mkdir()
        (folder / "summary.json").write_text(json.dumps({"testcase": "room", "status": "COMPLETED",
                                                         "metrics": dict.fromkeys(NAMES)}))
        (folder / "sim.json").write_text(json.dumps({"options": {"seed": 3, "fault": fault}}))
        return folder

    plain, gated, spelled = run("plain", None), run("gated", "laser:gated-10%"), run("spelled", GATED)
    assert len(compare(gated, spelled).pairing.pairs) == 1
    with pytest.raises(CompareError, match="same group, case, variant, seed and fault"):
        compare(plain, gated)
