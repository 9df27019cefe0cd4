# SPDX-License-Identifier: EPL-2.0
"""attach(): the evaluator on the router - subscriptions, the recording hook, mission_info fetched late."""

from __future__ import annotations

import subprocess
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from rei.evaluation import Evaluator, attach
from rei.wamp import Router, Topics, WampClient

from .traces import MISSION, MONITOR, WORLD, nominal

REPO = Path(__file__).resolve().parents[3]


class FakeClient:
    """Records subscriptions; mission_info answers only after ``fail_calls`` refusals (not registered yet)."""

    def __init__(self, fail_calls: int) -> None:
        self.handlers: dict[str, Callable[[Any], None]] = {}
        self.calls: list[str] = []
        self.fail_calls = fail_calls

    def subscribe(self, topic: str, handler: Callable[[Any], None]) -> None:
        self.handlers[topic] = handler

    def call(self, uri: str, timeout: float = 10.0) -> Any:
        self.calls.append(uri)
        if len(self.calls) <= self.fail_calls:
            raise RuntimeError("wamp.error.no_such_procedure")
        return MISSION


def test_attach_subscribes_forwards_and_fetches_mission_info_when_it_exists(tmp_path: Path) -> None:
    evaluator = Evaluator(tmp_path, monitor_config=MONITOR, world=WORLD)
    client = FakeClient(fail_calls=2)
    recorded: list[Any] = []
    attachment = attach(client, "r1", evaluator, also=recorded.append)  # type: ignore[arg-type]
    assert set(client.handlers) == {"rei.run.r1.signal", "rei.run.r1.mission"}
    assert attachment.wait_for_mission_info(timeout=10.0)
    assert client.calls == ["rei.run.r1.mission_info"] * 3
    messages = nominal().messages
    for message in messages:
        client.handlers["rei.run.r1.signal"](message)
    client.handlers["rei.run.r1.mission"]({"seq": 0, "t": 10.0, "event": "TASK_FAIL", "task_index": 0,
                                           "goal": [4.5, 0.5, 0.0], "reason": "aborted"})
    assert recorded == messages and evaluator.total == 20 + 5 - 2 + 0 + 1 + 0 + 10 + 5 + 10 + 20
    summary = evaluator.finish(status="COMPLETED", reason=None, sim_duration=20.0, wall_time=1.0, run_id="r1")
    assert summary.mission == "M" and summary.goals == 2
    attachment.stop()


def test_attach_gives_up_on_mission_info_after_its_timeout(tmp_path: Path) -> None:
    evaluator = Evaluator(tmp_path, monitor_config=MONITOR, world=WORLD)
    attachment = attach(FakeClient(fail_calls=10**6), "r2", evaluator, mission_info_timeout=0.2)  # type: ignore[arg-type]
    assert attachment.wait_for_mission_info(timeout=10.0) is False
    assert attachment.mission_info_error is not None
    assert "no_such_procedure" in attachment.mission_info_error


@pytest.fixture(scope="module")
def router() -> Iterator[Router]:
    """A real Crossbar router (the set-up script installs it when missing; never skipped)."""
    subprocess.run([str(REPO / "scripts" / "setup-router.sh")], check=True, capture_output=True, timeout=900)
    with Router(crossbar=REPO / ".venv-router" / "bin" / "crossbar", auth=False) as running:
        yield running


def test_live_signals_and_late_mission_info_through_a_real_router(router: Router, tmp_path: Path) -> None:
    topics = Topics("evaluation-live")
    evaluator = Evaluator(tmp_path, monitor_config=MONITOR, world=WORLD)
    with WampClient(router.ws_url) as listener, WampClient(router.rs_url) as sim:
        attachment = attach(listener, topics.run_id, evaluator)
        time.sleep(0.3)  # the simulation starts later than the evaluator
        sim.register(topics.mission_info, lambda: MISSION)
        messages = nominal(collision_with="table1").messages
        for message in messages:
            sim.publish(topics.signal, message)
        sim.flush()
        assert evaluator.wait_for_end(timeout=10.0)
        assert attachment.wait_for_mission_info(timeout=10.0)
    summary = evaluator.finish(status="COMPLETED", reason=None, sim_duration=20.0, wall_time=1.0,
                               run_id=topics.run_id)
    attachment.stop()
    assert summary.signals == len(messages) and summary.problems == ()
    assert summary.mission == "M"
    simple = summary.verdict("MISSION_SIMPLE")
    assert simple.status == "fail" and simple.evidence[0].object == "table1"
