# SPDX-License-Identifier: EPL-2.0
"""REI's ROS 2 messages (rei.sut.ros2): every type's CDR byte for byte as rosbags (an independent ROS 2 serializer)
writes it, each topic through DDS from one participant to another in a second process, on loopback only, and the
ROS domains runs take (rei.sut.ros2.environment.DomainLease)."""

from __future__ import annotations

import dataclasses
import json
import math
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.idl import IdlStruct
from cyclonedds.idl._support import Endianness
from cyclonedds.pub import DataWriter
from cyclonedds.topic import Topic
from rosbags.typesys import Stores, get_types_from_msg, get_typestore

from rei.geometry import Pose2D, Twist2D, quaternion_of_yaw
from rei.robots import FixedJoint
from rei.sut.api import LaserScan, NavGoal, StaticMap
from rei.sut.ros2 import messages as m
from rei.sut.ros2 import types as t
from rei.sut.ros2.action import new_goal_id
from rei.sut.ros2.environment import RUN_DOMAINS, DomainLease, cyclone_config, discovery_port

STORE = get_typestore(Stores.ROS2_HUMBLE)
#: What rosbags' Humble store lacks, from nav2_msgs/action/NavigateToPose.action (Humble) and action_msgs/srv/
#: CancelGoal.srv; a service's request or response is registered as a message of its fields.
EXTRA = {
    "nav2_msgs/action/NavigateToPose_Goal": "geometry_msgs/PoseStamped pose\nstring behavior_tree",
    "nav2_msgs/action/NavigateToPose_SendGoal_Request": "unique_identifier_msgs/UUID goal_id\n"
                                                        "nav2_msgs/NavigateToPose_Goal goal",
    "nav2_msgs/action/NavigateToPose_SendGoal_Response": "bool accepted\nbuiltin_interfaces/Time stamp",
    "action_msgs/srv/CancelGoal_Request": "action_msgs/GoalInfo goal_info",
    "action_msgs/srv/CancelGoal_Response": "int8 return_code\naction_msgs/GoalInfo[] goals_canceling",
    "nav2_msgs/action/NavigateToPose_Feedback": "geometry_msgs/PoseStamped current_pose\n"
                                                "builtin_interfaces/Duration navigation_time\n"
                                                "builtin_interfaces/Duration estimated_time_remaining\n"
                                                "int16 number_of_recoveries\nfloat32 distance_remaining",
    "nav2_msgs/action/NavigateToPose_FeedbackMessage": "unique_identifier_msgs/UUID goal_id\n"
                                                       "nav2_msgs/NavigateToPose_Feedback feedback",
    "nav2_msgs/action/NavigateToPose_GetResult_Request": "unique_identifier_msgs/UUID goal_id",
    # REI declares the reply up to the status; the releases' whole replies are RESULTS below
    "nav2_msgs/action/NavigateToPose_GetResult_Response": "int8 status",
    "nav2_msgs/action/NavigateToPose_ResultHumble": "std_msgs/Empty result",
    "nav2_msgs/action/NavigateToPose_ResultJazzy": "uint16 error_code\nstring error_msg",
    "nav2_msgs/action/NavigateToPose_GetResult_ResponseHumble": "int8 status\nnav2_msgs/NavigateToPose_ResultHumble result",
    "nav2_msgs/action/NavigateToPose_GetResult_ResponseJazzy": "int8 status\nnav2_msgs/NavigateToPose_ResultJazzy result",
}
for _name, _text in EXTRA.items():  # registered under msg names, as a .msg file's fields resolve them
    _package, _, _type = _name.split("/")
    STORE.register(get_types_from_msg(_text, f"{_package}/msg/{_type}"))
FRAMES = m.Frames()
SERVICE_TYPES = [t.NavigateToPose_SendGoal_Request, t.NavigateToPose_SendGoal_Response, t.CancelGoal_Request,
                 t.CancelGoal_Response, t.NavigateToPose_GetResult_Request, t.NavigateToPose_GetResult_Response]
