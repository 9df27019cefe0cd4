# SPDX-License-Identifier: EPL-2.0
"""WampClient(reconnect=...) against a real Crossbar router that is killed (SIGKILL: no GOODBYE, like a crash)
and restarted on the same ports with the same secrets (Router.restart)."""

from __future__ import annotations

import contextlib
import itertools
import os
import signal
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from autobahn.wamp.exception import ApplicationError

from rei.wamp import Router, WampClient, WampError

RECONNECT = 40.0  # s: the restart takes ~3 s on a quiet machine, and took over 15 s under a load of 10


def _wait(condition: Callable[[], bool], timeout: float = RECONNECT + 5, what: str = "condition") -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > deadline:
            raise AssertionError(f"{what} not met within {timeout} s")
        time.sleep(0.01)


def _crash(router: Router) -> None:
    """Kill the router's whole process group at once, as a crash would: no GOODBYE, no clean close."""
    assert router.pid is not None
    os.killpg(router.pid, signal.SIGKILL)
    _wait(lambda: router.poll() is not None, what="router death")


def _increasing(values: list[int]) -> bool:
    return all(a < b for a, b in itertools.pairwise(values))


class _Producer(threading.Thread):
    """Publishes ``{"seq": 0, 1, 2, ...}`` about every millisecond until told where to stop."""

    def __init__(self, client: WampClient, topic: str) -> None:
        super().__init__(name="test-producer", daemon=True)
        self.client, self.topic = client, topic
        self.next = 0
        self.end: int | None = None
        self.error: BaseException | None = None

    def run(self) -> None:
        try:
            while self.end is None or self.next < self.end:
                self.client.publish(self.topic, {"seq": self.next})
                self.next += 1
                time.sleep(0.001)
        except BaseException as error:  # noqa: BLE001 - reported by the test
            self.error = error

    def stop_after(self, count: int) -> int:
        """Publish ``count`` more messages and stop; returns the first seq of those."""
        first = self.next
        self.end = first + count
        return first


def test_a_stream_survives_a_router_crash_and_restart(crossbar: Path):
    topic, tail = "rei.run.restart.state", 500
    received: list[int] = []
    with (
        Router(crossbar=crossbar, auth=False) as router,
        WampClient(router.ws_url, reconnect=RECONNECT, name="test-sub") as sub,
        WampClient(router.rs_url, reconnect=RECONNECT, max_pending=64, name="test-pub") as pub,
    ):
        sub.subscribe(topic, lambda payload: received.append(payload["seq"]))
        producer = _Producer(pub, topic)
        producer.start()
        _wait(lambda: len(received) >= 300, what="stream before the crash")
        _crash(router)  # mid-stream: the producer keeps publishing into the outbox, then blocks
        router.restart()
        _wait(lambda: sub.reconnects == 1 and pub.reconnects == 1, what="both clients back")
        first = producer.stop_after(tail)
        producer.join(timeout=30)
        assert producer.error is None, f"publish() raised during the outage: {producer.error!r}"
        end = producer.next
        pub.flush()
        _wait(lambda: bool(received) and received[-1] == end - 1, what="the last message")
        assert pub.reconnects == 1 and sub.reconnects == 1
        assert pub.published == end, "every queued message is handed to a transport exactly once"
    assert _increasing(received), "out of order or duplicated"
    # Everything published once both were back arrives, in order, up to the last message.
    assert [s for s in received if s >= first] == list(range(first, end))
    # Some messages may be lost around the crash (on the wire, or before the subscriber re-subscribed).
    assert len(received) > end - 5000, f"{end - len(received)} of {end} lost"


def test_messages_queued_during_the_outage_are_delivered_in_order(crossbar: Path):
    topic = "rei.run.outage.state"
    received: list[int] = []
    with (
        Router(crossbar=crossbar, auth=False) as router,
        WampClient(router.ws_url, reconnect=RECONNECT, name="test-sub") as sub,
        WampClient(router.rs_url, reconnect=RECONNECT, max_pending=1000, name="test-pub") as pub,
    ):
        sub.subscribe(topic, lambda payload: received.append(payload["seq"]))
        lost = threading.Event()
        pub.on_connection_lost(lost.set)
        # The router drops events nobody is subscribed to: the queue waits until the subscriber is back.
        held: list[int] = []
        pub.hold_after_reconnect(lambda: (_wait(lambda: sub.reconnects == 1, what="subscriber back"),
                                          held.append(len(received))))
        for seq in range(100):
            pub.publish(topic, {"seq": seq})
        pub.flush()
        _wait(lambda: len(received) == 100, what="the first 100")
        _crash(router)
        assert lost.wait(10), "the publisher did not notice the loss"
        for seq in range(100, 400):
            pub.publish(topic, {"seq": seq})  # queued: there is no session to write them to
        router.restart()
        _wait(lambda: pub.reconnects == 1, what="publisher back")
        for seq in range(400, 500):
            pub.publish(topic, {"seq": seq})
        pub.flush()
        _wait(lambda: len(received) >= 500, timeout=10, what="all 500")
    assert received == list(range(500)), "nothing queued is dropped, the order is kept"
    assert held == [100], "nothing was sent before the gate opened"


