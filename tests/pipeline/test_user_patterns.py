# SPDX-License-Identifier: EPL-2.0
"""`rei run --patterns DIR`: a user's own VEPL pattern, its declared utility in the evaluation, and the same
scores when the run is judged again from its recording (`rei evaluate`). Real processes throughout."""

from __future__ import annotations

import csv
import json
from pathlib import Path

#: A new signal on every task start, worth what its pattern declares (simple_navigation has two goals).
USER_PATTERN = """\
// every task start, scored by its own declared utility
atomicEvent userTaskStarts() as mission TASK_START
signal SIG_USER_TASK_STARTED utility 7
rule "User: a task starts" on userTaskStarts emits SIG_USER_TASK_STARTED
"""


def _rows(path: Path) -> list[dict[str, str]]:
    return list(csv.DictReader(path.open()))


def test_a_users_signal_is_scored_with_its_declared_utility_live_and_replayed(
    run_cli, processes_mentioning, repo_root: Path, tmp_path: Path
) -> None:
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "tasks.vepl").write_text(USER_PATTERN)
    out = tmp_path / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--no-humans",
                     "--patterns", mine, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    rows = _rows(out / "events.csv")
    users = [r for r in rows if r["signal"] == "SIG_USER_TASK_STARTED"]
    starts = [r for r in rows if r["signal"] == "SIG_MISSION_TASK_START"]
    assert len(users) == len(starts) == 2
    assert {r["utility"] for r in users} == {"7"} and [r["t"] for r in users] == [r["t"] for r in starts]
    total = sum(float(r["utility"]) for r in rows)
    assert float(rows[-1]["total"]) == total
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "COMPLETED" and summary["total_utility"] == total
    assert summary["utilities"] == f"Table 3 + patterns (defaults + {out / 'patterns'})"
    assert summary["unknown_signals"] == {} and summary["counts"]["SIG_USER_TASK_STARTED"] == 2
    assert json.loads((out / "utilities.json").read_text())["SIG_USER_TASK_STARTED"] == 7.0
    assert (out / "patterns" / "tasks.vepl").read_text() == USER_PATTERN
    # judged again from the recording: the replay runs the kept patterns and scores them the same way
    again = run_cli("evaluate", out, timeout=300)
    assert again.returncode == 0, again.stdout + again.stderr
    assert _rows(out / "events.csv") == rows
    assert json.loads((out / "summary.json").read_text())["utilities"] == summary["utilities"]
    replayed = run_cli("monitor", "--replay", out, timeout=300)  # with the kept patterns, as the live monitor
    assert replayed.returncode == 0, replayed.stderr
    assert replayed.stdout.count("SIG_USER_TASK_STARTED") == 2
    assert processes_mentioning(out) == []


def test_invalid_patterns_fail_with_file_line_and_column_before_anything_starts(
    run_cli, processes_mentioning, repo_root: Path, tmp_path: Path
) -> None:
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "broken.vepl").write_text("\nqueryEvent x() as noSuchQuery found\n")
    out = tmp_path / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--no-humans",
                     "--patterns", bad, timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    assert f"{bad / 'broken.vepl'}:2:19: Unknown query 'noSuchQuery'" in result.stderr, result.stderr
    assert result.stderr.startswith("rei: error: --patterns "), result.stderr
    assert not out.exists()  # no run folder, no router, no simulation
    assert processes_mentioning(bad) == [] and processes_mentioning(out) == []
