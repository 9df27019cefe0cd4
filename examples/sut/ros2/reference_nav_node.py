# SPDX-License-Identifier: EPL-2.0
"""REI's reference navigation (``rei.sut.nav.NavController``) as a ROS 2 navigation stack on the wire: a system under
test for the ROS 2 bridge, standing in for Nav2 where no ROS 2 can be installed.

    rei run CASE --sut "ros2:python3 examples/sut/ros2/reference_nav_node.py" --sut-map

It is written on plain DDS (Cyclone DDS's Python binding and REI's ROS 2 types), and speaks what a ROS 2 node on
rmw_cyclonedds speaks: it reads ``rt/clock``, ``rt/odom``, ``rt/scan`` and the transient-local ``rt/map``, serves
nav2's NavigateToPose action (``navigate_to_pose/_action/send_goal``, ``get_result`` and ``cancel_goal`` with
rmw_cyclonedds's request header echoed in each reply, and the action's status topic), and publishes ``rt/cmd_vel`` exactly once per
new clock time, zero when idle. It takes ROS_DOMAIN_ID and CYCLONEDDS_URI from its environment, as the bridge sets
them. Goals are map-frame poses, the tolerance is 0.25 m (NavigateToPose goals carry none).

    rei run CASE --sut "ros2:python3 examples/sut/ros2/reference_nav_node.py --script FILE"

plays a ``script:FILE`` timeline instead (``rei.sut.script``; no map needed, every goal SUCCEEDED once it has
played), a script's sideways speed on ``cmd_vel``'s ``linear.y``.
"""

from __future__ import annotations

import os
import sys
import threading

import numpy as np
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import LaserScan, NavGoal, NavStatus, Observation, StaticMap
from rei.sut.nav import NavController
from rei.sut.rasterize import static_map_of_grid
from rei.sut.ros2 import messages as m
from rei.sut.ros2 import types as t
from rei.sut.ros2.action import action_topics, service_qos, status_qos
from rei.sut.ros2.dds import listening_reader
from rei.sut.script import ScriptController, load_script

FOOTPRINT = (0.281, 0.306)
MAX_LINEAR, MAX_ANGULAR, TOLERANCE = 0.26, 1.82, 0.25
ODOM_TIMEOUT = 0.05  # wall seconds a step waits for the odometry stamped with its own time
#: action_msgs/GoalStatus codes.
EXECUTING, SUCCEEDED, CANCELED, ABORTED = 2, 4, 5, 6
FINAL = {NavStatus.SUCCEEDED: SUCCEEDED, NavStatus.ABORTED: ABORTED, NavStatus.CANCELLED: CANCELED}


def pose2d_of(pose: t.Pose) -> Pose2D:
    return Pose2D(pose.position.x, pose.position.y, m.yaw_of(pose.orientation))