def test_a_registered_procedure_answers_again_after_the_restart(crossbar: Path):
    notified: list[tuple[str, str]] = []
    answers: list[Any] = []

    def reconnected() -> None:
        notified.append(("reconnected", threading.current_thread().name))
        # Off the loop thread, so it can call; its own registration is already restored.
        answers.append(server.call("rei.test.echo", "from the callback"))

    with (
        Router(crossbar=crossbar, auth=False) as router,
        WampClient(router.rs_url, reconnect=RECONNECT, name="test-server") as server,
        WampClient(router.ws_url, reconnect=RECONNECT, name="test-caller") as caller,
    ):
        server.subscribe("rei.test.unused", lambda payload: None)  # restored in order, before the procedure
        server.register("rei.test.echo", lambda value: value)
        server.on_connection_lost(lambda: notified.append(("lost", threading.current_thread().name)))
        server.on_reconnect(reconnected)
        caller_lost = threading.Event()
        caller.on_connection_lost(caller_lost.set)
        assert caller.call("rei.test.echo", 1) == 1
        _crash(router)
        assert caller_lost.wait(10)
        started = time.monotonic()
        with pytest.raises(WampError, match="reconnecting"):
            caller.call("rei.test.echo", 2)
        assert time.monotonic() - started < 1.0, "call() during the outage must fail at once"
        router.restart()
        _wait(lambda: server.reconnects == 1 and caller.reconnects == 1, what="both clients back")
        _wait(lambda: len(answers) == 1, timeout=10, what="the on_reconnect callback's call")
        assert caller.call("rei.test.echo", 3) == 3
    assert answers == ["from the callback"]
    assert [event for event, _ in notified] == ["lost", "reconnected"]
    assert all(thread != "test-server" for _, thread in notified), "callbacks must not run on the loop thread"


def test_without_reconnect_a_lost_router_still_fails_at_once(crossbar: Path):
    with Router(crossbar=crossbar, auth=False) as router:
        client = WampClient(router.rs_url, send_timeout=5.0).start()
        try:
            client.publish("rei.run.once.state", {"seq": 0})
            client.flush()
            _crash(router)
            with pytest.raises(WampError, match="lost"):
                deadline = time.monotonic() + 10
                while time.monotonic() < deadline:
                    client.publish("rei.run.once.state", {"seq": 1})
                    time.sleep(0.01)
            with pytest.raises(WampError, match="lost"):
                client.call("rei.test.echo", 1)
            assert client.reconnects == 0
        finally:
            with pytest.raises(WampError):
                client.close()


def test_a_router_that_never_comes_back_fails_after_the_reconnect_window(crossbar: Path):
    window = 2.0
    with Router(crossbar=crossbar, auth=False) as router:
        publisher = WampClient(router.rs_url, reconnect=window, max_pending=16).start()
        closer = WampClient(router.ws_url, reconnect=60.0).start()
        closer_lost = threading.Event()
        closer.on_connection_lost(closer_lost.set)
        try:
            publisher.publish("rei.run.gone.state", {"seq": 0})
            publisher.flush()
            _crash(router)
            crashed = time.monotonic()
            with pytest.raises(WampError, match=f"no reconnection within {window:g} s"):
                while time.monotonic() - crashed < 30:
                    publisher.publish("rei.run.gone.state", {"seq": 1})  # blocks once 16 are queued
                    time.sleep(0.001)
            assert window - 0.2 < time.monotonic() - crashed < window + 2.0
            assert publisher.reconnects == 0
            started = time.monotonic()
            with pytest.raises(WampError, match="no reconnection"):
                publisher.close(timeout=3.0)
            assert time.monotonic() - started < 3.0
            # close() while still reconnecting (60 s window) returns within its own timeout.
            assert closer_lost.wait(5)
            closer.publish("rei.run.gone.state", {"seq": 1})
            started = time.monotonic()
            with pytest.raises(WampError, match="not back within close"):
                closer.close(timeout=1.0)
            assert time.monotonic() - started < 3.0
        finally:
            for client in (publisher, closer):
                with contextlib.suppress(WampError):
                    client.close(timeout=1.0)


def test_wamp_cra_roles_authenticate_again_after_the_restart(crossbar: Path):
    run_id = "reauth"
    states: list[int] = []
    with (
        Router(crossbar=crossbar, auth=True, run_id=run_id) as router,
        WampClient(router.rs_url, auth=router.credentials("simulation"), reconnect=RECONNECT) as sim,
        WampClient(router.ws_url, auth=router.credentials("monitor"), reconnect=RECONNECT) as monitor,
    ):
        sim.register(f"rei.run.{run_id}.config", lambda: {"run_id": run_id})
        monitor.subscribe(f"rei.run.{run_id}.state", lambda payload: states.append(payload["seq"]))
        _crash(router)
        router.restart()
        _wait(lambda: sim.reconnects == 1 and monitor.reconnects == 1, what="both roles back")
        assert monitor.call(f"rei.run.{run_id}.config") == {"run_id": run_id}
        for seq in range(10):
            sim.publish(f"rei.run.{run_id}.state", {"seq": seq})
        sim.flush()
        _wait(lambda: len(states) == 10, timeout=10, what="state after the restart")
    assert states == list(range(10))


def test_call_when_registered_waits_for_the_procedure_and_passes_other_errors_at_once(crossbar: Path):
    with (
        Router(crossbar=crossbar, auth=False) as router,
        WampClient(router.rs_url, name="test-server") as server,
        WampClient(router.ws_url, name="test-caller") as caller,
    ):
        later = threading.Timer(0.5, server.register, ("rei.test.late", lambda: "here"))
        later.start()
        started = time.monotonic()
        assert caller.call_when_registered("rei.test.late", timeout=20) == "here"
        assert time.monotonic() - started >= 0.4  # it did wait for the registration
        later.join()

        def refuse() -> None:
            raise ApplicationError("rei.error.refused", "no")

        server.register("rei.test.refuse", refuse)
        started = time.monotonic()
        with pytest.raises(ApplicationError, match="rei.error.refused"):
            caller.call_when_registered("rei.test.refuse", timeout=20)
        assert time.monotonic() - started < 5  # not retried until the timeout
        with pytest.raises(ApplicationError, match="no_such_procedure"):
            caller.call_when_registered("rei.test.never", timeout=0.5)
