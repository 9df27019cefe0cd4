# SPDX-License-Identifier: EPL-2.0
"""rei.evaluation.metrics.compute on hand-made recordings: the reversal count's hysteresis, SPL's edge cases
(goal at the start, failure, no planned path) and state messages that are malformed (left out and counted, the
rest measured, the run still judged). The scripted drives in the real simulation are in
tests/simulation/test_navigation_metrics.py."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import rei.evaluation.evaluator as evaluator_module
from rei.evaluation import Evaluator
from rei.evaluation.metrics import compute_metrics, measure
from rei.evaluation.metrics.compute import REVERSAL, _reversals
from rei.wamp.recording import RecordingWriter, stream_path

from .traces import MISSION, MONITOR, WORLD

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"
STEP = 0.01  # m per state message, along x from the fixture's start (1, 1)
SAMPLES = 51


def _state(k: int, **extra: Any) -> dict[str, Any]:
    x = 1.0 + STEP * k
    return {"t": 0.05 * k, "robot": {"pose": [x, 1.0, 0.0, 0.0], "twist": [0.2, 0.0, 0.0], "odom": [x, 1.0, 0.0]},
            "objects": [], "contacts": [], **extra}


def _run(tmp_path: Path, states: list[dict[str, Any]], goals: list[tuple[float, float]] | None = None,
         success: bool = True) -> Path:
    """A run folder: the fixture's case, the given state messages and, with ``goals``, a mission of them."""
    run = tmp_path / "run"
    shutil.copytree(FIXTURE, run / "case")
    with RecordingWriter(stream_path(run, "state")) as writer:
        for state in states:
            writer.write(state)
    if goals is not None:
        end = states[-1]["t"]
        (run / "mission_info.json").write_text(json.dumps(
            {"mission": "m", "goals": [{"index": i, "x": x, "y": y} for i, (x, y) in enumerate(goals)]}))
        with RecordingWriter(stream_path(run, "mission")) as writer:
            writer.write({"t": 0.0, "event": "BEGIN"})
            for i in range(len(goals)):
                writer.write({"t": 0.0, "event": "TASK_START", "task_index": i})
                writer.write({"t": end, "event": "TASK_SUCCESS" if success else "TASK_FAIL", "task_index": i})
            writer.write({"t": end, "event": "END"})
    return run


def test_a_reversal_survives_jitter_and_pauses_against_the_leg() -> None:
    # 10 cm forward, then 8 cm back in 4 mm steps, each followed by 0.1 mm of forward jitter and a pause
    forward = [0.004] * 25
    back = [-0.0041, 0.0001, 0.0] * 20
    assert _reversals(np.array(forward + back)) == 1
    assert _reversals(np.array(back + forward)) == 1


def test_a_reversal_needs_two_legs_of_two_centimetres() -> None:
    assert _reversals(np.array([0.003, -0.003] * 50)) == 0  # rocking by millimetres
    assert _reversals(np.array([0.001] * 15 + [-0.001] * 30)) == 0  # 1.5 cm then back: the first leg too short
    assert _reversals(np.array([0.001] * 25 + [-0.001] * 19)) == 0  # 2.5 cm then 1.9 cm back: not yet turned
    assert _reversals(np.array([0.001] * 25 + [-0.001] * 20)) == 1
    legs = np.concatenate([np.full(15, sign * 0.01) for sign in (1, -1, 1, -1)])  # 15 cm each way, 4 legs
    assert _reversals(legs) == 3
    assert REVERSAL == 0.02


@pytest.mark.parametrize("bad", [[["tb3"]], [5], [["tb3", 7]]], ids=["one-name", "a-number", "not-a-name"])
def test_a_malformed_state_is_left_out_and_counted_and_the_rest_measured(tmp_path: Path, bad: Any) -> None:
    states = [_state(k) for k in range(SAMPLES)]
    states[20] = _state(20, contacts=bad)
    measured = measure(_run(tmp_path, states))
    # the whole drive is measured: the path around the left-out sample is as long (a straight line)
    assert measured.metrics["path_length"] == pytest.approx(STEP * (SAMPLES - 1))
    assert len(measured.notes) == 1 and "1 malformed state message(s)" in measured.notes[0]
    assert "message 20" in measured.notes[0] and "contacts" in measured.notes[0]


def test_a_torn_last_message_ends_the_stream(tmp_path: Path) -> None:
    run = _run(tmp_path, [_state(k) for k in range(SAMPLES)])
    with open(stream_path(run, "state"), "ab") as f:
        f.write(b"\x82\xa1t")  # the start of a map whose writer died
    measured = measure(run)
    assert measured.metrics["path_length"] == pytest.approx(STEP * (SAMPLES - 1)) and measured.notes == ()