ALL_TYPES = [t.Time, t.Header, t.Vector3, t.Point, t.Quaternion, t.Pose, t.PoseWithCovariance, t.Twist,
             t.TwistWithCovariance, t.Transform, t.TransformStamped, t.Odometry, t.MapMetaData, t.OccupancyGrid,
             t.LaserScan, t.TFMessage, t.Clock, t.String, t.Duration, t.PoseStamped, t.UUID, t.GoalInfo, t.GoalStatus,
             t.GoalStatusArray, t.NavigateToPose_Goal, t.NavigateToPose_Feedback,
             t.NavigateToPose_FeedbackMessage, *SERVICE_TYPES]
#: rmw_cyclonedds's request header before a service's fields: not a ROS field.
RMW_HEADER = ("rmw_client", "rmw_sequence")


def msgtype(cls: type[IdlStruct]) -> str:
    """``sensor_msgs::msg::dds_::LaserScan_`` -> ``sensor_msgs/msg/LaserScan`` (actions' and services' parts:
    the msg name they are registered under here)."""
    package, kind, dds, name = cls.__idl_typename__.split("::")
    assert kind in ("msg", "action", "srv") and dds == "dds_" and name.endswith("_")
    assert kind == "msg" or f"{package}/{kind}/{name[:-1]}" in EXTRA
    return f"{package}/msg/{name[:-1]}"


def ros_fields(value: IdlStruct | type[IdlStruct]) -> list[str]:
    return [f.name for f in dataclasses.fields(value) if f.name not in RMW_HEADER]


def to_rosbags(value: IdlStruct, typename: str) -> object:
    """The same values as a rosbags message, field by field as rosbags' own definition of ``typename`` lists them
    (its names, order and element types; only the values come from ``value``)."""
    _, fields = STORE.fielddefs[typename]
    assert ros_fields(value) == [name for name, _ in fields], typename
    kwargs = {}
    for name, (node, spec) in fields:
        item = getattr(value, name)
        if node.name == "NAME":
            kwargs[name] = to_rosbags(item, spec)
        elif node.name == "BASE":
            kwargs[name] = item
        else:  # ARRAY or SEQUENCE
            (element_node, element_spec), _size = spec
            if element_node.name == "NAME":
                kwargs[name] = [to_rosbags(element, element_spec) for element in item]
            else:
                kwargs[name] = np.array(item, dtype=getattr(np, element_spec[0]))
        if node.name == "BASE" and spec[0] == "bool":
            kwargs[name] = bool(item)
    return STORE.types[typename](**kwargs)


def rosbags_cdr(value: IdlStruct) -> bytes:
    typename = msgtype(type(value))
    return bytes(STORE.serialize_cdr(to_rosbags(value, typename), typename))


