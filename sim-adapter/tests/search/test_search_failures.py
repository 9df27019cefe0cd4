# SPDX-License-Identifier: EPL-2.0
"""Failures from a run's summary: a distinct failure is an event (what happened, with whom, where) with every
requirement it violates, not one per failed requirement; verdicts.xml has one test case per event."""

from __future__ import annotations

import json
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest

from rei.evaluation.junit import write_junit
from rei.evaluation.outcome import Status
from rei.search.failures import OldRecordError, distinct, events_of, failure_verdicts, failures_of
from rei.wamp.recording import RecordingWriter, stream_path

ROOM = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"  # floors 2 m wide: F_0_0 at (1, 1), ...
MS, MWHT, SEQ = "MISSION_SIMPLE", "MISSION_WITH_HUMAN_TRAJECTORY", "MISSION_SEQUENCE"
COLLISION_LASER = "GEOM_COLLISION_LASER_CORRECT"


def collision(t: float, obj: str, *, human: bool = False) -> dict[str, Any]:
    """A collision as verdicts.py writes its evidence: the robot's entry (MISSION_SIMPLE) or the object's own
    (MISSION_WITH_HUMAN_TRAJECTORY)."""
    if human:
        return {"text": f"human collision with {obj} at t={t:.3f} during task 0", "t": t,
                "signal": "SIG_OBJECT_COLLISION_BEGIN", "object": obj, "task": 0}
    return {"text": f"collision with {obj} at t={t:.3f} during task 0", "t": t,
            "signal": "SIG_GEOM_CLOSE_TRANSIT_COLLISION", "object": obj, "task": 0}


def fail(requirement: str, message: str, *evidence: dict[str, Any]) -> dict[str, Any]:
    return {"requirement": requirement, "status": "fail", "message": message, "evidence": list(evidence)}


def run_folder(folder: Path, *verdicts: dict[str, Any], utilities: dict[str, Any] | None = None) -> Path:
    """A search run folder: the robot drives along y = 1 at 1 m/s from x = 0.5 (on F_0_0 until t = 1.5, then F_1_0,
    from t = 3.5 F_2_0), the fixture room as its case (task.json names it), summary.json with ``verdicts``."""
    run, case = folder / "runs" / "tpe-0001", folder / "cases" / "tpe-0001"
    run.mkdir(parents=True)
    shutil.copytree(ROOM, case)
    with RecordingWriter(stream_path(run, "state")) as writer:
        for i in range(121):
            t = i / 20
            writer.write({"seq": i, "t": t, "full": i == 0, "objects": [], "contacts": [],
                          "robot": {"name": "tb3", "pose": [0.5 + t, 1.0, 0.0, 0.0], "twist": [1.0, 0.0, 0.0]}})
    (run / "task.json").write_text(json.dumps({"case_dir": str(case)}), encoding="utf-8")
    (run / "summary.json").write_text(json.dumps({"verdicts": list(verdicts)}), encoding="utf-8")
    if utilities is not None:
        (run / "utilities.json").write_text(json.dumps(utilities), encoding="utf-8")
    return run


def floor_at(x: float, y: float) -> str:
    return f"F_{int(x // 2)}_{int(y // 2)}"


def events(run: Path) -> list[Any]:
    summary = json.loads((run / "summary.json").read_text(encoding="utf-8"))
    return failures_of(summary, run, Path(json.loads((run / "task.json").read_text())["case_dir"]), floor_at)


