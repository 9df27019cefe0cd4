# SPDX-License-Identifier: EPL-2.0
"""Writes the monitor's scripted wall-approach trace with the Python side of the wire protocol.

Usage: python write_trace.py CASE_DIR OUT_DIR  ->  OUT_DIR/streams/state.msgpack, OUT_DIR/streams/mission.msgpack

The same script as the Java test's Traces.wallApproach(): 20 Hz, the robot drives at 0.2 m/s from x = 4 toward the
east wall (inner face x = 6), stops against it at t = 10 s and backs off at 0.15 m/s until t = 14 s. Encoded with
rei.wamp.codec and written with rei.wamp.recording, so the Java monitor proves it reads what the simulator writes.
Deterministic: the same inputs give byte-identical files.
"""

from __future__ import annotations

import json
import sys
from dataclasses import dataclass, field
from pathlib import Path

from rei.wamp.codec import LaserMode, encode_mission_event, encode_state, static_objects
from rei.wamp.recording import RecordingWriter, stream_path

HALF_X = 0.281 / 2
DT = 0.05


@dataclass
class Robot:
    name: str
    pose: tuple[float, float, float, float]
    twist: tuple[float, float, float]
    odom: tuple[float, float, float]
    laser_min: float
    laser_clearance: float
    laser_ranges: None = None


@dataclass
class State:
    t: float
    robot: Robot
    objects: list = field(default_factory=list)
    contacts: list = field(default_factory=list)


def robot_x(t: float) -> tuple[float, float]:
    stop = 6.0 - HALF_X
    if t <= 10:
        x = min(4.0 + 0.2 * t, stop)
        return x, (0.2 if x < stop else 0.0)
    return stop - 0.15 * (t - 10), -0.15


def main(case_dir: Path, out_dir: Path) -> None:
    world = json.loads((case_dir / "world.json").read_text())
    statics = static_objects(world)
    with RecordingWriter(stream_path(out_dir, "state")) as states, \
            RecordingWriter(stream_path(out_dir, "mission")) as missions:
        missions.write(encode_mission_event(0, 0.0, "BEGIN"))
        missions.write(encode_mission_event(1, 0.0, "TASK_START", 0, (5.8, 1.0, 0.0)))
        for k in range(281):
            t = k * DT
            x, vx = robot_x(t)
            contacts = [("tb3", "wall_east")] if 6.0 - (x + HALF_X) <= 0 else []
            # facing the wall, the beam straight ahead gives the clearance: the range less the half length (the
            # Java twin sends only the range and lets the monitor subtract the inscribed radius, the same here)
            robot = Robot("tb3", (x, 1.0, 0.0, 0.0), (vx, 0.0, 0.0), (x, 1.0, 0.0), 6.0 - x,
                          max(0.0, (6.0 - x) - HALF_X))
            full = statics if k % 20 == 0 else None  # a full frame every simulated second
            states.write(encode_state(State(t, robot, [], contacts), k, laser=LaserMode.MIN,
                                      nav_state="ACTIVE", full_frame_objects=full))
        missions.write(encode_mission_event(2, 10.0, "TASK_FAIL", 0, (5.8, 1.0, 0.0), reason="aborted"))
        missions.write(encode_mission_event(3, 14.0, "END"))


if __name__ == "__main__":
    main(Path(sys.argv[1]), Path(sys.argv[2]))
