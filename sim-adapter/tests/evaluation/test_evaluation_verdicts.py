# SPDX-License-Identifier: EPL-2.0
"""Table 4 verdicts on hand-written traces: each passes on one trace and fails or errs on another, and the
evidence names the times, signals, objects and tasks that decided it."""

from __future__ import annotations

import math

from rei.evaluation import Status, VerdictSettings
from rei.evaluation.metrics.social import AT_FAULT_SPEED, PersonCollision
from rei.evaluation.outcome import Evidence
from rei.evaluation.verdicts import REQUIREMENTS

from .traces import MISSION, MONITOR, TraceBuilder, judge_trace, nominal


def test_nominal_trace_passes_every_applicable_requirement_in_table_order() -> None:
    verdicts = judge_trace(nominal().messages)
    assert list(verdicts) == list(REQUIREMENTS)
    assert {name: v.status for name, v in verdicts.items()} == {
        "GEOM_CLOSE_LASER_CORRECT": Status.PASS, "GEOM_COLLISION_LASER_CORRECT": Status.PASS,
        "MISSION_SIMPLE": Status.PASS, "MISSION_SEQUENCE": Status.PASS,
        "MISSION_SEQUENCE_CYCLE": Status.NOT_APPLICABLE, "MISSION_WITH_HUMAN_TRAJECTORY": Status.PASS,
        "NO_ROBOT_AT_FAULT_COLLISION": Status.PASS,
    }


# -- GEOM_CLOSE_LASER_CORRECT -------------------------------------------------------------------------------

def test_close_confirmed_by_the_laser_names_entry_object_and_latency() -> None:
    verdict = judge_trace(nominal().messages)["GEOM_CLOSE_LASER_CORRECT"]
    assert verdict.status == Status.PASS
    (evidence,) = verdict.evidence
    assert (evidence.t, evidence.signal, evidence.object) == (5.0, "SIG_GEOM_FAR_TRANSIT_CLOSE", "table1")
    assert "laser reached CLOSE at t=5.100" in evidence.text and "+0.100 s" in evidence.text


def test_close_missed_by_the_laser_fails_with_the_geometric_entry() -> None:
    b = TraceBuilder().begin().geom(4.0, "FAR_TRANSIT_CLOSE").geom(7.5, "CLOSE_TRANSIT_FAR")
    verdict = judge_trace(b.task(10.0, 0).end(20.0).messages)["GEOM_CLOSE_LASER_CORRECT"]
    assert verdict.status == Status.FAIL
    assert verdict.message.startswith("1 geometric CLOSE episode(s) missed by the laser, 0 laser false alarm")
    (evidence,) = verdict.evidence
    assert (evidence.t, evidence.object) == (4.0, "table1") and evidence.text.startswith("missed")
    assert "to 7.500" in evidence.text


def test_laser_close_without_geometry_is_a_false_alarm() -> None:
    b = nominal(close=False)
    b.messages.clear()
    b.begin().laser(3.0, "FAR_TRANSIT_CLOSE").laser(3.2, "CLOSE_TRANSIT_FAR").task(10.0, 0).end(20.0)
    verdict = judge_trace(b.messages)["GEOM_CLOSE_LASER_CORRECT"]
    assert verdict.status == Status.FAIL
    assert verdict.message == "0 geometric CLOSE episode(s) missed by the laser, 1 laser false alarm(s)"
    (evidence,) = verdict.evidence
    assert (evidence.t, evidence.signal, evidence.object) == (3.0, "SIG_LASER_FAR_TRANSIT_CLOSE", "laser")
    assert evidence.text.startswith("false alarm")


def test_laser_within_the_tolerance_after_the_episode_still_confirms_it() -> None:
    b = TraceBuilder().begin().geom(4.0, "FAR_TRANSIT_CLOSE").geom(6.0, "CLOSE_TRANSIT_FAR")
    b.laser(6.9, "FAR_TRANSIT_CLOSE").laser(7.0, "CLOSE_TRANSIT_FAR").task(10.0, 0).end(20.0)
    assert judge_trace(b.messages)["GEOM_CLOSE_LASER_CORRECT"].status == Status.PASS
    strict = judge_trace(b.messages, settings=VerdictSettings(tolerance=0.5))["GEOM_CLOSE_LASER_CORRECT"]
    assert strict.status == Status.FAIL
    assert [e.t for e in strict.evidence] == [4.0, 6.9]  # the miss and the (now unmatched) laser episode


