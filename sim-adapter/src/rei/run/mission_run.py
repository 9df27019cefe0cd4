# SPDX-License-Identifier: EPL-2.0
"""The simulation loop of one mission (thesis 4.1.1, Fig. 9).

Per physics step the robot gets the controller's last command; at the control rate the mission executor is
ticked with the TRUE pose and the controller with what the robot observes; the data collector offers every
step's state to its sim-time schedule. Nothing reads the wall clock unless pacing to real time was asked for,
so a seed fixes the whole run and the recorded streams.
"""

from __future__ import annotations

import contextlib
import json
import math
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rei.artifacts import ArtifactError, Case, read_case
from rei.geometry import Twist2D
from rei.mission import MissionEvent, MissionExecutor, TaskResult, mission_info
from rei.sim.faults import FaultClock, FaultSchedule, as_schedule, fault_fields
from rei.sim.people.cost import people_cost
from rei.sim.simulation import Simulation
from rei.sut.api import Controller
from rei.sut.external.controller import SutError
from rei.sut.external.options import SutOptions
from rei.sut.registry import create_controller
from rei.wamp.collector import CollectorConfig, DataCollector, MissionPublisher

if TYPE_CHECKING:
    from rei.wamp.client import WampClient

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
    animation: str = "velocity"  # rei.sim.animator.DriveMode: how humans and moving objects are driven
    realtime: bool = False
    control_rate: float = 10.0
    physics_rate: float = 240.0
    collector: CollectorConfig = field(default_factory=CollectorConfig)
    sut: SutOptions | None = None  # an external system under test instead of ``controller`` (docs/sut.md)

    def __post_init__(self) -> None:
        if not (self.control_rate > 0 and self.physics_rate >= self.control_rate):
            raise ValueError(f"control rate must be in (0, physics rate], got {self.control_rate} Hz")

    @property
    def paced(self) -> bool:
        """Whether the loop keeps to the wall clock (asked for, or a free-running external SUT)."""
        return self.realtime or (self.sut is not None and self.sut.clock == "realtime")


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
    error: str | None = None  # what ended the run early (an external SUT that broke it)
    sut: dict[str, Any] | None = None  # an external SUT's counts (rei.sut.external.SutStats)
    people: dict[str, dict[str, Any]] | None = None  # what the robot cost each person (rei.sim.people.cost)
    faults: list[dict[str, str]] | None = None  # the run's fault schedule (the mission's, then --fault's)

    @property
    def succeeded(self) -> bool:
        return (self.error is None and not self.cut_off and len(self.tasks) == self.goals
                and all(t.succeeded for t in self.tasks))

    @property
    def real_time_factor(self) -> float:
        return self.sim_time / self.wall_time if self.wall_time > 0 else math.inf


Progress = Callable[[float, int, int], None]
"""Called about once per simulated second with (sim time, tasks done, tasks in the mission)."""


def check_faults(case: Case, options: MissionRunOptions) -> None:
    """Raise ``ArtifactError`` for faults this run cannot have: a command latency that is not whole control periods
    at its rate (the case's; --fault's are checked with the options), a stuck wheel of a holonomic robot (the
    language refuses the case's own, not a --fault's). `rei run` calls it once the case is generated, so that such
    a run is refused before its monitor and simulation start."""
    try:
        FaultSchedule(case.mission.faults).commands([], options.control_rate)
    except ValueError as error:
        raise ArtifactError(case.mission.path, f"faults: {error}") from None
    robot = case.world.robot
    if robot.drive.holonomic and any(f.kind == "stuck" for f in (FaultSchedule(case.mission.faults)
                                                                + as_schedule(options.fault)).faults):
        raise ArtifactError(case.world.path, f"robot: {robot.name} is holonomic, and a stuck wheel is a fault "
                                             "of a differential drive (it has no left or right wheel)")


