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
    (["--workers", "0"], "--workers must be at least 1, got 0"),  # not silently every core
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


def _side(root: Path, runs: dict[str, str]) -> Path:
    for case, status in runs.items():
        run = root / "runs" / f"g__{case}__base__r0"
        run.mkdir(parents=True)
        (run / "result.json").write_text(json.dumps({
            "key": run.name, "group": "g", "case": case, "variant": "base", "seed": 0, "status": status,
            "error": "crashed" if status == "ERROR" else None,
            "metrics": dict.fromkeys(NAMES) | ({"clearance_static_min": 0.2} if status == "COMPLETED" else {})}))
    return root


def test_compare_lists_the_runs_it_does_not_compare(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    a = _side(tmp_path / "a", {"r1": "COMPLETED", "r2": "COMPLETED", "r3": "COMPLETED"})
    b = _side(tmp_path / "b", {"r1": "COMPLETED", "r2": "ERROR", "r4": "COMPLETED"})
    assert main(["compare", str(a), str(b), "-o", str(tmp_path / "cmp")]) == 0
    out = capsys.readouterr().out
    assert "1 pair(s); 1 run(s) only in the baseline, 1 only in the candidate, 1 pair(s) with a side in ERROR" in out
    assert "not compared: g__r3__base__r0: only in the baseline" in out
    assert "not compared: g__r4__base__r0: only in the candidate" in out
    assert ("not compared: g__r2__base__r0 (baseline COMPLETED) and g__r2__base__r0 (candidate ERROR): crashed"
            in out)


@pytest.mark.parametrize(("text", "where"), [("metrics: {1: {p: 0.05}}\n", "1:11"), ("2: x\n", "1:1")])
def test_compare_stops_on_a_thresholds_key_that_is_no_text(text: str, where: str, tmp_path: Path,
                                                           capsys: pytest.CaptureFixture[str]) -> None:
    a = _side(tmp_path / "a", {"r1": "COMPLETED"})
    (tmp_path / "t.yaml").write_text(text)
    assert main(["compare", str(a), str(a), "-o", str(tmp_path / "cmp"), "--thresholds",
                 str(tmp_path / "t.yaml")]) == 2
    assert f"t.yaml:{where}: unknown" in capsys.readouterr().err
    assert not (tmp_path / "cmp").exists()


def test_compare_prints_every_mistake_of_the_thresholds_on_its_own_line(tmp_path: Path,
                                                                         capsys: pytest.CaptureFixture[str]) -> None:
    a = _side(tmp_path / "a", {"r1": "COMPLETED"})
    (tmp_path / "t.yaml").write_text("metrics:\n  time: {p: 0}\n  spl: {worse_by: x}\n")
    assert main(["compare", str(a), str(a), "-o", str(tmp_path / "cmp"), "--thresholds",
                 str(tmp_path / "t.yaml")]) == 2
    assert capsys.readouterr().err.splitlines() == [
        f"rei: error: {tmp_path / 't.yaml'}:2:13: time: 'p' must be a significance level in (0, 1], got 0",
        f"rei: error: {tmp_path / 't.yaml'}:3:19: spl: 'worse_by' must be a number, got 'x'"]
    assert not (tmp_path / "cmp").exists()


def test_an_output_that_is_a_file_is_a_usage_error_not_a_traceback(tmp_path: Path,
                                                                     capsys: pytest.CaptureFixture[str]) -> None:
    """rei compare, rei campaign and rei search with -o naming a file ended in FileExistsError's traceback (rei compare
    after comparing everything)."""
    taken = tmp_path / "taken"
    taken.write_text("not a folder\n")
    a = _side(tmp_path / "a", {"r1": "COMPLETED"})
    search_spec = Path(__file__).resolve().parents[3] / "examples" / "search" / "crossing.yaml"
    for argv in (["compare", str(a), str(a)], ["campaign", str(spec(tmp_path))], ["search", str(search_spec)]):
        assert main([*argv, "-o", str(taken)]) == 2, argv
        assert capsys.readouterr().err == f"rei: error: cannot write to {taken}: File exists\n", argv
    assert taken.read_text() == "not a folder\n"


def test_a_campaign_its_planning_refuses_leaves_out_as_it_was(tmp_path: Path,
                                                                capsys: pytest.CaptureFixture[str]) -> None:
    """Two groups whose rooms share a name but not their text: refused, after OUT's spec.yaml had been replaced by
    the refused spec (the runs there no longer had their spec beside them)."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "spec.yaml").write_text("the spec its runs ran\n")
    catalogue = Path(__file__).resolve().parents[3] / "examples" / "catalogues" / "office.rei"
    refused = tmp_path / "refused.yaml"
    refused.write_text("groups:\n  - name: a\n    rooms: {size: small, count: 1, seed: 1}\n  - name: b\n"
                       f"    rooms: {{size: small, count: 1, seed: 1, catalogue: {catalogue}}}\n")
    assert main(["campaign", str(refused), "-o", str(out), "--no-service"]) == 2
    assert "both named 'small_dense_h0_s1_01'" in capsys.readouterr().err
    assert (out / "spec.yaml").read_text() == "the spec its runs ran\n"
