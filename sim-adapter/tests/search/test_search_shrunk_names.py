# SPDX-License-Identifier: EPL-2.0
"""Shrunk cases are named by the failure, not by its rank: a search resumed with a larger budget that finds a new
failure more often than an old one ranks it first, and each failure keeps its own shrunk case, runs, shrunk.json
entry and verdicts.xml line (run_search on the fake maker and pool of search_fakes)."""

from __future__ import annotations

import json
import threading
import xml.etree.ElementTree as ET
from concurrent.futures import Future
from pathlib import Path
from typing import Any

import pytest
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

import rei.search.run as search_run
from rei.campaign.plan import RunTask
from rei.campaign.supervise import Outcome
from rei.search import study
from rei.search.run import run_search
from rei.search.shrink import failure_id
from rei.search.spec import parse_search_spec

SPEC = """\
name: fake
case: case.rei
seed: 1
budget: 1
sampler: random
shrink: {budget: 3}
parameters:
  - {object: bin1, floor: any}
  - {seed: [0, 100]}
objectives:
  - utility
"""
OLD, NEW = "R1/old/-", "R1/new/-"


class KeyedPool(FakePool):
    """The first evaluation fails on ``old``, every later one on ``new``; a shrinking step fails as the failure it
    shrinks (its key names the failure)."""

    def __init__(self) -> None:
        super().__init__(lambda text, seed, fault: [])

    def submit(self, task: RunTask) -> Future[Outcome]:
        if task.key.startswith("shrink-"):
            element = "old" if failure_id(OLD) in task.key else "new"
        else:
            element = "old" if task.key == "random-0000" else "new"
        self.rule = lambda text, seed, fault: [element]
        return super().submit(task)


def test_a_resumed_search_keeps_each_failure_s_shrunk_case(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder, **_: FakeMaker(folder, DIAGRAM))
    monkeypatch.setattr(search_run, "make_pool", lambda workers, ray, out, stop: KeyedPool())
    out = tmp_path / "out"

    def search(budget: int) -> dict[str, Any]:
        spec = parse_search_spec(SPEC, base=tmp_path, file="s.yaml").with_options(budget=budget)
        return run_search(spec, out, stop=threading.Event(), log=lambda _: None)

    first = search(1)
    assert [f["signature"] for f in first["failures"]] == [OLD]
    old_case = Path(first["failures"][0]["shrunk"]["case"])
    old_text = old_case.read_text(encoding="utf-8")
    old_runs = sorted(p.name for p in (out / "shrunk" / "runs").iterdir())
    assert old_case == out / "shrunk" / f"{failure_id(OLD)}.rei"
    assert old_runs and all(name.startswith(failure_id(OLD)) for name in old_runs)

    second = search(4)
    assert [f["signature"] for f in second["failures"]] == [NEW, OLD]  # the new one is found more often: first
    shrunk = json.loads((out / "shrunk.json").read_text(encoding="utf-8"))
    assert shrunk[OLD]["case"] == str(old_case) and old_case.read_text(encoding="utf-8") == old_text
    new_case = Path(shrunk[NEW]["case"])
    assert new_case == out / "shrunk" / f"{failure_id(NEW)}.rei" and new_case.is_file()
    runs = sorted(p.name for p in (out / "shrunk" / "runs").iterdir())
    assert [r for r in runs if r.startswith(failure_id(OLD))] == old_runs  # the old failure's runs untouched
    assert any(r.startswith(failure_id(NEW)) for r in runs)
    for run in (shrunk[OLD]["run"], shrunk[NEW]["run"]):  # each shrunk.json entry names a run of its own failure
        failed = json.loads((Path(run) / "summary.json").read_text(encoding="utf-8"))["verdicts"]
        assert [v["evidence"][0]["object"] for v in failed] == ["old" if run == shrunk[OLD]["run"] else "new"]
    cases = {c.get("name"): c.find("failure").get("message") for c in ET.parse(out / "verdicts.xml").iter("testcase")}
    # each reproduce line runs its own failure's shrunk case
    assert old_case.name in cases[OLD] and new_case.name not in cases[OLD]
    assert new_case.name in cases[NEW] and old_case.name not in cases[NEW]


def test_failure_ids_are_file_names_that_keep_signatures_apart() -> None:
    assert failure_id("MISSION_SIMPLE/walker/F_2_1").startswith("MISSION_SIMPLE-walker-F_2_1-")
    assert failure_id("R/a b\\c/-") .startswith("R-a_b_c-_-") and "/" not in failure_id("R/../x")
    assert failure_id("R/a_b/c") != failure_id("R/a/b_c") != failure_id("R/a b/c")
    assert failure_id(OLD) == failure_id("R1/old/-")  # the same in every invocation
