# SPDX-License-Identifier: EPL-2.0
"""The random baseline in the search's folder (run_search on the fake maker and pool of search_fakes): it keeps
the search's outputs and adds its own figures beside them, whichever of the two ran last; a random search alone in
its folder is that folder's search."""

from __future__ import annotations

import json
import threading
from pathlib import Path
from typing import Any

import pytest
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

import rei.search.run as search_run
from rei.search import study
from rei.search.run import run_search
from rei.search.spec import parse_search_spec

SPEC = """\
name: fake
case: case.rei
seed: 1
budget: 3
parameters:
  - {object: bin1, floor: any}
  - {seed: [0, 100]}
objectives:
  - utility
"""


def snapshot(out: Path) -> dict[str, bytes]:
    """The search's own outputs, besides search.json and search.html."""
    files = [out / "verdicts.xml", out / "shrunk.json", *sorted((out / "shrunk").rglob("*"))]
    return {str(p.relative_to(out)): p.read_bytes() for p in files if p.is_file()}


def without_baseline(out: Path) -> dict[str, Any]:
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    document.pop("baseline")
    return document


@pytest.fixture
def search(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Any:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder, **_: FakeMaker(folder, DIAGRAM))
    pools: list[FakePool] = []

    def make_pool(workers: int, ray: str | None, out: Path, stop: threading.Event) -> FakePool:
        pools.append(FakePool(lambda text, seed, fault: ["walker"] if seed < 50 else []))
        return pools[-1]

    monkeypatch.setattr(search_run, "make_pool", make_pool)

    def run(out: Path, **options: Any) -> tuple[dict[str, Any], int]:
        before = sum(len(p.ran) for p in pools)
        spec = parse_search_spec(SPEC, base=tmp_path, file="s.yaml").with_options(**options)
        document = run_search(spec, out, stop=threading.Event(), log=lambda _: None)
        return document, sum(len(p.ran) for p in pools) - before

    return run


def test_the_baseline_keeps_the_search_s_outputs_and_shows_beside_them(tmp_path: Path, search: Any) -> None:
    out = tmp_path / "out"
    tpe, _ = search(out)
    assert tpe["sampler"] == "tpe" and tpe["baseline"] is None and tpe["failures"][0]["shrunk"]["case"]
    kept, main = snapshot(out), without_baseline(out)

    baseline, ran = search(out, sampler="random", budget=4)
    assert ran == 4  # its own evaluations, no shrinking: a baseline is there to compare
    assert snapshot(out) == kept and without_baseline(out) == main  # the search's outputs as they were
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    assert document["sampler"] == "tpe" and document["budget"] == 3
    side = document["baseline"]
    assert side["sampler"] == "random" and side["budget"] == 4 and side["counts"]["simulated"] == 4
    assert [r["key"] for r in side["evaluations"]] == [f"random-{k:04d}" for k in range(4)]
    assert all(f["shrunk"] is None for f in side["failures"])
    # what `rei search` prints and exits with: the baseline's own figures
    assert baseline["counts"] == side["counts"] and baseline["failures"] == side["failures"]
    page = (out / "search.html").read_text(encoding="utf-8")
    assert "rei search fake (tpe)" in page and 'id="baseline"' in page
    assert "<th>search (tpe)</th><th>random baseline</th>" in page and "<td>budget</td><td>3</td><td>4</td>" in page

    _, ran = search(out)  # the search again, finished: nothing runs, its outputs show the baseline too
    assert ran == 0 and snapshot(out) == kept
    assert json.loads((out / "search.json").read_text(encoding="utf-8")) == document
    assert 'id="baseline"' in (out / "search.html").read_text(encoding="utf-8")


def test_a_random_search_alone_in_its_folder_is_the_folder_s_search(tmp_path: Path, search: Any) -> None:
    out = tmp_path / "out"
    document, _ = search(out, sampler="random")
    assert document["sampler"] == "random" and document["baseline"] is None
    assert json.loads((out / "search.json").read_text(encoding="utf-8"))["sampler"] == "random"
    assert (out / "verdicts.xml").is_file() and 'id="baseline"' not in (out / "search.html").read_text("utf-8")
