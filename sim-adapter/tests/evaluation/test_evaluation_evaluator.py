# SPDX-License-Identifier: EPL-2.0
"""The Evaluator: events.csv row by row, summary.json, verdicts.xml, stream problems, threads."""

from __future__ import annotations

import csv
import json
import threading
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest

from rei.evaluation import COLUMNS, Evaluator, MissionInfo, Status, load_utilities, replay
from rei.evaluation.log import format_number

from .traces import MISSION, MONITOR, WORLD, TraceBuilder, nominal


def _evaluator(out: Path, **kwargs: Any) -> Evaluator:
    options: dict[str, Any] = {"mission_info": MISSION, "monitor_config": MONITOR, "world": WORLD, **kwargs}
    return Evaluator(out, **options)


def test_events_csv_has_exact_rows_flushed_before_finish(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path)
    b = TraceBuilder().begin().geom(5.25, "FAR_TRANSIT_CLOSE", "table1").at(6.0, "SIG_NEW_THING", "y")
    events = tmp_path / "events.csv"
    assert events.read_text() == "t,signal,utility,total,subject,object\n"
    for message in b.messages[:2]:
        evaluator.on_signal(message)
    assert events.read_text() == ("t,signal,utility,total,subject,object\n"
                                  "0.000000,SIG_MISSION_BEGIN,20,20,tb3,mission\n"
                                  "0.000000,SIG_MISSION_TASK_START,5,25,tb3,task_0\n")
    for message in b.messages[2:]:
        evaluator.on_signal(message)
    rows = list(csv.reader(events.open()))
    assert tuple(rows[0]) == COLUMNS
    assert rows[3:] == [["5.250000", "SIG_GEOM_FAR_TRANSIT_CLOSE", "-2", "23", "tb3", "table1"],
                        ["6.000000", "SIG_NEW_THING", "0", "23", "tb3", "y"]]
    assert evaluator.total == 23
    assert evaluator.utility_over_time == [(0.0, 20.0), (0.0, 25.0), (5.25, 23.0), (6.0, 23.0)]
    summary = evaluator.finish(status="COMPLETED", reason=None, sim_duration=7.0, wall_time=1.0, run_id="r1")
    assert summary.unknown_signals == {"SIG_NEW_THING": 1}
    assert len(events.read_text().splitlines()) == 5


def test_format_number() -> None:
    assert [format_number(v) for v in (-10.0, 0.0, 0.5, -1.25, 1e20)] == [
        "-10", "0", "0.5", "-1.25", "100000000000000000000"]


def test_summary_json_has_totals_counts_tasks_and_verdicts(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path, utilities=load_utilities(None))
    evaluator.on_mission({"seq": 0, "t": 10.0, "event": "TASK_FAIL", "task_index": 0, "goal": [4.5, 0.5, 0.0],
                          "reason": "planner failure: aborted"})
    messages = TraceBuilder().begin().task(10.0, 0, "FAIL").end(20.0).messages
    summary = replay(messages, evaluator, sim_duration=20.5, wall_time=2.5, run_id="run-7")
    data = json.loads((tmp_path / "summary.json").read_text())
    assert data["format"] == "rei-summary/1"
    assert (data["mission"], data["testcase"], data["run_id"], data["status"], data["error"]) == (
        "M", "Case", "run-7", "COMPLETED", None)
    assert (data["sim_duration"], data["wall_time"]) == (20.5, 2.5)
    assert data["total_utility"] == 20 + 5 - 100 + 5 + 10 + 20 == summary.total_utility
    assert data["counts"] == {"SIG_MISSION_BEGIN": 1, "SIG_MISSION_END": 1, "SIG_MISSION_TASK_FAIL": 1,
                              "SIG_MISSION_TASK_START": 2, "SIG_MISSION_TASK_SUCCESS": 1}
    assert data["tasks"]["goals"] == 2
    assert (data["tasks"]["started"], data["tasks"]["succeeded"], data["tasks"]["failed"]) == (2, 1, 1)
    assert data["tasks"]["list"][0] == {"index": 0, "outcome": "FAIL", "started": 0.0, "ended": 10.0,
                                        "reason": "planner failure: aborted"}
    verdicts = {v["requirement"]: v for v in data["verdicts"]}
    assert verdicts["MISSION_SEQUENCE"]["status"] == "pass"
    assert verdicts["MISSION_SEQUENCE"]["evidence"][0] == {
        "text": "task 0: TASK_FAIL at t=10.000 (planner failure: aborted)", "t": 10.0,
        "signal": "SIG_MISSION_TASK_FAIL", "object": "task_0", "task": 0}
    # NO_ROBOT_AT_FAULT_COLLISION passes too: no collision with the walker (nothing to judge in the state)
    assert data["verdict_counts"] == {"pass": 6, "fail": 0, "error": 0, "not-applicable": 1}
    assert data["files"] == {"events": "events.csv", "verdicts": "verdicts.xml"}
    assert ET.parse(tmp_path / "verdicts.xml").getroot().get("tests") == "7"


def test_finish_is_final_and_idempotent(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path)
    first = replay(nominal().messages, evaluator, run_id="r")
    evaluator.on_signal({"seq": 99, "t": 30.0, "signal": "SIG_MISSION_END", "subject": "tb3",
                         "object": "mission", "distance": 0.0})
    assert evaluator.late_signals == 1
    assert evaluator.finish(status="ERROR", reason="again", sim_duration=1, wall_time=1, run_id="x") is first
    assert json.loads((tmp_path / "summary.json").read_text())["status"] == "COMPLETED"


