# SPDX-License-Identifier: EPL-2.0
"""The command lines of rei compare and of rei campaign's --controller and --compare: mistakes stop them before
anything runs; a regression is exit 1 with its files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rei.cli import main
from rei.evaluation.metrics import NAMES

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "simple_navigation.rei"


def spec(tmp_path: Path) -> Path:
    path = tmp_path / "spec.yaml"
    path.write_text(f"groups:\n  - name: g\n    cases: [{EXAMPLE}]\n")
    return path


@pytest.mark.parametrize(("extra", "message"), [
    (["--controller", "nav:bogus=1"], "--controller nav:bogus=1: nav parameter 'bogus=1'"),
    (["--controller", "teleport"], "--controller teleport: unknown controller 'teleport'"),
    (["--thresholds", "t.yaml"], "--thresholds needs --compare BASELINE"),
    (["--compare", "nowhere"], "--compare nowhere: no such campaign folder"),
])
def test_campaign_options_are_checked_first(extra: list[str], message: str, tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["campaign", str(spec(tmp_path)), "-o", str(tmp_path / "out"), *extra]) == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_compare_exits_one_on_a_regression(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    for side, clearance in (("a", 0.3), ("b", 0.1)):
        for seed in (0, 1):
            run = tmp_path / side / "runs" / f"g__room__base__r{seed}"
            run.mkdir(parents=True)
            (run / "result.json").write_text(json.dumps({
                "key": run.name, "group": "g", "case": "room", "variant": "base", "seed": seed, "status": "COMPLETED",
                "metrics": dict.fromkeys(NAMES) | {"clearance_static_min": clearance + 0.01 * seed}}))
    code = main(["compare", str(tmp_path / "a"), str(tmp_path / "b"), "-o", str(tmp_path / "cmp")])
    out = capsys.readouterr().out
    assert code == 1 and "regressions: clearance_static_min" in out and "2 pair(s)" in out
    assert {p.name for p in (tmp_path / "cmp").iterdir()} == {"compare.html", "compare.json", "verdicts.xml"}
    assert main(["compare", str(tmp_path / "a"), str(tmp_path / "a"), "-o", str(tmp_path / "same")]) == 0
