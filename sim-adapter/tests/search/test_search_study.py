# SPDX-License-Identifier: EPL-2.0
"""The search loop on a fake maker and pool (search_fakes): what the study is told and what search.json says for
each kind of candidate."""

from __future__ import annotations

import threading
from pathlib import Path
from typing import Any

import pytest
from optuna.trial import TrialState
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

from rei.run.jvm import JvmResult
from rei.search import candidates, study
from rei.search.candidates import VALID, Candidate, CandidateMaker
from rei.search.outputs import records
from rei.search.space import Edit
from rei.search.spec import SearchSpec, parse_search_spec

SPEC = """\
name: fake
case: case.rei
seed: 1
budget: 3
sampler: random
parameters:
  - {object: bin1, floor: any}
  - {seed: [0, 100]}
objectives:
  - utility
"""


def spec(folder: Path, text: str = SPEC) -> SearchSpec:
    (folder / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    return parse_search_spec(text, base=folder, file="s.yaml")


def search(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, pool: FakePool, broken: tuple[str, ...] = (),
           text: str = SPEC) -> study.Search:
    out = tmp_path / "out"
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder: FakeMaker(folder, DIAGRAM, broken))
    return study.Search(spec(tmp_path, text), out, pool, threading.Event(), log=lambda _: None)


def constraints(trial: Any) -> list[float]:
    return [v for k, v in trial.system_attrs.items() if "constraint" in k]


def test_a_generator_failure_is_an_evaluation_in_error_not_an_infeasible_point(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    pool = FakePool(lambda text, seed, fault: [])
    s = search(tmp_path, monkeypatch, pool, broken=("random-0001",))
    progress = s.run()
    assert (progress.simulated, progress.errors, progress.invalid) == (3, 1, 0)
    assert len(pool.ran) == 2
    trial = s.study.trials[1]
    assert trial.state == TrialState.FAIL
    assert constraints(trial) == []  # not told as infeasible
    assert constraints(s.study.trials[0]) == [0.0]  # a simulated one is feasible
    record = records(s.study, s.out)[1]
    assert (record["status"], record["error"]) == ("ERROR", "random-0001 could not be generated (exit 1): disk full")
    assert not (s.out / "candidates" / "random-0001.rei").exists()


def test_the_real_maker_leaves_no_candidate_file_when_generation_fails(tmp_path: Path,
                                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    def no_server(*_: Any) -> Any:
        raise OSError("no warm JVM here")

    monkeypatch.setattr(candidates, "JarServer", no_server)
    monkeypatch.setattr(candidates, "run_jar", lambda *_, **__: JvmResult(1, 0.1, 0.1, "No space left on device"))
    maker = CandidateMaker.__new__(CandidateMaker)  # the engine is not needed to generate
    maker.out, maker._generator, maker._base_folder = tmp_path, None, tmp_path
    _, problem = maker.generate(Candidate("tpe-0001", Edit((), 0, None), VALID, "testcase T {}\n"))
    assert problem == "tpe-0001.rei could not be generated (exit 1): No space left on device"
    assert not (tmp_path / "candidates" / "tpe-0001.rei").exists()


ABSENT_SPEC = SPEC.replace("  - utility\n", "  - {metric: clearance_humans_min}\n  - utility\n")


def test_a_value_a_run_does_not_have_is_no_best_value(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # the fake runs have no metrics: no clearance to humans, scored 10^6 for the sampler but shown as absent
    lines: list[str] = []
    s = search(tmp_path, monkeypatch, FakePool(lambda text, seed, fault: []), text=ABSENT_SPEC)
    s.log = lines.append
    s.run()
    assert s.study.trials[0].values[0] == 1e6  # what the sampler is told
    assert lines and all("1e+06" not in line for line in lines)
    assert "metric:clearance_humans_min absent" in lines[-1]
    assert lines[-1].endswith("best metric:clearance_humans_min -, utility 10")
