# SPDX-License-Identifier: EPL-2.0
"""A campaign's resume after its test case was edited runs the case's runs again (they ran another room), and a
case that no longer generates makes them ERROR; before, the resume kept the old results as finished, said "0 in
ERROR" and exited 0 while the case could not even be generated. With the real generator, simulation and monitor."""

from __future__ import annotations

import csv
from pathlib import Path
from typing import Any

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "simple_navigation.rei"


def runs(out: Path) -> dict[str, dict[str, str]]:
    with open(out / "runs.csv", newline="", encoding="utf-8") as f:
        return {row["key"]: row for row in csv.DictReader(f)}


def test_an_edited_case_runs_again_and_one_that_no_longer_generates_is_an_error(tmp_path: Path,
                                                                                 run_cli: Any) -> None:
    (tmp_path / "short.txt").write_text("1.0 0.1 0.0\n", encoding="utf-8")  # a controller that gives up at once
    case = tmp_path / "lab.rei"
    case.write_text(EXAMPLE.read_text(encoding="utf-8"), encoding="utf-8")
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"name: edited\ncontroller: script:{tmp_path / 'short.txt'}\ngroups:\n  - name: g\n"
                    "    cases: [lab.rei]\n", encoding="utf-8")
    out = tmp_path / "out"
    key = "g__lab__base__r0"

    first = run_cli("campaign", spec, "-o", out, "--workers", "1", "--no-service", timeout=300)
    assert first.returncode == 0, first.stdout + first.stderr
    before = (out / "runs" / key / "result.json").stat().st_mtime_ns

    again = run_cli("campaign", spec, "-o", out, "--workers", "1", "--no-service", timeout=300)
    assert "1 finished already, 0 to run" in again.stdout, again.stdout  # unchanged: kept

    case.write_text(case.read_text(encoding="utf-8").replace("on F_2_1", "on F_3_1"), encoding="utf-8")
    moved = run_cli("campaign", spec, "-o", out, "--workers", "1", "--no-service", timeout=300)
    assert moved.returncode == 0, moved.stdout + moved.stderr
    assert "0 finished already, 1 to run" in moved.stdout, moved.stdout
    assert (out / "runs" / key / "result.json").stat().st_mtime_ns > before
    assert '"F_3_1"' in (out / "cases" / "lab" / "world.json").read_text(encoding="utf-8")

    case.write_text(case.read_text(encoding="utf-8").replace("    goto F_5_3\n", ""), encoding="utf-8")
    broken = run_cli("campaign", spec, "-o", out, "--workers", "1", "--no-service", timeout=300)
    assert broken.returncode == 1, broken.stdout + broken.stderr
    assert "1/1 runs finished, 1 in ERROR" in broken.stdout, broken.stdout
    # recorded now, not earlier: it said "1 finished already"
    assert "0 finished already, 1 in ERROR (case not generated), 0 to run" in broken.stdout, broken.stdout
    row = runs(out)[key]
    assert row["status"] == "ERROR" and "could not be generated" in row["error"], row