class ReferenceNavNode:
    def __init__(self, participant: DomainParticipant, script: ScriptController | None = None) -> None:
        self.participant = participant
        self.lock = threading.Condition()
        self.nav: NavController | ScriptController | None = script
        self.script = script is not None
        self.odom: t.Odometry | None = None
        self.scan: LaserScan | None = None
        self.clock_ns = 0  # the newest clock time
        self.goals = 0
        self.active: t.UUID | None = None  # the goal being pursued
        self.statuses: dict[bytes, t.GoalStatus] = {}  # every goal this server has had
        self.result_requests: dict[bytes, list[t.NavigateToPose_GetResult_Request]] = {}  # of running goals
        names = action_topics("navigate_to_pose")

        def reader(topic: str, kind: type, qos, callback) -> DataReader:  # type: ignore[no-untyped-def]
            return listening_reader(participant, Topic(participant, topic, kind), qos, callback)

        def writer(topic: str, kind: type, qos) -> DataWriter:  # type: ignore[no-untyped-def]
            return DataWriter(participant, Topic(participant, topic, kind), qos=qos)

        topics = m.TOPICS
        self.cmd_vel = writer(topics["cmd_vel"].dds_name, t.Twist, topics["cmd_vel"].qos)
        self.goal_reply = writer(names["send_goal_reply"], t.NavigateToPose_SendGoal_Response, service_qos())
        self.cancel_reply = writer(names["cancel_reply"], t.CancelGoal_Response, service_qos())
        self.result_reply = writer(names["get_result_reply"], t.NavigateToPose_GetResult_Response, service_qos())
        self.status = writer(names["status"], t.GoalStatusArray, status_qos())
        self.readers = [
            reader(topics["clock"].dds_name, t.Clock, topics["clock"].qos, self.on_clock),
            reader(topics["odom"].dds_name, t.Odometry, topics["odom"].qos, self.on_odom),
            reader(topics["scan"].dds_name, t.LaserScan, topics["scan"].qos, self.on_scan),
            reader(topics["map"].dds_name, t.OccupancyGrid, topics["map"].qos, self.on_map),
            reader(names["send_goal_request"], t.NavigateToPose_SendGoal_Request, service_qos(), self.on_goal),
            reader(names["cancel_request"], t.CancelGoal_Request, service_qos(), self.on_cancel),
            reader(names["get_result_request"], t.NavigateToPose_GetResult_Request, service_qos(),
                   self.on_result_request),
        ]

    # -- inputs (DDS threads) ----------------------------------------------------------------------------------

    def on_clock(self, reader: DataReader) -> None:
        with self.lock:
            for clock in reader.take(N=16):
                self.clock_ns = max(self.clock_ns, m.nanoseconds(clock.clock))
            self.lock.notify_all()

    def on_odom(self, reader: DataReader) -> None:
        with self.lock:
            for odom in reader.take(N=16):
                self.odom = odom
            self.lock.notify_all()

    def on_scan(self, reader: DataReader) -> None:
        for msg in reader.take(N=4):
            self.scan = LaserScan(m.nanoseconds(msg.header.stamp) * 1e-9, msg.angle_min, msg.angle_increment,
                                  msg.range_min, msg.range_max, np.asarray(msg.ranges, dtype=float))

    def on_map(self, reader: DataReader) -> None:
        for grid in reader.take(N=1):
            if self.script:
                continue
            info = grid.info
            static_map = static_map_of_grid(grid.data, info.width, info.height, info.resolution,
                                            pose2d_of(info.origin), FOOTPRINT)
            nav = NavController(MAX_LINEAR, MAX_ANGULAR, FOOTPRINT)
            with self.lock:
                nav.reset(static_map, pose2d_of(self.odom.pose.pose) if self.odom else Pose2D(0.0, 0.0))
                if self.active is not None:
                    self.finish(ABORTED)
                self.nav = nav
            print(f"map {info.width}x{info.height} cells: {len(static_map.obstacles)} rectangles", flush=True)

    def on_goal(self, reader: DataReader) -> None:
        for request in reader.take(N=4):
            with self.lock:
                accepted = self.nav is not None  # no goals before the map
                if accepted:
                    if self.active is not None:
                        self.finish(ABORTED)  # nav2 aborts the goal a new one replaces
                    self.goals += 1
                    self.nav.set_goal(NavGoal(self.goals, pose2d_of(request.goal.pose.pose), TOLERANCE))
                    self.active = request.goal_id
                    self.set_status(request.goal_id, EXECUTING)
            self.goal_reply.write(t.NavigateToPose_SendGoal_Response(
                rmw_client=request.rmw_client, rmw_sequence=request.rmw_sequence, accepted=accepted,
                stamp=t.Time(sec=self.clock_ns // 10**9, nanosec=self.clock_ns % 10**9)))

    def on_cancel(self, reader: DataReader) -> None:
        for request in reader.take(N=4):
            canceling = []
            with self.lock:
                if self.active is not None and bytes(self.active.uuid) == bytes(request.goal_info.goal_id.uuid):
                    canceling.append(t.GoalInfo(goal_id=self.active))
                    if self.nav is not None:
                        self.nav.cancel()
                    self.finish(CANCELED)
            self.cancel_reply.write(t.CancelGoal_Response(
                rmw_client=request.rmw_client, rmw_sequence=request.rmw_sequence,
                return_code=0 if canceling else 2, goals_canceling=canceling))  # 2: ERROR_UNKNOWN_GOAL_ID

    def on_result_request(self, reader: DataReader) -> None:
        """Answered at once for an ended goal, else when it ends (an unknown goal: status UNKNOWN, as rcl_action)."""
        for request in reader.take(N=4):
            with self.lock:
                goal = bytes(request.goal_id.uuid)
                status = self.statuses.get(goal)
                if status is not None and status.status == EXECUTING:
                    self.result_requests.setdefault(goal, []).append(request)
                else:
                    self.answer_result(request, status.status if status is not None else 0)

    # -- the action's state (under self.lock) ------------------------------------------------------------------

    def answer_result(self, request: t.NavigateToPose_GetResult_Request, code: int) -> None:
        self.result_reply.write(t.NavigateToPose_GetResult_Response(
            rmw_client=request.rmw_client, rmw_sequence=request.rmw_sequence, status=code))

    def set_status(self, goal_id: t.UUID, code: int) -> None:
        self.statuses[bytes(goal_id.uuid)] = t.GoalStatus(goal_info=t.GoalInfo(goal_id=goal_id), status=code)
        self.status.write(t.GoalStatusArray(status_list=list(self.statuses.values())))

    def finish(self, code: int) -> None:
        assert self.active is not None
        self.set_status(self.active, code)
        for request in self.result_requests.pop(bytes(self.active.uuid), []):
            self.answer_result(request, code)
        self.active = None

    # -- the step ------------------------------------------------------------------------------------------

    def run(self) -> None:
        stepped = 0
        while True:
            with self.lock:
                if not self.lock.wait_for(lambda last=stepped: self.clock_ns > last, timeout=1.0):
                    continue
                now = stepped = self.clock_ns
                self.lock.wait_for(lambda t=now: self.odom is not None and m.nanoseconds(self.odom.header.stamp) >= t,
                                   timeout=ODOM_TIMEOUT)
                cmd = Twist2D()
                if self.odom is not None and self.nav is not None:
                    odom = self.odom
                    twist = odom.twist.twist
                    cmd = self.nav.step(Observation(now * 1e-9, pose2d_of(odom.pose.pose),
                                                    Twist2D(twist.linear.x, twist.angular.z, twist.linear.y),
                                                    self.scan))
                    if self.active is not None and self.nav.status in FINAL:
                        self.finish(FINAL[self.nav.status])
            self.cmd_vel.write(m.twist(cmd))


def main() -> None:
    domain = int(os.environ.get("ROS_DOMAIN_ID", "0"))
    participant = DomainParticipant(domain)  # CYCLONEDDS_URI from the environment: the bridge's loopback set-up
    script = None
    if sys.argv[1:2] == ["--script"]:
        script = ScriptController(load_script(sys.argv[2]))
        script.reset(StaticMap((0.0, 0.0, 1.0, 1.0), (), (0.0, 0.0)), Pose2D(0.0, 0.0))  # both ignored
    print(f"{'script' if script else 'reference navigation'} on DDS domain {domain}", flush=True)
    try:
        ReferenceNavNode(participant, script).run()
    except KeyboardInterrupt:
        sys.exit(0)


if __name__ == "__main__":
    main()