def samples() -> dict[str, IdlStruct]:
    """One of each type, from REI's builders where there is one, with awkward values: inf, nan, negative, odd
    lengths (padding), empty sequences and strings, non-ASCII frame ids, extreme integers."""
    scan = LaserScan(0.2, -math.pi, 2 * math.pi / 7, 0.12, 3.5, np.array([0.5, math.inf, 3.4, -math.inf, 1e-3, 7.0, 0.3]))
    boxes = ((1.0, 1.0, 0.0, 0.5, 0.3), (2.5, 1.5, 0.7, 1.0, 0.2), (0.0, 1.0, 0.0, 0.1, 2.0))
    odometry = m.odometry(12.3, Pose2D(-1.5, 2.25, -2.9), Twist2D(-0.2, 1.5), FRAMES)
    odometry.pose.covariance = [float(i) - 17.5 for i in range(36)]
    odometry.twist.covariance[35] = math.nan
    goal_id = new_goal_id()
    navigate = m.navigate_goal(4.2, NavGoal(1, Pose2D(5.5, 3.5, -1.0), 0.25), FRAMES)
    return {
        "time": t.Time(sec=-(2**31), nanosec=2**32 - 1),
        "header": t.Header(stamp=t.Time(sec=2**31 - 1, nanosec=1), frame_id=""),
        "header_odd": m.header(0.1, "base_scän/ü"),
        "vector3": t.Vector3(x=-0.0, y=math.inf, z=-1e-308),
        "point": t.Point(x=1.0, y=-2.0, z=3.5),
        "quaternion": m.quaternion(-1.0),
        "pose": t.Pose(position=t.Point(x=4.0), orientation=m.quaternion(3.0)),
        "pose_with_covariance": t.PoseWithCovariance(covariance=[1e300 * (-1) ** i for i in range(36)]),
        "twist": m.twist(Twist2D(0.26, -1.82)),
        "twist_with_covariance": t.TwistWithCovariance(twist=m.twist(Twist2D(-0.1, 0.0))),
        "transform": t.Transform(translation=t.Vector3(x=1.0, y=2.0), rotation=m.quaternion(0.5)),
        "transform_stamped": m.transforms(0.3, Pose2D(1.0, 2.0, 0.3), FRAMES, with_map=False).transforms[0],
        "odometry": odometry,
        "map_meta_data": t.MapMetaData(map_load_time=m.stamp(0.0), resolution=0.05, width=7, height=3),
        "occupancy_grid": m.occupancy_grid(StaticMap((0.0, 0.0, 3.0, 2.0), boxes, (0.3, 0.3)), FRAMES),
        "occupancy_grid_odd": t.OccupancyGrid(header=m.header(1.0, "m"), data=[-1, 0, 100, 127, -128]),
        "occupancy_grid_empty": t.OccupancyGrid(),
        "laser_scan": m.laser_scan(scan, 0.1, FRAMES),
        "laser_scan_intensities": t.LaserScan(header=m.header(0.0, "x"), ranges=[math.nan],
                                              intensities=[1.0, -2.5, math.inf]),
        "laser_scan_empty": t.LaserScan(),
        "tf": m.transforms(4.5, Pose2D(-3.0, 0.5, 2.0), FRAMES, with_map=True),
        "tf_empty": t.TFMessage(),
        "tf_static": m.static_transforms((FixedJoint("lidar", "base_link", "base_scan", (0.05, -0.01, 0.18),
                                                  quaternion_of_yaw(3.0)),)),
        "robot_description": m.robot_description('<robot name="rü">\n  <link name="base_footprint"/>\n</robot>\n'),
        "string_empty": t.String(),
        "clock": m.clock(0.3),
        "duration": t.Duration(sec=-3, nanosec=999_999_999),
        "pose_stamped": t.PoseStamped(header=m.header(2.0, "map"), pose=t.Pose(orientation=m.quaternion(1.0))),
        "uuid": goal_id,
        "goal_info": t.GoalInfo(goal_id=goal_id, stamp=m.stamp(3.0)),
        "goal_status": t.GoalStatus(goal_info=t.GoalInfo(goal_id=goal_id), status=-1),
        "goal_status_array": t.GoalStatusArray(status_list=[
            t.GoalStatus(goal_info=t.GoalInfo(goal_id=goal_id), status=4), t.GoalStatus(status=2)]),
        "goal_status_array_empty": t.GoalStatusArray(),
        "navigate_to_pose_goal": navigate,
        "navigate_to_pose_goal_tree": t.NavigateToPose_Goal(behavior_tree="/bt/ü.xml"),
        "send_goal_request": t.NavigateToPose_SendGoal_Request(rmw_client=2**64 - 1, rmw_sequence=-(2**63),
                                                                goal_id=goal_id, goal=navigate),
        "send_goal_response": t.NavigateToPose_SendGoal_Response(rmw_client=7, rmw_sequence=1, accepted=True,
                                                                  stamp=m.stamp(0.1)),
        "cancel_goal_request": t.CancelGoal_Request(rmw_client=7, rmw_sequence=2,
                                                    goal_info=t.GoalInfo(goal_id=goal_id)),
        "cancel_goal_response": t.CancelGoal_Response(rmw_client=7, rmw_sequence=2, return_code=-3,
                                                      goals_canceling=[t.GoalInfo(goal_id=goal_id), t.GoalInfo()]),
        "cancel_goal_response_empty": t.CancelGoal_Response(),
        "feedback": t.NavigateToPose_Feedback(
            current_pose=t.PoseStamped(header=m.header(2.0, "map")), navigation_time=t.Duration(sec=3),
            estimated_time_remaining=t.Duration(sec=-1, nanosec=5), number_of_recoveries=-(2**15),
            distance_remaining=math.inf),
        "feedback_message": t.NavigateToPose_FeedbackMessage(goal_id=goal_id, feedback=t.NavigateToPose_Feedback(
            distance_remaining=1.5, number_of_recoveries=3)),
        "get_result_request": t.NavigateToPose_GetResult_Request(rmw_client=9, rmw_sequence=3, goal_id=goal_id),
        "get_result_response": t.NavigateToPose_GetResult_Response(rmw_client=9, rmw_sequence=3, status=4),
    }


