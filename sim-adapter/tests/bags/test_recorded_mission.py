# SPDX-License-Identifier: EPL-2.0
"""A bag's goals and results as mission events: the cases a recorded run has and a simulated one has not."""

from __future__ import annotations

from pathlib import Path

from rei.artifacts.mission import GoalSpec, MissionSpec
from rei.bags.mission import RecordedMission
from rei.bags.reader import RecordedGoal, RecordedResult
from rei.geometry import Pose2D
from rei.sut.api import NavStatus
from rei.wamp.collector import MissionPublisher
from rei.wamp.recording import read_recording, stream_path

MISSION = MissionSpec(Path("mission.xml"), "M", "T", "Lab", "tb3", "world", None, Pose2D(0, 0, 0),
                      (GoalSpec(0, None, Pose2D(1, 0, 0), 0.2, 60.0), GoalSpec(1, None, Pose2D(2, 0, 0), 0.4, 60.0)))
AT_GOAL = Pose2D(1.0, 0.05, 0.0)


def _events(tmp_path: Path, feed) -> list[tuple[float, str, int, str | None]]:
    with MissionPublisher("import", tmp_path) as publisher:
        mission = RecordedMission(MISSION, publisher)
        feed(mission)
    return [(m["t"], m["event"], m["task_index"], m.get("reason"))
            for m in read_recording(stream_path(tmp_path, "mission"))]


def test_a_new_goal_while_one_runs_cancels_it_and_its_late_result_is_not_taken_for_the_new_one(tmp_path) -> None:
    def feed(mission: RecordedMission) -> None:
        mission.goal(1.0, RecordedGoal("a", Pose2D(1, 0, 0)))
        mission.goal(2.0, RecordedGoal("b", Pose2D(3, 0, 0)))
        mission.results(2.1, (RecordedResult("a", NavStatus.CANCELLED, "preempted"),), AT_GOAL)
        mission.results(5.0, (RecordedResult("b", NavStatus.ABORTED, "no path"),), AT_GOAL)
        mission.end(6.0)

    assert _events(tmp_path, feed) == [
        (1.0, "BEGIN", -1, None), (1.0, "TASK_START", 0, None),
        (2.0, "TASK_FAIL", 0, "the controller cancelled the goal: a new goal replaced it"),
        (2.0, "TASK_START", 1, None),
        (5.0, "TASK_FAIL", 1, "planner failure: the navigation aborted: no path"),
        (6.0, "END", -1, "2 of 2 tasks failed"),
    ]


def test_a_pose_goal_takes_the_first_final_state_of_a_goal_not_shown_before_it_was_sent(tmp_path) -> None:
    def feed(mission: RecordedMission) -> None:
        mission.results(0.5, (RecordedResult("old", None, ""),), None)  # running before the goal was sent
        mission.goal(1.0, RecordedGoal(None, Pose2D(1, 0, 0)))
        mission.results(1.5, (RecordedResult("old", NavStatus.SUCCEEDED, ""),
                              RecordedResult("new", None, "")), AT_GOAL)
        mission.results(3.0, (RecordedResult("old", NavStatus.SUCCEEDED, ""),
                              RecordedResult("new", NavStatus.SUCCEEDED, "")), AT_GOAL)
        mission.results(3.5, (RecordedResult("new", NavStatus.SUCCEEDED, ""),), AT_GOAL)  # repeated while kept
        mission.end(4.0)

    assert _events(tmp_path, feed) == [
        (1.0, "BEGIN", -1, None), (1.0, "TASK_START", 0, None), (3.0, "TASK_SUCCESS", 0, None),
        (4.0, "END", -1, None),
    ]


def test_tolerances_come_from_the_cases_goals_by_index_and_its_last_beyond_them(tmp_path) -> None:
    off_by = Pose2D(1.3, 0.0, 0.0)  # 0.3 m from each goal: beyond goal 0's 0.2 m, within goal 1's 0.4 m

    def feed(mission: RecordedMission) -> None:
        for index, goal_id in enumerate("abc"):
            mission.goal(float(index), RecordedGoal(goal_id, Pose2D(1, 0, 0)))
            mission.results(index + 0.5, (RecordedResult(goal_id, NavStatus.SUCCEEDED, ""),), off_by)
        assert [goal["tolerance"] for goal in mission.info()["goals"]] == [0.2, 0.4, 0.4]
        mission.end(3.0)

    outcomes = [(event, index) for _, event, index, _ in _events(tmp_path, feed) if event.startswith("TASK_")
                and event != "TASK_START"]
    assert outcomes == [("TASK_FAIL", 0), ("TASK_SUCCESS", 1), ("TASK_SUCCESS", 2)]
