# SPDX-License-Identifier: EPL-2.0
"""State and mission messages: field presence per configuration, float64 and inf on the wire, full frames."""

from __future__ import annotations

import struct

import numpy as np
import pytest

from rei.wamp.codec import LaserMode, encode_mission_event, encode_state, pack, static_objects, unpack

from .fakes import make_state


def test_default_message_has_the_wire_protocol_fields_in_order():
    message = encode_state(make_state(0), 0, nav_state="ACTIVE")
    assert list(message) == ["seq", "t", "objects", "robot", "contacts"]
    assert list(message["robot"]) == ["name", "pose", "twist", "odom", "laser_min", "laser_clearance",
                                      "nav_state"]
    assert message["objects"] == [
        {"name": "h1", "type": "HUMAN", "pose": [4.0, 3.5, 0.85, 0.0], "twist": [-0.0, 0.0, 1.0]}
    ]
    assert message["contacts"] == [["tb3", "h1"]]


@pytest.mark.parametrize(
    ("laser", "contacts", "odometry", "nav", "absent"),
    [
        (LaserMode.FULL, True, True, "IDLE", set()),
        (LaserMode.MIN, True, True, "IDLE", {"laser_ranges"}),
        (LaserMode.NONE, False, False, None,
         {"laser_min", "laser_clearance", "laser_ranges", "odom", "nav_state", "contacts"}),
    ],
)
def test_optional_fields_follow_the_configuration(laser, contacts, odometry, nav, absent):
    message = encode_state(make_state(1), 1, laser=laser, contacts=contacts, odometry=odometry, nav_state=nav)
    present = set(message) | set(message["robot"])
    everything = {"laser_min", "laser_clearance", "laser_ranges", "odom", "nav_state", "contacts"}
    assert everything - present == absent
    assert "full" not in message


def test_full_laser_without_a_scan_this_step_omits_only_the_ranges():
    state = make_state(2)
    state = type(state)(
        state.t,
        type(state.robot)(**{**state.robot.__dict__, "laser_ranges": None}),
        state.objects,
        state.contacts,
    )
    robot = encode_state(state, 0, laser=LaserMode.FULL)["robot"]
    assert "laser_min" in robot and "laser_ranges" not in robot


def test_floats_are_float64_and_inf_survives():
    message = encode_state(make_state(3), 3, laser=LaserMode.FULL)
    ranges = message["robot"]["laser_ranges"]
    assert all(type(r) is float for r in ranges)  # float32 numpy input became Python floats
    assert ranges[-1] == float("inf")
    data = pack(message)
    assert b"\xcb" + struct.pack(">d", float("inf")) in data  # msgpack float64 inf, not float32 or nil
    assert unpack(data) == message
    assert message["robot"]["laser_ranges"][0] == pytest.approx(
        float(np.float32(0.5 + 0.1 * np.sin(3 / 240)))
    )


def test_no_float32_on_the_wire():
    types = _msgpack_type_bytes(pack(encode_state(make_state(5, beams=360), 5, laser=LaserMode.FULL)))
    assert 0xCB in types and 0xCA not in types


def _msgpack_type_bytes(data: bytes) -> list[int]:
    """The leading type byte of every msgpack object in ``data`` (a minimal walker for the types we emit)."""
    out: list[int] = []
    i = 0

    def one() -> None:
        nonlocal i
        b = data[i]
        out.append(b)
        i += 1
        if b <= 0x7F or b >= 0xE0 or b in (0xC0, 0xC2, 0xC3):
            return
        if 0x80 <= b <= 0x8F:
            for _ in range(2 * (b & 0x0F)):
                one()
        elif 0x90 <= b <= 0x9F:
            for _ in range(b & 0x0F):
                one()
        elif 0xA0 <= b <= 0xBF:
            i += b & 0x1F
        elif b == 0xDC:
            n = struct.unpack(">H", data[i : i + 2])[0]
            i += 2
            for _ in range(n):
                one()
        elif b == 0xD9:
            i += 1 + data[i]
        else:
            i += {0xCA: 4, 0xCB: 8, 0xCC: 1, 0xCD: 2, 0xCE: 4, 0xCF: 8, 0xD0: 1, 0xD1: 2, 0xD2: 4, 0xD3: 8}[b]

    one()
    assert i == len(data)
    return out


def test_full_frame_adds_walls_and_static_furniture_at_rest(world):
    statics = static_objects(world)
    categories = {o["category"] for o in world["objects"]}
    assert {"WALL", "STATIC"} <= categories and "FLOOR" in categories
    assert {o["type"] for o in statics} == {"WALL", "STATIC"}
    assert all(o["twist"] == [0.0, 0.0, 0.0] for o in statics)
    message = encode_state(make_state(0), 0, full_frame_objects=statics)
    assert message["full"] is True and list(message)[:3] == ["seq", "t", "full"]
    assert [o["name"] for o in message["objects"]] == ["h1"] + [o["name"] for o in statics]


def test_pose_and_twist_lengths_are_checked():
    state = make_state(0)
    bad = type(state.objects[0])("x", "HUMAN", (1.0, 2.0, 3.0), (0.0, 0.0, 0.0))
    with pytest.raises(ValueError, match="pose of x needs 4"):
        encode_state(type(state)(0.0, state.robot, (bad,), ()), 0)


def test_mission_events():
    assert encode_mission_event(0, 0.0, "BEGIN") == {
        "seq": 0,
        "t": 0.0,
        "event": "BEGIN",
        "task_index": -1,
        "goal": None,
    }
    fail = encode_mission_event(3, 12.5, "TASK_FAIL", 1, (5.5, 3.5, 0.0), reason="timeout")
    assert fail["goal"] == [5.5, 3.5, 0.0] and fail["reason"] == "timeout"
    with pytest.raises(ValueError, match="reason"):
        encode_mission_event(3, 12.5, "TASK_FAIL", 1, (5.5, 3.5, 0.0))
    with pytest.raises(ValueError, match="task_index"):
        encode_mission_event(1, 1.0, "TASK_START")
    with pytest.raises(ValueError):
        encode_mission_event(1, 1.0, "LUNCH")
