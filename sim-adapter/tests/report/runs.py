# SPDX-License-Identifier: EPL-2.0
"""Synthetic run folders for the report's unit tests: the fixture room, a robot driving a straight line, a human
walking, signals, events.csv and summary.json, each optional so tests can take pieces away."""

from __future__ import annotations

import csv
import json
import math
import shutil
from pathlib import Path
from typing import Any

from rei.wamp.recording import RecordingWriter

ROOM = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"

SIGNALS = [
    {"seq": 0, "t": 0.0, "signal": "SIG_MISSION_BEGIN", "subject": "tb3", "object": "mission", "distance": 0.0},
    {"seq": 1, "t": 2.0, "signal": "SIG_GEOM_FAR_TRANSIT_CLOSE", "subject": "tb3", "object": "table1",
     "distance": 0.24},
    {"seq": 2, "t": 3.0, "signal": "SIG_GEOM_CLOSE_TRANSIT_COLLISION", "subject": "tb3", "object": "table1",
     "distance": 0.0},
    {"seq": 3, "t": 4.0, "signal": "SIG_MISSION_END", "subject": "tb3", "object": "mission", "distance": 0.0},
]
UTILITY = {"SIG_MISSION_BEGIN": 20.0, "SIG_GEOM_FAR_TRANSIT_CLOSE": -2.0,
           "SIG_GEOM_CLOSE_TRANSIT_COLLISION": -10.0, "SIG_MISSION_END": 20.0}


def state(seq: int, t: float, *, laser: list[float] | None = None) -> dict[str, Any]:
    """The robot at x = 0.5 + 0.1 t on y = 0.5, its odometry drifting 1 cm per second in y; a human walking."""
    robot: dict[str, Any] = {"name": "tb3", "pose": [0.5 + 0.1 * t, 0.5, 0.0, 0.0], "twist": [0.1, 0.0, 0.0],
                             "odom": [0.5 + 0.1 * t, 0.5 + 0.01 * t, 0.0], "laser_min": 1.0}
    if laser is not None:
        robot["laser_ranges"] = laser
    message: dict[str, Any] = {"seq": seq, "t": t, "objects": [
        {"name": "h1", "type": "HUMAN", "pose": [1.0, 3.0 - 0.1 * t, 0.85, 0.0], "twist": [0.0, -0.1, 0.0]}],
        "robot": robot, "contacts": []}
    if seq == 0:
        message["full"] = True
        message["objects"].append({"name": "table1", "type": "STATIC", "pose": [3.5, 1.5, 0.375, 0.0],
                                   "twist": [0.0, 0.0, 0.0]})
    return message


def make_run(out: Path, *, states: int = 81, rate: float = 20.0, signals: bool = True, events: bool = True,
             summary: bool = True, laser: bool = False, case: bool = True) -> Path:
    """A run folder in `out` with `states` state messages at `rate` Hz (81 at 20 Hz: t = 0 .. 4 s)."""
    out.mkdir(parents=True, exist_ok=True)
    if case:
        shutil.copytree(ROOM, out / "case")
    with RecordingWriter(out / "streams" / "state.msgpack") as writer:
        for i in range(states):
            ranges = [math.inf if b % 3 == 0 else 1.5 for b in range(360)] if laser else None
            writer.write(state(i, i / rate, laser=ranges))
    with RecordingWriter(out / "streams" / "mission.msgpack") as writer:
        writer.write({"seq": 0, "t": 0.0, "event": "BEGIN", "task_index": -1, "goal": None})
        writer.write({"seq": 1, "t": 4.0, "event": "END", "task_index": -1, "goal": None})
    if signals:
        with RecordingWriter(out / "streams" / "signal.msgpack") as writer:
            for message in SIGNALS:
                writer.write(message)
    if events:
        with open(out / "events.csv", "w", newline="", encoding="utf-8") as f:
            rows = csv.writer(f, lineterminator="\n")
            rows.writerow(["t", "signal", "utility", "total", "subject", "object"])
            total = 0.0
            for message in SIGNALS:
                total += UTILITY[message["signal"]]
                rows.writerow([f"{message['t']:.6f}", message["signal"], UTILITY[message["signal"]], total,
                               message["subject"], message["object"]])
    if summary:
        (out / "summary.json").write_text(json.dumps({
            "format": "rei-summary/1", "mission": "Deliver", "testcase": "Room", "run_id": "abc123",
            "status": "COMPLETED", "error": None, "sim_duration": 4.0, "wall_time": 1.5, "total_utility": 28.0,
            "verdicts": [
                {"requirement": "MISSION_SIMPLE", "status": "fail", "message": "1 collision(s), first with table1",
                 "evidence": [{"text": "collision with table1", "t": 3.0,
                               "signal": "SIG_GEOM_CLOSE_TRANSIT_COLLISION", "object": "table1", "task": 0}]},
                {"requirement": "MISSION_WITH_HUMAN_TRAJECTORY", "status": "pass", "message": "<no> collision",
                 "evidence": []}]}))
    return out
