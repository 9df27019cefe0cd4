# SPDX-License-Identifier: EPL-2.0
"""Resuming a search (an OUT with a study) with a spec that searches something else is refused at what changed,
in the given spec's file, before anything runs: its spec.yaml was overwritten silently and the old trials lacked the
new parameters. The same spec reformatted, another budget, sampler, shrink budget or name resume."""

from __future__ import annotations

import dataclasses
import threading
from pathlib import Path

import pytest
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

from rei.campaign.spec import SpecError
from rei.search import study
from rei.search.spec import load_search_spec

SPEC = """\
case: case.rei
seed: 1
budget: 2
sampler: random
parameters:
  - {object: bin1, floor: any}
  - {human: walker, start: [0, 10], speed: [0.5, 1.5]}
  - {seed: [0, 100]}
objectives:
  - utility
"""

REFORMATTED = """\
# the same search, written otherwise
case: ./case.rei
sampler: random
seed: 1
budget: 5            # a larger budget continues it
shrink: {budget: 2}
name: renamed
parameters:
  - seed: [0, 100]
  - human: walker
    speed: [0.5, 1.5]
    start: [0.0, 10.0]
  - {object: bin1, floor: any}
objectives:
  - {utility: minimize}
"""

ADVICE = ("a changed spec is another search: give a new -o OUT, or restore the spec as {out}/spec.yaml has it to "
          "resume (budget, sampler, shrink and name may change)")


@pytest.fixture
def started(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A folder with the base case and an OUT where a 2-evaluation search of SPEC ran (fake maker and pool)."""
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder, log=print, **_: FakeMaker(folder, DIAGRAM))
    assert run(tmp_path, SPEC).simulated == 2
    return tmp_path


def run(folder: Path, text: str, name: str = "s.yaml", out: str = "out") -> study.SearchProgress:
    (folder / name).write_text(text, encoding="utf-8")
    search = study.Search(load_search_spec(folder / name), folder / out, FakePool(lambda *_: []),
                          threading.Event(), log=lambda _: None)
    return search.run()


def refusal(folder: Path, text: str) -> str:
    with pytest.raises(SpecError) as raised:
        run(folder, text, "edited.yaml")
    return str(raised.value)


def test_the_same_spec_reformatted_renamed_and_with_a_larger_budget_resumes(started: Path) -> None:
    assert run(started, REFORMATTED, "other.yaml").simulated == 5
    assert (started / "out" / "spec.yaml").read_text(encoding="utf-8") == REFORMATTED
    assert run(started, SPEC.replace("sampler: random", "sampler: nsga2")).simulated == 2  # a study of its own


@pytest.mark.parametrize(("change", "expected"), [
    (("start: [0, 10]", "start: [0, 20]"), ("edited.yaml:7:28: this OUT holds a search started with another spec: "
                                           "walker.start is [0, 20] here, [0, 10] there")),
    (("  - {seed: [0, 100]}\n", "  - {seed: [0, 100]}\n  - {robot: tb3, floor: any}\n"),
     "edited.yaml:9:25: this OUT holds a search started with another spec: tb3.floor is searched here, not there"),
    (("  - {object: bin1, floor: any}\n", ""),
     "edited.yaml:6:3: this OUT holds a search started with another spec: bin1.floor is searched there, not here"),
    (("  - utility\n", "  - utility\n  - {metric: clearance_humans_min}\n"),
     ("edited.yaml:10:3: this OUT holds a search started with another spec: the objectives are utility (minimize), "
     "metric:clearance_humans_min (minimize) here, utility (minimize) there")),
    (("seed: 1", "seed: 7"), ("edited.yaml:2:7: this OUT holds a search started with another spec: seed is 7 here, "
                             "1 there")),
    (("budget: 2\n", "budget: 2\nhumans: false\ntimeout: 60\n"),
     ("edited.yaml:5:10: this OUT holds a search started with another spec: timeout is 60 here, 300 there "
     "(and 1 more change(s))")),
])
def test_an_edited_spec_is_refused_at_what_changed(started: Path, change: tuple[str, str], expected: str) -> None:
    assert SPEC.count(change[0]) == 1
    assert refusal(started, SPEC.replace(*change)) == f"{started}/{expected}; {ADVICE.format(out=started / 'out')}"
    assert (started / "out" / "spec.yaml").read_text(encoding="utf-8") == SPEC  # the started search's, kept


def test_rei_search_refuses_an_edited_spec_before_anything_runs(started: Path,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    from rei.cli import main

    (started / "edited.yaml").write_text(SPEC.replace("seed: 1", "seed: 7"), encoding="utf-8")
    journal = (started / "out" / "study.journal").read_bytes()
    assert main(["search", str(started / "edited.yaml"), "-o", str(started / "out"), "--budget", "4"]) == 2
    assert capsys.readouterr().err == (f"rei: error: {started / 'edited.yaml'}:2:7: this OUT holds a search started "
                                       f"with another spec: seed is 7 here, 1 there; "
                                       f"{ADVICE.format(out=started / 'out')}\n")
    assert (started / "out" / "study.journal").read_bytes() == journal


def test_a_new_out_starts_another_search(started: Path) -> None:
    assert run(started, SPEC.replace("seed: 1", "seed: 7"), "edited.yaml", out="new").simulated == 2


MAPPINGS = """\
rooms: {size: small, density: sparse, humans: 1, seed: 0}
sut: {command: "rei nav-sut"}
parameters:
  - {object: bin1, floor: [F_1_0, F_2_0]}
objectives:
  - utility
"""


@pytest.mark.parametrize(("change", "expected"), [
    (("", ""), None),
    (("rooms: {size: small, density: sparse, humans: 1, seed: 0}",
      "rooms:\n  seed: 0\n  humans: 1\n  size: small\n  density: sparse"), None),  # the same, written otherwise
    (("seed: 0}", "seed: 3}"), "s.yaml:1:8: this OUT holds a search started with another spec: rooms is another here"),
    (('"rei nav-sut"', '"rei nav-sut --fast"'),
     "s.yaml:2:6: this OUT holds a search started with another spec: sut is another here"),
    (("[F_1_0, F_2_0]", "any"),
     "s.yaml:4:27: this OUT holds a search started with another spec: bin1.floor is any here, [F_1_0, F_2_0] there"),
])
def test_generated_rooms_and_an_external_sut_are_compared_by_their_settings(
        tmp_path: Path, change: tuple[str, str], expected: str | None) -> None:
    from rei.search.spec import check_resumable, parse_search_spec

    given = dataclasses.replace(parse_search_spec(MAPPINGS.replace(*change), base=tmp_path, file="s.yaml"),
                                source=tmp_path / "s.yaml")
    if expected is None:
        check_resumable(given, MAPPINGS, "out/spec.yaml")
        return
    with pytest.raises(SpecError) as raised:
        check_resumable(given, MAPPINGS, "out/spec.yaml")
    assert str(raised.value) == f"{expected}; {ADVICE.format(out='out')}"
