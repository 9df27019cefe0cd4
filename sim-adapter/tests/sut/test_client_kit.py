# SPDX-License-Identifier: EPL-2.0
"""The Python client kit (rei.sut.client, docs/sut.md) against what users of it get wrong, without a router."""

from __future__ import annotations

import queue

import pytest

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import NavGoal, Observation
from rei.sut.client import Session, SystemUnderTest, _serve
from rei.sut.external import protocol


class _Client:
    def __init__(self) -> None:
        self.published: list[tuple[str, dict]] = []

    def publish(self, uri: str, payload: dict) -> None:
        self.published.append((uri.rsplit(".", 1)[1], payload))


def _serve_messages(sut: SystemUnderTest, *messages: tuple[str, dict]) -> _Client:
    inbox: queue.SimpleQueue = queue.SimpleQueue()
    for message in messages:
        inbox.put(message)
    client = _Client()
    session = Session("r", "lockstep", 10.0, 10.0, Pose2D(0.5, 0.5), {}, 1, None)
    _serve(sut, client, "r", session, inbox)
    return client


def _tick(k: int) -> tuple[str, dict]:
    observation = Observation(k / 10, Pose2D(0.5, 0.5), Twist2D(), None)
    return "tick", protocol.tick_message(k, observation, new_scan=False, scan_time=0.1)


_GOAL = ("goal", protocol.goal_message(0.0, NavGoal(0, Pose2D(2.0, 0.5), 0.25)))
_END = ("end", protocol.end_message(0.3, "the run is over"))


@pytest.mark.parametrize("answer", [None, (0.2, 0.0)])
def test_an_on_tick_that_returns_no_twist_is_named_with_its_tick_and_time(answer) -> None:
    """A forgotten ``return`` (None) or a tuple was an AttributeError inside the kit ("'NoneType' object has no
    attribute 'v'" in client.py), naming neither the callback nor the tick."""
    class Forgetful(SystemUnderTest):
        def on_tick(self, tick):
            return Twist2D(0.1, 0.0) if tick.tick < 2 else answer

    with pytest.raises(TypeError, match=r"Forgetful.on_tick returned .* for tick 2 \(t=0.200 s\): it must return "
                                        r"a Twist2D"):
        _serve_messages(Forgetful(), _GOAL, *[_tick(k) for k in (0, 1, 2)], _END)


def test_a_subclass_that_does_not_call_super_init_is_served() -> None:
    """An ``__init__`` of its own without ``super().__init__()`` raised AttributeError ('_report') in the kit at
    the first tick before a goal."""
    class OwnInit(SystemUnderTest):
        def __init__(self, speed: float) -> None:
            self.speed = speed

        def on_tick(self, tick):
            if self.goal is not None:
                self.feedback("going")
            return Twist2D(self.speed, 0.0)

    client = _serve_messages(OwnInit(0.2), _tick(0), _GOAL, _tick(1), _END)
    assert [topic for topic, _ in client.published] == ["command", "status", "status", "command"]
    assert client.published[2][1] == {"goal_id": 0, "status": "ACTIVE", "text": "going"}


def test_a_refusal_says_the_router_s_words_and_the_run_id_to_check() -> None:
    """A wrong REI_RUN_ID printed autobahn's repr: "the router refused: ApplicationError(error=<wamp.error.
    not_authorized>, args=[...], kwargs={}, enc_algo=None, callee=None, ..."."""
    from autobahn.wamp.exception import ApplicationError

    from rei.sut.client import _refusal

    error = ApplicationError("wamp.error.not_authorized", 'session is not authorized to subscribe to topic '
                             '"rei.run.abc.sut.tick" on realm "rei"')
    message = _refusal(error, "abc")
    assert message.startswith('the router refused: wamp.error.not_authorized: session is not authorized to '
                              'subscribe to topic "rei.run.abc.sut.tick"')
    assert "is REI_RUN_ID='abc' the id of the run you joined?" in message
    assert "enc_algo" not in message
