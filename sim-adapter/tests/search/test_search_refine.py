# SPDX-License-Identifier: EPL-2.0
"""Encounter-guided refinement (rei.search.refine): which person's start moves, by how much, and when it is on."""

from __future__ import annotations

import itertools
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from optuna.distributions import CategoricalDistribution, FloatDistribution

from rei.evaluation.metrics.encounter import Encounter
from rei.search.refine import LEAST_SHIFT, enabled, refined
from rei.search.spec import load_search_spec

DISTRIBUTIONS = {"a.start": FloatDistribution(0, 900), "a.speed": FloatDistribution(0.3, 1.5),
                 "b.start": FloatDistribution(0, 900), "c.loop": CategoricalDistribution([True, False])}
PARAMS = {"a.start": 100.0, "a.speed": 1.0, "b.start": 50.0, "c.loop": True}


def test_the_nearest_person_not_met_yet_is_moved_by_the_shift() -> None:
    found = [Encounter("b", -3.0), Encounter("a", 40.0)]
    params, chosen = refined(PARAMS, DISTRIBUTIONS, found, met=set())
    assert chosen.human == "b" and params == {**PARAMS, "b.start": 47.0}
    params, chosen = refined(PARAMS, DISTRIBUTIONS, found, met={"b"})
    assert chosen.human == "a" and params == {**PARAMS, "a.start": 140.0}


def test_when_everyone_was_met_the_nearest_moves() -> None:
    found = [Encounter("a", 40.0), Encounter("b", -3.0)]
    _, chosen = refined(PARAMS, DISTRIBUTIONS, found, met={"a", "b"})
    assert chosen.human == "b"


def test_a_start_stays_in_its_range_and_a_step_that_cannot_move_is_skipped() -> None:
    params, _ = refined(PARAMS, DISTRIBUTIONS, [Encounter("b", -80.0)], met=set())
    assert params["b.start"] == 0.0
    at_edge = {**PARAMS, "b.start": 0.0}
    assert refined(at_edge, DISTRIBUTIONS, [Encounter("b", -80.0)], met=set()) is None
    # the edge blocks b, so a is moved instead
    _, chosen = refined(at_edge, DISTRIBUTIONS, [Encounter("b", -80.0), Encounter("a", 90.0)], set())
    assert chosen.human == "a"


def test_people_whose_start_is_not_searched_and_tiny_shifts_are_left_to_the_sampler() -> None:
    assert refined(PARAMS, DISTRIBUTIONS, [Encounter("c", 5.0)], met=set()) is None
    assert refined(PARAMS, DISTRIBUTIONS, [Encounter("a", LEAST_SHIFT / 2)], met=set()) is None
    assert refined(PARAMS, DISTRIBUTIONS, [], met=set()) is None


@pytest.mark.parametrize(("sampler", "objective", "refine", "on"), [
    ("tpe", "encounter_margin_humans", "true", True),
    ("nsga2", "encounter_margin_humans", "true", True),
    ("cmaes", "encounter_margin_humans", "true", False),  # CMA-ES would learn from points it did not draw
    ("tpe", "encounter_margin_humans, direction: maximize", "true", False),  # it moves people onto the robot
    ("tpe", "encounter_margin_humans", "false", False),
    ("random", "encounter_margin_humans", "true", False),  # a baseline's draws stay its own
    ("qmc", "encounter_margin_humans", "true", False),
    ("tpe", "clearance_humans_min", "true", False),  # it follows the margin's slope only
])
def test_it_is_on_for_learning_samplers_that_search_the_margin(tmp_path: Path, sampler: str, objective: str,
                                                               refine: str, on: bool) -> None:
    (tmp_path / "c.rei").write_text("", encoding="utf-8")
    spec_file = tmp_path / "s.yaml"
    spec_file.write_text(f"case: c.rei\nsampler: {sampler}\nrefine: {refine}\nparameters:\n"
                         f"  - {{human: walker, start: [0, 20]}}\nobjectives:\n  - {{metric: {objective}}}\n",
                         encoding="utf-8")
    assert enabled(load_search_spec(spec_file)) is on


def test_refine_must_be_a_boolean(tmp_path: Path) -> None:
    from rei.campaign.spec import SpecError

    (tmp_path / "c.rei").write_text("", encoding="utf-8")
    spec_file = tmp_path / "s.yaml"
    spec_file.write_text("case: c.rei\nrefine: often\nparameters:\n  - {human: walker, start: [0, 20]}\n"
                         "objectives:\n  - {metric: encounter_margin_humans}\n", encoding="utf-8")
    with pytest.raises(SpecError, match=r"s\.yaml:2:9"):
        load_search_spec(spec_file)