def test_every_ros2_type_is_declared_and_named_as_rosidl_does() -> None:
    for cls in ALL_TYPES:
        assert msgtype(cls) in STORE.fielddefs
        assert ros_fields(cls) == [name for name, _ in STORE.fielddefs[msgtype(cls)][1]]
    assert {type(value) for value in samples().values()} == set(ALL_TYPES)


@pytest.mark.parametrize("name", list(samples()))
def test_the_cdr_is_byte_for_byte_what_rosbags_writes(name: str) -> None:
    value = samples()[name]
    ours = value.serialize(endianness=Endianness.Little)
    assert ours[:4] == b"\x00\x01\x00\x00"  # CDR_LE, XCDR1: what rmw_cyclonedds sends
    if type(value) in SERVICE_TYPES:  # rmw_cyclonedds's header (8-aligned: the fields align as without it)
        header = value.rmw_client.to_bytes(8, "little") + value.rmw_sequence.to_bytes(8, "little", signed=True)
        assert ours == ours[:4] + header + rosbags_cdr(value)[4:]
    else:
        assert ours == rosbags_cdr(value)
    back = type(value).deserialize(ours)
    assert back.serialize(endianness=Endianness.Little) == ours


@pytest.mark.parametrize("release", ["Humble", "Jazzy"])
def test_a_get_result_reply_of_either_release_reads_as_its_status(release: str) -> None:
    """Humble's NavigateToPose result is std_msgs/Empty, Jazzy's error_code and error_msg, under one DDS type name:
    REI's declaration (up to the status) is a prefix of both, and reads both."""
    result = ({"result": STORE.types["std_msgs/msg/Empty"]()} if release == "Humble" else
              {"error_code": 9001, "error_msg": "failed to load the tree ü"})
    result_type = f"nav2_msgs/msg/NavigateToPose_Result{release}"
    reply_type = f"nav2_msgs/msg/NavigateToPose_GetResult_Response{release}"
    theirs = bytes(STORE.serialize_cdr(STORE.types[reply_type](
        status=6, result=STORE.types[result_type](**result)), reply_type))
    header = (7).to_bytes(8, "little") + (5).to_bytes(8, "little", signed=True)
    wire = theirs[:4] + header + theirs[4:]  # as rmw_cyclonedds sends it
    ours = t.NavigateToPose_GetResult_Response(rmw_client=7, rmw_sequence=5, status=6)
    assert len(wire) > len(ours.serialize(endianness=Endianness.Little))
    assert wire.startswith(ours.serialize(endianness=Endianness.Little))
    assert t.NavigateToPose_GetResult_Response.deserialize(wire) == ours


def test_cmd_vel_s_linear_y_is_the_sideways_speed_both_ways() -> None:
    assert m.command(t.Twist(linear=t.Vector3(x=0.1, y=-0.2), angular=t.Vector3(z=0.3))) == Twist2D(0.1, 0.3, -0.2)
    assert m.twist(Twist2D(0.1, 0.3, -0.2)).linear.y == -0.2
    assert m.odometry(1.0, Pose2D(0.0, 0.0), Twist2D(0.1, 0.3, -0.2), FRAMES).twist.twist.linear.y == -0.2


