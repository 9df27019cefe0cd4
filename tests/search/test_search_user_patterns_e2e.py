# SPDX-License-Identifier: EPL-2.0
"""A search spec's ``patterns:`` (the user's VEPL patterns, as `rei run --patterns`): every run's monitor runs them,
so a ``{signal: ...}`` objective may name a signal they declare and reads its count and first time from the runs;
each saved case's `rei run` line carries ``--patterns``; a resume with other patterns (another folder, or the same
one edited since) is another search; a folder that is missing or does not compile is refused at the spec's key
before anything runs. Real room editor engine, generator, simulation, monitor jar and evaluator, on the example's
crossing with a budget of 1."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path
from typing import Any

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"
TIMEOUT = 300.0
BUDGET = 1

#: A signal of the user's own at every task start (the default patterns say SIG_MISSION_TASK_START then).
USER_PATTERN = """\
// every task that starts, by a pattern of the user's own
atomicEvent userTaskStarts() as mission TASK_START
signal SIG_USER_TASK_STARTED utility 5
rule "User: a task starts" on userTaskStarts emits SIG_USER_TASK_STARTED
"""

SPEC = f"""\
case: crossing.rei
seed: 3
budget: {BUDGET}
sampler: random
patterns: PATTERNS
timeout: 120
parameters:
  - {{human: walker, start: [5, 11], speed: [0.6, 1.5]}}
objectives:
  - {{signal: SIG_USER_TASK_STARTED, of: first}}
  - {{signal: SIG_USER_TASK_STARTED, of: count}}
shrink: {{budget: 0}}
"""


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="utf-8") as file:
        return list(csv.DictReader(file))


@pytest.fixture(scope="module")
def searched(tmp_path_factory: pytest.TempPathFactory, run_cli: Any) -> tuple[Path, Path, Any]:
    folder = tmp_path_factory.mktemp("patterns")
    shutil.copy(EXAMPLE / "crossing.rei", folder / "crossing.rei")
    (folder / "mine").mkdir()
    (folder / "mine" / "done.vepl").write_text(USER_PATTERN, encoding="utf-8")
    (folder / "s.yaml").write_text(SPEC.replace("PATTERNS", "mine"), encoding="utf-8")
    out = folder / "out"
    result = run_cli("search", folder / "s.yaml", "-o", out, "--workers", "1", timeout=TIMEOUT)
    return folder, out, result


def test_every_run_runs_the_users_patterns_and_the_objective_reads_their_signal(searched: tuple[Path, Path, Any]) -> None:
    folder, out, result = searched
    assert result.returncode in (0, 1), result.stdout + result.stderr
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    assert [o["label"] for o in document["objectives"]] == ["signal:SIG_USER_TASK_STARTED:first",
                                                            "signal:SIG_USER_TASK_STARTED:count"]
    assert document["counts"]["simulated"] == BUDGET and document["counts"]["errors"] == 0
    for record in document["evaluations"]:
        assert record["status"] == "COMPLETED", record
        run = Path(record["run"])
        rows = _rows(run / "events.csv")
        mine = [r for r in rows if r["signal"] == "SIG_USER_TASK_STARTED"]
        starts = [r for r in rows if r["signal"] == "SIG_MISSION_TASK_START"]
        # the user's signal comes with every task start (two goals), scored with the utility its pattern declares
        assert len(mine) == 2 and [r["t"] for r in mine] == [r["t"] for r in starts], rows
        assert {r["utility"] for r in mine} == {"5"}
        assert record["values"] == [pytest.approx(float(mine[0]["t"])), len(mine)], record
        assert json.loads((run / "summary.json").read_text())["counts"]["SIG_USER_TASK_STARTED"] == len(mine)
        # the run keeps the patterns it ran, so `rei evaluate` of it replays them
        assert (run / "patterns" / "done.vepl").read_text(encoding="utf-8") == USER_PATTERN
        # the saved case's `rei run` line runs them too
        first = Path(record["case"]).read_text(encoding="utf-8").splitlines()[0]
        assert f" --patterns {folder / 'mine'}" in first, first


def test_a_resume_with_other_patterns_is_another_search(searched: tuple[Path, Path, Any], run_cli: Any) -> None:
    folder, out, _ = searched
    (folder / "other").mkdir()
    (folder / "other" / "done.vepl").write_text(USER_PATTERN, encoding="utf-8")
    (folder / "other.yaml").write_text(SPEC.replace("PATTERNS", "other"), encoding="utf-8")
    result = run_cli("search", folder / "other.yaml", "-o", out, "--workers", "1", timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    assert (f"{folder / 'other.yaml'}:5:11: this OUT holds a search started with another spec: patterns is "
            f"{folder / 'other'} here, {folder / 'mine'} there") in result.stderr, result.stderr
    # the same folder with a pattern edited since the runs ran it: their copy tells
    (folder / "mine" / "done.vepl").write_text(USER_PATTERN.replace("utility 5", "utility 6"), encoding="utf-8")
    result = run_cli("search", folder / "s.yaml", "-o", out, "--workers", "1", timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    assert (f"{folder / 's.yaml'}:5:11: this OUT holds a search whose runs ran other patterns than "
            f"{folder / 'mine'} has now ({out / 'runs' / 'random-0000' / 'patterns'} has theirs)") in result.stderr, \
        result.stderr


@pytest.mark.parametrize(("pattern", "objective", "expected"), [
    (None, "SIG_USER_TASK_STARTED", ["rei: error: s.yaml:5:11: --patterns {folder}/mine: not a folder"]),
    ("\nqueryEvent x() as noSuchQuery found\n", "SIG_USER_TASK_STARTED",
     ["rei: error: s.yaml:5:11: --patterns {folder}/mine: pattern files do not validate:",
      "{folder}/mine/done.vepl:2:19: Unknown query 'noSuchQuery'"]),
    (USER_PATTERN, "SIG_USER_TASK_STRTED",
     [("rei: error: s.yaml:10:14: unknown signal 'SIG_USER_TASK_STRTED' (did you mean SIG_USER_TASK_STARTED?); "
      "known: ")]),
])
def test_patterns_that_do_not_serve_are_refused_at_the_spec_before_anything_runs(
        tmp_path: Path, run_cli: Any, pattern: str | None, objective: str, expected: list[str]) -> None:
    shutil.copy(EXAMPLE / "crossing.rei", tmp_path / "crossing.rei")
    if pattern is not None:
        (tmp_path / "mine").mkdir()
        (tmp_path / "mine" / "done.vepl").write_text(pattern, encoding="utf-8")
    (tmp_path / "s.yaml").write_text(SPEC.replace("PATTERNS", "mine").replace("SIG_USER_TASK_STARTED, of: first",
                                                                             f"{objective}, of: first"))
    out = tmp_path / "out"
    result = run_cli("search", "s.yaml", "-o", out, timeout=120, cwd=tmp_path)
    assert result.returncode == 2, result.stdout + result.stderr
    for fragment in expected:
        assert fragment.format(folder=tmp_path) in result.stderr, result.stderr
    assert not out.exists()  # nothing ran
