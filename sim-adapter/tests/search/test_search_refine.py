# SPDX-License-Identifier: EPL-2.0
"""Encounter-guided refinement (rei.search.refine): which person's start moves, by how much, and when it is on."""

from __future__ import annotations

from pathlib import Path

import pytest
from optuna.distributions import CategoricalDistribution, FloatDistribution

from rei.evaluation.metrics.encounter import Encounter
from rei.search.refine import LEAST_SHIFT, enabled, refined
from rei.search.spec import load_search_spec

DISTRIBUTIONS = {"a.start": FloatDistribution(0, 900), "a.speed": FloatDistribution(0.3, 1.5),
                 "b.start": FloatDistribution(0, 900), "c.loop": CategoricalDistribution([True, False])}
PARAMS = {"a.start": 100.0, "a.speed": 1.0, "b.start": 50.0, "c.loop": True}


def test_the_nearest_person_not_met_yet_is_moved_by_the_shift() -> None:
    found = [Encounter("b", 3.0, -3.0), Encounter("a", 40.0, 40.0)]
    params, chosen = refined(PARAMS, DISTRIBUTIONS, found, met=set())
    assert chosen.human == "b" and params == {**PARAMS, "b.start": 47.0}
    params, chosen = refined(PARAMS, DISTRIBUTIONS, found, met={"b"})
    assert chosen.human == "a" and params == {**PARAMS, "a.start": 140.0}


def test_when_everyone_was_met_the_nearest_moves() -> None:
    found = [Encounter("a", 40.0, 40.0), Encounter("b", 3.0, -3.0)]
    _, chosen = refined(PARAMS, DISTRIBUTIONS, found, met={"a", "b"})
    assert chosen.human == "b"


def test_a_start_stays_in_its_range_and_a_step_that_cannot_move_is_skipped() -> None:
    params, _ = refined(PARAMS, DISTRIBUTIONS, [Encounter("b", 80.0, -80.0)], met=set())
    assert params["b.start"] == 0.0
    at_edge = {**PARAMS, "b.start": 0.0}
    assert refined(at_edge, DISTRIBUTIONS, [Encounter("b", 80.0, -80.0)], met=set()) is None
    # the edge blocks b, so a is moved instead
    _, chosen = refined(at_edge, DISTRIBUTIONS, [Encounter("b", 80.0, -80.0), Encounter("a", 90.0, 90.0)], set())
    assert chosen.human == "a"


def test_people_whose_start_is_not_searched_and_tiny_shifts_are_left_to_the_sampler() -> None:
    assert refined(PARAMS, DISTRIBUTIONS, [Encounter("c", 5.0, 5.0)], met=set()) is None
    assert refined(PARAMS, DISTRIBUTIONS, [Encounter("a", LEAST_SHIFT / 2, LEAST_SHIFT / 2)], met=set()) is None
    assert refined(PARAMS, DISTRIBUTIONS, [], met=set()) is None


@pytest.mark.parametrize(("sampler", "objective", "refine", "on"), [
    ("tpe", "encounter_margin_humans", "true", True),
    ("nsga2", "encounter_margin_humans", "true", True),
    ("cmaes", "encounter_margin_humans", "true", True),
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
