# SPDX-License-Identifier: EPL-2.0
"""The people's delay and detour metrics from sim.json's ``people`` (rei.sim.people.cost writes them)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rei.evaluation.metrics.compute import _cost_to_people


def _sim(tmp_path: Path, people: dict | None) -> Path:
    (tmp_path / "sim.json").write_text(json.dumps({"sim_time": 30.0, **({"people": people} if people else {})}))
    return tmp_path


def test_mean_and_largest_delay_over_the_people_who_have_one(tmp_path: Path) -> None:
    people = {"ann": {"delay": 1.5, "detour": 0.8, "censored": False},
              "bob": {"delay": 4.5, "detour": None, "censored": True},
              "cid": {"delay": None, "detour": None, "censored": False}}
    assert _cost_to_people(_sim(tmp_path, people)) == {
        "people_delay_mean": pytest.approx(3.0), "people_delay_max": 4.5, "people_detour_mean": pytest.approx(0.8)}


def test_no_people_who_see_the_robot_no_figures(tmp_path: Path) -> None:
    assert set(_cost_to_people(_sim(tmp_path, None)).values()) == {None}
    assert set(_cost_to_people(tmp_path / "missing").values()) == {None}