def test_rei_values_map_to_the_ros_fields() -> None:
    assert m.stamp(0.3) == t.Time(sec=1000, nanosec=300_000_000) and m.nanoseconds(m.stamp(0.0)) == 1000 * 10**9
    odom = m.odometry(1.0, Pose2D(1.0, 2.0, math.pi / 2), Twist2D(0.2, -0.5), FRAMES)
    assert (odom.header.frame_id, odom.child_frame_id) == ("odom", "base_link")
    assert m.yaw_of(odom.pose.pose.orientation) == pytest.approx(math.pi / 2)
    assert m.command(odom.twist.twist) == Twist2D(0.2, -0.5) == m.command(m.twist(Twist2D(0.2, -0.5)))
    tf = m.transforms(1.0, Pose2D(1.0, 2.0, 0.3), FRAMES, with_map=True)
    assert [(e.header.frame_id, e.child_frame_id) for e in tf.transforms] == [("map", "odom"), ("odom", "base_link")]
    scan = m.laser_scan(LaserScan(0.2, -1.0, 1.0, 0.12, 3.5, np.array([0.5, math.inf, 3.4])), 0.1, FRAMES)
    assert (scan.angle_min, scan.angle_max, scan.header.frame_id) == (-1.0, 1.0, "base_scan")
    assert math.isinf(scan.ranges[1])
    grid = m.occupancy_grid(StaticMap((0.0, 0.0, 3.0, 2.0), ((1.0, 1.0, 0.0, 0.5, 0.3),), (0.3, 0.3)), FRAMES)
    assert (grid.info.width, grid.info.height, grid.info.origin.position.x) == (80, 60, -0.5)
    cells = np.array(grid.data).reshape(60, 80)
    assert cells[30, 30] == 100 and cells[0, 0] == 0 and set(grid.data) == {0, 100}
    assert {topic.dds_name for topic in m.TOPICS.values()} == {
        "rt/clock", "rt/odom", "rt/tf", "rt/scan", "rt/map", "rt/robot_description", "rt/tf_static", "rt/cmd_vel"}
    [lidar] = m.static_transforms(
        (FixedJoint("lidar", "base_link", "base_scan", (0.05, -0.01, 0.18), quaternion_of_yaw(0.5)),)).transforms
    assert (lidar.header.frame_id, lidar.child_frame_id, lidar.header.stamp) == ("base_link", "base_scan", m.stamp(0.0))
    position = lidar.transform.translation
    assert (position.x, position.y, position.z, m.yaw_of(lidar.transform.rotation)) == pytest.approx(
        (0.05, -0.01, 0.18, 0.5))


# --- through DDS ---------------------------------------------------------------------------------------------

def loopback_config(trace: str) -> str:
    """The bridge's Cyclone configuration (loopback only, unicast discovery), with a trace that shows which
    interfaces it selected."""
    return cyclone_config(Path(trace))


#: The receiving participant, in its own process: reads each topic with the bridge's QoS for it and prints what
#: it got as CDR, one JSON line per sample; gives up after a few seconds.
RECEIVER = """
import json, sys, time
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.idl._support import Endianness
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from rei.sut.ros2 import messages as m
domain_id, config, expected, wait = int(sys.argv[1]), sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
domain = Domain(domain_id, config)
participant = DomainParticipant(domain_id)
readers = {key: DataReader(participant, Topic(participant, spec.dds_name, spec.type), qos=spec.qos)
           for key, spec in m.TOPICS.items()}
print(json.dumps({"ready": True}), flush=True)
got, deadline = 0, time.monotonic() + wait
while got < expected and time.monotonic() < deadline:
    for key, reader in readers.items():
        for sample in reader.take(N=10):
            got += 1
            print(json.dumps({"topic": key, "cdr": sample.serialize(endianness=Endianness.Little).hex()}), flush=True)
    time.sleep(0.005)
"""