def test_brief_unconfirmed_close_is_a_miss() -> None:
    # the 0.55 s graze of simple_navigation's turn at goal 0: the laser's per-beam clearance sees the corner
    # that does it, so there is no grace for brief episodes any more
    b = TraceBuilder().begin().geom(15.8, "FAR_TRANSIT_CLOSE", "W_4_0_bottom")
    b.geom(16.35, "CLOSE_TRANSIT_FAR", "W_4_0_bottom").task(20.0, 0).end(30.0)
    verdict = judge_trace(b.messages)["GEOM_CLOSE_LASER_CORRECT"]
    assert verdict.status == Status.FAIL
    (miss,) = verdict.evidence
    assert (miss.t, miss.object) == (15.8, "W_4_0_bottom") and miss.text.startswith("missed")


def test_brief_close_that_reached_collision_is_judged() -> None:
    b = TraceBuilder().begin().geom(5.0, "FAR_TRANSIT_CLOSE").geom(5.1, "CLOSE_TRANSIT_COLLISION")
    b.geom(5.2, "COLLISION_TRANSIT_CLOSE").geom(5.3, "CLOSE_TRANSIT_FAR").task(10.0, 0).end(20.0)
    verdict = judge_trace(b.messages)["GEOM_CLOSE_LASER_CORRECT"]
    assert verdict.status == Status.FAIL and verdict.evidence[0].t == 5.0


def test_close_that_begins_in_the_last_tolerance_window_is_undecided() -> None:
    b = TraceBuilder().begin().task(10.0, 0).geom(19.5, "FAR_TRANSIT_CLOSE").end(20.0)
    verdict = judge_trace(b.messages)["GEOM_CLOSE_LASER_CORRECT"]
    assert verdict.status == Status.PASS
    assert "undecided" in verdict.evidence[0].text and verdict.evidence[0].t == 19.5


def test_laser_verdicts_do_not_apply_without_laser_data() -> None:
    verdicts = judge_trace(nominal().messages, settings=VerdictSettings(laser=False))
    assert verdicts["GEOM_CLOSE_LASER_CORRECT"].status == Status.NOT_APPLICABLE
    assert verdicts["GEOM_COLLISION_LASER_CORRECT"].status == Status.NOT_APPLICABLE


# -- GEOM_COLLISION_LASER_CORRECT ---------------------------------------------------------------------------

def test_collision_seen_by_the_laser_with_a_lag_passes() -> None:
    verdict = judge_trace(nominal(collision_with="table1").messages)["GEOM_COLLISION_LASER_CORRECT"]
    assert verdict.status == Status.PASS
    (evidence,) = verdict.evidence
    assert (evidence.t, evidence.signal, evidence.object) == (
        12.5, "SIG_GEOM_CLOSE_TRANSIT_COLLISION", "table1")
    assert "+0.400 s" in evidence.text


def test_collision_the_laser_never_sensed_fails() -> None:
    b = TraceBuilder().begin().task(10.0, 0).geom(12.0, "FAR_TRANSIT_CLOSE").laser(12.1, "FAR_TRANSIT_CLOSE")
    b.geom(12.5, "CLOSE_TRANSIT_COLLISION").end(20.0)  # stuck against the table until the end
    verdict = judge_trace(b.messages)["GEOM_COLLISION_LASER_CORRECT"]
    assert verdict.status == Status.FAIL
    (evidence,) = verdict.evidence
    assert (evidence.t, evidence.object) == (12.5, "table1")
    assert "to the end of the run (20.000)" in evidence.text
    assert judge_trace(b.messages)["GEOM_CLOSE_LASER_CORRECT"].status == Status.PASS