def test_one_collision_that_fails_two_requirements_is_one_distinct_failure_listing_both(tmp_path: Path) -> None:
    # issue #37: the crossing's every human collision was MISSION_SIMPLE/walker/F_2_1 and
    # MISSION_WITH_HUMAN_TRAJECTORY/walker/F_2_1, two distinct failures of one event
    run = run_folder(tmp_path, fail(MS, "1 collision(s), first with walker at t=2.000", collision(2.0, "walker")),
                     fail(MWHT, "1 collision(s) with humans, not fewer than N_COLLISION = 1",
                          collision(2.0, "walker", human=True)))
    [failure] = events(run)
    assert failure.signature == "COLLISION/walker/F_1_0"
    assert failure.requirements == (MS, MWHT) and failure.t == 2.0
    assert failure.what == "collision with walker at t=2.000 during task 0"
    assert MS in failure.message and MWHT in failure.message
    # two evaluations with that collision: one distinct failure, found twice, listing both requirements
    records = [{"key": key, "utility": -10.0, "failures": [failure.to_dict()]} for key in ("tpe-0001", "tpe-0002")]
    [group] = distinct(records)
    assert (group.failure.signature, group.keys, group.requirements) == (
        "COLLISION/walker/F_1_0", ["tpe-0001", "tpe-0002"], (MS, MWHT))
    # verdicts.xml: one test case for the event, its message naming both requirements
    write_junit(tmp_path / "v.xml", failure_verdicts([group], {}), suite="s", properties={})
    [case] = ET.parse(tmp_path / "v.xml").getroot().iter("testcase")
    assert case.get("name") == "COLLISION/walker/F_1_0"
    message = case.find("failure").get("message")  # type: ignore[union-attr]
    assert f"fails {MS}, {MWHT}" in message and "collision with walker at t=2.000" in message, message


def test_each_collision_of_a_run_is_an_event_placed_where_it_began(tmp_path: Path) -> None:
    # pushed by the walker, the robot then hits a wall: two events, the wall's only a MISSION_SIMPLE failure;
    # the walker's later contacts in the run are the same event, placed at the first
    run = run_folder(tmp_path, fail(MS, "3 collision(s)", collision(1.0, "walker"), collision(2.5, "walker"),
                                    collision(4.0, "W_2_0_bottom")),
                     fail(MWHT, "2 collision(s) with humans", collision(1.0, "walker", human=True),
                          collision(2.5, "walker", human=True)))
    assert [(f.signature, f.requirements, f.t) for f in events(run)] == [
        ("COLLISION/walker/F_0_0", (MS, MWHT), 1.0), ("COLLISION/W_2_0_bottom/F_2_0", (MS,), 4.0)]


def test_a_failure_without_event_evidence_is_an_event_of_its_own_kind(tmp_path: Path) -> None:
    # the pushed robot's planner reports a goal it did not reach: MISSION_SEQUENCE's evidence is a task's failure,
    # no zone entry; it is its own event, not merged into the collision
    feedback = {"text": "task 0: no correct feedback from the robot: TASK_FAIL at t=4.500 (false success)", "t": 4.5,
                "signal": "SIG_MISSION_TASK_FAIL", "object": "task_0", "task": 0}
    run = run_folder(tmp_path, fail(MS, "1 collision(s)", collision(1.0, "walker")),
                     fail(SEQ, "1 goal(s) without correct feedback", feedback),
                     fail(MWHT, "1 collision(s) with humans", collision(1.0, "walker", human=True)))
    assert [(f.signature, f.requirements) for f in events(run)] == [
        ("COLLISION/walker/F_0_0", (MS, MWHT)), ("MISSION_SEQUENCE/task_0/F_2_0", (SEQ,))]


def test_the_laser_missing_the_collision_is_the_same_event_a_false_alarm_is_another(tmp_path: Path) -> None:
    missed = {"text": "missed: geometry COLLISION with walker from t=2.000 to 2.400, but the laser did not reach "
                      "COLLISION within 0.5 s of it", "t": 2.0, "signal": "SIG_GEOM_CLOSE_TRANSIT_COLLISION",
              "object": "walker"}
    alarm = {"text": "false alarm: the laser reported COLLISION from t=4.000 to 4.200 with no geometric COLLISION",
             "t": 4.0, "signal": "SIG_LASER_CLOSE_TRANSIT_COLLISION", "object": "table1"}
    gap = {"text": "the monitor lost 3 state message(s) before this time", "t": 3.0, "signal": "SIG_MONITOR_DATA_GAP",
           "object": ""}
    run = run_folder(tmp_path, fail(COLLISION_LASER, "1 missed, 1 false alarm(s)", missed, alarm),
                     fail(MS, "1 collision(s)", collision(2.0, "walker"), gap))
    found = events(run)
    assert [(f.signature, f.requirements) for f in found] == [
        ("COLLISION/walker/F_1_0", (COLLISION_LASER, MS)), ("LASER_COLLISION/table1/F_2_0", (COLLISION_LASER,))]
    assert found[0].what == "collision with walker at t=2.000 during task 0"  # what happened, not what was measured


