# SPDX-License-Identifier: EPL-2.0
"""The mission executor (thesis 4.3.2, 6.2.3): feeds goals one by one to the controller and reports the tasks.

It is ticked by the simulation loop with the simulation time and the robot's TRUE pose, never sleeps and never
reads a wall clock, so a run is reproducible and can go faster than real time. Judging success on the true pose
is the point: a task fails when "the planner reports success when it is not actually reaching its goal"
(thesis 5.2.1), which the planner's own odometry could never reveal.

Per control step the loop calls ``executor.tick(t, true_pose)`` and then ``controller.step(observation)``; the
loop also calls ``controller.reset(static_map, start)`` once before the first tick.
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from rei.artifacts.mission import MissionSpec
from rei.geometry import Pose2D
from rei.sut.api import Controller, NavGoal, NavStatus


class MissionEventKind(enum.Enum):
    """Mission events; with the ``SIG_MISSION_`` prefix they are the thesis's signals (Table 3)."""

    BEGIN = "BEGIN"
    TASK_START = "TASK_START"
    TASK_SUCCESS = "TASK_SUCCESS"
    TASK_FAIL = "TASK_FAIL"
    END = "END"


#: The fault kinds per sensor (contract/vocabulary.json ``faults.kinds``; rei.sim.faults implements them). Each
#: window edge of a fault is a mission-topic event besides MissionEventKind's: FAULT_<SENSOR>_<KIND>_BEGIN/_END.
FAULT_KINDS: dict[str, tuple[str, ...]] = {"laser": ("impulse", "freeze", "blackout", "occlusion", "noise"),
                                            "odometry": ("drift", "jump"), "drive": ("slip", "stuck"),
                                            "commands": ("latency", "loss"), "pose": ("kidnap",)}
FAULT_EVENTS: tuple[str, ...] = tuple(f"FAULT_{sensor.upper()}_{kind.upper()}_{edge}"
                                      for sensor, kinds in FAULT_KINDS.items() for kind in kinds
                                      for edge in ("BEGIN", "END"))


@dataclass(frozen=True, slots=True)
class MissionEvent:
    """One mission event. ``task_index``/``goal`` are set for task events; ``reason`` says why a task failed
    (and, on END, how many tasks failed)."""

    t: float
    event: MissionEventKind
    task_index: int | None = None
    goal: Pose2D | None = None
    reason: str | None = None


@dataclass(frozen=True, slots=True)
class TaskResult:
    index: int
    succeeded: bool
    started: float
    ended: float
    reason: str | None


Sink = Callable[[MissionEvent], None]


class MissionExecutor:
    def __init__(self, mission: MissionSpec, controller: Controller, sink: Sink | None = None) -> None:
        self.mission = mission
        self.controller = controller
        self.sink: Sink = sink if sink is not None else (lambda event: None)
        self.results: list[TaskResult] = []
        self._task: int | None = None
        self._task_start = 0.0
        self._started = False
        self._done = False

    @property
    def done(self) -> bool:
        """True once END has been emitted."""
        return self._done

    @property
    def current_task(self) -> int | None:
        return self._task

    def tick(self, t: float, true_pose: Pose2D) -> None:
        """Advance the mission at simulation time ``t``; ``true_pose`` is the simulator's, not the odometry."""
        if self._done:
            return
        if not self._started:
            self._started = True
            self._emit(t, MissionEventKind.BEGIN)
            self._next(t, 0)
            return
        assert self._task is not None
        goal = self.mission.goals[self._task]
        status = self.controller.status
        if status in FINAL_STATUSES:
            self._finish(t, task_outcome(status, self.controller.status_text, true_pose, goal.pose, goal.tolerance))
        elif t - self._task_start > goal.timeout:
            self.controller.cancel()
            self._finish(t, f"timeout: the goal was not reached within {goal.timeout:g} s")

    # -- internals -----------------------------------------------------------------------------------------

    def _next(self, t: float, index: int) -> None:
        if index >= len(self.mission.goals):
            self._task = None
            self._done = True
            failed = sum(not r.succeeded for r in self.results)
            reason = f"{failed} of {len(self.results)} tasks failed" if failed else None
            self._emit(t, MissionEventKind.END, reason=reason)
            return
        goal = self.mission.goals[index]
        self._task, self._task_start = index, t
        self._emit(t, MissionEventKind.TASK_START, index, goal.pose)
        self.controller.set_goal(NavGoal(index, goal.pose, goal.tolerance))

    def _finish(self, t: float, failure: str | None) -> None:
        assert self._task is not None
        index = self._task
        goal = self.mission.goals[index]
        self.results.append(TaskResult(index, failure is None, self._task_start, t, failure))
        kind = MissionEventKind.TASK_SUCCESS if failure is None else MissionEventKind.TASK_FAIL
        self._emit(t, kind, index, goal.pose, failure)
        self._next(t, index + 1)

    def _emit(self, t: float, kind: MissionEventKind, index: int | None = None, goal: Pose2D | None = None,
              reason: str | None = None) -> None:
        self.sink(MissionEvent(t, kind, index, goal, reason))


#: The navigation's states that end a task.
FINAL_STATUSES = (NavStatus.SUCCEEDED, NavStatus.ABORTED, NavStatus.CANCELLED)


def task_outcome(status: NavStatus, status_text: str, true_pose: Pose2D, goal: Pose2D,
                 tolerance: float) -> str | None:
    """How a task ends on a final ``status``: None when it succeeded, else the TASK_FAIL reason. Success is judged
    on the true pose, so a planner's success short of the goal is a failure (used for recorded runs too)."""
    if status is NavStatus.SUCCEEDED:
        distance = true_pose.distance_to(goal)
        if distance <= tolerance:
            return None
        return (f"false success: the planner reported success but the robot is {distance:.2f} m from the goal "
                f"(tolerance {tolerance:g} m)")
    if status is NavStatus.ABORTED:
        return _with_detail("planner failure: the navigation aborted", status_text)
    if status is NavStatus.CANCELLED:
        return _with_detail("the controller cancelled the goal", status_text)
    raise ValueError(f"{status.value} does not end a task")


def _with_detail(message: str, detail: str) -> str:
    return f"{message}: {detail}" if detail else message


#: A run whose mission is not its case's (an imported bag's goals) records the one it had here, in the run folder,
#: as ``mission_info`` gives it; re-evaluation prefers it to the case's.
MISSION_INFO_FILE = "mission_info.json"


def mission_info(mission: MissionSpec) -> dict[str, Any]:
    """Mission description for the ``mission_info`` RPC (thesis 6.1.4): plain JSON-able values."""
    return {
        "name": mission.name,
        "testcase": mission.testcase,
        "environment": mission.environment,
        "robot": mission.robot,
        "frame": mission.frame,
        "start": {"floor": mission.start_floor, "x": mission.start.x, "y": mission.start.y,
                  "yaw": mission.start.yaw},
        "goals": [
            {"index": g.index, "floor": g.floor, "x": g.pose.x, "y": g.pose.y, "yaw": g.pose.yaw,
             "tolerance": g.tolerance, "timeout": g.timeout}
            for g in mission.goals
        ],
    }
