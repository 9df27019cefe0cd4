# SPDX-License-Identifier: EPL-2.0
"""The room editor's engine failing inside is not an invalid candidate: with the real engine run from a copy of
its jar, overwritten in place while it runs (as a rebuild does: its classes and its default catalogue can no longer
be read), the search's candidate maker starts the engine again once; when the new engine works the candidate is
made as usual, and when it fails again the search stops with ``EngineFailure`` and tells the study nothing about
the candidate (no invalid trial, no penalty: the trial is asked again when the search resumes)."""

from __future__ import annotations

import functools
import shutil
import threading
from pathlib import Path
from typing import Any

import pytest
from optuna.trial import TrialState

from rei import toolchain
from rei.edit import EngineFailure, engine_command
from rei.search import candidates, study
from rei.search.candidates import CandidateMaker
from rei.search.spec import load_search_spec
from rei.search.study import Search

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


def _search(tmp_path: Path, jar: _Jar, log: Any, monkeypatch: pytest.MonkeyPatch) -> Search:
    folder = tmp_path / "spec"
    folder.mkdir()
    for name in ("crossing.rei", "crossing.yaml"):
        shutil.copy(EXAMPLE / name, folder / name)
    spec = load_search_spec(folder / "crossing.yaml").with_options(budget=2)
    command = engine_command(jar.path, toolchain.find_java().executable)
    monkeypatch.setattr(study, "CandidateMaker", functools.partial(CandidateMaker, engine=command))
    # the pool is never reached: the first candidate fails before it would run
    from rei.search.run import _LazyPool

    def no_pool() -> Any:
        raise AssertionError("a candidate reached the pool")

    return Search(spec, tmp_path / "out", _LazyPool(no_pool, 1, "local"), threading.Event(), log)


def test_an_engine_failing_twice_stops_the_search_and_no_candidate_is_told_invalid(
        tmp_path: Path, jar: _Jar, monkeypatch: pytest.MonkeyPatch) -> None:
    lines: list[str] = []
    search = _search(tmp_path, jar, lines.append, monkeypatch)
    try:
        jar.break_()
        with pytest.raises(EngineFailure) as failure:
            search.run()
    finally:
        search.close()
    assert "failed inside" in str(failure.value) and "could not be started again" in str(failure.value), failure.value
    assert "The edit engine failed (" in str(failure.value), failure.value  # the engine's own answer, kind internal
    assert any("starting it again" in line for line in lines), lines
    assert search.progress.invalid == 0
    trials = search.study.get_trials(deepcopy=False)
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
