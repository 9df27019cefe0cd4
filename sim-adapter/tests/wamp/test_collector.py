# SPDX-License-Identifier: EPL-2.0
"""The collector's schedule in simulation time, full frames, recordings and determinism (no router needed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from rei.geometry import Pose2D
from rei.wamp import CollectorConfig, DataCollector, LaserMode, read_recording, stream_path

from .fakes import make_state


def _run(out: Path, config: CollectorConfig, steps: int, world=None) -> list[dict]:
    with DataCollector("run1", out, config=config, world=world) as collector:
        published = [m for i in range(steps) if (m := collector.step(make_state(i), "ACTIVE")) is not None]
    return published


def test_rate_is_counted_in_simulation_time(tmp_path: Path):
    # 10 simulated seconds at 240 Hz steps, 20 Hz publishing: 200 messages, one per 1/20 s, whatever wall time.
    published = _run(tmp_path, CollectorConfig(rate_hz=20.0, full_frame_period=1.0), 2400)
    assert [m["seq"] for m in published] == list(range(200))
    assert [round(m["t"] * 20, 6) for m in published] == [float(k) for k in range(200)]
    assert [m["seq"] for m in published if m.get("full")] == list(range(0, 200, 20))


def test_due_predicts_step_without_consuming_the_schedule(tmp_path: Path):
    with DataCollector("run1", tmp_path, config=CollectorConfig(rate_hz=20.0)) as collector:
        for i in range(100):
            state = make_state(i)
            expected = collector.due(state.t)
            assert collector.due(state.t) == expected
            assert (collector.step(state) is not None) == expected
        assert collector.seq == 9  # t = 0, 0.05, ..., 0.40 within 100 steps of 1/240 s


def test_the_simulators_own_state_type_encodes(tmp_path: Path):
    from rei.sim.state import ObjectState, RobotState, SimState

    robot = RobotState(
        "tb3",
        (1.0, 2.0, 0.0, 0.5),
        (0.2, 0.0, 0.1),
        Pose2D(1.0, 2.0, 0.5),
        0.7,
        np.array([0.7, np.inf], dtype=np.float32),
    )
    state = SimState(
        0.25,
        robot,
        (ObjectState("h1", "HUMAN", (3.0, 3.0, 0.85, 0.0), (0.5, 0.0, 0.0)),),
        (("tb3", "table1"),),
    )
    with DataCollector("run1", tmp_path, config=CollectorConfig(laser=LaserMode.FULL)) as collector:
        message = collector.step(state, "ACTIVE")
    assert message is not None
    assert message["robot"]["laser_ranges"] == [float(np.float32(0.7)), float("inf")]
    assert message["robot"]["odom"] == [1.0, 2.0, 0.5] and message["contacts"] == [["tb3", "table1"]]
    assert read_recording(stream_path(tmp_path, "state")) == [message]


def test_rate_zero_publishes_every_step_and_only_the_first_full_frame(tmp_path: Path):
    published = _run(tmp_path, CollectorConfig(rate_hz=0, full_frame_period=0), 30)
    assert [m["seq"] for m in published] == list(range(30))
    assert [m["seq"] for m in published if m.get("full")] == [0]


def test_steps_coarser_than_the_period_publish_once_per_step(tmp_path: Path):
    with DataCollector("run1", tmp_path, config=CollectorConfig(rate_hz=1000.0)) as collector:
        sent = [collector.step(make_state(i, dt=0.01)) is not None for i in range(10)]
    assert all(sent) and collector.seq == 10


def test_time_must_increase(tmp_path: Path):
    with DataCollector("run1", tmp_path) as collector:
        collector.publish(make_state(5))
        with pytest.raises(ValueError, match="must increase"):
            collector.publish(make_state(5))


def test_recording_is_the_published_stream_and_deterministic(tmp_path: Path, world):
    config = CollectorConfig(rate_hz=60.0, laser=LaserMode.FULL)
    first = _run(tmp_path / "a", config, 500, world)
    _run(tmp_path / "b", config, 500, world)
    a, b = stream_path(tmp_path / "a", "state"), stream_path(tmp_path / "b", "state")
    assert a == tmp_path / "a" / "streams" / "state.msgpack"
    assert read_recording(a) == first
    assert a.read_bytes() == b.read_bytes()


def test_truncated_recording_is_reported(tmp_path: Path):
    _run(tmp_path, CollectorConfig(rate_hz=0), 5)
    path = stream_path(tmp_path, "state")
    path.write_bytes(path.read_bytes()[:-3])
    with pytest.raises(ValueError, match="truncated"):
        read_recording(path)


@pytest.mark.parametrize("bad", [{"rate_hz": -1.0}, {"rate_hz": float("nan")}, {"full_frame_period": -2.0}])
def test_config_is_validated(bad):
    with pytest.raises(ValueError):
        CollectorConfig(**bad)


def test_run_id_must_fit_in_one_uri_component(tmp_path: Path):
    with pytest.raises(ValueError, match="run id"):
        DataCollector("a.b", tmp_path)


@pytest.mark.parametrize(("objects", "published"), [(None, {"h1"}), (("HUMAN",), {"h1"}), (("h1",), {"h1"}),
                                                    (("DYNAMIC",), set()), ((), set())])
def test_objects_select_the_moving_objects_in_every_message(tmp_path: Path, world, objects, published):
    messages = _run(tmp_path, CollectorConfig(rate_hz=20.0, objects=objects), 480, world)
    assert {o["name"] for m in messages for o in m["objects"] if o["type"] in ("HUMAN", "DYNAMIC")} == published
    full = [m for m in messages if m.get("full")]
    assert len(full) == 2 and all(o["name"] in published for m in full for o in m["objects"])
    with DataCollector("run1", tmp_path / "c", config=CollectorConfig(objects=objects), world=world) as collector:
        wire = collector.serve_config()["collector"]["objects"]
    assert wire == (None if objects is None else list(objects))


def test_objects_must_name_a_moving_object_or_a_category(tmp_path: Path, world):
    with pytest.raises(ValueError, match=r"'table1' is neither a moving object of the case \(h1\) nor a category "
                                         r"\(DYNAMIC, HUMAN\)"):
        DataCollector("run1", tmp_path, config=CollectorConfig(objects=("table1",)), world=world)


def test_full_frames_carry_no_static_obstacle_of_the_world(tmp_path: Path, world):
    # world.json's walls and static furniture never move: a receiver has them from world.json, and repeating them
    # made every full frame of a map room (1,327 walls in Nav2's depot) ~140 KB
    statics = {o["name"] for o in world["objects"] if o["category"] in ("WALL", "STATIC", "FLOOR")}
    assert statics
    messages = _run(tmp_path, CollectorConfig(rate_hz=20.0, full_frame_period=1.0), 480, world)
    full = [m for m in messages if m.get("full")]
    assert [m["seq"] for m in full] == [0, 20]
    assert all({o["name"] for o in m["objects"]} == {"h1"} for m in messages)
    assert statics.isdisjoint(o["name"] for m in messages for o in m["objects"])