def test_a_zone_entry_the_user_s_patterns_declare_is_an_event(tmp_path: Path) -> None:
    # the run's own patterns declare SIG_BUMP as the robot's entry into COLLISION (utilities.json, as the monitor
    # writes it): its evidence is the collision, grouped with the per-object signal of the same contact
    bump = {**collision(2.0, "walker"), "signal": "SIG_BUMP"}
    run = run_folder(tmp_path, fail(MS, "1 collision(s)", bump),
                     fail(MWHT, "1 collision(s) with humans", collision(2.0, "walker", human=True)),
                     utilities={"SIG_BUMP": {"utility": -10, "transition": {"source": "GEOM", "from": "CLOSE",
                                                                          "to": "COLLISION"}}})
    assert [(f.signature, f.requirements) for f in events(run)] == [("COLLISION/walker/F_1_0", (MS, MWHT))]


def test_the_element_comes_from_the_first_evidence_that_names_one(tmp_path: Path) -> None:
    # a verdict with no event evidence whose evidence opens with a timed line naming nothing: grouped by the
    # object, not by '-'
    summary = {"verdicts": [{"requirement": "MISSION_SIMPLE", "status": "fail", "message": "collided", "evidence": [
        {"text": "the robot stopped", "t": 3.5}, {"text": "contact", "t": 4.25, "object": "bin1"},
        {"text": "contact", "t": 6.0, "object": "walker"}]}]}
    [failure] = failures_of(summary, tmp_path, tmp_path, lambda x, y: "F_0_0")
    assert (failure.kind, failure.element, failure.t) == ("MISSION_SIMPLE", "bin1", 4.25)


def test_without_a_named_element_the_first_timed_evidence_places_it(tmp_path: Path) -> None:
    summary = {"verdicts": [{"requirement": "MISSION_SIMPLE", "status": "fail", "message": "late", "evidence": [
        {"text": "goal 1"}, {"text": "timeout", "t": 30.0}]}, {"requirement": "R2", "status": "pass"}]}
    [failure] = failures_of(summary, tmp_path, tmp_path, lambda x, y: "F_0_0")
    assert (failure.element, failure.t, failure.signature) == ("-", 30.0, "MISSION_SIMPLE/-/-")


def old_records(*requirements: str) -> list[dict[str, Any]]:
    """Failures as a journal of an earlier rei search has them: one per failed requirement."""
    return [{"requirement": r, "element": "walker", "place": "F_1_0", "t": 2.0, "message": "hit",
             "signature": f"{r}/walker/F_1_0"} for r in requirements]


def test_an_evaluation_recorded_per_requirement_is_found_again_as_events_from_its_run(tmp_path: Path) -> None:
    run = run_folder(tmp_path, fail(MS, "1 collision(s)", collision(2.0, "walker")),
                     fail(MWHT, "1 collision(s) with humans", collision(2.0, "walker", human=True)))
    found = events_of(old_records(MS, MWHT), run)  # placed on the case's own floors (world.json)
    assert [(f["signature"], f["requirements"]) for f in found] == [("COLLISION/walker/F_1_0", [MS, MWHT])]
    assert events_of(found, run) == found  # events are kept as recorded


def test_an_evaluation_recorded_per_requirement_without_its_run_is_refused(tmp_path: Path) -> None:
    with pytest.raises(OldRecordError, match=r"recorded by an earlier rei search, one failure per requirement.*"
                                             r"give a new -o OUT"):
        events_of(old_records(MS, MWHT), tmp_path / "runs" / "tpe-0009")


def test_verdicts_xml_has_one_test_case_when_nothing_was_found(tmp_path: Path) -> None:
    write_junit(tmp_path / "v.xml", failure_verdicts([], {}, 12), suite="s", properties={})
    [case] = ET.parse(tmp_path / "v.xml").getroot().iter("testcase")
    assert case.get("name") == "no failure found" and list(case) == []  # passing: no failure or error element
    assert failure_verdicts([], {}, 12)[0].message == "no failure found in 12 evaluation(s)"


@pytest.mark.parametrize(("simulated", "errors"), [(12, 3), (0, 0)])
def test_nothing_found_with_runs_in_error_vouches_for_nothing(simulated: int, errors: int) -> None:
    [verdict] = failure_verdicts([], {}, simulated, errors)
    assert verdict.status == Status.ERROR
