# SPDX-License-Identifier: EPL-2.0
"""The client side of nav2's NavigateToPose action on plain DDS, laid out as rmw_cyclonedds carries a ROS 2 action.

An action is two services and two topics under ``<name>/_action/``: REI sends goals (``send_goal``) and cancels
them (``cancel_goal``), and reads the goals' states from ``status`` (action_msgs/GoalStatusArray, which the server
publishes on every change, with the final state). A service is a request topic ``rq/<service>Request`` and a
reply topic ``rr/<service>Reply``; rmw_cyclonedds puts its request header (the client's 64-bit id, a sequence
number) before the fields and echoes it in the reply, and a server answers only a client whose request writer and
reply reader carry the same ``clientid=...;`` in their user data. ``get_result`` is not used: the status topic
has the final state, and NavigateToPose's result differs between ROS 2 releases. Feedback is not read.
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


def action_topics(name: str) -> dict[str, str]:
    """DDS topic names of action ``name`` (``navigate_to_pose`` -> ``rq/navigate_to_pose/_action/...``)."""
    base = name.strip("/") + "/_action/"
    return {"send_goal_request": f"rq/{base}send_goalRequest", "send_goal_reply": f"rr/{base}send_goalReply",
            "cancel_request": f"rq/{base}cancel_goalRequest", "cancel_reply": f"rr/{base}cancel_goalReply",
            "status": f"rt/{base}status"}


def new_goal_id() -> t.UUID:
    return t.UUID(uuid=list(secrets.token_bytes(16)))


class NavigateToPoseClient:
    """Sends goals, cancels them and follows their states; ``on_final(goal id, status)`` is called (on a DDS
    thread) once per goal when its state becomes final."""

    def __init__(self, participant: DomainParticipant, name: str,
                 on_final: Callable[[bytes, NavStatus], None]) -> None:
        self.name = name
        self._id = secrets.randbits(63)
        self._sequence = 0
        self._on_final = on_final
        self._lock = threading.Condition()
        self._replies: dict[int, bool] = {}  # sequence number -> accepted
        self._finals: set[bytes] = set()
        names = action_topics(name)
        qos = service_qos(self._id)

        def topic(key: str, kind: type) -> Topic:
            return Topic(participant, names[key], kind)

        self._send = DataWriter(participant, topic("send_goal_request", t.NavigateToPose_SendGoal_Request), qos)
        self._send_reply = listening_reader(participant, topic("send_goal_reply", t.NavigateToPose_SendGoal_Response),
                                            qos, self._on_send_reply)
        self._cancel = DataWriter(participant, topic("cancel_request", t.CancelGoal_Request), qos)
        # read only so that the server sees a reply reader of this client (it answers no client without one)
        self._cancel_reply = listening_reader(participant, topic("cancel_reply", t.CancelGoal_Response), qos,
                                              lambda reader: reader.take(N=16))
        self._status = listening_reader(participant, topic("status", t.GoalStatusArray), status_qos(), self._on_status)

    def server_ready(self) -> bool:
        """The server's request readers and reply writers are matched (discovery is done both ways)."""
        return all(len(entity.get_matched_subscriptions() if isinstance(entity, DataWriter)
                       else entity.get_matched_publications()) > 0
                   for entity in (self._send, self._send_reply, self._cancel, self._status))

    def send(self, goal_id: t.UUID, goal: t.NavigateToPose_Goal, timeout: float) -> bool | None:
        """Send a goal and wait up to ``timeout`` wall seconds for the server's answer: accepted, rejected, or None
        when it did not answer."""
        with self._lock:
            self._sequence += 1
            sequence = self._sequence
        self._send.write(t.NavigateToPose_SendGoal_Request(rmw_client=self._id, rmw_sequence=sequence,
                                                            goal_id=goal_id, goal=goal))
        with self._lock:
            self._lock.wait_for(lambda: sequence in self._replies, timeout=timeout)
            return self._replies.pop(sequence, None)

    def cancel(self, goal_id: t.UUID) -> None:
        with self._lock:
            self._sequence += 1
            sequence = self._sequence
        self._cancel.write(t.CancelGoal_Request(rmw_client=self._id, rmw_sequence=sequence,
                                                goal_info=t.GoalInfo(goal_id=goal_id)))

    # -- DDS listeners (their threads) ---------------------------------------------------------------------

    def _on_send_reply(self, reader: DataReader) -> None:
        replies = [reply for reply in reader.take(N=16) if isinstance(reply, t.NavigateToPose_SendGoal_Response)]
        with self._lock:
            for reply in replies:
                if reply.rmw_client == self._id:  # a reply to another client of the same server
                    self._replies[reply.rmw_sequence] = bool(reply.accepted)
            self._lock.notify_all()

    def _on_status(self, reader: DataReader) -> None:
        for array in reader.take(N=16):
            if not isinstance(array, t.GoalStatusArray):
                continue
            for entry in array.status_list:
                goal = bytes(entry.goal_info.goal_id.uuid)
                final = ACTION_MSGS_FINAL.get(entry.status)
                if final is None or goal in self._finals:
                    continue
                self._finals.add(goal)
                self._on_final(goal, final)