def test_laser_collision_without_geometric_collision_is_a_false_alarm() -> None:
    b = TraceBuilder().begin().laser(2.0, "FAR_TRANSIT_CLOSE").laser(2.0, "CLOSE_TRANSIT_COLLISION")
    b.laser(2.1, "COLLISION_TRANSIT_CLOSE").laser(2.1, "CLOSE_TRANSIT_FAR").task(10.0, 0).end(20.0)
    verdicts = judge_trace(b.messages)
    for name in ("GEOM_CLOSE_LASER_CORRECT", "GEOM_COLLISION_LASER_CORRECT"):
        assert verdicts[name].status == Status.FAIL
        assert verdicts[name].evidence[0].t == 2.0 and "false alarm" in verdicts[name].evidence[0].text


# -- MISSION_SIMPLE ------------------------------------------------------------------------------------------

def test_mission_without_collision_passes_simple() -> None:
    verdict = judge_trace(nominal().messages)["MISSION_SIMPLE"]
    assert verdict.status == Status.PASS and verdict.message == "no collision in 20.0 s"


def test_a_collision_during_a_fault_is_reported_with_it() -> None:
    b = TraceBuilder().begin().task(10.0, 0).at(11.0, "FAULT_LASER_BLACKOUT_BEGIN", "mission")
    b.at(11.5, "FAULT_LASER_NOISE_BEGIN", "mission").geom(12.0, "FAR_TRANSIT_CLOSE")
    b.geom(12.5, "CLOSE_TRANSIT_COLLISION").at(13.0, "FAULT_LASER_BLACKOUT_END", "mission")
    b.geom(14.0, "COLLISION_TRANSIT_CLOSE").geom(14.5, "CLOSE_TRANSIT_COLLISION").end(20.0)
    verdict = judge_trace(b.messages)["MISSION_SIMPLE"]
    assert verdict.status == Status.FAIL
    first, second = verdict.evidence
    assert first.text == ("collision with table1 at t=12.500 during task 1, while laser blackout and laser noise "
                          "were active")
    assert second.text == "collision with table1 at t=14.500 during task 1, while laser noise was active"
    assert judge_trace(nominal(collision_with="table1").messages)["MISSION_SIMPLE"].evidence[0].text.endswith(
        "during task 1")


def test_collision_fails_simple_with_time_object_and_task() -> None:
    verdict = judge_trace(nominal(collision_with="table1").messages)["MISSION_SIMPLE"]
    assert verdict.status == Status.FAIL
    assert verdict.message == "1 collision(s), first with table1 at t=12.500"
    assert verdict.evidence == (Evidence("collision with table1 at t=12.500 during task 1", 12.5,
                                         "SIG_GEOM_CLOSE_TRANSIT_COLLISION", "table1", 1),)


def test_state_data_gap_makes_simple_an_error_but_not_a_seen_collision() -> None:
    gap = nominal()
    gap.at(8.0, "MONITOR_DATA_GAP", "state", 3.0)
    verdict = judge_trace(gap.messages)["MISSION_SIMPLE"]
    assert verdict.status == Status.ERROR
    assert verdict.evidence[0] == Evidence("the monitor lost 3 state message(s) before this time", 8.0,
                                           "SIG_MONITOR_DATA_GAP", "state")
    collided = nominal(collision_with="table1").at(8.0, "MONITOR_DATA_GAP", "state", 3.0)
    assert judge_trace(collided.messages)["MISSION_SIMPLE"].status == Status.FAIL


def test_data_gap_errs_every_verdict_that_reads_the_lost_stream() -> None:
    state_gap = {n: v.status for n, v in judge_trace(
        nominal().at(8.0, "MONITOR_DATA_GAP", "state", 1.0).messages).items()}
    assert state_gap == {
        "GEOM_CLOSE_LASER_CORRECT": Status.ERROR, "GEOM_COLLISION_LASER_CORRECT": Status.ERROR,
        "MISSION_SIMPLE": Status.ERROR, "MISSION_SEQUENCE": Status.PASS,
        "MISSION_SEQUENCE_CYCLE": Status.NOT_APPLICABLE, "MISSION_WITH_HUMAN_TRAJECTORY": Status.ERROR,
        "NO_ROBOT_AT_FAULT_COLLISION": Status.ERROR,  # its collisions come from the signals, which may miss one
    }
    mission_gap = judge_trace(nominal().at(8.0, "MONITOR_DATA_GAP", "mission", 1.0).messages)
    assert mission_gap["MISSION_SEQUENCE"].status == Status.ERROR
    assert mission_gap["MISSION_SIMPLE"].status == Status.PASS


