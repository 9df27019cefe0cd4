# SPDX-License-Identifier: EPL-2.0
"""`rei search` with a spec that has several mistakes, some only the base case can tell (a person it does not
have) and some the spec alone (an unknown metric, a bad speed): every one is reported at once, each on its own
`rei: error: FILE:LINE:COLUMN: ...` line in the order of the file, exit code 2, and nothing runs. Real room editor
engine, on the example's crossing."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"

SPEC = """\
case: crossing.rei
budget: 1
parameters:
  - {human: walkr, start: [5, 11], speed: [0, 1.5]}
  - {object: bin1, floor: [F_0_0, F_9_9]}
objectives:
  - {metric: clearence_humans_min}
"""


def test_an_unknown_person_and_an_unknown_metric_are_both_reported(tmp_path: Path, run_cli: Any) -> None:
    shutil.copy(EXAMPLE / "crossing.rei", tmp_path / "crossing.rei")
    spec = tmp_path / "s.yaml"
    spec.write_text(SPEC, encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", spec, "-o", out, timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == 4, result.stderr
    assert lines[:3] == [
        f"rei: error: {spec}:4:13: the base case has no human or moving object named 'walkr'; it has walker",
        f"rei: error: {spec}:4:43: a speed (m/s) must be positive, got 0",
        f"rei: error: {spec}:5:27: the base case's room has no floor 'F_9_9'"], result.stderr
    assert lines[3].startswith(f"rei: error: {spec}:7:14: unknown metric 'clearence_humans_min'; known: success, ")
    assert not out.exists()  # nothing ran
