# SPDX-License-Identifier: EPL-2.0
"""A bag's pose, odometry and scans as REI's recorded state stream, so ``rei evaluate`` judges the real run.

The pose topic stands for the true pose the monitor judges (a localization estimate such as ``/amcl_pose``, or a
motion-capture pose); its twist is derived from consecutive poses. The odometry, when there is one, fills the
robot's ``odom`` (its belief); the newest scan fills ``laser_min``. Times count from the first pose. States are
sampled like a simulation's (20 per second, a full frame every second) by the same collector, so the monitor
cannot tell an imported run from a simulated one. Humans of the case are not in a bag: an imported run has none.
Goals and navigation results, when the bag has them, become the mission stream and ``OUT/mission_info.json``
(rei.bags.mission); without them the mission's requirements on goals do not apply.

Nothing partial is left behind that looks complete: the streams are written into a scratch folder and moved into
``OUT/streams`` only when the whole bag was read; ``OUT/sim.json`` is written last.
"""

from __future__ import annotations

import json
import math
import shutil
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rei.artifacts import read_case
from rei.bags.mission import RecordedMission
from rei.bags.reader import BagError, RecordedGoal, Sample, read_samples
from rei.geometry import Pose2D, wrap_angle
from rei.mission.executor import MISSION_INFO_FILE
from rei.sim.clearance import FootprintClearance
from rei.sim.state import RobotState, SimState
from rei.wamp.codec import LaserMode
from rei.wamp.collector import CollectorConfig, DataCollector, MissionPublisher
from rei.wamp.recording import stream_path

#: Metres a pose may lie outside the floors before the import refuses it (the robot's own size, localization noise).
ROOM_MARGIN = 0.5


@dataclass(frozen=True, slots=True)
class ImportResult:
    duration: float
    messages: int
    states: int
    goals: int
    failed_tasks: int
    wall_time: float

    @property
    def messages_per_second(self) -> float:
        return self.messages / self.wall_time if self.wall_time > 0 else math.inf


def import_bag(bag: Path, out: Path, case_dir: Path, topics: Mapping[str, str], *,
               progress: Callable[[float], None] | None = None) -> ImportResult:
    """Write ``out/streams/state.msgpack`` and ``out/sim.json`` from the bag (topics: role -> topic)."""
    case = read_case(case_dir)
    world = case.world
    scratch = out / ".import"
    shutil.rmtree(scratch, ignore_errors=True)
    started = time.perf_counter()
    laser = LaserMode.MIN if "scan" in topics else LaserMode.NONE
    config = CollectorConfig(laser=laser, contacts=False, odometry="odom" in topics, nav_state=False)
    world_json = json.loads((case_dir / "world.json").read_text(encoding="utf-8"))
    monitor_json = json.loads((case_dir / "monitor.json").read_text(encoding="utf-8"))
    t0: float | None = None
    previous: tuple[float, Pose2D] | None = None
    odom: Pose2D | None = None
    scan_min, scan_clearance, messages, next_progress = math.inf, math.inf, 0, 0.0
    clearance = FootprintClearance(world.robot.size[0], world.robot.size[1])
    t = 0.0
    early: list[Sample] = []  # goals and results stamped before the first pose, handled at t = 0
    try:
        with (DataCollector("import", scratch, config=config, world=world_json, monitor=monitor_json) as collector,
              MissionPublisher("import", scratch) as publisher):
            mission = RecordedMission(case.mission, publisher)
            for sample in read_samples(bag, topics):
                messages += 1
                if sample.role in ("goal", "result"):
                    if t0 is None:
                        early.append(sample)
                    else:
                        _mission_sample(mission, sample, max(0.0, round(sample.t - t0, 6)), previous, bag, topics,
                                        world.bounds)
                    continue
                if sample.role == "odom":
                    odom = sample.value[0]
                elif sample.role == "scan":
                    scan = sample.value
                    ranges = _valid_ranges(scan.ranges, scan.range_min, scan.range_max)
                    scan_min = float(ranges.min()) if len(ranges) else math.inf
                    scan_clearance = clearance(ranges, scan.angle_min, scan.angle_increment)
                if sample.role != "pose":
                    continue
                pose: Pose2D = sample.value
                _check_inside(pose, world.bounds, bag, topics["pose"], sample.t, case_dir.name)
                if t0 is None:
                    t0 = sample.t
                # to the microsecond: stamps are whole nanoseconds, 1 ns off the 20 Hz grid would sample twice
                t = round(sample.t - t0, 6)
                if previous is not None and t <= previous[0]:
                    continue  # the same stamp again: nothing new to sample
                twist = _twist(previous, (t, pose))
                previous = (t, pose)
                for waiting in early:
                    _mission_sample(mission, waiting, 0.0, previous, bag, topics, world.bounds)
                early.clear()
                if collector.due(t):
                    collector.step(_state(world.robot.name, t, pose, twist, odom or pose, (scan_min, scan_clearance),
                                          laser))
                if progress is not None and t >= next_progress:
                    progress(t)
                    next_progress += 10.0
            if t0 is None:
                raise BagError(f"{bag}: topic {topics['pose']} has no messages")
            mission.end(t)
            states = collector.seq
        if not mission.goals:
            stream_path(scratch, "mission").unlink(missing_ok=True)
        streams = out / "streams"
        shutil.rmtree(streams, ignore_errors=True)
        (scratch / "streams").replace(streams)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    info = out / MISSION_INFO_FILE
    info.unlink(missing_ok=True)
    if mission.goals:
        info.write_text(json.dumps(mission.info(), indent=2) + "\n", encoding="utf-8")
    result = ImportResult(duration=t, messages=messages, states=states, goals=mission.goals,
                          failed_tasks=mission.failed, wall_time=time.perf_counter() - started)
    _write_summary(out, bag, topics, result, laser)
    return result