def test_run_without_mission_end_is_never_a_pass() -> None:
    cut = TraceBuilder().begin().geom(5.0, "FAR_TRANSIT_CLOSE").laser(5.1, "FAR_TRANSIT_CLOSE")
    verdicts = judge_trace(cut.messages, end_time=30.0)
    for name in ("GEOM_CLOSE_LASER_CORRECT", "GEOM_COLLISION_LASER_CORRECT", "MISSION_SIMPLE",
                 "MISSION_SEQUENCE", "MISSION_WITH_HUMAN_TRAJECTORY", "NO_ROBOT_AT_FAULT_COLLISION"):
        assert verdicts[name].status == Status.ERROR, name
        assert "without SIG_MISSION_END" in verdicts[name].message
        assert verdicts[name].evidence[0].t == 30.0


def test_run_that_ended_in_error_is_never_a_pass() -> None:
    verdicts = judge_trace(nominal().messages, completed=False, error_reason="the monitor died")
    verdict = verdicts["MISSION_SIMPLE"]
    assert verdict.status == Status.ERROR
    assert verdict.message == "cannot judge: the run ended in ERROR: the monitor died"


# -- MISSION_SEQUENCE ----------------------------------------------------------------------------------------

def test_every_goal_with_a_final_state_passes_sequence_even_a_reported_failure() -> None:
    b = TraceBuilder().begin().task(10.0, 0, "FAIL").end(20.0)
    verdict = judge_trace(b.messages, task_reasons={0: "planner failure: the navigation aborted"})[
        "MISSION_SEQUENCE"]
    assert verdict.status == Status.PASS
    assert [(e.t, e.task) for e in verdict.evidence] == [(10.0, 0), (20.0, 1)]
    assert "TASK_FAIL at t=10.000 (planner failure: the navigation aborted)" in verdict.evidence[0].text


def test_timeout_and_false_success_fail_sequence() -> None:
    b = TraceBuilder().begin().task(10.0, 0, "FAIL").end(20.0, outcome="FAIL")
    verdict = judge_trace(b.messages, task_reasons={
        0: "timeout: the goal was not reached within 120 s",
        1: "false success: the planner reported success but the robot is 2.82 m from the goal"})[
        "MISSION_SEQUENCE"]
    assert verdict.status == Status.FAIL
    assert [(e.t, e.task, e.signal) for e in verdict.evidence] == [
        (10.0, 0, "SIG_MISSION_TASK_FAIL"), (20.0, 1, "SIG_MISSION_TASK_FAIL")]
    assert "timeout" in verdict.evidence[0].text and "false success" in verdict.evidence[1].text


def test_goal_without_final_state_fails_sequence_when_the_mission_ended() -> None:
    b = TraceBuilder().begin().task(10.0, 0).at(20.0, "MISSION_END", "mission")  # task 1 never finished
    verdict = judge_trace(b.messages)["MISSION_SEQUENCE"]
    assert verdict.status == Status.FAIL
    assert verdict.evidence[0].text == "task 1 started at t=10.000 but has no final state"
    assert verdict.evidence[0].task == 1


def test_goal_never_started_fails_sequence() -> None:
    b = TraceBuilder().begin().task(10.0, 0, start_next=False).at(10.0, "MISSION_END", "mission")
    verdict = judge_trace(b.messages)["MISSION_SEQUENCE"]
    assert verdict.status == Status.FAIL and verdict.evidence[0].text.startswith("task 1 never started")


