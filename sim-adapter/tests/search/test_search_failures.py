# SPDX-License-Identifier: EPL-2.0
"""Failures from a run's summary: which element and time a failed verdict is grouped by."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rei.evaluation.junit import write_junit
from rei.evaluation.outcome import Status
from rei.search.failures import failure_verdicts, failures_of


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


def test_verdicts_xml_has_one_test_case_when_nothing_was_found(tmp_path: Path) -> None:
    write_junit(tmp_path / "v.xml", failure_verdicts([], {}, 12), suite="s", properties={})
    [case] = ET.parse(tmp_path / "v.xml").getroot().iter("testcase")
    assert case.get("name") == "no failure found" and list(case) == []  # passing: no failure or error element
    assert failure_verdicts([], {}, 12)[0].message == "no failure found in 12 evaluation(s)"


@pytest.mark.parametrize(("simulated", "errors"), [(12, 3), (0, 0)])
def test_nothing_found_with_runs_in_error_vouches_for_nothing(simulated: int, errors: int) -> None:
    [verdict] = failure_verdicts([], {}, simulated, errors)
    assert verdict.status == Status.ERROR