def run_mission(
    case_dir: Path,
    out_dir: Path,
    options: MissionRunOptions,
    *,
    run_id: str,
    client: WampClient | None = None,
    progress: Progress | None = None,
    controller: Controller | None = None,
) -> MissionRunResult:
    """Run the case's mission once; the streams it published are recorded under ``out_dir/streams``.

    ``controller``: this controller object instead of the one ``options.controller`` names (benchmarks wrap
    the reference navigation to time it).

    An external SUT that breaks the run (``SutError``) ends it early: the result carries the error, and everything
    published until then is recorded."""
    case = read_case(case_dir)
    check_faults(case, options)
    time_limit = sum(goal.timeout for goal in case.mission.goals) + TIME_LIMIT_MARGIN
    control_every = max(1, round(options.physics_rate / options.control_rate))
    wall_start = time.perf_counter()
    error = None
    interrupted: BaseException | None = None
    external = None
    executor: MissionExecutor | None = None
    with contextlib.ExitStack() as stack:
        sim = stack.enter_context(Simulation(case, seed=options.seed, physics_rate=options.physics_rate,
                                             humans=options.humans, fault=options.fault,
                                             animation_mode=options.animation))
        collector = stack.enter_context(DataCollector(
            run_id, out_dir, config=options.collector, client=client, monitor=_json(case_dir / "monitor.json"),
            world=_json(case_dir / "world.json")))
        missions = stack.enter_context(MissionPublisher(run_id, out_dir, client=client,
                                                        mission_info=mission_info(case.mission)))
        try:
            if controller is None and options.sut is not None:
                if client is None:
                    raise SutError("an external system under test needs a router (not --no-router)")
                from rei.sut.external.session import external_sut  # the WAMP client: only with a router
                controller = external = stack.enter_context(external_sut(
                    options.sut, client, run_id, out_dir, case=case, static_map=sim.static_map(),
                    control_rate=options.control_rate, now=lambda: sim.t))
                wall_start = time.perf_counter()  # the SUT's start-up is not the mission's time
            elif controller is None:
                controller = create_controller(options.controller)
            executor = MissionExecutor(case.mission, controller, lambda event: _publish(missions, event))
            controller.reset(sim.static_map(), case.mission.start)
            command = Twist2D()
            next_progress = 0.0
            faults = FaultClock(sim.faults)
            # the commands' faults sit between the controller (in-process, an external SUT, a ROS bridge) and the
            # robot; a latency not a whole number of control periods is refused before the first step
            commands = sim.faults.commands(sim.fault_generators, options.control_rate) if sim.faults.of(
                "commands") else None
            while not executor.done and sim.t < time_limit:
                if sim.steps % control_every == 0:
                    executor.tick(sim.t, sim.robot_pose())
                # a fault window's edge is published at the first step at or after it (the scans follow the same
                # schedule), after the mission's BEGIN and before the controller sees this step's observation
                for edge in faults.due(sim.t):
                    missions.publish(sim.t, edge.event, reason=edge.fault.describe())
                if sim.steps % control_every == 0:
                    command = controller.step(sim.observation())
                    if commands is not None:
                        command = commands.apply(sim.t, command)
                sim.step(command)
                if collector.due(sim.t):  # a snapshot costs; build it only when it will be sent
                    collector.step(sim.state(), controller.status.value)
                if options.paced:
                    _pace(wall_start, sim.t)
                if progress is not None and sim.t >= next_progress:
                    progress(sim.t, len(executor.results), len(case.mission.goals))
                    next_progress += 1.0
        except SutError as broken:
            error = str(broken)
        except (SystemExit, KeyboardInterrupt) as stopping:  # SIGTERM (rei sim's sigterm_unwinds: `rei run` stops
            interrupted = stopping  # it so) or Ctrl-C: the summary is still written (the SUT's exit code, how far)
            error = f"{'interrupted (Ctrl-C)' if isinstance(stopping, KeyboardInterrupt) else 'stopped by SIGTERM'} " \
                    f"at t={sim.t:.3f} s"
        wall_time = time.perf_counter() - wall_start
        people = None if sim.crowd is None else people_cost(sim.crowd, sim.t)
        stack.close()  # stops the SUT first: its exit code belongs in the summary
        done = executor is not None and executor.done
        result = MissionRunResult(
            run_id=run_id, sim_time=sim.t, wall_time=wall_time, steps=sim.steps,
            tasks=tuple(executor.results) if executor is not None else (), goals=len(case.mission.goals),
            state_messages=collector.seq, mission_messages=missions.seq, cut_off=error is None and not done,
            error=error,
            sut=None if external is None else external.stats.to_json(), people=people,
            faults=[{"sensor": f.sensor, "kind": f.kind, **fault_fields(f), "description": f.describe()}
                    for f in sim.faults.faults])
    _write_summary(out_dir, case_dir, options, result)
    if interrupted is not None:
        raise interrupted
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


def _write_summary(out_dir: Path, case_dir: Path, options: MissionRunOptions, result: MissionRunResult) -> None:
    summary = {
        "run_id": result.run_id,
        "case": str(Path(case_dir).resolve()),  # where the generated case is (rei.run.reevaluate.case_of_run)
        "options": {**{k: v for k, v in asdict(options).items() if k not in ("collector", "sut")},
                    **({"sut": _sut_options(options.sut)} if options.sut is not None else {}),
                    "laser": options.collector.laser.value},  # what the verdicts need to know (rei.run.reevaluate)
        "sim_time": result.sim_time,
        "wall_time": result.wall_time,
        "real_time_factor": result.real_time_factor,
        "steps": result.steps,
        "cut_off": result.cut_off,
        "succeeded": result.succeeded,
        **({"error": result.error} if result.error is not None else {}),
        **({"sut": result.sut} if result.sut is not None else {}),
        **({"people": result.people} if result.people is not None else {}),
        "tasks": [asdict(task) for task in result.tasks],
        **({"faults": result.faults} if result.faults else {}),
        "messages": {"state": result.state_messages, "mission": result.mission_messages},
    }
    (out_dir / "sim.json").write_text(json.dumps(summary, indent=2) + "\n", encoding="utf-8")


def _sut_options(sut: SutOptions) -> dict[str, Any]:
    """The external SUT's settings as a run keeps them (no paths: the router and credentials were the run's)."""
    return {"command": sut.command, "attach": sut.attach, "clock": sut.clock, "deadline": sut.deadline,
            "map": sut.offer_map, "join_timeout": sut.join_timeout}