def test_tasks_out_of_goal_order_fail_sequence() -> None:
    b = TraceBuilder().at(0.0, "MISSION_BEGIN", "mission").at(0.0, "MISSION_TASK_START", "task_1")
    b.at(5.0, "MISSION_TASK_SUCCESS", "task_1").at(5.0, "MISSION_TASK_START", "task_0")
    b.at(9.0, "MISSION_TASK_SUCCESS", "task_0").at(9.0, "MISSION_END", "mission")
    verdict = judge_trace(b.messages)["MISSION_SEQUENCE"]
    assert verdict.status == Status.FAIL
    assert verdict.evidence[0].text == "task 1 started, expected task 0 (goal order)"


def test_mission_without_goals_makes_mission_requirements_not_applicable() -> None:
    b = TraceBuilder().at(0.0, "MISSION_BEGIN", "mission").at(0.0, "MISSION_END", "mission")
    verdicts = judge_trace(b.messages, mission={"name": "Empty", "goals": []})
    assert verdicts["MISSION_SEQUENCE"].status == Status.NOT_APPLICABLE
    assert verdicts["MISSION_SIMPLE"].status == Status.NOT_APPLICABLE


def test_sequence_without_mission_info_is_judged_on_the_tasks_seen() -> None:
    verdict = judge_trace(nominal().messages, mission=None)["MISSION_SEQUENCE"]
    assert verdict.status == Status.PASS
    assert verdict.evidence[-1].text == "mission information unavailable: judged on the 2 task(s) seen"


# -- MISSION_SEQUENCE_CYCLE ----------------------------------------------------------------------------------

CYCLE = {"name": "Patrol", "start": {"x": 0.5, "y": 0.5},
         "goals": [{"index": 0, "pose": [4.5, 0.5, 0.0], "tolerance": 0.25},
                   {"index": 1, "pose": [0.6, 0.5, 3.1], "tolerance": 0.25},
                   {"index": 2, "pose": [4.5, 0.4, 0.0], "tolerance": 0.25}]}


def test_back_and_forth_mission_without_collision_passes_cycle() -> None:
    b = TraceBuilder().begin().task(10.0, 0).task(20.0, 1).end(30.0, last_task=2)
    verdict = judge_trace(b.messages, mission=CYCLE)["MISSION_SEQUENCE_CYCLE"]
    assert verdict.status == Status.PASS
    assert "(0.50, 0.50) -> (4.50, 0.50) -> (0.60, 0.50) -> (4.50, 0.40)" in verdict.evidence[0].text


def test_collision_in_a_back_and_forth_mission_fails_cycle() -> None:
    b = TraceBuilder().begin().task(10.0, 0).geom(12.0, "FAR_TRANSIT_CLOSE", "walker")
    b.geom(12.0, "CLOSE_TRANSIT_COLLISION", "walker").geom(12.4, "COLLISION_TRANSIT_CLOSE", "walker")
    b.task(20.0, 1).end(30.0, last_task=2)
    verdict = judge_trace(b.messages, mission=CYCLE)["MISSION_SEQUENCE_CYCLE"]
    assert verdict.status == Status.FAIL
    assert [(e.t, e.object, e.task) for e in verdict.evidence] == [(12.0, "walker", 1)]


def test_cycle_does_not_apply_to_a_one_way_mission_and_errs_without_goal_positions() -> None:
    verdict = judge_trace(nominal().messages)["MISSION_SEQUENCE_CYCLE"]
    assert verdict.status == Status.NOT_APPLICABLE
    assert verdict.evidence[0].text == "path: (0.50, 0.50) -> (4.50, 0.50) -> (5.50, 3.50)"
    assert judge_trace(nominal().messages, mission=None)["MISSION_SEQUENCE_CYCLE"].status == Status.ERROR
    # the goals of the mission topic stand in for missing mission_info
    from_events = judge_trace(nominal().messages, mission=None, task_goals={0: (1.0, 1.0), 1: (2.0, 2.0)})
    assert from_events["MISSION_SEQUENCE_CYCLE"].status == Status.NOT_APPLICABLE


