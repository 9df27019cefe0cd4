# SPDX-License-Identifier: EPL-2.0
"""Encounter-guided refinement end to end (real room editor engine, generator, simulation, monitor jar and
evaluator) on the example's crossing: a TPE search of the walker's start in 0-60 s on the encounter margin. The
design's first point leaves the walker seconds off the robot; the refinement asked next moves only its start by the
measured shift, and its own run, measured from the recorded streams, comes nearer to a meeting."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import optuna

from rei.search.study import journal

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"
SPEC = """\
case: crossing.rei
seed: 1
budget: 3
timeout: 120
parameters:
  - {human: walker, start: [0, 60]}
objectives:
  - {metric: encounter_margin_humans}
shrink: {budget: 0}
"""


def test_a_near_miss_is_refined_towards_the_meeting(tmp_path: Path, run_cli: Any) -> None:
    shutil.copy(EXAMPLE / "crossing.rei", tmp_path / "crossing.rei")
    (tmp_path / "s.yaml").write_text(SPEC, encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", tmp_path / "s.yaml", "-o", out, "--workers", "1", timeout=300.0)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    trials = optuna.load_study(study_name="tpe", storage=journal(out)).trials
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    records = {r["number"]: r for r in document["evaluations"]}
    # trial 1 was asked while trial 0 ran (the design's second point); trial 2 refines trial 0
    first, refinement = trials[0], trials[2]
    assert "design" in first.user_attrs and refinement.user_attrs.get("refinement") == 1
    before = records[0]["metrics"]["encounter_margin_humans"]
    after = records[2]["metrics"]["encounter_margin_humans"]
    assert before > 0.5, before  # a near miss to refine, not a meeting already
    assert refinement.params["walker.start"] != first.params["walker.start"]
    assert abs(refinement.params["walker.start"] - first.params["walker.start"]) <= before + 1e-6
    assert after < before, (before, after)
    assert f"refine tpe-0000: walker {before:.2f} s off a meeting" in result.stdout
    assert document["counts"]["simulated"] == 3 and document["counts"]["interrupted"] == 0