def wait_until(condition, seconds: float) -> bool:  # type: ignore[no-untyped-def]
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.01)
    return True


def test_each_topic_crosses_dds_between_two_participants_on_loopback(tmp_path) -> None:  # type: ignore[no-untyped-def]
    lease = DomainLease.claim()  # a domain no run or other test uses meanwhile
    domain_id = lease.domain
    values = samples()
    sent = {"clock": values["clock"], "odom": values["odometry"], "tf": values["tf"], "scan": values["laser_scan"],
            "map": values["occupancy_grid"], "robot_description": values["robot_description"],
            "tf_static": values["tf_static"], "cmd_vel": values["twist"]}
    assert set(sent) == set(m.TOPICS)
    receiver = subprocess.Popen(
        [sys.executable, "-c", RECEIVER, str(domain_id), loopback_config(str(tmp_path / "receiver.log")),
         str(len(sent)), "8"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert json.loads(receiver.stdout.readline()) == {"ready": True}
        domain = Domain(domain_id, loopback_config(str(tmp_path / "sender.log")))  # noqa: F841 (kept alive)
        participant = DomainParticipant(domain_id)
        writers = {key: DataWriter(participant, Topic(participant, spec.dds_name, spec.type), qos=spec.qos)
                   for key, spec in m.TOPICS.items()}
        for key, writer in writers.items():
            assert wait_until(lambda w=writer: w.get_publication_matched_status().current_count == 1, 5.0), key
        for key, writer in writers.items():
            writer.write(sent[key])
        out, err = receiver.communicate(timeout=15)
    finally:
        if receiver.poll() is None:
            receiver.kill()
            receiver.wait()
        lease.release()
    received = {line["topic"]: bytes.fromhex(line["cdr"]) for line in map(json.loads, out.splitlines())}
    assert received == {key: value.serialize(endianness=Endianness.Little) for key, value in sent.items()}, err
    for log in ("sender.log", "receiver.log"):
        trace = (tmp_path / log).read_text()
        assert "selected interfaces: lo (" in trace and "eth" not in trace.split("selected interfaces:")[1][:80]


#: A process that takes a domain and holds it until killed, printing it.
HOLDER = """
import sys, time
from pathlib import Path
from rei.sut.ros2.environment import DomainLease
lease = DomainLease.claim(folder=Path(sys.argv[1]))
print(lease.domain, flush=True)
time.sleep(60)
"""


def test_concurrent_runs_take_different_domains_and_a_dead_runs_domain_is_free_again(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """A campaign's workers each hold a domain of their own; a run killed with SIGKILL leaves no lock behind."""
    holder = subprocess.Popen([sys.executable, "-c", HOLDER, str(tmp_path)], stdout=subprocess.PIPE, text=True)
    try:
        held = int(holder.stdout.readline())
        assert held in RUN_DOMAINS
        with DomainLease.claim(folder=tmp_path) as mine:
            assert mine.domain != held
            with pytest.raises(RuntimeError, match=f"ROS domain {held} is held by another run"):
                DomainLease.claim(held, folder=tmp_path)
        holder.send_signal(signal.SIGKILL)
        holder.wait(timeout=10)
        with DomainLease.claim(held, folder=tmp_path) as again:  # the kernel dropped the dead holder's lock
            assert again.domain == held
    finally:
        if holder.poll() is None:
            holder.kill()
            holder.wait()


def test_a_domain_a_ros2_participant_outside_rei_uses_is_skipped(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """Participant 0's RTPS discovery port (the same for every DDS vendor) bound: someone is on that domain."""
    with DomainLease.claim(folder=tmp_path) as first:
        candidate = first.domain
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as squatter:
        try:
            squatter.bind(("127.0.0.1", discovery_port(candidate)))
        except OSError:
            pytest.fail(f"port {discovery_port(candidate)} is taken although domain {candidate} was free")
        with DomainLease.claim(folder=tmp_path) as lease:
            assert lease.domain != candidate
    assert discovery_port(101) < 32768  # ROS 2's bound for Linux: below the ephemeral ports
