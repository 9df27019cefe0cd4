# SPDX-License-Identifier: EPL-2.0
"""Failures from a run's summary: which element and time a failed verdict is grouped by."""

from __future__ import annotations

from pathlib import Path

from rei.search.failures import failures_of


def test_the_element_comes_from_the_first_evidence_that_names_one(tmp_path: Path) -> None:
    # a verdict whose evidence opens with a timed line naming nothing: grouped by the object, not by '-'
    summary = {"verdicts": [{"requirement": "MISSION_SIMPLE", "status": "fail", "message": "collided", "evidence": [
        {"text": "the robot stopped", "t": 3.5}, {"text": "contact", "t": 4.25, "object": "bin1"},
        {"text": "contact", "t": 6.0, "object": "walker"}]}]}
    [failure] = failures_of(summary, tmp_path, tmp_path, lambda x, y: "F_0_0")
    assert (failure.element, failure.t) == ("bin1", 4.25)


def test_without_a_named_element_the_first_timed_evidence_places_it(tmp_path: Path) -> None:
    summary = {"verdicts": [{"requirement": "MISSION_SIMPLE", "status": "fail", "message": "late", "evidence": [
        {"text": "goal 1"}, {"text": "timeout", "t": 30.0}]}, {"requirement": "R2", "status": "pass"}]}
    [failure] = failures_of(summary, tmp_path, tmp_path, lambda x, y: "F_0_0")
    assert (failure.element, failure.t, failure.signature) == ("-", 30.0, "MISSION_SIMPLE/-/-")