def test_a_return_trip_to_the_start_is_a_cycle() -> None:
    there_and_back = {"name": "Return", "start": {"x": 0.5, "y": 0.5},
                      "goals": [{"index": 0, "x": 4.5, "y": 0.5}, {"index": 1, "x": 0.5, "y": 0.6}]}
    verdict = judge_trace(nominal().messages, mission=there_and_back)["MISSION_SEQUENCE_CYCLE"]
    assert verdict.status == Status.PASS


# -- MISSION_WITH_HUMAN_TRAJECTORY ---------------------------------------------------------------------------

def test_human_collisions_below_n_collision_pass_and_at_it_fail() -> None:
    trace = nominal(collision_with="walker").messages
    allowed = judge_trace(trace, monitor={"requirements": {"maxHumanCollisions": 2}})[
        "MISSION_WITH_HUMAN_TRAJECTORY"]
    assert allowed.status == Status.PASS
    assert allowed.message == "1 collision(s) with humans (walker), fewer than N_COLLISION = 2"
    failed = judge_trace(trace, monitor=MONITOR)["MISSION_WITH_HUMAN_TRAJECTORY"]
    assert failed.status == Status.FAIL
    assert failed.message == "1 collision(s) with humans, not fewer than N_COLLISION = 1"
    assert [(e.t, e.object, e.signal) for e in failed.evidence] == [
        (12.5, "walker", "SIG_GEOM_CLOSE_TRANSIT_COLLISION")]


def test_a_human_bumping_a_robot_that_already_touches_a_wall_is_counted_from_the_per_object_episodes() -> None:
    """The robot-level state stays COLLISION from the wall on: Table 2 has no new signal for the human, the
    per-object signals have one (thesis 5.1.6.2's single zone would undercount)."""
    b = TraceBuilder().begin()
    b.geom(5.0, "FAR_TRANSIT_CLOSE", "W_0_0_bottom").geom(5.5, "CLOSE_TRANSIT_COLLISION", "W_0_0_bottom")
    b.at(5.5, "OBJECT_COLLISION_BEGIN", "W_0_0_bottom")
    b.at(6.0, "OBJECT_COLLISION_BEGIN", "walker").at(6.8, "OBJECT_COLLISION_END", "walker")
    b.at(8.0, "OBJECT_COLLISION_END", "W_0_0_bottom").geom(8.0, "COLLISION_TRANSIT_CLOSE", "W_0_0_bottom")
    b.geom(9.0, "CLOSE_TRANSIT_FAR", "W_0_0_bottom")
    verdicts = judge_trace(b.task(10.0, 0).end(20.0).messages)
    human = verdicts["MISSION_WITH_HUMAN_TRAJECTORY"]
    assert human.status == Status.FAIL, human
    assert [(e.t, e.object, e.signal) for e in human.evidence] == [(6.0, "walker", "SIG_OBJECT_COLLISION_BEGIN")]
    simple = verdicts["MISSION_SIMPLE"]  # Table 2's robot-level count: one collision, with the wall
    assert simple.message.startswith("1 collision(s), first with W_0_0_bottom at t=5.500"), simple.message
    # without per-object signals (hand-written rules) the robot-level collisions are all there is: none with a human
    robot_level = [m for m in b.messages if "OBJECT_COLLISION" not in m["signal"]]
    assert judge_trace(robot_level)["MISSION_WITH_HUMAN_TRAJECTORY"].status == Status.PASS


def test_collisions_with_other_objects_do_not_count_against_humans() -> None:
    verdict = judge_trace(nominal(collision_with="table1").messages)["MISSION_WITH_HUMAN_TRAJECTORY"]
    assert verdict.status == Status.PASS


def test_human_requirement_needs_humans_and_n_collision() -> None:
    no_humans = judge_trace(nominal().messages, world={"objects": [{"name": "table1", "category": "STATIC"}]})
    assert no_humans["MISSION_WITH_HUMAN_TRAJECTORY"].status == Status.NOT_APPLICABLE
    left_out = judge_trace(nominal().messages, settings=VerdictSettings(humans=False))
    assert left_out["MISSION_WITH_HUMAN_TRAJECTORY"].status == Status.NOT_APPLICABLE
    unknown = judge_trace(nominal().messages, monitor={"requirements": {}})["MISSION_WITH_HUMAN_TRAJECTORY"]
    assert unknown.status == Status.ERROR and "maxHumanCollisions" in unknown.message


