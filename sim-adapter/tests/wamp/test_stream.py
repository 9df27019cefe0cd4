# SPDX-License-Identifier: EPL-2.0
"""End to end through the real router: a subscriber in another process, the RPCs, loss is never silent."""

from __future__ import annotations

import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

import pytest

from rei.wamp import (
    CollectorConfig,
    DataCollector,
    LaserMode,
    MissionPublisher,
    Router,
    WampClient,
    WampError,
    read_recording,
    stream_path,
)

from .fakes import make_state

SUBSCRIBER = Path(__file__).with_name("subscriber_process.py")
N = 2000


def _start_subscriber(url: str, topic: str, count: int, out: Path) -> subprocess.Popen[str]:
    process = subprocess.Popen(
        [sys.executable, str(SUBSCRIBER), url, topic, str(count), str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert process.stdout is not None
    line = process.stdout.readline().strip()
    if line != "READY":
        process.kill()
        raise AssertionError(
            f"subscriber did not start: {line!r} {process.stderr.read() if process.stderr else ''}"
        )
    return process


@pytest.mark.parametrize("publisher_transport", ["rawsocket", "websocket"])
def test_subscriber_process_receives_every_seq_in_order(
    router: Router, tmp_path: Path, publisher_transport: str
):
    run_id = f"gapless_{publisher_transport}"
    received_file = tmp_path / "received.msgpack"
    # The subscriber uses websocket, like the Java monitor will.
    subscriber = _start_subscriber(router.ws_url, f"rei.run.{run_id}.state", N, received_file)
    try:
        # A small outbox forces the backpressure path: the loop below outruns the router.
        with WampClient(router.url(publisher_transport), max_pending=32) as client:  # type: ignore[arg-type]
            config = CollectorConfig(rate_hz=0, laser=LaserMode.FULL)
            with DataCollector(run_id, tmp_path, config=config, client=client) as collector:
                started = time.monotonic()
                for i in range(N):
                    collector.publish(make_state(i, beams=360))
                elapsed = time.monotonic() - started
        out, err = subscriber.communicate(timeout=60)
    finally:
        if subscriber.poll() is None:
            subscriber.kill()
    assert subscriber.returncode == 0, f"subscriber: {out} {err}"
    received = read_recording(received_file)
    assert [m["seq"] for m in received] == list(range(N))
    recording = stream_path(tmp_path, "state")
    assert received_file.read_bytes() == recording.read_bytes(), "recording differs from what was received"
    assert N / elapsed > 240, f"only {N / elapsed:.0f} msg/s published"


def test_config_and_mission_info_rpcs_answer(router: Router, tmp_path: Path, world, monitor):
    info = {
        "mission": "Deliver",
        "testcase": "RoomSixByFour",
        "environment": "FixtureLab",
        "robot": "tb3",
        "goals": [{"index": 0, "pose": [5.0, 3.0, 0.0], "tolerance": 0.25, "timeout": 120.0}],
    }
    config = CollectorConfig(rate_hz=10.0, laser=LaserMode.NONE)
    events: list[dict[str, Any]] = []
    got_all = threading.Event()

    def on_mission(payload: dict[str, Any]) -> None:
        events.append(payload)
        if len(events) == 4:
            got_all.set()

    with WampClient(router.rs_url) as sim, WampClient(router.ws_url) as monitor_client:
        monitor_client.subscribe("rei.run.rpc1.mission", on_mission)
        collector = DataCollector("rpc1", tmp_path, config=config, client=sim, monitor=monitor, world=world)
        mission = MissionPublisher("rpc1", tmp_path, client=sim, mission_info=info)
        served = monitor_client.call("rei.run.rpc1.config")
        assert served["run_id"] == "rpc1"
        assert served["topics"]["state"] == "rei.run.rpc1.state"
        assert served["topics"]["missionInfo"] == "rei.run.rpc1.mission_info"
        assert served["collector"] == {
            "rate_hz": 10.0,
            "laser": "none",
            "contacts": True,
            "odometry": True,
            "nav_state": True,
            "full_frame_period": 1.0,
            "objects": None,
        }
        assert served["monitor"] == monitor and served["world"] == world
        assert monitor_client.call("rei.run.rpc1.mission_info") == info
        mission.publish(0.0, "BEGIN")
        mission.publish(0.0, "TASK_START", 0, (5.0, 3.0, 0.0))
        mission.publish(9.5, "TASK_SUCCESS", 0, (5.0, 3.0, 0.0))
        mission.publish(9.5, "END")
        assert got_all.wait(10)
        collector.close()
        mission.close()
    assert [e["event"] for e in events] == ["BEGIN", "TASK_START", "TASK_SUCCESS", "END"]
    assert [e["seq"] for e in events] == [0, 1, 2, 3]
    assert read_recording(stream_path(tmp_path, "mission")) == events


def test_a_lost_router_is_an_error_not_a_silent_drop(crossbar: Path, tmp_path: Path):
    router = Router(crossbar=crossbar, auth=False).start()
    client = WampClient(router.rs_url, send_timeout=5.0).start()
    try:
        client.publish("rei.run.lost.state", {"seq": 0})
        client.flush()
        router.stop()
        with pytest.raises(WampError, match="lost|closed"):
            deadline = time.monotonic() + 10
            while time.monotonic() < deadline:
                client.publish("rei.run.lost.state", {"seq": 1})
                time.sleep(0.01)
    finally:
        router.stop()
        with pytest.raises(WampError):
            client.close()


def test_join_failures_are_clear_errors(router: Router):
    with pytest.raises(WampError, match="cannot join realm 'nope'.*no_such_realm"):
        WampClient(router.ws_url, realm="nope", connect_timeout=5).start()
    with pytest.raises(WampError, match="cannot join"):
        WampClient("rs://127.0.0.1:1", connect_timeout=5).start()
    client = WampClient(router.rs_url).start()
    client.close()
    with pytest.raises(WampError, match="not started"):
        client.publish("rei.run.x.state", {"seq": 0})