REFINE_SPEC = """\
name: fake
case: case.rei
seed: 1
budget: 12
sampler: tpe
parameters:
  - {human: walker, start: [0, 900]}
  - {seed: [0, 100]}
objectives:
  - {metric: encounter_margin_humans}
"""


def _search(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, meeting_of: Callable[[float], float]) -> Any:
    """A TPE search on the fake pool whose walker meets the robot when it sets off at ``meeting_of(start)``."""
    import json
    import threading

    from search_fakes import FakeMaker, FakePool
    from test_search_space import DIAGRAM

    from rei.search import study

    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    (tmp_path / "s.yaml").write_text(REFINE_SPEC, encoding="utf-8")
    monkeypatch.setattr(study, "CandidateMaker", lambda case, folder, log=print, **_: FakeMaker(folder, DIAGRAM))
    starts: dict[str, float] = {}

    class MeetingPool(FakePool):
        def submit(self, task):  # type: ignore[no-untyped-def]
            done = super().submit(task)
            case = json.loads((Path(task.case_dir) / "case.json").read_text(encoding="utf-8"))
            start = next(op["points"][0]["seconds"] for op in json.loads(case["text"])
                         if op.get("op") == "setTrajectory")
            starts[task.key] = start
            summary_file = Path(task.run_dir) / "summary.json"
            summary = json.loads(summary_file.read_text(encoding="utf-8"))
            summary["metrics"] = {"encounter_margin_humans": abs(start - meeting_of(start))}
            summary_file.write_text(json.dumps(summary), encoding="utf-8")
            return done

    def encounters(run_dir: Path, case_dir: Path) -> list[Encounter]:
        start = starts[run_dir.name]
        return [Encounter("walker", meeting_of(start) - start)]

    monkeypatch.setattr(study, "encounters", encounters)
    s = study.Search(load_search_spec(tmp_path / "s.yaml"), tmp_path / "out", MeetingPool(lambda *_: []),
                     threading.Event(), log=lambda _: None)
    s.run()
    return s


def test_a_refinement_runs_next_before_the_rest_of_the_design(tmp_path: Path,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    """A refinement is the next point asked after the one running beside it, not the design's next point."""
    from rei.search.design import sobol_design

    s = _search(tmp_path, monkeypatch, lambda start: 300.0)
    trials = s.study.trials
    design = sobol_design(s.space.distributions, 2, 1)
    # 0 and 1 are the design (1 was asked while 0 ran); 2 refines 0: the walker's start moved onto the meeting
    assert [t.params for t in trials[:2]] == design
    assert trials[2].user_attrs.get("refinement") == 1
    assert trials[2].params["walker.start"] == pytest.approx(300.0, abs=0.01)
    assert trials[2].params["seed"] == trials[0].params["seed"]
    assert trials[2].values[0] == pytest.approx(0.0, abs=0.01)
    asked_design = [t.params for t in trials if "design" in t.user_attrs]
    assert asked_design == design  # each design point asked once


def test_a_refinement_is_refined_again_up_to_its_depth(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A robot that reacts: the meeting moves half as far as the person does, so each step halves the margin."""
    from rei.search.refine import DEPTH

    s = _search(tmp_path, monkeypatch, lambda start: 300.0 + 0.5 * (start - 300.0))
    first = s.study.trials[0]
    chain = [first]
    for trial in s.study.trials[1:]:
        if trial.user_attrs.get("refinement") == len(chain) and trial.params["seed"] == first.params["seed"]:
            chain.append(trial)
    assert len(chain) == DEPTH + 1
    margins = [t.values[0] for t in chain]
    assert all(b == pytest.approx(a / 2, abs=0.01) for a, b in itertools.pairwise(margins))
    assert max(t.user_attrs.get("refinement", 0) for t in s.study.trials) == DEPTH


def test_a_refinement_left_waiting_at_the_budget_is_no_evaluation(tmp_path: Path,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """The halving robot leaves a refinement enqueued after the last run: the journal keeps it for a resume with a
    larger budget, search.json does not list it (it was never asked, let alone run or interrupted)."""
    from optuna.trial import TrialState

    from rei.search.outputs import counts, records

    s = _search(tmp_path, monkeypatch, lambda start: 300.0 + 0.5 * (start - 300.0))
    assert any(t.state == TrialState.WAITING for t in s.study.trials)
    found = records(s.study, s.out)
    assert len(found) == 12 and all(r["status"] == "COMPLETED" for r in found)
    assert counts(found)["interrupted"] == 0
