# SPDX-License-Identifier: EPL-2.0
"""A campaign spec's ``patterns:`` and ``utilities:`` (as `rei run --patterns DIR --utilities YAML`): every run's
monitor runs the user's patterns - in the replay worker, through the campaign's warm monitor JVM - and the
evaluator scores their signal with the user's utility; a pattern that does not compile stops the campaign at the
spec's key before anything runs. Real simulation, monitor jar and evaluator, one run."""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "simple_navigation.rei"

USER_PATTERN = """\
atomicEvent userTaskStarts() as mission TASK_START
signal SIG_USER_TASK_STARTED utility 7
rule "User: a task starts" on userTaskStarts emits SIG_USER_TASK_STARTED
"""

SPEC = f"""\
name: mine
timeout: 240
patterns: mine
utilities: utilities.yaml
variants: [{{name: base, humans: false}}]
groups:
  - name: example
    cases: [{EXAMPLE}]
"""


def _write(folder: Path, pattern: str) -> Path:
    (folder / "mine").mkdir()
    (folder / "mine" / "tasks.vepl").write_text(pattern, encoding="utf-8")
    (folder / "utilities.yaml").write_text("SIG_USER_TASK_STARTED: 9\n", encoding="utf-8")
    (folder / "c.yaml").write_text(SPEC, encoding="utf-8")
    return folder / "c.yaml"


def test_every_run_runs_the_users_patterns_scored_with_the_users_utilities(tmp_path: Path, run_cli: Any) -> None:
    out = tmp_path / "out"
    result = run_cli("campaign", _write(tmp_path, USER_PATTERN), "-o", out, "--workers", "1", timeout=400)
    assert result.returncode == 0, result.stdout + result.stderr
    run = out / "runs" / "example__simple_navigation__base__r0"
    with (run / "events.csv").open(newline="", encoding="utf-8") as file:
        rows = list(csv.DictReader(file))
    mine = [r for r in rows if r["signal"] == "SIG_USER_TASK_STARTED"]
    starts = [r for r in rows if r["signal"] == "SIG_MISSION_TASK_START"]
    assert len(mine) == 2 and [r["t"] for r in mine] == [r["t"] for r in starts], rows
    assert {r["utility"] for r in mine} == {"9"}  # the user's file wins over the pattern's 7
    summary = json.loads((run / "summary.json").read_text(encoding="utf-8"))
    assert summary["counts"]["SIG_USER_TASK_STARTED"] == 2 and summary["unknown_signals"] == {}
    assert (run / "patterns" / "tasks.vepl").read_text(encoding="utf-8") == USER_PATTERN
    task = json.loads((run / "task.json").read_text(encoding="utf-8"))
    assert task["patterns"] == str(tmp_path / "mine") and task["utilities"] == str(tmp_path / "utilities.yaml")


def test_patterns_that_do_not_compile_stop_the_campaign_at_the_spec(tmp_path: Path, run_cli: Any) -> None:
    out = tmp_path / "out"
    result = run_cli("campaign", _write(tmp_path, "\nqueryEvent x() as noSuchQuery found\n"), "-o", out,
                     timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    assert f"{tmp_path / 'c.yaml'}:3:11: --patterns {tmp_path / 'mine'}: pattern files do not validate:" \
        in result.stderr, result.stderr
    assert f"{tmp_path / 'mine' / 'tasks.vepl'}:2:19: Unknown query 'noSuchQuery'" in result.stderr
    assert not (out / "runs").exists()
