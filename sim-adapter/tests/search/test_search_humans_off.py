# SPDX-License-Identifier: EPL-2.0
"""``humans: false`` runs without the base case's humans: a parameter of a human's walk would change nothing, so it
is refused at the human's name before anything runs; a moving object's walk (it stays in such runs) is searched."""

from __future__ import annotations

import copy
import threading
from pathlib import Path

import pytest
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

from rei.campaign.spec import SpecError
from rei.search import study
from rei.search.spec import parse_search_spec

SPEC = """\
case: case.rei
humans: false
sampler: random
budget: 1
parameters:
  - {object: bin1, floor: any}
  - {human: walker, start: [0, 10], speed: [0.5, 1.5]}
objectives:
  - utility
"""


def make_search(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, text: str, kind: str = "human") -> study.Search:
    diagram = copy.deepcopy(DIAGRAM)
    diagram["movers"][0]["kind"] = kind
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    spec = parse_search_spec(text, base=tmp_path, file="s.yaml")
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder, log=print, **_: FakeMaker(folder, diagram))
    return study.Search(spec, tmp_path / "out", FakePool(lambda *_: []), threading.Event(), log=lambda _: None)


def test_a_humans_walk_is_refused_at_its_name_when_the_runs_have_no_humans(tmp_path: Path,
                                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    with pytest.raises(SpecError) as raised:
        make_search(tmp_path, monkeypatch, SPEC)
    assert str(raised.value) == ("s.yaml:7:13: walker is a human and the spec runs without humans (humans: false): "
                                 "its start would change nothing; remove its parameters or set humans: true")


def test_with_humans_or_for_a_moving_object_the_walk_is_searched(tmp_path: Path,
                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    with_humans = make_search(tmp_path, monkeypatch, SPEC.replace("humans: false", "humans: true"))
    assert {"walker.start", "walker.speed"} <= set(with_humans.space.distributions)
    (tmp_path / "dynamic").mkdir()
    moving = make_search(tmp_path / "dynamic", monkeypatch, SPEC, kind="dynamic")
    assert {"walker.start", "walker.speed"} <= set(moving.space.distributions)
    assert not moving.spec.humans