def _check_inside(pose: Pose2D, bounds: tuple[float, float, float, float], bag: Path, topic: str, t: float,
                  case: str) -> None:
    xmin, ymin, xmax, ymax = bounds
    if not (xmin - ROOM_MARGIN <= pose.x <= xmax + ROOM_MARGIN and ymin - ROOM_MARGIN <= pose.y <= ymax + ROOM_MARGIN):
        raise BagError(f"{bag}: topic {topic} at {t:.3f} s: pose ({pose.x:.2f}, {pose.y:.2f}) is outside the room "
                       f"of {case} ({xmin:g}..{xmax:g} x {ymin:g}..{ymax:g} m): is it the right case, or the map "
                       "frame?")


def _mission_sample(mission: RecordedMission, sample: Sample, t: float, robot: tuple[float, Pose2D] | None,
                    bag: Path, topics: Mapping[str, str], bounds: tuple[float, float, float, float]) -> None:
    if sample.role == "goal":
        goal: RecordedGoal = sample.value
        _check_inside(goal.pose, bounds, bag, topics["goal"], sample.t, "the case")
        mission.goal(t, goal)
    else:
        mission.results(t, sample.value, robot[1] if robot is not None else None)


def _twist(previous: tuple[float, Pose2D] | None, current: tuple[float, Pose2D]) -> tuple[float, float, float]:
    """World-frame (vx, vy, wz) from two consecutive poses; zero for the first."""
    if previous is None or current[0] <= previous[0]:
        return (0.0, 0.0, 0.0)
    (t0, a), (t1, b) = previous, current
    dt = t1 - t0
    return ((b.x - a.x) / dt, (b.y - a.y) / dt, wrap_angle(b.yaw - a.yaw) / dt)


def _valid_ranges(ranges: np.ndarray, range_min: float, range_max: float) -> np.ndarray:
    """The ranges with readings outside [range_min, range_max] (ROS's "no valid return") as ``inf``."""
    ranges = np.asarray(ranges, dtype=float)
    return np.where((ranges >= range_min) & (ranges <= range_max), ranges, math.inf)


def _state(name: str, t: float, pose: Pose2D, twist: tuple[float, float, float], odom: Pose2D,
           laser_values: tuple[float, float], laser: LaserMode) -> SimState:
    """``laser_values``: the newest scan's minimum and clearance (the sensor taken at the footprint's centre)."""
    laser_min, clearance = laser_values if laser is not LaserMode.NONE else (math.inf, math.inf)
    robot = RobotState(name=name, pose=(pose.x, pose.y, 0.0, pose.yaw), twist=twist, odom=odom,
                       laser_min=laser_min, laser_ranges=None, laser_clearance=clearance)
    return SimState(t=t, robot=robot, objects=(), contacts=())


def _write_summary(out: Path, bag: Path, topics: Mapping[str, str], result: ImportResult, laser: LaserMode) -> None:
    """What ``rei evaluate`` reads of a run (rei.run.reevaluate.RunSettings.from_run), and where it came from."""
    summary = {
        "run_id": "import", "source": {"bag": str(bag.resolve()), "topics": dict(topics)},
        "options": {"humans": False, "laser": laser.value, "mission": result.goals > 0},
        "sim_time": result.duration, "wall_time": result.wall_time, "messages": {"state": result.states},
        "bag_messages": result.messages, "goals": result.goals,
    }
    (out / "sim.json").write_text(json.dumps(summary, indent=2) + "\n", encoding="utf-8")


__all__ = ["BagError", "ImportResult", "import_bag"]
