# SPDX-License-Identifier: EPL-2.0
"""verdicts.xml: one JUnit testsuite, one testcase per requirement, counts, evidence where CI shows it."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from rei.evaluation import REQUIREMENTS, Evaluator, replay
from rei.evaluation.junit import write_junit
from rei.evaluation.outcome import Evidence, Status, Verdict

from .traces import MISSION, MONITOR, WORLD, nominal


def test_verdicts_xml_structure_counts_and_evidence(tmp_path: Path) -> None:
    evaluator = Evaluator(tmp_path, mission_info=MISSION, monitor_config=MONITOR, world=WORLD)
    trace = nominal(collision_with="walker").at(16.0, "MONITOR_DATA_GAP", "mission", 2.0)
    replay(trace.messages, evaluator, run_id="run-1", sim_duration=20.0)
    root = ET.parse(tmp_path / "verdicts.xml").getroot()
    assert root.tag == "testsuite" and root.get("name") == "Case.M"
    # errors: MISSION_SEQUENCE (the mission stream's gap) and NO_ROBOT_AT_FAULT_COLLISION (no recorded state here
    # to tell who was at fault in the collision with the walker)
    assert [root.get(k) for k in ("tests", "failures", "errors", "skipped")] == ["7", "2", "2", "1"]
    properties = {p.get("name"): p.get("value") for p in root.iter("property")}
    assert properties["run_id"] == "run-1" and properties["total_utility"] == str(int(evaluator.total))
    cases = {c.get("name"): c for c in root.findall("testcase")}
    assert list(cases) == list(REQUIREMENTS)
    assert {c.get("classname") for c in cases.values()} == {"rei.requirements"}

    simple = cases["MISSION_SIMPLE"].find("failure")
    assert simple is not None and simple.get("message") == "1 collision(s), first with walker at t=12.500"
    line = "t=12.500 SIG_GEOM_CLOSE_TRANSIT_COLLISION walker task=1: collision with walker"
    assert line in (simple.text or "")
    human = cases["MISSION_WITH_HUMAN_TRAJECTORY"].find("failure")
    assert human is not None and "walker" in (human.text or "")
    fault = cases["NO_ROBOT_AT_FAULT_COLLISION"].find("error")
    assert fault is not None and "t=12.500 SIG_GEOM_CLOSE_TRANSIT_COLLISION walker task=1" in (fault.text or "")
    assert "cannot tell who was at fault" in (fault.text or "")
    sequence = cases["MISSION_SEQUENCE"].find("error")
    assert sequence is not None and "t=16.000 SIG_MONITOR_DATA_GAP mission" in (sequence.text or "")
    skipped = cases["MISSION_SEQUENCE_CYCLE"].find("skipped")
    assert skipped is not None and "not a back-and-forth cycle" in (skipped.get("message") or "")
    passed = cases["GEOM_CLOSE_LASER_CORRECT"]
    assert [child.tag for child in passed] == ["system-out"]
    assert "t=5.000 SIG_GEOM_FAR_TRANSIT_CLOSE table1" in (passed.findtext("system-out") or "")


def test_characters_xml_can_not_carry_are_replaced(tmp_path: Path) -> None:
    verdict = Verdict("MISSION_SEQUENCE", Status.FAIL, "bad\x00reason", (Evidence("ctrl\x1b[0m", 1.0),))
    path = write_junit(tmp_path / "v.xml", [verdict], suite="s", properties={"run_id": "r\x07"})
    failure = ET.parse(path).getroot().find("testcase/failure")
    assert failure is not None and failure.get("message") == "bad\ufffdreason"
    assert "ctrl\ufffd[0m" in (failure.text or "")
