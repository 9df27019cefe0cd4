# SPDX-License-Identifier: EPL-2.0
"""A requirement relative to a fault, through the whole pipeline (router, simulation, monitor jar, Drools,
evaluator): examples/faults' blackout and its pattern "the speed falls below 0.05 m/s within 1 s of a blackout's
start" fails for the reference navigation, which drives on blind, and holds for the same navigation told to
stand while its lidar sees nothing; the blackout's window is published as signals and listed by the evaluator,
live and when the run is judged again from its recording."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest


def _signals(out: Path) -> list[tuple[float, str]]:
    return [(float(r["t"]), r["signal"]) for r in csv.DictReader((out / "events.csv").open())]


@pytest.mark.parametrize(("controller", "expected", "absent"), [
    ("nav", "SIG_DROVE_ON_BLIND", "SIG_STOPPED_WHEN_BLIND"),
    ("nav:stop_when_blind=true", "SIG_STOPPED_WHEN_BLIND", "SIG_DROVE_ON_BLIND"),
])
def test_the_blackout_requirement_tells_a_robot_that_stops_from_one_that_drives_on(
    controller: str, expected: str, absent: str, run_cli, repo_root: Path, tmp_path: Path
) -> None:
    example = repo_root / "examples" / "faults"
    out = tmp_path / "out"
    result = run_cli("run", example / "blackout.rei", "-o", out, "--controller", controller,
                     "--queries", example, "--patterns", example, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    signals = _signals(out)
    assert (4.0, "SIG_FAULT_LASER_BLACKOUT_BEGIN") in signals and (7.0, "SIG_FAULT_LASER_BLACKOUT_END") in signals
    verdict = [(t, s) for t, s in signals if s in (expected, absent)]
    assert len(verdict) == 1 and verdict[0][1] == expected and 4.0 < verdict[0][0] <= 5.1, verdict
    summary = json.loads((out / "summary.json").read_text())
    assert summary["faults"] == [{"fault": "laser blackout", "begin": 4.0, "end": 7.0}]
    assert summary["counts"]["SIG_FAULT_LASER_BLACKOUT_BEGIN"] == 1 and summary["unknown_signals"] == {}
    again = run_cli("evaluate", out, timeout=300)
    assert again.returncode == 0, again.stdout + again.stderr
    assert _signals(out) == signals
    assert json.loads((out / "summary.json").read_text())["faults"] == summary["faults"]


def test_windows_of_one_kind_inside_one_another_are_listed_as_scheduled(run_cli, repo_root: Path,
                                                                        tmp_path: Path) -> None:
    """The evaluator pairs each END with the fault that ends then (sim.json's schedule), not with the window that
    began first: the inner blackout's END closed the outer window (summary.json read 2-6 and 4-10)."""
    case = tmp_path / "nested.rei"
    case.write_text((repo_root / "examples" / "faults" / "blackout.rei").read_text().replace(
        "laser blackout from 4s to 7s", "laser blackout from 2s to 10s\n    laser blackout from 4s to 6s"))
    out = tmp_path / "out"
    result = run_cli("run", case, "-o", out, timeout=300)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    assert [s for s in _signals(out) if "FAULT" in s[1]] == [
        (2.0, "SIG_FAULT_LASER_BLACKOUT_BEGIN"), (4.0, "SIG_FAULT_LASER_BLACKOUT_BEGIN"),
        (6.0, "SIG_FAULT_LASER_BLACKOUT_END"), (10.0, "SIG_FAULT_LASER_BLACKOUT_END")]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["faults"] == [{"fault": "laser blackout", "begin": 2.0, "end": 10.0},
                                 {"fault": "laser blackout", "begin": 4.0, "end": 6.0}]
