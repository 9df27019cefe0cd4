# SPDX-License-Identifier: EPL-2.0
"""The client side of nav2's NavigateToPose action on plain DDS, following the ROS 2 action protocol as rclcpp's
and rclpy's clients do, laid out as rmw_cyclonedds carries a ROS 2 action.

An action is three services and two topics under ``<name>/_action/``: REI sends a goal (``send_goal``); once the
server accepts it, asks for its result (``get_result``, whose reply comes when the goal has ended and carries the
final state); reads the goals' states from ``status`` (action_msgs/GoalStatusArray) and the ``feedback`` topic;
and cancels goals (``cancel_goal``). A goal's final state is the first one either the status topic or the result
reply says (some servers, such as ros2-client's, publish the final status only after the result was asked for).
A service is a request topic ``rq/<service>Request`` and a reply topic ``rr/<service>Reply``; rmw_cyclonedds puts
its request header (the client's 64-bit id, a sequence number) before the fields and echoes it in the reply, and a
server answers only a client whose request writer and reply reader carry the same ``clientid=...;`` in their user
data.
"""

from __future__ import annotations

import secrets
import threading
from collections.abc import Callable
from typing import Any

from cyclonedds.core import Policy, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from rei.sut.api import NavStatus
from rei.sut.ros2 import types as t
from rei.sut.ros2.dds import listening_reader
from rei.sut.ros_conventions import ACTION_MSGS_FINAL


def service_qos(client_id: int | None = None) -> Qos:
    """rmw_qos_profile_services_default (reliable, volatile, keep-last 10) in XCDR1, with the client's id in the
    user data when given."""
    policies: list[Any] = [Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
                           Policy.Durability.Volatile, Policy.History.KeepLast(10),
                           Policy.DataRepresentation(use_cdrv0_representation=True)]
    if client_id is not None:
        policies.append(Policy.Userdata(f"clientid={client_id:016x};".encode()))
    return Qos(*policies)


def status_qos() -> Qos:
    """rcl_action's status topic: reliable, transient-local, keep-last 1 (a late reader gets the latest)."""
    return Qos(Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
               Policy.Durability.TransientLocal, Policy.History.KeepLast(1),
               Policy.DataRepresentation(use_cdrv0_representation=True))


def feedback_qos() -> Qos:
    """rcl_action's feedback topic: rmw_qos_profile_default (reliable, volatile, keep-last 10)."""
    return Qos(Policy.Reliability.Reliable(max_blocking_time=duration(milliseconds=100)),
               Policy.Durability.Volatile, Policy.History.KeepLast(10),
               Policy.DataRepresentation(use_cdrv0_representation=True))


def action_topics(name: str) -> dict[str, str]:
    """DDS topic names of action ``name`` (``navigate_to_pose`` -> ``rq/navigate_to_pose/_action/...``)."""
    base = name.strip("/") + "/_action/"
    return {"send_goal_request": f"rq/{base}send_goalRequest", "send_goal_reply": f"rr/{base}send_goalReply",
            "get_result_request": f"rq/{base}get_resultRequest", "get_result_reply": f"rr/{base}get_resultReply",
            "cancel_request": f"rq/{base}cancel_goalRequest", "cancel_reply": f"rr/{base}cancel_goalReply",
            "status": f"rt/{base}status", "feedback": f"rt/{base}feedback"}


def new_goal_id() -> t.UUID:
    return t.UUID(uuid=list(secrets.token_bytes(16)))


