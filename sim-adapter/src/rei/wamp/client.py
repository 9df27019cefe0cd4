# SPDX-License-Identifier: EPL-2.0
"""A WAMP session usable from synchronous code: the bridge between the simulation loop and the router.

Why a thread: the simulation loop is synchronous and runs faster than real time; autobahn is asynchronous. The
client owns an asyncio loop in a daemon thread. ``publish()`` never talks to the network itself: it appends the
message to an outbox and wakes the loop with ``call_soon_threadsafe`` (once per burst, not per message). A
drain task on the loop publishes with ``acknowledge=False`` (no round trip per message) in FIFO order. A message
leaves the outbox only once handed to a live transport.

Backpressure instead of loss: at most ``max_pending`` messages wait in the outbox (a semaphore the caller
acquires), and the drain task stops writing while the socket's send buffer holds more than ``HIGH_WATER`` bytes.
A simulation that outruns the router therefore blocks in ``publish()``; if the router takes nothing for
``send_timeout`` seconds, or the connection is lost, ``publish()`` raises ``WampError``. Nothing is dropped
silently.

Reconnection (opt-in, ``reconnect=SECONDS``) survives a router that dies and comes back (``Router.restart()``):
after an unexpected loss the client retries with a short back-off (0.1 s doubling to 1 s) until ``reconnect``
seconds have passed, joins again with the same credentials, restores every subscription and registration in the
order they were made, and only then resumes draining, so queued messages keep their order. Meanwhile
``publish()`` keeps queueing (and blocks once ``max_pending`` are queued; the outage does not count as
backpressure), ``flush()``/``close()`` wait within their timeouts, and ``call()``, ``register()``,
``subscribe()`` and ``publish_acknowledged()`` raise ``WampError`` at once: a caller that must retry does so from
an ``on_reconnect`` callback. Messages already written to the dead socket are lost on the wire and not
retransmitted; subscribers see the gap in ``seq``. When the window passes, the client fails as without
reconnection. The router drops an event nobody is subscribed to, so a publisher that is back before its subscribers
would lose its whole queue: ``hold_after_reconnect(gate)`` keeps the queue until ``gate()`` returns (e.g. once
the subscriber's procedure answers again).

``close()`` flushes: it waits until the outbox is empty, then leaves the realm and waits for the router's GOODBYE.
The router handles a connection's messages in order, so its GOODBYE proves every earlier PUBLISH was dispatched.

Handlers of ``register()``/``subscribe()`` run on the client's loop thread: keep them short and thread-safe
(the collector's RPCs return data computed before the run). Callbacks of ``on_reconnect()`` and
``on_connection_lost()`` run on a short-lived thread of their own, so they may call back into the client.
"""

from __future__ import annotations

import asyncio
import collections
import concurrent.futures
import logging
import ssl
import threading
import time
from collections.abc import Callable, Coroutine, Mapping
from dataclasses import dataclass
from types import TracebackType
from typing import Any, Literal, Self, TypeVar
from urllib.parse import urlparse

import txaio

txaio.use_asyncio()

from autobahn.asyncio.rawsocket import WampRawSocketClientFactory
from autobahn.asyncio.wamp import ApplicationSession
from autobahn.asyncio.websocket import WampWebSocketClientFactory
from autobahn.wamp.exception import ApplicationError, TransportLost
from autobahn.wamp.serializer import MsgPackSerializer
from autobahn.wamp.types import Challenge, CloseDetails, ComponentConfig, PublishOptions, SessionDetails

from rei.wamp.auth import Credentials

T = TypeVar("T")

#: Bytes in the socket's user-space send buffer above which the drain task pauses (and resumes below LOW).
HIGH_WATER = 256 * 1024
LOW_WATER = 64 * 1024
_YIELD_EVERY = 64  # messages written between two yields to the loop (so RPCs are answered during bursts)
_NO_ACK = PublishOptions(acknowledge=False)
#: Pause between two reconnection attempts: the first, doubled after each failure up to the second.
_BACKOFF = (0.1, 1.0)
#: Reasons a session ends with when the router goes away (crash, restart): worth reconnecting; others are final.
_RECOVERABLE = frozenset({CloseDetails.REASON_TRANSPORT_LOST, "wamp.close.system_shutdown"})
_LOST = "connection to the router lost"
_NO_SUCH_PROCEDURE = "wamp.error.no_such_procedure"
_ANSWER_GRACE = 5.0  # seconds a call sent just before call_when_registered's deadline may wait for its answer