def test_the_evaluator_keeps_the_metrics_and_notes_a_malformed_state(tmp_path: Path) -> None:
    states = [_state(k) for k in range(SAMPLES)]
    states[7] = _state(7, contacts=[5])
    run = _run(tmp_path, states)
    summary = Evaluator(run, mission_info=MISSION, monitor_config=MONITOR, world=WORLD).finish(
        status="COMPLETED", reason=None, sim_duration=2.5, wall_time=1.0, run_id="r")
    assert summary.metrics_error is None
    assert summary.metrics["path_length"] == pytest.approx(STEP * (SAMPLES - 1))
    assert any("malformed state message" in p.text for p in summary.problems)


def test_a_failure_of_the_metrics_does_not_cost_the_summary(tmp_path: Path,
                                                             monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(_: Path) -> None:  # an unforeseen bug inside the metrics
        raise RuntimeError("boom")

    monkeypatch.setattr(evaluator_module, "measure", broken)
    summary = Evaluator(tmp_path, mission_info=MISSION, monitor_config=MONITOR, world=WORLD).finish(
        status="COMPLETED", reason=None, sim_duration=1.0, wall_time=1.0, run_id="r")
    assert summary.metrics_error == "metrics failed: RuntimeError: boom"
    data = json.loads((tmp_path / "summary.json").read_text())
    assert data["metrics_error"] == summary.metrics_error and data["verdicts"]


def test_spl_is_one_when_the_goal_is_the_start(tmp_path: Path) -> None:
    states = [{**_state(0), "t": 0.05 * k} for k in range(SAMPLES)]  # standing on the goal
    m = compute_metrics(_run(tmp_path, states, goals=[(1.0, 1.0)]))
    assert m["success"] is True and m["spl"] == 1.0


def test_spl_on_success_is_the_shortest_over_the_driven(tmp_path: Path) -> None:
    m = compute_metrics(_run(tmp_path, [_state(k) for k in range(SAMPLES)], goals=[(1.5, 1.0)]))
    # the planner's grid path to a goal 0.5 m ahead on a free line: the driven path, to a cell
    assert m["success"] is True and m["spl"] == pytest.approx(1.0, abs=0.05)


def test_spl_is_zero_on_failure_and_null_without_a_planned_path(tmp_path: Path) -> None:
    states = [_state(k) for k in range(SAMPLES)]
    failed = compute_metrics(_run(tmp_path / "a", states, goals=[(5.0, 1.0)], success=False))
    assert failed["success"] is False and failed["spl"] == 0.0
    walled = compute_metrics(_run(tmp_path / "b", states, goals=[(0.0, 1.0)], success=False))  # inside a wall
    assert walled["success"] is False and walled["spl"] is None


def test_the_shortest_path_of_a_described_robot_takes_its_outline(tmp_path: Path) -> None:
    """SPL's shortest path plans with the robot's outline as the navigation does (its radii about its origin): a
    round robot of radius 0.17 fits through a 0.44 m gap in a wall across the room, from (1, 1) to (5, 1); a box
    robot of its bounding square (0.34 m, circumscribed radius 0.24) does not, and neither did the round robot
    when its bounding box was planned."""
    from rei.artifacts.world import read_world
    from rei.evaluation.metrics.compute import _shortest_path

    def world(footprint: dict[str, Any] | None) -> Path:
        data = json.loads((FIXTURE / "world.json").read_text())
        data["objects"] = [o for o in data["objects"] if o["category"] in ("FLOOR", "WALL")]
        for name, y0, y1 in (("low", 0.0, 1.78), ("high", 2.22, 4.0)):  # the wall at x = 3, a gap at y = 2
            data["objects"].append({"name": name, "category": "STATIC", "type": "Wall", "shape": "BOX",
                                    "size": [0.1, y1 - y0, 1.0], "pose": [3.0, (y0 + y1) / 2, 0.5, 0.0],
                                    "mass": 0.0, "inertia": [0, 0, 0], "colour": [1, 1, 1, 1], "floor": "F_1_0"})
        data["robot"]["size"] = [0.34, 0.34, 0.2]
        if footprint is not None:
            data["robot"]["footprint"] = footprint
        path = tmp_path / ("round.json" if footprint else "square.json")
        path.write_text(json.dumps(data))
        return path

    round_ = _shortest_path(read_world(world({"type": "circle", "x": 0.0, "y": 0.0, "radius": 0.17})),
                            (1.0, 1.0), [(5.0, 1.0)])
    assert round_ is not None and 2 * math.hypot(2.0, 1.0) <= round_ < 2 * math.hypot(2.0, 1.0) + 0.05
    assert _shortest_path(read_world(world(None)), (1.0, 1.0), [(5.0, 1.0)]) is None
