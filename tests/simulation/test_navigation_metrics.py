# SPDX-License-Identifier: EPL-2.0
"""The navigation metrics (docs/metrics.md) of scripted drives in the real simulation, each against a computation
of its own from the recorded states and the case: a straight drive of known length and speed that stops 0.1 m
from a table, a turn in place followed by back-and-forth, and a drive into the table. A human walks the next lane
during the runs; another waits in the lane beyond it and crosses the robot's lane only after the runs, where the
straight drives passed (the encounter margin counts the schedule past the run's end)."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from rei.evaluation.metrics import LIST_KEYS, NAMES, compute_metrics
from rei.wamp.recording import read_recording

CASE = """testcase MetricsDrive {
  room Lane size 5 x 3 {
    object table1 : Table on F_3_0
    human walker trajectory [F_0_1 @ 0s, F_4_1 @ 10s] once
    human crosser trajectory [F_1_2 @ 20s, F_1_0 @ 30s] once
    robot tb3 : Waffle on F_0_0
  }
  mission ToTable { goto F_2_0 within 60s goto F_2_0 }
}
"""
SPEED = 0.2
HALF_X, HALF_Y = 0.281 / 2, 0.306 / 2  # the Waffle's footprint
TABLE_FACE = 3.5 - 1.2 / 2  # the table's near side (table on F_3_0, 1.2 m long)
START_FRONT = 0.5 + HALF_X
STRAIGHT = (TABLE_FACE - 0.1 - START_FRONT) / SPEED  # seconds of driving to stop 0.1 m before the table
SCRIPTS = {
    "straight": f"{STRAIGHT:.4f} {SPEED} 0.0\n",
    "turn": "6.2832 0.0 1.0\n1.5 0.2 0.0\n1.5 -0.2 0.0\n1.5 0.2 0.0\n1.5 -0.2 0.0\n",  # one turn, 3 reversals
    "ram": f"{STRAIGHT + 0.7:.4f} {SPEED} 0.0\n",  # on into the table for 0.7 s
}


class Drive:
    def __init__(self, out: Path) -> None:
        self.out = out
        self.metrics = compute_metrics(out)
        self.states = read_recording(out / "streams" / "state.msgpack")
        self.mission = read_recording(out / "streams" / "mission.msgpack")
        self.t = np.array([s["t"] for s in self.states])
        pose = np.array([s["robot"]["pose"] for s in self.states])
        self.x, self.y, self.yaw = pose[:, 0], pose[:, 1], np.unwrap(pose[:, 3])
        self.begin = next(m["t"] for m in self.mission if m["event"] == "BEGIN")
        self.end = next(m["t"] for m in self.mission if m["event"] == "END")

    def human(self, name: str = "walker") -> np.ndarray:
        return np.array([[o["pose"][0], o["pose"][1]] for s in self.states for o in s["objects"]
                         if o["name"] == name])


@pytest.fixture(scope="module")
def drives(run_cli, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Drive]:
    folder = tmp_path_factory.mktemp("metrics")
    (folder / "drive.rei").write_text(CASE, encoding="utf-8")
    generated = run_cli("generate", folder / "drive.rei", "-o", folder / "case")
    assert generated.returncode == 0, generated.stderr
    out = {}
    for name, script in SCRIPTS.items():
        (folder / f"{name}.script").write_text(script, encoding="utf-8")
        sim = run_cli("sim", folder / "case", "-o", folder / name, "--no-router",
                      "--controller", f"script:{folder / f'{name}.script'}")
        assert sim.returncode in (0, 1), sim.stderr
        out[name] = Drive(folder / name)
    return out


def test_every_metric_is_there_in_the_agreed_order(drives: dict[str, Drive]) -> None:
    assert list(drives["straight"].metrics) == [*NAMES, *LIST_KEYS]


def test_a_straight_drive_of_known_length_and_speed(drives: dict[str, Drive]) -> None:
    d = drives["straight"]
    m = d.metrics
    sample = SPEED * 0.05  # one state sample of travel at 20 Hz
    displacement = math.hypot(d.x[-1] - d.x[0], d.y[-1] - d.y[0])
    assert abs(m["path_length"] - SPEED * STRAIGHT) <= sample
    assert abs(m["path_length"] - displacement) <= 0.002  # a straight line is as long as its ends are apart
    assert abs(m["speed_peak"] - SPEED) <= 0.005
    assert m["speed_mean"] == pytest.approx(m["path_length"] / (d.end - d.begin))
    # both goals are on F_2_0, which the robot reaches when the script ends (then it is judged, task by task)
    last = max(e["t"] for e in d.mission if e["event"] == "TASK_SUCCESS")
    assert m["success"] is True and m["time"] == pytest.approx(last - d.begin)
    assert STRAIGHT < m["time"] <= STRAIGHT + 0.25 and len(m["task_times"]) == 2
    # the way is straight and free: the shortest path is the start-to-goal distance (a cell of the planner)
    assert m["spl"] == pytest.approx(2.0 / m["path_length"], abs=0.05 / m["path_length"])
    assert m["rotation_in_place"] < 0.01 and m["oscillations"] == 0 and m["collision_episodes"] == 0
    assert m["odom_drift"] < 0.005


def test_a_drive_that_stops_a_tenth_of_a_metre_from_the_table(drives: dict[str, Drive]) -> None:
    d = drives["straight"]
    m = d.metrics
    assert np.abs(d.yaw).max() < 0.01  # the footprint stays square to the table: its front is x + HALF_X
    gap = TABLE_FACE - (d.x + HALF_X)
    assert abs(m["clearance_static_min"] - gap.min()) <= 0.002
    assert abs(m["clearance_static_min"] - 0.1) <= SPEED * 0.05
    # CLOSE (monitor.json close 0.25 m) only at the table: the walls are 0.297 m from the footprint's sides
    assert abs(m["close_time"] - 0.05 * np.count_nonzero(gap < 0.25)) <= 0.05 + 1e-9
    # the walker walks the parallel lane 1 m away, the crosser waits 2 m away: circles of 0.5 m against the rectangle
    gaps = []
    for name in ("walker", "crosser"):
        human = d.human(name)
        dx, dy = np.abs(human[:, 0] - d.x) - HALF_X, np.abs(human[:, 1] - d.y) - HALF_Y
        gaps.append(np.hypot(np.maximum(dx, 0), np.maximum(dy, 0)) - 0.25)
    human_gap = np.min(gaps, axis=0)
    assert abs(m["clearance_humans_min"] - human_gap.min()) <= 0.002
    assert abs(m["clearance_humans_mean_min"] - human_gap.mean()) <= 0.002


def own_encounter_margin(d: Drive) -> tuple[float | None, float]:
    """The least |t_k - tau| over the mission's state samples k and each human's schedule (animation.json, every
    0.01 s and at the samples' times, up to a second past the later of the run's and the schedule's ends) where
    its circle (world.json) comes nearer than the collision threshold (monitor.json) to the robot's rectangle;
    and how far the recorded humans were from their schedules at the samples' times."""
    case = d.out.parent / "case"
    animation = json.loads((case / "animation.json").read_text())
    world = json.loads((case / "world.json").read_text())
    threshold = json.loads((case / "monitor.json").read_text())["thresholds"]["collision"]
    inside = (d.t >= d.begin - 1e-9) & (d.t <= d.end + 1e-9)
    t, x, y, yaw = d.t[inside], d.x[inside, None], d.y[inside, None], d.yaw[inside, None]
    least, off_schedule = None, 0.0
    for o in animation["objects"]:
        if o["category"] != "HUMAN":
            continue
        # two control points walked once: the Catmull-Rom is the straight uniform walk between them, waiting at
        # the first before and staying at the last after, which np.interp gives exactly
        assert len(o["points"]) == 2 and not o["loop"]
        times = [p["t"] for p in o["points"]]
        xs, ys = [p["x"] for p in o["points"]], [p["y"] for p in o["points"]]
        recorded = d.human(o["name"])
        scheduled = np.column_stack((np.interp(d.t, times, xs), np.interp(d.t, times, ys)))
        off_schedule = max(off_schedule, float(np.hypot(*(recorded - scheduled).T).max()))
        taus = np.union1d(np.arange(0.0, max(d.end, times[-1]) + 1.0, 0.01), t)
        dx, dy = np.interp(taus, times, xs)[None, :] - x, np.interp(taus, times, ys)[None, :] - y
        along = np.abs(np.cos(yaw) * dx + np.sin(yaw) * dy)  # the human's centre in the robot's frame
        across = np.abs(-np.sin(yaw) * dx + np.cos(yaw) * dy)
        distance = np.hypot(np.maximum(along - HALF_X, 0), np.maximum(across - HALF_Y, 0))
        radius = next(w["size"][0] / 2 for w in world["objects"] if w["name"] == o["name"])
        conflict = distance < radius + threshold
        if conflict.any():
            margin = float(np.abs(t[:, None] - taus[None, :])[conflict].min())
            least = margin if least is None else min(least, margin)
    return least, off_schedule


def test_the_encounter_margin_counts_a_crossing_after_the_run(drives: dict[str, Drive]) -> None:
    for name, d in drives.items():
        own, off_schedule = own_encounter_margin(d)
        assert off_schedule < 0.02, name  # the simulator walks the schedule on the states' clock
        m = d.metrics["encounter_margin_humans"]
        if own is None:
            assert m is None, name
        else:  # within one state sample (0.05 s) and the metric's schedule step (0.05 s)
            assert m is not None and abs(m - own) <= 0.05 + 0.05 + 1e-9, (name, m, own)
    # the straight drives pass x = 1.5 about 5 s in; the crosser, who sets off at 20 s, would meet their
    # footprints about 22 s later. The turn stays at the start, 0.56 m from the crosser's line: no margin
    for name in ("straight", "ram"):
        assert 20.0 < drives[name].metrics["encounter_margin_humans"] < 23.0, name
    assert drives["turn"].metrics["encounter_margin_humans"] is None


def test_jerk_is_the_integrated_squared_second_difference(drives: dict[str, Drive]) -> None:
    for d in drives.values():
        inside = [k for k, t in enumerate(d.t) if d.begin <= t <= d.end]  # the mission's span, as documented
        t = d.t[inside]
        twist = np.array([d.states[k]["robot"]["twist"] for k in inside])
        yaw = d.yaw[inside]
        forward = twist[:, 0] * np.cos(yaw) + twist[:, 1] * np.sin(yaw)
        for values, key in ((forward, "jerk_linear"), (twist[:, 2], "jerk_angular")):
            total = 0.0
            for k in range(1, len(t) - 1):  # the second divided difference, over its own half-span
                span = t[k + 1] - t[k - 1]
                second = 2 * ((values[k + 1] - values[k]) / (t[k + 1] - t[k])
                              - (values[k] - values[k - 1]) / (t[k] - t[k - 1])) / span
                total += second**2 * span / 2
            assert d.metrics[key] == pytest.approx(total, rel=1e-9)
    assert drives["turn"].metrics["jerk_angular"] > 10 * drives["straight"].metrics["jerk_angular"]


def test_a_turn_in_place_then_back_and_forth(drives: dict[str, Drive]) -> None:
    d = drives["turn"]
    m = d.metrics
    moved = int(np.argmax(np.hypot(d.x - d.x[0], d.y - d.y[0]) > 0.01))  # the first state off the spot
    turned = d.yaw[moved - 1] - d.yaw[0]
    assert abs(m["rotation_in_place"] - turned) <= np.abs(np.diff(d.yaw)).max()  # within one state sample
    assert abs(m["rotation_in_place"] - 2 * math.pi) < 0.05 * 2 * math.pi
    assert m["oscillations"] == 3  # forwards, back, forwards, back
    odom = np.array([s["robot"]["odom"][:2] for s in d.states])
    assert m["odom_drift"] == pytest.approx(float(np.hypot(odom[:, 0] - d.x, odom[:, 1] - d.y).max()))
    assert m["odom_drift"] > 0.01  # the wheels' odometry sees less than the whole turn
    assert m["success"] is False and m["spl"] == 0.0  # it never went to F_2_0


def test_a_drive_into_the_table_is_one_collision_episode(drives: dict[str, Drive]) -> None:
    d = drives["ram"]
    m = d.metrics
    touching = np.array([any("table1" in pair for pair in s.get("contacts") or ()) for s in d.states])
    gap = TABLE_FACE - (d.x + HALF_X)
    colliding = touching | (gap < 0.01)  # monitor.json collision 0.01 m
    assert colliding.any() and m["collision_episodes"] == 1 and m["collision_objects"] == 1
    # pushing into the table, the simulator lets the bodies overlap by a fraction of a millimetre: a negative gap
    assert -0.005 < m["clearance_static_min"] < 0
    assert abs(m["clearance_static_min"] - gap.min()) <= 0.002
    first, last = np.flatnonzero(colliding)[[0, -1]]
    assert abs(m["collision_time"] - (min(d.t[last] + 0.05, d.end) - d.t[first])) <= 0.05 + 1e-9


def test_a_recording_without_a_mission_has_no_goal_metrics(drives: dict[str, Drive], tmp_path: Path) -> None:
    copy = tmp_path / "imported"
    shutil.copytree(drives["straight"].out, copy)
    sim = json.loads((copy / "sim.json").read_text())
    sim["options"]["mission"] = False  # as rei import writes it for a bag without goals
    (copy / "sim.json").write_text(json.dumps(sim))
    m = compute_metrics(copy)
    assert m["success"] is None and m["time"] is None and m["spl"] is None and m["task_times"] is None
    assert m["path_length"] == pytest.approx(drives["straight"].metrics["path_length"], abs=1e-3)