# -- NO_ROBOT_AT_FAULT_COLLISION ------------------------------------------------------------------------------

def _bump(b: TraceBuilder, t: float, person: str = "walker") -> TraceBuilder:
    """A per-object collision with ``person`` at ``t`` (cep/patterns/contacts.vepl), over before the end."""
    return b.at(t, "OBJECT_COLLISION_BEGIN", person).at(t + 0.5, "OBJECT_COLLISION_END", person)


def test_a_collision_with_the_robot_at_fault_fails_naming_the_person_time_and_approach_speed() -> None:
    b = _bump(TraceBuilder().begin(), 6.0).task(10.0, 0).end(20.0)
    verdict = judge_trace(b.messages, person_collisions=(PersonCollision("walker", 6.0, 0.26),))[
        "NO_ROBOT_AT_FAULT_COLLISION"]
    assert verdict.status == Status.FAIL, verdict
    assert verdict.message == ("1 collision(s) with people with the robot at fault, first with walker at t=6.000 "
                               "(0.26 m/s towards them)")
    (evidence,) = verdict.evidence
    # the signal's coordinates: the search folds this failure into the collision's event (rei.search.failures)
    assert (evidence.t, evidence.signal, evidence.object, evidence.task) == (
        6.0, "SIG_OBJECT_COLLISION_BEGIN", "walker", 0)
    assert evidence.text == ("robot at fault: it drove into walker at 0.26 m/s towards their centre (more than "
                             "0.05 m/s) at t=6.000 during task 0")


def test_a_person_walking_into_a_robot_that_stands_or_backs_away_passes() -> None:
    b = _bump(_bump(TraceBuilder().begin(), 6.0), 8.0).task(10.0, 0).end(20.0)
    measured = (PersonCollision("walker", 6.0, 0.0), PersonCollision("walker", 8.0, AT_FAULT_SPEED))
    verdict = judge_trace(b.messages, person_collisions=measured)["NO_ROBOT_AT_FAULT_COLLISION"]
    assert verdict.status == Status.PASS, verdict
    assert verdict.message == "2 collision(s) with people (walker), none with the robot at fault"
    assert [(e.t, e.object) for e in verdict.evidence] == [(6.0, "walker"), (8.0, "walker")]
    assert verdict.evidence[1].text.startswith("person at fault: walker walked into the robot at t=8.000")
    assert "+0.05 m/s" in verdict.evidence[1].text  # AT_FAULT_SPEED itself is not yet the robot's fault


def test_the_signalled_collision_is_judged_by_the_recorded_one_of_the_same_person_and_sample() -> None:
    b = _bump(TraceBuilder().begin(), 6.0).task(10.0, 0).end(20.0)
    # the monitor's clock rounds to the millisecond: the recorded sample 0.4 ms off is the same collision
    near = judge_trace(b.messages, person_collisions=(PersonCollision("walker", 6.0004, 0.2),))
    assert near["NO_ROBOT_AT_FAULT_COLLISION"].status == Status.FAIL
    for measured in ((PersonCollision("walker", 6.05, 0.2),),  # a sample later: another collision
                     (PersonCollision("other", 6.0, 0.2),),  # someone else
                     (),  # the state shows none
                     None):  # the state was not measured
        verdict = judge_trace(b.messages, person_collisions=measured)["NO_ROBOT_AT_FAULT_COLLISION"]
        assert verdict.status == Status.ERROR, (measured, verdict)
        assert verdict.evidence[0].text.startswith("collision with walker at t=6.000 during task 0: cannot tell "
                                                   "who was at fault")
    unknown_speed = judge_trace(b.messages, person_collisions=(PersonCollision("walker", 6.0, math.nan),))
    assert "velocity was not recorded" in unknown_speed["NO_ROBOT_AT_FAULT_COLLISION"].evidence[0].text