def test_error_status_is_recorded_and_turns_passes_into_errors(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path)
    summary = replay(nominal().messages, evaluator, status="ERROR", reason="simulation exited with 137")
    assert (summary.status, summary.error) == ("ERROR", "simulation exited with 137")
    assert summary.verdict("MISSION_SIMPLE").status == Status.ERROR
    with pytest.raises(ValueError, match="status must be one of"):
        _evaluator(tmp_path / "b").finish(status="DONE", reason=None, sim_duration=0, wall_time=0, run_id="r")


def test_malformed_repeated_and_lost_signals_are_stream_problems(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path)
    messages = nominal().messages
    evaluator.on_signal({"seq": 0, "t": "soon", "signal": "SIG_MISSION_BEGIN"})
    evaluator.on_signal(messages[0])
    evaluator.on_signal({**messages[0], "t": 0.5})  # repeated seq, other content
    for message in messages[3:]:  # seq 1 and 2 lost
        evaluator.on_signal(message)
    summary = evaluator.finish(status="COMPLETED", reason=None, sim_duration=20.0, wall_time=0.0, run_id="r")
    texts = [p.text for p in summary.problems]
    assert texts[0] == "malformed signal skipped: signal field 't' must be a number, got 'soon'"
    assert texts[1] == "signal seq 0 repeated with other content, skipped"
    assert texts[2] == "lost 2 signal(s) (seq 1 to 2)"
    assert summary.signals == len(messages) - 2
    assert summary.verdict("MISSION_SIMPLE").status == Status.ERROR
    assert len((tmp_path / "events.csv").read_text().splitlines()) == 1 + len(messages) - 2


def test_mission_info_can_arrive_later_in_either_shape(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path, mission_info=None)
    assert not evaluator.has_mission_info
    evaluator.set_mission_info({"goals": "none"})  # unreadable: noted, not raised
    assert not evaluator.has_mission_info
    evaluator.set_mission_info({"mission": "Proto", "testcase": "T", "goals": [
        {"index": 0, "pose": [4.5, 0.5, 0.0], "tolerance": 0.25, "timeout": 60.0}]})
    summary = replay(TraceBuilder().begin().end(9.0, last_task=0).messages, evaluator)
    assert (summary.mission, summary.testcase, summary.goals) == ("Proto", "T", 1)
    assert "mission_info ignored: mission_info 'goals' must be a list, got 'none'" in [
        p.text for p in summary.problems]
    executor_shape = MissionInfo.from_message(MISSION)
    assert executor_shape.start == (0.5, 0.5) and executor_shape.goals[1].x == 5.5


def test_fed_from_one_thread_while_another_reads_totals(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path)
    messages = [{"seq": i, "t": i * 0.01, "signal": "SIG_GEOM_FAR_TRANSIT_CLOSE" if i % 2 == 0 else
                 "SIG_GEOM_CLOSE_TRANSIT_FAR", "subject": "tb3", "object": "table1", "distance": 0.2}
                for i in range(2000)]

    def expected(count: int) -> float:  # -2, +1, -2, +1, ...
        return -(count // 2) - 2 * (count % 2)

    feeder = threading.Thread(target=lambda: [evaluator.on_signal(m) for m in messages])
    feeder.start()
    snapshots = 0
    while feeder.is_alive() or snapshots == 0:
        history = evaluator.utility_over_time
        assert [total for _, total in history[-5:]] == [
            expected(k) for k in range(max(1, len(history) - 4), len(history) + 1)]
        snapshots += 1
    feeder.join()
    assert evaluator.total == expected(2000) == -1000 and len(evaluator.utility_over_time) == 2000


def test_wait_for_end_returns_when_mission_end_arrives(tmp_path: Path) -> None:
    evaluator = _evaluator(tmp_path)
    assert evaluator.wait_for_end(timeout=0.01) is False
    messages = nominal().messages
    timer = threading.Timer(0.05, lambda: [evaluator.on_signal(m) for m in messages])
    timer.start()
    assert evaluator.wait_for_end(timeout=10.0) is True
    timer.join()
    assert evaluator.ended


def test_late_signals_fill_their_holes_and_identical_repeats_are_ignored(tmp_path: Path) -> None:
    """A router restart: some signals arrive late (republished, or recovered from the monitor's file)."""
    messages = nominal().messages
    reference = replay(messages, _evaluator(tmp_path / "reference"))
    evaluator = _evaluator(tmp_path / "restarted")
    for message in (*messages[:2], *messages[4:]):  # seq 2 and 3 missed live
        evaluator.on_signal(message)
    evaluator.on_signal(messages[-1])  # republished after the reconnection: identical
    assert evaluator.reconcile(messages) == 2
    summary = evaluator.finish(status="COMPLETED", reason=None, sim_duration=None, wall_time=0.0, run_id="r")
    assert [v.status for v in summary.verdicts] == [v.status for v in reference.verdicts]
    assert summary.signals == reference.signals and summary.total_utility == reference.total_utility
    assert (tmp_path / "restarted" / "events.csv").read_text() == (tmp_path / "reference" / "events.csv").read_text()
    assert [p.text for p in summary.problems] == [
        "2 signal(s) missed live were recovered from the monitor's signal file",
        "1 identical repeated signal(s) ignored"]
