# SPDX-License-Identifier: EPL-2.0
"""`rei run --patterns DIR`: a user's own VEPL pattern, its declared utility in the evaluation, and the same
scores when the run is judged again from its recording (`rei evaluate`). Real processes throughout."""

from __future__ import annotations

import csv
import json
import subprocess
from pathlib import Path

import pytest

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
    assert json.loads((out / "utilities.json").read_text())["SIG_USER_TASK_STARTED"] == {"utility": 7.0}
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


def test_every_bad_pattern_file_is_reported_a_too_deep_one_too(run_cli, repo_root: Path, tmp_path: Path) -> None:
    """A file nested deeper than VEPL's limit (refused before the parser recurses) hides no other file's error."""
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "a_deep.vepl").write_text("queryEvent a as robotFar found\ncomplexEvent c() { as " + "(" * 3000 + "a"
                                     + ")" * 3000 + " }\n")
    (bad / "b_unknown.vepl").write_text("\nqueryEvent x() as noSuchQuery found\n")
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", tmp_path / "out", "--no-humans",
                     "--patterns", bad, timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    column = len("complexEvent c() { as ") + 100  # the brace is level 1: the 100th '(' is level 101
    assert f"{bad / 'a_deep.vepl'}:2:{column}: Brackets nested deeper than 100 levels" in result.stderr, result.stderr
    assert f"{bad / 'b_unknown.vepl'}:2:19: Unknown query 'noSuchQuery'" in result.stderr, result.stderr
    assert "Exception" not in result.stderr and "StackOverflow" not in result.stderr, result.stderr


@pytest.mark.parametrize("text, where, message", [
    ("", ":1:1: The file declares no event, signal or rule", "emptyFile"),
    ("package org.example.patterns\nimport-queries org.example.queries.*\n", ":1:1: The file declares no event",
     "emptyFile"),
    ("queryEvent far() as robotFar lost\ncomplexEvent e() { as far }\nrule r on e {\n  println(\"x\")\n}\n",
     ":3:13: A rule in REI publishes signals instead of running an action block", "actionBlock"),
])
def test_patterns_viatra_cep_users_write_get_one_positioned_error_and_no_crash(
    text: str, where: str, message: str, run_cli, repo_root: Path, tmp_path: Path
) -> None:
    folder = tmp_path / "patterns"
    folder.mkdir()
    (folder / "mine.vepl").write_text(text)
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", tmp_path / "out",
                     "--patterns", folder, timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    assert f"{folder / 'mine.vepl'}{where}" in result.stderr and message in result.stderr, result.stderr
    assert "Exception" not in result.stderr and result.stderr.count("mine.vepl:") == 1, result.stderr


def test_a_users_file_named_like_a_default_pattern_file_compiles_beside_it(java, monitor_jar: Path,
                                                                          tmp_path: Path) -> None:
    folder = tmp_path / "patterns"
    folder.mkdir()
    (folder / "geometry.vepl").write_text("queryEvent nearSomething as robotClose found\nsignal SIG_USER_NEAR\n"
                                          "rule \"near\" on nearSomething emits SIG_USER_NEAR\n")
    utilities = tmp_path / "utilities.json"
    result = subprocess.run([str(java.executable), "-jar", str(monitor_jar), "--compile-only", "--patterns", str(folder),
                             "--utilities-out", str(utilities)], capture_output=True, text=True, timeout=120,
                            check=False)
    assert result.returncode == 0, result.stderr
    declared = json.loads(utilities.read_text())
    assert "SIG_USER_NEAR" in declared and declared["SIG_GEOM_FAR_TRANSIT_CLOSE"]["utility"] == -2.0