def test_a_robot_at_fault_stands_against_missing_data_and_no_collision_passes_without_a_state() -> None:
    b = _bump(_bump(TraceBuilder().begin(), 6.0), 8.0).at(9.0, "MONITOR_DATA_GAP", "state", 2.0)
    messages = b.task(10.0, 0).end(20.0).messages
    seen = judge_trace(messages, person_collisions=(PersonCollision("walker", 8.0, 0.2),))
    assert seen["NO_ROBOT_AT_FAULT_COLLISION"].status == Status.FAIL  # the 6.0 one unjudged, the 8.0 one stands
    nothing = judge_trace(nominal().messages)["NO_ROBOT_AT_FAULT_COLLISION"]  # collisions with the table only
    assert nothing.status == Status.PASS and nothing.message == "no collision with people (walker)"


def test_a_person_bumping_a_robot_that_touches_a_wall_is_judged_and_tables_are_not_people() -> None:
    b = TraceBuilder().begin()
    b.geom(5.0, "FAR_TRANSIT_CLOSE", "W_0_0_bottom").geom(5.5, "CLOSE_TRANSIT_COLLISION", "W_0_0_bottom")
    b.at(5.5, "OBJECT_COLLISION_BEGIN", "W_0_0_bottom")
    _bump(b, 6.0)
    b.at(8.0, "OBJECT_COLLISION_END", "W_0_0_bottom").geom(8.0, "COLLISION_TRANSIT_CLOSE", "W_0_0_bottom")
    b.geom(9.0, "CLOSE_TRANSIT_FAR", "W_0_0_bottom")
    verdict = judge_trace(b.task(10.0, 0).end(20.0).messages, person_collisions=(
        PersonCollision("walker", 6.0, -0.1),))["NO_ROBOT_AT_FAULT_COLLISION"]
    assert verdict.status == Status.PASS and [e.object for e in verdict.evidence] == ["walker"]
    table = judge_trace(nominal(collision_with="table1").messages, person_collisions=(
        PersonCollision("walker", 1.0, 0.3),))["NO_ROBOT_AT_FAULT_COLLISION"]
    assert table.status == Status.PASS  # no collision with a person signalled: nothing to judge


def test_robot_at_fault_needs_humans() -> None:
    no_humans = judge_trace(nominal().messages, world={"objects": [{"name": "table1", "category": "STATIC"}]})
    assert no_humans["NO_ROBOT_AT_FAULT_COLLISION"].status == Status.NOT_APPLICABLE
    left_out = judge_trace(nominal().messages, settings=VerdictSettings(humans=False))
    assert left_out["NO_ROBOT_AT_FAULT_COLLISION"].status == Status.NOT_APPLICABLE


# -- stream integrity ----------------------------------------------------------------------------------------

def test_lost_signals_err_every_applicable_verdict() -> None:
    problem = Evidence("lost 2 signal(s) (seq 4 to 5)", 7.0)
    verdicts = judge_trace(nominal().messages, stream_problems=(problem,))
    assert {v.status for n, v in verdicts.items() if n != "MISSION_SEQUENCE_CYCLE"} == {Status.ERROR}
    assert all(problem in v.evidence for n, v in verdicts.items() if n != "MISSION_SEQUENCE_CYCLE")


def test_inconsistent_laser_transition_errs_the_laser_verdicts_only() -> None:
    b = TraceBuilder().begin().laser(1.2, "COLLISION_TRANSIT_CLOSE").laser(1.2, "CLOSE_TRANSIT_FAR")
    verdicts = judge_trace(b.task(10.0, 0).end(20.0).messages)
    assert verdicts["GEOM_CLOSE_LASER_CORRECT"].status == Status.ERROR
    assert verdicts["GEOM_CLOSE_LASER_CORRECT"].evidence[0].text == (
        "SIG_LASER_COLLISION_TRANSIT_CLOSE while the laser zone was FAR: a transition is missing")
    assert verdicts["MISSION_SIMPLE"].status == Status.PASS


def test_mission_fixture_is_not_a_cycle() -> None:
    assert len(MISSION["goals"]) == 2