_log = logging.getLogger(__name__)


class WampError(RuntimeError):
    """Connection, join, backpressure time-out or a lost connection: the stream is not intact."""


class _Session(ApplicationSession):
    """The session of one connection; reports join, leave and disconnect to the owning client."""

    def __init__(self, client: WampClient, joined: asyncio.Future[_Session]) -> None:
        super().__init__(ComponentConfig(realm=client.realm))
        self.client = client
        self.joined = joined  # resolved by the router's WELCOME, failed if the session ends before
        #: How the session ended: the router's GOODBYE (or the transport-lost details), None for a bare disconnect.
        self.left: asyncio.Future[CloseDetails | None] = joined.get_loop().create_future()

    def onConnect(self) -> None:
        auth = self.client.auth
        if auth is None:
            self.join(self.config.realm)
        else:
            self.join(self.config.realm, authmethods=[auth.method], authid=auth.authid)

    def onChallenge(self, challenge: Challenge) -> str:
        auth = self.client.auth
        if auth is None:
            raise ValueError(f"the router asks for {challenge.method} authentication; no credentials given")
        return auth.answer(challenge.method, challenge.extra)

    async def onJoin(self, details: SessionDetails) -> None:
        if not self.joined.done():
            self.joined.set_result(self)

    def onLeave(self, details: CloseDetails) -> Any:
        if not self.joined.done():
            self.joined.set_exception(WampError(f"session ended: {_describe(details)}"))
        if not self.left.done():
            self.left.set_result(details)
        self.client._on_leave(self, details)
        return super().onLeave(details)

    def onDisconnect(self) -> None:
        if not self.joined.done():
            self.joined.set_exception(WampError("the router closed the connection before the session joined"))
        if not self.left.done():
            self.left.set_result(None)
        self.client._on_disconnect(self)
        super().onDisconnect()


@dataclass(frozen=True, slots=True)
class _Attachment:
    """A subscription or registration the client made: made again on every new session."""

    kind: Literal["subscribe", "register"]
    uri: str
    handler: Callable[..., Any]

    def apply(self, session: ApplicationSession) -> Any:
        if self.kind == "subscribe":
            return session.subscribe(self.handler, self.uri)
        return session.register(self.handler, self.uri)


