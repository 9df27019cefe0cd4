# SPDX-License-Identifier: EPL-2.0
"""A recorded run's mission: the goals the robot was sent and the results its navigation gave, as the mission
events the executor emits in a simulated run (rei.mission.executor), so the mission's requirements are judged.

Each goal in the bag is a task, in the order sent; its final state is the result with its goal id. A pose goal
(nav2's /goal_pose, for which bt_navigator sends the action itself) has no id: it takes the first final state of
a goal the status topic had not shown before the pose goal was sent. Success is judged on the recorded pose, as the executor judges it on the true pose:
a success short of the goal's tolerance is a false success. A new goal while one runs ends the running one as
cancelled (move_base preempts it); a goal without a result when the bag ends fails. A goal's tolerance is that of
the case's goal with the same index (its last goal's beyond them).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from rei.artifacts.mission import MissionSpec
from rei.bags.reader import RecordedGoal, RecordedResult
from rei.geometry import Pose2D
from rei.mission.executor import MissionEventKind, task_outcome
from rei.wamp.collector import MissionPublisher


@dataclass(slots=True)
class _Task:
    index: int
    goal_id: str | None
    pose: Pose2D
    tolerance: float


class RecordedMission:
    """Turns goals and results, fed in time order with the robot's pose then, into recorded mission events."""

    def __init__(self, case_mission: MissionSpec, publisher: MissionPublisher) -> None:
        self._case = case_mission
        self._publisher = publisher
        self._tasks: list[_Task] = []
        self._running: _Task | None = None
        self._finished: set[str] = set()  # goal ids whose final state has been taken
        self._seen: set[str] = set()  # goal ids of every result or status so far
        self._earlier: set[str] = set()  # those seen before the running task's goal was sent
        self.failed = 0

    @property
    def goals(self) -> int:
        return len(self._tasks)

    def goal(self, t: float, goal: RecordedGoal) -> None:
        if not self._tasks:
            self._publisher.publish(t, MissionEventKind.BEGIN)
        if self._running is not None:
            self._finish(t, self._running, "the controller cancelled the goal: a new goal replaced it")
        task = _Task(len(self._tasks), goal.goal_id, goal.pose, self._tolerance(len(self._tasks)))
        self._tasks.append(task)
        self._running = task
        self._earlier = set(self._seen)
        self._publisher.publish(t, MissionEventKind.TASK_START, task.index, task.pose)

    def results(self, t: float, results: tuple[RecordedResult, ...], robot: Pose2D | None) -> None:
        for result in results:
            self._seen.add(result.goal_id)
            if result.status is None or result.goal_id in self._finished:
                continue  # still running, or a status array repeating a final state while the server keeps it
            task = self._running
            if task is None or (result.goal_id != task.goal_id if task.goal_id is not None
                                else result.goal_id in self._earlier):
                continue  # a goal sent before the recording began, or one already replaced
            self._finished.add(result.goal_id)
            reason = (f"no pose recorded before the result at t={t:.3f}" if robot is None
                      else task_outcome(result.status, result.text, robot, task.pose, task.tolerance))
            self._finish(t, task, reason)

    def end(self, t: float) -> None:
        """The bag's end: a goal still running fails; END says how many failed."""
        if not self._tasks:
            return
        if self._running is not None:
            self._finish(t, self._running, f"no result for the goal before the recording ended at t={t:.3f}")
        total = len(self._tasks)
        self._publisher.publish(t, MissionEventKind.END,
                                reason=f"{self.failed} of {total} tasks failed" if self.failed else None)

    def info(self) -> dict[str, Any]:
        """The mission information of the recorded run (what the evaluator compares the tasks with)."""
        case = self._case
        return {
            "name": case.name, "testcase": case.testcase, "environment": case.environment, "robot": case.robot,
            "frame": case.frame, "recorded": True,
            "goals": [{"index": task.index, "x": task.pose.x, "y": task.pose.y, "yaw": task.pose.yaw,
                       "tolerance": task.tolerance} for task in self._tasks],
        }

    def _finish(self, t: float, task: _Task, reason: str | None) -> None:
        kind = MissionEventKind.TASK_SUCCESS if reason is None else MissionEventKind.TASK_FAIL
        self.failed += reason is not None
        self._publisher.publish(t, kind, task.index, task.pose, reason)
        self._running = None

    def _tolerance(self, index: int) -> float:
        goals = self._case.goals  # a mission has at least one (rei.artifacts.mission)
        return goals[min(index, len(goals) - 1)].tolerance

