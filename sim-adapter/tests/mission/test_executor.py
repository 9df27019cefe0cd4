# SPDX-License-Identifier: EPL-2.0
"""The mission executor: task events for good runs, planner failures, timeouts and false successes."""

from __future__ import annotations

from pathlib import Path

from sut.kinematic import KinematicWorld, rect_room

from rei.artifacts.mission import GoalSpec, MissionSpec
from rei.geometry import Pose2D, Twist2D
from rei.mission import MissionEvent, MissionEventKind, MissionExecutor, mission_info
from rei.sut.api import Controller, NavGoal, NavStatus, Observation, StaticMap
from rei.sut.nav import NavController

B, START, OK, FAIL, END = (MissionEventKind.BEGIN, MissionEventKind.TASK_START, MissionEventKind.TASK_SUCCESS,
                           MissionEventKind.TASK_FAIL, MissionEventKind.END)
WALLED_IN = [(4.5, 3.0, 0.0, 1.1, 0.1), (4.5, 2.0, 0.0, 1.1, 0.1), (4.0, 2.5, 0.0, 0.1, 1.1),
             (5.0, 2.5, 0.0, 0.1, 1.1)]


def mission(*goals: tuple[float, float, float]) -> MissionSpec:
    """A mission from (x, y, timeout) goals, starting at (0.5, 0.5), tolerance 0.25."""
    return MissionSpec(
        path=Path("mission.xml"), name="M", testcase="T", environment="Lab", robot="tb3", frame="world",
        start_floor="F_0_0", start=Pose2D(0.5, 0.5, 0.0),
        goals=tuple(GoalSpec(i, None, Pose2D(x, y, 0.0), 0.25, timeout) for i, (x, y, timeout) in enumerate(goals)),
    )


def run(spec, controller: Controller, world: KinematicWorld, max_time: float = 300.0) -> list[MissionEvent]:
    """The simulation loop as the lead will write it: tick the executor, then step the controller."""
    events: list[MissionEvent] = []
    executor = MissionExecutor(spec, controller, events.append)
    controller.reset(world.static_map, world.pose)
    while not executor.done and world.t < max_time:
        executor.tick(world.t, world.pose)
        world.apply(controller.step(world.observation()))
    assert executor.done
    executor.tick(world.t, world.pose)  # ticks after END emit nothing
    return events


def kinds(events: list[MissionEvent]) -> list[tuple[MissionEventKind, int | None]]:
    return [(e.event, e.task_index) for e in events]


def test_good_run_emits_begin_start_success_end():
    world = KinematicWorld(rect_room(6, 4), Pose2D(0.5, 0.5, 0.0))
    events = run(mission((5.5, 3.5, 120), (0.5, 3.5, 120)), NavController(), world)
    assert kinds(events) == [(B, None), (START, 0), (OK, 0), (START, 1), (OK, 1), (END, None)]
    assert all(e.reason is None for e in events)
    assert events[1].goal == Pose2D(5.5, 3.5) and events[2].goal == Pose2D(5.5, 3.5)
    times = [e.t for e in events]
    assert times == sorted(times) and times[0] == 0.0 and 20.0 < times[2] < 60.0


def test_unreachable_goal_fails_with_the_planner_reason_and_the_mission_goes_on():
    world = KinematicWorld(rect_room(6, 4, WALLED_IN), Pose2D(0.5, 0.5, 0.0))
    events = run(mission((4.5, 2.5, 120), (2.0, 1.0, 120)), NavController(), world)
    assert kinds(events) == [(B, None), (START, 0), (FAIL, 0), (START, 1), (OK, 1), (END, None)]
    assert events[2].reason.startswith("planner failure: the navigation aborted: planning failed: no path")
    assert events[2].t < 1.0
    assert events[-1].reason == "1 of 2 tasks failed"


class Stuck(Controller):
    """Accepts goals and never gets anywhere; records cancels."""

    def __init__(self, claim_success: bool = False) -> None:
        self.claim_success = claim_success
        self._status = NavStatus.IDLE
        self.goals: list[NavGoal] = []
        self.cancels = 0

    def reset(self, static_map: StaticMap, start: Pose2D) -> None:
        self._status = NavStatus.IDLE

    def set_goal(self, goal: NavGoal) -> None:
        self.goals.append(goal)
        self._status = NavStatus.ACTIVE

    def cancel(self) -> None:
        self.cancels += 1
        self._status = NavStatus.CANCELLED

    def step(self, observation: Observation) -> Twist2D:
        if self.claim_success and self._status is NavStatus.ACTIVE:
            self._status = NavStatus.SUCCEEDED
        return Twist2D()

    @property
    def status(self) -> NavStatus:
        return self._status


def test_timeout_cancels_the_controller_and_fails_the_task():
    stuck = Stuck()
    world = KinematicWorld(rect_room(6, 4), Pose2D(0.5, 0.5, 0.0))
    events = run(mission((5.5, 3.5, 3.0), (1.0, 0.5, 2.0)), stuck, world)
    assert kinds(events) == [(B, None), (START, 0), (FAIL, 0), (START, 1), (FAIL, 1), (END, None)]
    assert events[2].reason == "timeout: the goal was not reached within 3 s"
    assert 3.0 < events[2].t <= 3.2
    assert events[4].reason == "timeout: the goal was not reached within 2 s"
    assert stuck.cancels == 2
    assert [g.index for g in stuck.goals] == [0, 1]


def test_false_success_is_a_failure_judged_on_the_true_pose():
    liar = Stuck(claim_success=True)
    world = KinematicWorld(rect_room(6, 4), Pose2D(0.5, 0.5, 0.0))
    events = run(mission((5.5, 3.5, 60), (0.6, 0.5, 60)), liar, world)
    assert kinds(events) == [(B, None), (START, 0), (FAIL, 0), (START, 1), (OK, 1), (END, None)]
    assert events[2].reason == (
        "false success: the planner reported success but the robot is 5.83 m from the goal (tolerance 0.25 m)"
    )
    assert events[2].t == 0.1  # judged at the first tick after the claim


def test_mission_info_describes_the_mission():
    info = mission_info(mission((5.5, 3.5, 120)))
    assert info == {
        "name": "M", "testcase": "T", "environment": "Lab", "robot": "tb3", "frame": "world",
        "start": {"floor": "F_0_0", "x": 0.5, "y": 0.5, "yaw": 0.0},
        "goals": [{"index": 0, "floor": None, "x": 5.5, "y": 3.5, "yaw": 0.0, "tolerance": 0.25, "timeout": 120.0}],
    }
