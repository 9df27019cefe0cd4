# SPDX-License-Identifier: EPL-2.0
"""The room editor's engine failing inside is not an invalid candidate: with the real engine run from a copy of
its jar, overwritten in place while it runs (as a rebuild does: its classes and its default catalogue can no longer
be read), the search's candidate maker starts the engine again once; when the new engine works the candidate is
made as usual, and when it fails again `rei search` stops (exit 2, a message) and tells the study nothing about the
candidate (no invalid trial, no penalty: the trial is asked again when the search resumes)."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import pytest
from optuna.trial import TrialState

from rei import toolchain
from rei.cli import main
from rei.edit import engine_command
from rei.search import candidates, study
from rei.search.candidates import CandidateMaker
from rei.search.spec import load_search_spec
from rei.search.study import open_study

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"


class _Jar:
    """A copy of rei-room-editor.jar that can be broken in place (same file, zeros over it) and mended."""

    def __init__(self, original: Path, folder: Path) -> None:
        folder.mkdir(parents=True, exist_ok=True)
        self.path = folder / original.name
        shutil.copyfile(original, self.path)
        self._bytes = self.path.read_bytes()

    def break_(self) -> None:
        with self.path.open("r+b") as out:
            out.write(bytes(len(self._bytes)))

    def mend(self) -> None:
        with self.path.open("r+b") as out:
            out.write(self._bytes)


@pytest.fixture
def jar(tmp_path: Path, room_editor_jar: Path) -> _Jar:
    return _Jar(room_editor_jar, tmp_path / "engine")


def test_an_engine_failing_twice_stops_rei_search_and_no_candidate_is_told_invalid(
        tmp_path: Path, jar: _Jar, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    folder = tmp_path / "spec"
    folder.mkdir()
    for name in ("crossing.rei", "crossing.yaml"):
        shutil.copy(EXAMPLE / name, folder / name)
    command = engine_command(jar.path, toolchain.find_java().executable)

    def maker(*args: Any, **options: Any) -> CandidateMaker:
        made = CandidateMaker(*args, engine=command, **options)
        jar.break_()  # rebuilt while the search runs, after the base case was opened
        return made

    monkeypatch.setattr(study, "CandidateMaker", maker)
    out = tmp_path / "out"
    code = main(["search", str(folder / "crossing.yaml"), "-o", str(out), "--workers", "1", "--budget", "2"])
    printed = capsys.readouterr()
    assert code == 2, printed
    assert "rei: error: search stopped: the room editor's engine failed inside on candidate tpe-0000" in printed.err
    assert "could not be started again" in printed.err and "run the same command to resume" in printed.err
    assert "The edit engine failed (" in printed.out, printed.out  # the engine's own answer: kind internal
    assert "tpe-0000: the room editor's engine failed inside" in printed.out and "invalid" not in printed.out
    trials = open_study(out, load_search_spec(folder / "crossing.yaml").with_options(budget=2)).get_trials(deepcopy=False)
    # the candidate's trial stays running (asked again when the search resumes); the others are TPE's start-up
    # design, still waiting; none was told anything
    assert [t.state for t in trials if t.state != TrialState.WAITING] == [TrialState.RUNNING], trials
    assert not any(t.user_attrs.get("status") or t.system_attrs.get("constraints") for t in trials), trials


def test_an_engine_that_works_again_after_the_restart_makes_the_candidate(tmp_path: Path, jar: _Jar) -> None:
    lines: list[str] = []

    def log(line: str) -> None:
        lines.append(line)
        if "starting it again" in line:
            jar.mend()  # the rebuild is over: the new engine reads a whole jar

    command = engine_command(jar.path, toolchain.find_java().executable)
    spec = load_search_spec(EXAMPLE / "crossing.yaml")
    assert spec.case is not None
    maker = CandidateMaker(spec.case, tmp_path / "out", engine=command, log=log)
    try:
        from rei.search.space import Space

        space = Space(spec.parameters, maker.diagram, maker.palette)
        params = {name: d.low if hasattr(d, "low") else d.choices[0] for name, d in space.distributions.items()}
        before = maker.make("before", space.edit(params))
        jar.break_()
        after = maker.make("after", space.edit(params))
    finally:
        maker.close()
    assert len([line for line in lines if "starting it again" in line]) == 1, lines
    assert "The edit engine failed (" in lines[0], lines
    assert before.status in (candidates.VALID, candidates.UNPLANNABLE), before
    assert (after.status, after.text, after.problems) == (before.status, before.text, before.problems)
