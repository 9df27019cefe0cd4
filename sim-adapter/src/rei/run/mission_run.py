# SPDX-License-Identifier: EPL-2.0
"""The simulation loop of one mission (thesis 4.1.1, Fig. 9).

Per physics step the robot gets the controller's last command; at the control rate the mission executor is
ticked with the TRUE pose and the controller with what the robot observes; the data collector offers every
step's state to its sim-time schedule. Nothing reads the wall clock unless pacing to real time was asked for,
so a seed fixes the whole run and the recorded streams.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path

from rei.artifacts import read_case
from rei.geometry import Twist2D
from rei.mission import MissionEvent, MissionExecutor, TaskResult, mission_info
from rei.sim.simulation import Simulation
from rei.sut.registry import create_controller
from rei.wamp.client import WampClient
from rei.wamp.collector import CollectorConfig, DataCollector, MissionPublisher

#: Sim seconds allowed beyond the sum of task timeouts before the run is cut (a controller that never
#: reports can not hang a run).
TIME_LIMIT_MARGIN = 30.0


@dataclass(frozen=True, slots=True)
class MissionRunOptions:
    """How to run: which controller, which seed, which variant of the world."""

    controller: str = "nav"
    seed: int = 0
    humans: bool = True
    fault: str | None = None
    realtime: bool = False
    control_rate: float = 10.0
    physics_rate: float = 240.0
    collector: CollectorConfig = field(default_factory=CollectorConfig)

    def __post_init__(self) -> None:
        if not (self.control_rate > 0 and self.physics_rate >= self.control_rate):
            raise ValueError(f"control rate must be in (0, physics rate], got {self.control_rate} Hz")


@dataclass(frozen=True, slots=True)
class MissionRunResult:
    run_id: str
    sim_time: float
    wall_time: float
    steps: int
    tasks: tuple[TaskResult, ...]
    goals: int
    state_messages: int
    mission_messages: int
    cut_off: bool

    @property
    def succeeded(self) -> bool:
        return not self.cut_off and len(self.tasks) == self.goals and all(t.succeeded for t in self.tasks)

    @property
    def real_time_factor(self) -> float:
        return self.sim_time / self.wall_time if self.wall_time > 0 else math.inf


Progress = Callable[[float, int, int], None]
"""Called about once per simulated second with (sim time, tasks done, tasks in the mission)."""


def run_mission(
    case_dir: Path,
    out_dir: Path,
    options: MissionRunOptions,
    *,
    run_id: str,
    client: WampClient | None = None,
    progress: Progress | None = None,
) -> MissionRunResult:
    """Run the case's mission once; the streams it published are recorded under ``out_dir/streams``."""
    case = read_case(case_dir)
    controller = create_controller(options.controller)
    time_limit = sum(goal.timeout for goal in case.mission.goals) + TIME_LIMIT_MARGIN
    control_every = max(1, round(options.physics_rate / options.control_rate))
    wall_start = time.perf_counter()
    with (
        Simulation(case, seed=options.seed, physics_rate=options.physics_rate, humans=options.humans,
                   fault=options.fault) as sim,
        DataCollector(run_id, out_dir, config=options.collector, client=client,
                      monitor=_json(case_dir / "monitor.json"), world=_json(case_dir / "world.json")) as collector,
        MissionPublisher(run_id, out_dir, client=client, mission_info=mission_info(case.mission)) as missions,
    ):
        executor = MissionExecutor(case.mission, controller, lambda event: _publish(missions, event))
        controller.reset(sim.static_map(), case.mission.start)
        command = Twist2D()
        next_progress = 0.0
        while not executor.done and sim.t < time_limit:
            if sim.steps % control_every == 0:
                executor.tick(sim.t, sim.robot_pose())
                command = controller.step(sim.observation())
            sim.step(command)
            if collector.due(sim.t):  # a snapshot costs; build it only when it will be sent
                collector.step(sim.state(), controller.status.value)
            if options.realtime:
                _pace(wall_start, sim.t)
            if progress is not None and sim.t >= next_progress:
                progress(sim.t, len(executor.results), len(case.mission.goals))
                next_progress += 1.0
        result = MissionRunResult(
            run_id=run_id, sim_time=sim.t, wall_time=time.perf_counter() - wall_start, steps=sim.steps,
            tasks=tuple(executor.results), goals=len(case.mission.goals), state_messages=collector.seq,
            mission_messages=missions.seq, cut_off=not executor.done)
    _write_summary(out_dir, options, result)
    return result


def _publish(missions: MissionPublisher, event: MissionEvent) -> None:
    goal = None if event.goal is None else (event.goal.x, event.goal.y, event.goal.yaw)
    task = -1 if event.task_index is None else event.task_index
    missions.publish(event.t, event.event.value, task, goal, event.reason)


def _pace(wall_start: float, sim_t: float) -> None:
    ahead = wall_start + sim_t - time.perf_counter()
    if ahead > 0.001:
        time.sleep(ahead)


def _json(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))


def _write_summary(out_dir: Path, options: MissionRunOptions, result: MissionRunResult) -> None:
    summary = {
        "run_id": result.run_id,
        "options": {**{k: v for k, v in asdict(options).items() if k != "collector"},
                    "laser": options.collector.laser.value},  # what the verdicts need to know (rei.run.reevaluate)
        "sim_time": result.sim_time,
        "wall_time": result.wall_time,
        "real_time_factor": result.real_time_factor,
        "steps": result.steps,
        "cut_off": result.cut_off,
        "succeeded": result.succeeded,
        "tasks": [asdict(task) for task in result.tasks],
        "messages": {"state": result.state_messages, "mission": result.mission_messages},
    }
    (out_dir / "sim.json").write_text(json.dumps(summary, indent=2) + "\n", encoding="utf-8")