class WampClient:
    """One WAMP session (msgpack serializer) in a background thread; see the module docstring.

    ``reconnect``: seconds to keep trying to reconnect after an unexpected loss of the connection; 0 (the
    default) fails at once.
    """

    def __init__(
        self,
        url: str,
        realm: str = "rei",
        *,
        max_pending: int = 1024,
        connect_timeout: float = 10.0,
        send_timeout: float = 30.0,
        name: str = "rei-wamp",
        auth: Credentials | None = None,
        ssl_context: ssl.SSLContext | None = None,
        reconnect: float = 0.0,
    ) -> None:
        parsed = urlparse(url)
        if parsed.scheme not in ("ws", "rs", "wss", "rss") or not parsed.hostname or not parsed.port:
            raise ValueError(f"WAMP URL must be ws[s]://host:port/path or rs[s]://host:port, got {url!r}")
        if parsed.scheme in ("wss", "rss") and ssl_context is None:
            ssl_context = ssl.create_default_context()
        if max_pending < 1:
            raise ValueError("max_pending must be >= 1")
        if reconnect < 0:
            raise ValueError("reconnect must be >= 0 seconds")
        self.url = url
        self.realm = realm
        self._host = parsed.hostname
        self._port = parsed.port
        self._scheme = parsed.scheme
        self.auth = auth
        self._ssl = ssl_context if parsed.scheme in ("wss", "rss") else None
        self._connect_timeout = connect_timeout
        self._send_timeout = send_timeout
        self._reconnect_window = reconnect
        self._name = name
        self._slots = threading.Semaphore(max_pending)
        self._lock = threading.Lock()
        self._outbox: collections.deque[tuple[str, Any]] = collections.deque()
        self._wake_scheduled = False
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        # The live session and its transport; both None before the join and while reconnecting.
        self._session: _Session | None = None
        self._transport: asyncio.Transport | None = None
        self._attachments: list[_Attachment] = []  # loop thread only
        self._wake: asyncio.Event | None = None
        self._drain_task: asyncio.Task[None] | None = None
        self._reconnect_task: asyncio.Task[None] | None = None
        self._reconnects = 0
        self._reconnect_callbacks: list[Callable[[], object]] = []
        self._lost_callbacks: list[Callable[[], object]] = []
        self._resume_gates: list[Callable[[], object]] = []
        self._held = False  # loop thread only: queued messages wait for the resume gates after a reconnection
        self._notifier: threading.Thread | None = None
        self._failure: str | None = None
        self._closing = False
        self.published = 0

    # -- lifecycle -------------------------------------------------------------------------------------------

    def start(self) -> WampClient:
        """Connect and join the realm; raises WampError within ``connect_timeout``."""
        if self._thread is not None:
            raise WampError("client already started")
        self._loop = asyncio.new_event_loop()
        self._thread = threading.Thread(target=self._run_loop, name=self._name, daemon=True)
        self._thread.start()
        opening = self._submit(self._start_session())
        try:
            opening.result(timeout=self._connect_timeout)
        except (concurrent.futures.TimeoutError, OSError, WampError) as error:
            opening.cancel()  # aborts a half-open connection
            self._stop_loop()
            detail = str(error) or type(error).__name__
            raise WampError(f"cannot join realm {self.realm!r} at {self.url}: {detail}") from error
        return self

    def close(self, timeout: float = 10.0) -> None:
        """Flush every queued message, leave the realm, stop the thread. Raises WampError if messages were lost.

        While reconnecting, it waits (within ``timeout``) for the new session to take the outbox."""
        if self._loop is None:
            return
        self._closing = True
        leaving: concurrent.futures.Future[None] | None = None
        try:
            if self._failure is None:
                leaving = self._submit(self._leave())
                leaving.result(timeout=timeout)
        except concurrent.futures.TimeoutError as error:
            if leaving is not None:
                leaving.cancel()
            self._failure = self._failure or self._close_timeout_reason(timeout)
            raise WampError(self._failure) from error
        finally:
            self._stop_loop()
        if self._failure is not None:
            raise WampError(f"{self.url}: {self._failure}")

    def __enter__(self) -> Self:
        return self.start()

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        if exc_type is None:
            self.close()
        else:
            try:
                self.close()
            except WampError:
                pass  # the original exception matters more

    # -- thread-safe API -------------------------------------------------------------------------------------

    @property
    def failure(self) -> str | None:
        """Why the session is lost for good (None while it is live or reconnecting)."""
        return self._failure

    @property
    def reconnects(self) -> int:
        """How many times the client reconnected after losing the router."""
        return self._reconnects

    def on_reconnect(self, callback: Callable[[], object]) -> None:
        """Run ``callback()`` after each reconnection, once subscriptions and registrations are restored, on a
        thread of its own (it may ``call()`` procedures)."""
        self._reconnect_callbacks.append(callback)

    def hold_after_reconnect(self, gate: Callable[[], object]) -> None:
        """After each reconnection, keep the queued messages until ``gate()`` returns (it runs on a thread of its
        own and may ``call()`` procedures; it must bound its own wait). An exception counts as returning."""
        self._resume_gates.append(gate)

    def on_connection_lost(self, callback: Callable[[], object]) -> None:
        """Run ``callback()`` when a connection is lost and reconnection starts, on a thread of its own."""
        self._lost_callbacks.append(callback)

    def publish(self, topic: str, payload: Mapping[str, Any]) -> None:
        """Queue one event (positional argument ``payload``); blocks while ``max_pending`` are queued."""
        self._check()
        self._acquire_slot()
        assert self._loop is not None
        with self._lock:
            self._outbox.append((topic, payload))
            wake = not self._wake_scheduled
            self._wake_scheduled = True
        if wake:
            self._loop.call_soon_threadsafe(self._wake_drain)

    def publish_acknowledged(self, topic: str, payload: Mapping[str, Any], timeout: float = 10.0) -> None:
        """Publish one event and wait for the router's answer; raises autobahn's ``ApplicationError`` (e.g.
        ``wamp.error.not_authorized``) when the router refuses it. Not ordered with ``publish()``'s outbox."""
        session = self._joined_session()
        options = PublishOptions(acknowledge=True)
        self._submit(_on_loop(lambda: session.publish(topic, payload, options=options))).result(timeout=timeout)

    def flush(self, timeout: float = 10.0) -> None:
        """Block until every queued message is written to the socket."""
        self._check()
        try:
            self._submit(self._flushed()).result(timeout=timeout)
        except concurrent.futures.TimeoutError as error:
            raise WampError(f"flush did not complete within {timeout} s") from error
        self._check()

    def register(self, uri: str, handler: Callable[..., Any], timeout: float = 10.0) -> None:
        """Register a procedure; ``handler`` runs on the client's thread. Restored after a reconnection."""
        self._attach(_Attachment("register", uri, handler), timeout)

    def subscribe(self, topic: str, handler: Callable[..., Any], timeout: float = 10.0) -> None:
        """Subscribe; ``handler(payload)`` runs on the client's thread. Restored after a reconnection."""
        self._attach(_Attachment("subscribe", topic, handler), timeout)

    def call(self, uri: str, *args: Any, timeout: float = 10.0) -> Any:
        """Call a procedure and return its result."""
        session = self._joined_session()
        return self._submit(_on_loop(lambda: session.call(uri, *args))).result(timeout=timeout)

    def call_when_registered(self, uri: str, *args: Any, timeout: float = 10.0, interval: float = 0.1) -> Any:
        """``call()``, retried every ``interval`` s while the procedure is not registered (yet, or again after a
        router restart) or this client is reconnecting; the last error is raised after ``timeout`` seconds. A call
        sent near the deadline still gets ``_ANSWER_GRACE`` s for the router's answer: on a loaded machine even a
        refusal can take longer than the little time that was left."""
        deadline = time.monotonic() + timeout
        while True:
            try:
                return self.call(uri, *args, timeout=max(_ANSWER_GRACE, deadline - time.monotonic()))
            except (ApplicationError, WampError) as error:
                absent = isinstance(error, ApplicationError) and error.error == _NO_SUCH_PROCEDURE
                reconnecting = isinstance(error, WampError) and self._failure is None
                if not (absent or reconnecting) or time.monotonic() + interval > deadline:
                    raise
            time.sleep(interval)

    # -- loop side -------------------------------------------------------------------------------------------

    def _run_loop(self) -> None:
        assert self._loop is not None
        asyncio.set_event_loop(self._loop)
        self._loop.run_forever()
        self._loop.close()

    def _submit(self, coro: Coroutine[Any, Any, T]) -> concurrent.futures.Future[T]:
        assert self._loop is not None
        return asyncio.run_coroutine_threadsafe(coro, self._loop)

    def _stop_loop(self) -> None:
        loop, thread = self._loop, self._thread
        if loop is None or thread is None:
            return

        async def shutdown() -> None:
            tasks = [task for task in (self._drain_task, self._reconnect_task) if task is not None]
            for task in tasks:
                task.cancel()
            await asyncio.gather(*tasks, return_exceptions=True)
            # Not live any more first: the abort's disconnect must not start a reconnection.
            transport, self._transport, self._session = self._transport, None, None
            if transport is not None:
                transport.abort()
                await asyncio.sleep(0)  # let the abort close the socket before the loop stops

        if loop.is_running():
            try:
                asyncio.run_coroutine_threadsafe(shutdown(), loop).result(timeout=5.0)
            except (concurrent.futures.TimeoutError, RuntimeError):
                pass
            loop.call_soon_threadsafe(loop.stop)
        thread.join(timeout=5.0)
        self._loop = None
        self._thread = None

    async def _start_session(self) -> None:
        self._wake = asyncio.Event()
        self._go_live(*await self._open())
        self._drain_task = asyncio.get_running_loop().create_task(self._drain())

    async def _open(self) -> tuple[_Session, asyncio.Transport]:
        """Connect, join, and make again every subscription and registration made so far (none at start)."""
        loop = asyncio.get_running_loop()
        joined: asyncio.Future[_Session] = loop.create_future()
        transport, _ = await loop.create_connection(
            self._factory(lambda: _Session(self, joined)), self._host, self._port, ssl=self._ssl
        )
        try:
            session = await _joined(joined, transport)
            for attachment in self._attachments:
                await attachment.apply(session)
        except BaseException:
            joined.cancel()  # no one waits for it any more
            transport.abort()  # a failed or cancelled attempt must not leave a connection behind
            raise
        return session, transport  # type: ignore[return-value]

    def _factory(self, make_session: Callable[[], _Session]) -> Any:
        if self._scheme in ("rs", "rss"):
            return WampRawSocketClientFactory(make_session, serializer=MsgPackSerializer())
        factory = WampWebSocketClientFactory(make_session, url=self.url, serializers=[MsgPackSerializer()])
        # No compression (CPU per message), no pings (loopback: a dead peer closes its socket).
        factory.setProtocolOptions(autoPingInterval=0, tcpNoDelay=True, perMessageCompressionOffers=[])
        return factory

    def _go_live(self, session: _Session, transport: asyncio.Transport) -> None:
        self._session, self._transport = session, transport
        self._wake_drain()  # what was queued while there was no session goes out now, in order

    def _on_leave(self, session: _Session, details: CloseDetails) -> None:
        if session is not self._session or self._closing or self._failure is not None:
            return  # a failed attempt, or our own GOODBYE
        if self._reconnect_window > 0 and details.reason in _RECOVERABLE:
            return  # _on_disconnect follows and reconnects
        self._failure = f"session ended: {_describe(details)}"

    def _on_disconnect(self, session: _Session) -> None:
        if session is not self._session:
            return  # a failed attempt, or a session already replaced
        self._session = self._transport = None
        said_goodbye = self._closing and _is_goodbye(session.left.result())
        if self._failure is None and not said_goodbye:
            if self._reconnect_window > 0:
                self._reconnect_task = asyncio.get_running_loop().create_task(self._reconnect())
                self._notify(self._lost_callbacks)
                return
            self._failure = _LOST
        self._release_waiters()

    async def _reconnect(self) -> None:
        """Open a new session, backing off between attempts, until the reconnect window closes."""
        loop = asyncio.get_running_loop()
        deadline = loop.time() + self._reconnect_window
        pause, longest = _BACKOFF
        while True:
            attempt = min(self._connect_timeout, deadline - loop.time())
            try:
                live = await asyncio.wait_for(self._open(), attempt)
            except Exception as error:  # noqa: BLE001 - whatever failed this attempt, the next one may succeed
                last_error = str(error) or type(error).__name__
            else:
                self._held = bool(self._resume_gates)
                self._go_live(*live)
                self._reconnects += 1
                self._notify(self._reconnect_callbacks)
                if self._held:
                    self._pass_gates(loop)
                return
            remaining = deadline - loop.time()
            if remaining <= 0:
                self._failure = self._failure or (
                    f"{_LOST}; no reconnection within {self._reconnect_window:g} s (last attempt: {last_error})"
                )
                self._release_waiters()
                return
            await asyncio.sleep(min(pause, remaining))
            pause = min(2 * pause, longest)

    def _notify(self, callbacks: list[Callable[[], object]]) -> None:
        """Run ``callbacks`` off the loop thread (they may block on this client), after the previous batch."""
        if not callbacks:
            return
        batch, previous = tuple(callbacks), self._notifier

        def run() -> None:
            if previous is not None:
                previous.join()  # "lost" before "reconnected", even if a callback is slow
            for callback in batch:
                try:
                    callback()
                except Exception:  # noqa: BLE001 - one failing callback must not silence the others
                    _log.exception("%s: callback %r failed", self._name, callback)

        self._notifier = threading.Thread(target=run, name=f"{self._name}-notify", daemon=True)
        self._notifier.start()

    def _pass_gates(self, loop: asyncio.AbstractEventLoop) -> None:
        """Run the resume gates off the loop thread, then let the drain task go on."""
        gates = tuple(self._resume_gates)

        def run() -> None:
            for gate in gates:
                try:
                    gate()
                except Exception:  # noqa: BLE001 - a failing gate must not keep the queue forever
                    _log.exception("%s: resume gate %r failed", self._name, gate)
            loop.call_soon_threadsafe(self._release_hold)

        threading.Thread(target=run, name=f"{self._name}-resume", daemon=True).start()

    def _release_hold(self) -> None:
        self._held = False
        self._wake_drain()

    def _release_waiters(self) -> None:
        # Unblock a producer waiting in publish(): it then sees the failure.
        for _ in range(len(self._outbox) + 1):
            self._slots.release()

    def _wake_drain(self) -> None:
        if self._wake is not None:
            self._wake.set()

    async def _drain(self) -> None:
        assert self._wake is not None
        while True:
            await self._wake.wait()
            self._wake.clear()
            with self._lock:
                self._wake_scheduled = False
            await self._write_outbox()

    async def _write_outbox(self) -> None:
        """Publish from the head of the outbox while a session is live. A message is removed only once handed to
        the transport: without a session it stays first in line for the next one (see _go_live)."""
        written = 0
        while (session := await self._writable()) is not None:
            with self._lock:
                if not self._outbox:
                    return
                topic, payload = self._outbox[0]
            try:
                session.publish(topic, payload, options=_NO_ACK)
            except TransportLost:
                return  # lost under us: _on_disconnect follows
            with self._lock:
                self._outbox.popleft()
            self.published += 1
            self._slots.release()
            written += 1
            if written % _YIELD_EVERY == 0:
                await asyncio.sleep(0)

    async def _writable(self) -> _Session | None:
        """The live session once its socket has room again (after HIGH_WATER: below LOW_WATER); None without a
        live session or while its transport is closing (a write there would be dropped by asyncio)."""
        transport = self._transport
        if transport is not None and transport.get_write_buffer_size() > HIGH_WATER:
            while transport.get_write_buffer_size() > LOW_WATER and not transport.is_closing():
                await asyncio.sleep(0.0005)
        transport = self._transport
        if self._failure is not None or transport is None or transport.is_closing() or self._held:
            return None
        return self._session

    async def _flushed(self) -> None:
        """Until the outbox is empty and written to a live socket; returns early on a failure (callers check)."""
        while self._failure is None:
            with self._lock:
                empty = not self._outbox
            transport = self._transport
            if empty and transport is not None and transport.get_write_buffer_size() == 0:
                return
            await asyncio.sleep(0.001)

    async def _leave(self) -> None:
        while True:
            await self._flushed()
            session = self._session
            if self._failure is not None or session is None:
                return
            session.leave()
            if _is_goodbye(await session.left):
                return
            # Lost before the router's GOODBYE: with reconnection the next session flushes and leaves again.

    def _attach(self, attachment: _Attachment, timeout: float) -> None:
        session = self._joined_session()

        async def attach() -> None:
            await _on_loop(lambda: attachment.apply(session))
            self._attachments.append(attachment)  # in the order made; a reconnection restores them so

        self._submit(attach()).result(timeout=timeout)

    # -- helpers ---------------------------------------------------------------------------------------------

    def _check(self) -> None:
        if self._failure is not None:
            raise WampError(f"{self.url}: {self._failure}")
        if self._loop is None:
            raise WampError("client not started (or closed)")

    def _acquire_slot(self) -> None:
        # Time spent reconnecting is the router's absence, not backpressure: wait on until the window decides.
        while not self._slots.acquire(timeout=self._send_timeout):
            self._check()
            if self._session is not None:
                raise WampError(f"backpressure: the router accepted nothing for {self._send_timeout} s")
        self._check()  # released by a failure, not by the drain

    def _joined_session(self) -> _Session:
        self._check()
        session = self._session
        if session is None:
            raise WampError(f"{self.url}: not joined ({_LOST}; reconnecting)")
        return session

    def _close_timeout_reason(self, timeout: float) -> str:
        if self._session is None:
            undelivered = len(self._outbox)
            return f"{_LOST}; not back within close()'s {timeout:g} s, {undelivered} messages undelivered"
        return f"no GOODBYE from the router within {timeout} s"


def _describe(details: CloseDetails) -> str:
    return f"{details.reason} {details.message or ''}".strip()


def _is_goodbye(details: CloseDetails | None) -> bool:
    """Whether a session ended with the router's GOODBYE rather than with the loss of its connection."""
    return details is not None and details.reason not in _RECOVERABLE


async def _joined(joined: asyncio.Future[_Session], transport: asyncio.BaseTransport) -> _Session:
    """The session once joined. Fails as soon as the connection closes, also before the transport handshake:
    autobahn creates the session only after it, so a router that drops the connection then (it is starting up)
    would otherwise leave the attempt waiting for its whole timeout."""
    while not joined.done():
        if transport.is_closing():
            raise WampError("the router closed the connection before the session joined")
        await asyncio.wait({joined}, timeout=0.05)
    return joined.result()


async def _on_loop(operation: Callable[[], Any]) -> Any:
    """Run a session operation on the loop thread (autobahn is not thread-safe) and await its future.

    A request cut off by the loss of the connection raises WampError, like every other loss."""
    try:
        return await operation()
    except TransportLost as error:
        raise WampError(_LOST) from error
    except ApplicationError as error:
        if error.error in _RECOVERABLE:
            raise WampError(f"{_LOST} ({error.error})") from error
        raise
