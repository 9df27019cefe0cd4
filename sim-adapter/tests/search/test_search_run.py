# SPDX-License-Identifier: EPL-2.0
"""``rei search``'s lifetime: whatever stops it (an exception, Ctrl-C, SIGTERM), the workers are told to stop
before the pool waits for them, and SIGTERM unwinds instead of killing the process with its workers left running."""

from __future__ import annotations

import argparse
import os
import signal
import threading
import types
from pathlib import Path
from typing import Any

import pytest

import rei.search.run as search_run
import rei.search.spec as search_spec
from rei.cli import search as cli_search


class ClosingPool:
    name, workers = "fake", 1

    def __init__(self, stop: threading.Event) -> None:
        self.stop = stop
        self.stop_at_close: bool | None = None

    def close(self) -> None:
        self.stop_at_close = self.stop.is_set()


@pytest.mark.parametrize("raised", [KeyboardInterrupt, RuntimeError])
def test_the_workers_are_stopped_before_the_pool_waits_for_them(raised: type[BaseException], tmp_path: Path,
                                                                monkeypatch: pytest.MonkeyPatch) -> None:
    pools: list[ClosingPool] = []
    closed: list[bool] = []

    class FailingSearch:  # Ctrl-C while shrinking, or an exception while a candidate is made, after runs started
        def __init__(self, spec: Any, out: Path, pool: ClosingPool, stop: threading.Event, log: Any) -> None:
            self.pool = pool

        def run(self) -> Any:
            raise raised()

        def close(self) -> None:
            closed.append(True)

    def make_pool(workers: int, ray: str | None, out: Path, stop: threading.Event, router: bool = False,
                  people: bool = False) -> ClosingPool:
        pools.append(ClosingPool(stop))
        return pools[-1]

    monkeypatch.setattr(search_run, "Search", FailingSearch)
    monkeypatch.setattr(search_run, "make_pool", make_pool)
    spec = types.SimpleNamespace(humans=False, case=None, rooms=None, sut=None)  # what run_search reads itself
    with pytest.raises(raised):
        search_run.run_search(spec, tmp_path, ray="somewhere")  # type: ignore[arg-type]
    assert closed == [True]
    assert pools[0].stop_at_close is True


def test_sigterm_during_a_search_unwinds(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    reached: list[str] = []

    class Spec:
        source = None  # a spec from no file: nothing to compare with a search in OUT (rei.search.study.check_resume)

        def with_options(self, **_: Any) -> Spec:
            return self

    def run_search(*args: Any, **kwargs: Any) -> Any:
        if signal.getsignal(signal.SIGTERM) in (signal.SIG_DFL, signal.SIG_IGN, None):
            pytest.fail("SIGTERM would kill rei search on the spot, its workers left running")
        try:
            os.kill(os.getpid(), signal.SIGTERM)
            threading.Event().wait(5)  # the handler raises here
        finally:
            reached.append("finally")
        return None

    monkeypatch.setattr(search_spec, "load_search_spec", lambda path: Spec())
    monkeypatch.setattr(search_run, "run_search", run_search)
    args = argparse.Namespace(spec=tmp_path / "s.yaml", output=tmp_path / "out", workers=1, ray=None, budget=None,
                              sampler=None, no_shrink=False)
    with pytest.raises(SystemExit) as exit_:
        cli_search.run(args)
    assert exit_.value.code == 128 + signal.SIGTERM
    assert reached == ["finally"]
