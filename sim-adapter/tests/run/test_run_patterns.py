# SPDX-License-Identifier: EPL-2.0
"""A run's VEPL patterns: the monitor's options, the copy kept in OUT and the selection read back for a replay.

Compiling them (``check``) takes the monitor jar: tests/pipeline/test_user_patterns.py runs it.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rei.run.patterns import PATTERNS_DIR, SELECTION_FILE, PatternError, PatternSelection, check, record


def _patterns(folder: Path) -> Path:
    folder.mkdir()
    (folder / "b.vepl").write_text("signal SIG_B utility 1\n")
    (folder / "a.vepl").write_text("signal SIG_A\n")
    (folder / "notes.txt").write_text("not a pattern")
    (folder / "sub").mkdir()
    (folder / "sub" / "c.vepl").write_text("signal SIG_C\n")  # the monitor does not read below the folder
    return folder


def test_the_monitor_options_and_the_name_in_the_summary(tmp_path: Path) -> None:
    assert PatternSelection().monitor_args() == []
    assert PatternSelection().describe() == "patterns (defaults)"
    mine = PatternSelection(tmp_path, defaults=False)
    assert mine.monitor_args() == ["--patterns", str(tmp_path), "--no-default-patterns"]
    assert mine.describe() == f"patterns ({tmp_path})"
    assert PatternSelection(tmp_path).describe() == f"patterns (defaults + {tmp_path})"
    with pytest.raises(ValueError, match="--no-default-patterns needs --patterns DIR"):
        PatternSelection(None, defaults=False)


def test_a_run_keeps_a_copy_and_a_replay_reads_the_selection_back(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    assert PatternSelection.recorded(out) == PatternSelection()  # a run without patterns of its own
    kept = record(PatternSelection(_patterns(tmp_path / "mine"), defaults=False), out)
    assert kept == PatternSelection(out / PATTERNS_DIR, defaults=False)
    assert sorted(p.name for p in (out / PATTERNS_DIR).iterdir()) == ["a.vepl", "b.vepl"]
    assert json.loads((out / SELECTION_FILE).read_text()) == {
        "source": str((tmp_path / "mine").resolve()), "default_patterns": False}
    assert PatternSelection.recorded(out) == kept
    # the next run in the same folder, without patterns: a replay must not pick up the old ones
    assert record(PatternSelection(), out) == PatternSelection()
    assert not (out / PATTERNS_DIR).exists() and not (out / SELECTION_FILE).exists()
    assert PatternSelection.recorded(out) == PatternSelection()


def test_recording_the_run_folders_own_copy_keeps_it(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    own = _patterns(out / PATTERNS_DIR)
    assert record(PatternSelection(own), out) == PatternSelection(own)
    assert (own / "a.vepl").is_file() and (own / "notes.txt").is_file()  # nothing deleted
    assert PatternSelection.recorded(out) == PatternSelection(own, defaults=True)


def test_a_folder_that_is_not_one_of_patterns_fails_before_any_jvm(tmp_path: Path) -> None:
    with pytest.raises(PatternError, match="not a folder"):
        check(PatternSelection(tmp_path / "missing"))
    (tmp_path / "empty").mkdir()
    with pytest.raises(PatternError, match="no .vepl files in it"):
        check(PatternSelection(tmp_path / "empty"))
