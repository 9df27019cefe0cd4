# SPDX-License-Identifier: EPL-2.0
"""CMA-ES draws every categorical parameter (the floors) independently at random; Optuna's own warning is switched
off, so `rei search` says it once at start, naming them, and says nothing when every parameter is numeric."""

from __future__ import annotations

import threading
from pathlib import Path

import pytest
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

from rei.search import study
from rei.search.spec import parse_search_spec

SPEC = """\
case: case.rei
sampler: cmaes
parameters:
  - {object: bin1, floor: any, yaw: [0, 90]}
  - {human: walker, loop: [true, false]}
objectives:
  - utility
"""


def start_lines(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, text: str) -> list[str]:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    spec = parse_search_spec(text, base=tmp_path, file="s.yaml")
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder, log=print, **_: FakeMaker(folder, DIAGRAM))
    lines: list[str] = []
    study.Search(spec, tmp_path / "out", FakePool(lambda *_: []), threading.Event(), log=lines.append)
    return lines


def test_cmaes_notes_its_categorical_parameters_at_start(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    assert start_lines(tmp_path, monkeypatch, SPEC) == [
        ("note: cmaes draws the categorical parameters (bin1.floor, walker.loop) independently at random, learning "
        "only the numeric ones; tpe or nsga2 learn both")]


@pytest.mark.parametrize("text", [SPEC.replace("sampler: cmaes", "sampler: tpe"),
                                  SPEC.replace("floor: any, ", "").replace("  - {human: walker, loop: [true, false]}\n",
                                                                           "")])
def test_no_note_for_another_sampler_or_numeric_parameters(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                           text: str) -> None:
    assert not [line for line in start_lines(tmp_path, monkeypatch, text) if line.startswith("note:")]