class NavigateToPoseClient:
    """Sends goals, asks for their results, cancels them and follows their states; ``on_final(goal id, status)``
    is called (on a DDS thread) once per goal when its state becomes final."""

    def __init__(self, participant: DomainParticipant, name: str,
                 on_final: Callable[[bytes, NavStatus], None]) -> None:
        self.name = name
        self._id = secrets.randbits(63)
        self._sequence = 0
        self._on_final = on_final
        self._lock = threading.Condition()
        self._replies: dict[int, bool] = {}  # send_goal's sequence number -> accepted
        self._result_of: dict[int, bytes] = {}  # get_result's sequence number -> goal id
        self._finals: set[bytes] = set()
        self._listed: set[bytes] = set()  # goal ids the status topic has shown: goals the server accepted
        self._by_status: set[int] = set()  # send_goal sequence numbers taken as accepted from the status topic
        self.feedback_count = 0
        names = action_topics(name)
        qos = service_qos(self._id)

        def topic(key: str, kind: type) -> Topic:
            return Topic(participant, names[key], kind)

        self._send = DataWriter(participant, topic("send_goal_request", t.NavigateToPose_SendGoal_Request), qos)
        self._send_reply = listening_reader(participant, topic("send_goal_reply", t.NavigateToPose_SendGoal_Response),
                                            qos, self._on_send_reply)
        self._result = DataWriter(participant, topic("get_result_request", t.NavigateToPose_GetResult_Request), qos)
        self._result_reply = listening_reader(
            participant, topic("get_result_reply", t.NavigateToPose_GetResult_Response), qos, self._on_result_reply)
        self._cancel = DataWriter(participant, topic("cancel_request", t.CancelGoal_Request), qos)
        # read only so that the server sees a reply reader of this client (it answers no client without one)
        self._cancel_reply = listening_reader(participant, topic("cancel_reply", t.CancelGoal_Response), qos,
                                              lambda reader: reader.take(N=16))
        self._status = listening_reader(participant, topic("status", t.GoalStatusArray), status_qos(), self._on_status)
        # read (and counted, not used): a server may wait for a feedback reader before it takes goals
        self._feedback = listening_reader(participant, topic("feedback", t.NavigateToPose_FeedbackMessage),
                                          feedback_qos(), self._on_feedback)

    def server_ready(self) -> bool:
        """The server's request readers, reply writers and status writer are matched (discovery is done both
        ways)."""
        return not self.unmatched()

    def unmatched(self) -> list[str]:
        """The DDS topics of the action that no server endpoint matches yet (for a message that names them)."""
        entities = (self._send, self._send_reply, self._result, self._result_reply, self._cancel, self._status)
        return [entity.topic.name for entity in entities
                if not (entity.get_matched_subscriptions() if isinstance(entity, DataWriter)
                        else entity.get_matched_publications())]

    def send(self, goal_id: t.UUID, goal: t.NavigateToPose_Goal) -> int:
        """Send a goal; its request's sequence number, for ``answer``."""
        sequence = self._next()
        self._send.write(t.NavigateToPose_SendGoal_Request(rmw_client=self._id, rmw_sequence=sequence,
                                                            goal_id=goal_id, goal=goal))
        return sequence

    def answer(self, sequence: int, goal_id: t.UUID, timeout: float) -> bool | None:
        """The server's answer to send_goal request ``sequence`` within ``timeout`` wall seconds: accepted,
        rejected, or None (none yet). Once accepted, the goal's result is asked for (get_result), as rclcpp's and
        rclpy's clients do.

        A goal the status topic lists was accepted (only accepted goals have a status) even if its reply never
        comes: a server whose reply writer had not yet discovered this client's reply reader (RustDDS's servers do
        not wait for it, unlike rmw_cyclonedds's) sends the reply to nobody, whereas the transient-local status
        reaches a late reader."""
        goal = bytes(goal_id.uuid)
        with self._lock:
            self._lock.wait_for(lambda: sequence in self._replies or goal in self._listed, timeout=timeout)
            accepted = self._replies.pop(sequence, None)
            if accepted is None and goal in self._listed:
                accepted = True  # its reply may still come (ros2-client publishes the status first)
                self._by_status.add(sequence)
        if accepted:
            result_sequence = self._next()
            with self._lock:
                self._result_of[result_sequence] = bytes(goal_id.uuid)
            self._result.write(t.NavigateToPose_GetResult_Request(
                rmw_client=self._id, rmw_sequence=result_sequence, goal_id=goal_id))
        return accepted

    @property
    def replies_missed(self) -> int:
        """Goals accepted per the status topic whose send_goal reply never came."""
        with self._lock:
            return sum(1 for sequence in self._by_status if sequence not in self._replies)

    def cancel(self, goal_id: t.UUID) -> None:
        self._cancel.write(t.CancelGoal_Request(rmw_client=self._id, rmw_sequence=self._next(),
                                                goal_info=t.GoalInfo(goal_id=goal_id)))

    def _next(self) -> int:
        with self._lock:
            self._sequence += 1
            return self._sequence

    def _final(self, goal: bytes, code: int) -> None:
        final = ACTION_MSGS_FINAL.get(code)
        with self._lock:
            if final is None or goal in self._finals:
                return
            self._finals.add(goal)
        self._on_final(goal, final)

    # -- DDS listeners (their threads) ---------------------------------------------------------------------

    def _on_send_reply(self, reader: DataReader) -> None:
        replies = [reply for reply in reader.take(N=16) if isinstance(reply, t.NavigateToPose_SendGoal_Response)]
        with self._lock:
            for reply in replies:
                if reply.rmw_client == self._id:  # a reply to another client of the same server
                    self._replies[reply.rmw_sequence] = bool(reply.accepted)
            self._lock.notify_all()

    def _on_result_reply(self, reader: DataReader) -> None:
        for reply in reader.take(N=16):
            if not isinstance(reply, t.NavigateToPose_GetResult_Response) or reply.rmw_client != self._id:
                continue
            with self._lock:
                goal = self._result_of.pop(reply.rmw_sequence, None)
            if goal is not None:
                self._final(goal, reply.status)

    def _on_status(self, reader: DataReader) -> None:
        for array in reader.take(N=16):
            if isinstance(array, t.GoalStatusArray):
                with self._lock:
                    self._listed.update(bytes(entry.goal_info.goal_id.uuid) for entry in array.status_list)
                    self._lock.notify_all()
                for entry in array.status_list:
                    self._final(bytes(entry.goal_info.goal_id.uuid), entry.status)

    def _on_feedback(self, reader: DataReader) -> None:
        samples = reader.take(N=16)
        with self._lock:
            self.feedback_count += len(samples)
