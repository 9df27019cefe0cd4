# SPDX-License-Identifier: EPL-2.0
"""SIGTERM during the search loop: `rei search` exits 143 (128 + SIGTERM, as a supervisor that sent it expects),
not 130 (Ctrl-C's), and the journal it leaves resumes: the run that was starting is asked again first."""

from __future__ import annotations

import argparse
import os
import signal
import threading
from pathlib import Path
from typing import Any

import pytest
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

from rei.campaign.plan import RunTask
from rei.cli import search as cli_search
from rei.lifetime import sigterm_unwinds
from rei.search import run as search_run
from rei.search import study
from rei.search.spec import parse_search_spec

SPEC = """\
case: case.rei
sampler: random
seed: 2
budget: 4
parameters:
  - {seed: [0, 100]}
objectives:
  - utility
"""


class TerminatedPool(FakePool):
    """FakePool's runs; the process gets SIGTERM as run number ``at`` (from 1) is submitted."""

    def __init__(self, at: int) -> None:
        super().__init__(lambda *_: [])
        self.at = at

    def submit(self, task: RunTask) -> Any:
        if len(self.ran) + 1 == self.at:
            os.kill(os.getpid(), signal.SIGTERM)
            threading.Event().wait(5)  # the handler raises here
        return super().submit(task)


def fakes(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder, log=print, **_: FakeMaker(folder, DIAGRAM))


def make_search(tmp_path: Path, pool: FakePool) -> study.Search:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    spec = parse_search_spec(SPEC, base=tmp_path, file="s.yaml")
    return study.Search(spec, tmp_path / "out", pool, threading.Event(), log=lambda _: None)


def test_sigterm_stops_the_loop_with_143_and_the_journal_resumes(tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    fakes(monkeypatch)
    first = make_search(tmp_path, TerminatedPool(at=3))
    with sigterm_unwinds():
        progress = first.run()
    assert progress.interrupted == 128 + signal.SIGTERM and first.stop.is_set()
    # the third run was being submitted and the second (submitted before it) not yet told: both left running
    cut = [t for t in first.study.trials if t.state.name == "RUNNING"]
    assert cut and progress.simulated + len(cut) == 3
    resumed = make_search(tmp_path, FakePool(lambda *_: []))
    again = resumed.run()
    assert again.interrupted == 0 and again.simulated == 4
    simulated = [t for t in resumed.study.trials if t.user_attrs.get("simulated")]
    told_first = progress.simulated
    assert len(simulated) == 4  # the cut ones asked again first, in their order
    assert [t.params for t in simulated[told_first:told_first + len(cut)]] == [t.params for t in cut]


def test_rei_search_exits_143_after_sigterm_and_130_after_ctrl_c(tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    fakes(monkeypatch)
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    (tmp_path / "s.yaml").write_text(SPEC, encoding="utf-8")

    class Interrupting(FakePool):
        def submit(self, task: RunTask) -> Any:
            raise KeyboardInterrupt

    for pool, status in ((TerminatedPool(at=2), 143), (Interrupting(lambda *_: []), 130)):
        out = tmp_path / f"out{status}"
        monkeypatch.setattr(search_run, "make_pool", lambda *_, pool=pool: pool)
        args = argparse.Namespace(spec=tmp_path / "s.yaml", output=out, workers=1, ray=None, budget=None,
                                  sampler=None, no_shrink=False)
        assert cli_search.run(args) == status
        assert (out / "search.json").is_file()  # the outputs of what finished are written
