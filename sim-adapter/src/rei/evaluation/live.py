# SPDX-License-Identifier: EPL-2.0
"""Feeding an Evaluator: live from the router (``attach``) or offline from recorded signals (``replay``).

Live, the evaluator subscribes to ``rei.run.<id>.signal`` and ``.mission`` and asks the mission executor's
``mission_info`` procedure for the mission (thesis 6.1.5). The procedure only exists once the simulation has
started - usually after the subscriptions, which must be in place before the first signal - so it is called
from a background thread: right away, again whenever a message arrives, and every ``MISSION_INFO_RETRY``
seconds, until it answers, the evaluator finishes, or ``mission_info_timeout`` passes. It can not be called
from a subscription handler: handlers run on the client's loop thread, which a blocking call would deadlock.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable, Iterable, Mapping
from typing import TYPE_CHECKING, Any

from rei.evaluation.evaluator import Evaluator
from rei.evaluation.summary import Summary

if TYPE_CHECKING:
    from rei.wamp.client import WampClient
from rei.wamp.topics import Topics

MISSION_INFO_RETRY = 0.5
_CALL_TIMEOUT = 5.0


class Attachment:
    """The live link of one evaluator; ``stop()`` ends the mission_info fetcher (subscriptions end with the
    client)."""

    def __init__(self, client: WampClient, topics: Topics, evaluator: Evaluator, timeout: float) -> None:
        self.topics = topics
        self.mission_info_error: str | None = None
        self._client = client
        self._evaluator = evaluator
        self._deadline = time.monotonic() + timeout
        self._wake = threading.Event()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        if not evaluator.has_mission_info:
            self._thread = threading.Thread(target=self._fetch, name="rei-evaluator-mission-info",
                                            daemon=True)
            self._thread.start()

    def poke(self) -> None:
        """A message arrived: the mission executor is probably up, try mission_info now."""
        self._wake.set()

    def stop(self, timeout: float = 5.0) -> None:
        self._stop.set()
        self._wake.set()
        if self._thread is not None:
            self._thread.join(timeout)

    def wait_for_mission_info(self, timeout: float | None = None) -> bool:
        deadline = None if timeout is None else time.monotonic() + timeout
        while not self._evaluator.has_mission_info:
            if self._thread is None or not self._thread.is_alive():
                return self._evaluator.has_mission_info
            if deadline is not None and time.monotonic() >= deadline:
                return False
            time.sleep(0.05)
        return True

    def _fetch(self) -> None:
        while not (self._stop.is_set() or self._evaluator.finished or self._evaluator.has_mission_info):
            try:
                info = self._client.call(self.topics.mission_info, timeout=_CALL_TIMEOUT)
            except Exception as error:  # noqa: BLE001 - not registered yet, client closing: retry until the deadline
                if time.monotonic() >= self._deadline:
                    self.mission_info_error = f"mission_info did not answer: {type(error).__name__}: {error}"
                    return
                self._wake.wait(MISSION_INFO_RETRY)
                self._wake.clear()
                continue
            if isinstance(info, Mapping):
                self._evaluator.set_mission_info(info)
            else:
                self.mission_info_error = f"mission_info returned {type(info).__name__}, not a map"
            return


def attach(client: WampClient, run_id: str, evaluator: Evaluator, *,
           also: Callable[[Any], object] | None = None, mission: bool = True,
           mission_info_timeout: float = 600.0) -> Attachment:
    """Subscribe ``evaluator`` to run ``run_id``'s signals (and mission events) on a started client.

    ``also(payload)`` sees every signal payload first (e.g. ``RecordingWriter.write`` to keep
    ``OUT/streams/signal.msgpack``); it runs on the client's thread.
    """
    topics = Topics(run_id)
    attachment: Attachment | None = None

    def on_signal(payload: Any) -> None:
        if also is not None:
            also(payload)
        evaluator.on_signal(payload)
        if attachment is not None:
            attachment.poke()

    def on_mission(payload: Any) -> None:
        evaluator.on_mission(payload)
        if attachment is not None:
            attachment.poke()

    client.subscribe(topics.signal, on_signal)
    if mission:
        client.subscribe(topics.mission, on_mission)
    attachment = Attachment(client, topics, evaluator, mission_info_timeout)
    return attachment


def replay(signals: Iterable[Mapping[str, Any]], evaluator: Evaluator, *,
           missions: Iterable[Mapping[str, Any]] = (), status: str = "COMPLETED", reason: str | None = None,
           sim_duration: float | None = None, wall_time: float = 0.0, run_id: str = "replay") -> Summary:
    """Evaluate recorded signals offline (e.g. ``read_recording(OUT/streams/signal.msgpack)``) and finish.

    ``missions``: the recorded mission stream, for the TASK_FAIL reasons; ``sim_duration``: the simulated
    length of the run (default: the last signal's time).
    """
    for message in missions:
        evaluator.on_mission(message)
    for message in signals:
        evaluator.on_signal(message)
    return evaluator.finish(status=status, reason=reason, sim_duration=sim_duration, wall_time=wall_time,
                            run_id=run_id)
