# SPDX-License-Identifier: EPL-2.0
"""Triggers SIG_NAVIGATION_ABORTED_TWICE: writes the recording of a run of standstill.rei whose navigation reports
ABORTED at t = 3 s, recovers (ACTIVE) at 4 s and aborts again at 6 s within task 0, then aborts once in task 1.

REI's own mission executor ends a task at its first ABORTED, so no simulation gives this; a navigation stack with
recovery behaviours does, and its recording (or an imported bag) is what the monitor then judges. Usage:

    rei generate examples/patterns/cases/standstill.rei -o OUT/case
    .venv/bin/python examples/patterns/cases/aborted_twice.py OUT
    rei monitor --replay OUT --queries examples/patterns --patterns examples/patterns
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field
from pathlib import Path

from rei.wamp.codec import encode_mission_event, encode_state
from rei.wamp.recording import RecordingWriter, stream_path

DT = 0.05
GOAL = (1.5, 0.5, 0.0)


@dataclass
class Robot:
    name: str = "tb3"
    pose: tuple[float, float, float, float] = (0.5, 0.5, 0.0, 0.0)
    twist: tuple[float, float, float] = (0.0, 0.0, 0.0)
    odom: tuple[float, float, float] = (0.5, 0.5, 0.0)
    laser_min: float = float("inf")
    laser_ranges: None = None
    laser_clearance: float = float("inf")


@dataclass
class State:
    t: float
    robot: Robot = field(default_factory=Robot)
    objects: list = field(default_factory=list)
    contacts: list = field(default_factory=list)


def nav_state(t: float) -> str:
    """ACTIVE, with ABORTED over [3, 4) and [6, 7) in task 0 and [8, 8.5) in task 1."""
    return "ABORTED" if 3 <= t < 4 or 6 <= t < 7 or 8 <= t < 8.5 else "ACTIVE"


def main(out: Path) -> None:
    with RecordingWriter(stream_path(out, "state")) as states, RecordingWriter(stream_path(out, "mission")) as missions:
        events = [(0.0, "BEGIN", -1, None), (0.0, "TASK_START", 0, GOAL), (7.0, "TASK_FAIL", 0, GOAL),
                  (7.0, "TASK_START", 1, GOAL), (8.5, "TASK_FAIL", 1, GOAL), (10.0, "END", -1, None)]
        for seq, (t, event, task, goal) in enumerate(events):
            reason = "planner failure: the navigation aborted" if event == "TASK_FAIL" else None
            missions.write(encode_mission_event(seq, t, event, task, goal, reason))
        for k in range(201):
            t = round(k * DT, 6)
            states.write(encode_state(State(t), k, nav_state=nav_state(t), full_frame_objects=[] if k == 0 else None))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: aborted_twice.py OUT")
    main(Path(sys.argv[1]))
