# SPDX-License-Identifier: EPL-2.0
"""A WAMP session usable from synchronous code: the bridge between the simulation loop and the router.

Why a thread: the simulation loop is synchronous and runs faster than real time; autobahn is asynchronous. The
client owns an asyncio loop in a daemon thread. ``publish()`` never talks to the network itself: it appends the
message to an outbox and wakes the loop with ``call_soon_threadsafe`` (once per burst, not per message). A
drain task on the loop publishes with ``acknowledge=False`` (no round trip per message) in FIFO order.

Backpressure instead of loss: at most ``max_pending`` messages wait in the outbox (a semaphore the caller
acquires), and the drain task stops writing while the socket's send buffer holds more than ``HIGH_WATER`` bytes.
A simulation that outruns the router therefore blocks in ``publish()``; if the router takes nothing for
``send_timeout`` seconds, or the connection is lost, ``publish()`` raises ``WampError``. Nothing is dropped
silently.

``close()`` flushes: it waits until the outbox is empty, then leaves the realm and waits for the router's GOODBYE.
The router handles a connection's messages in order, so its GOODBYE proves every earlier PUBLISH was dispatched.

Handlers of ``register()``/``subscribe()`` run on the client's loop thread: keep them short and thread-safe
(the collector's RPCs return data computed before the run).
"""

from __future__ import annotations

import asyncio
import collections
import concurrent.futures
import ssl
import threading
from collections.abc import Callable, Coroutine, Mapping
from types import TracebackType
from typing import Any, Self, TypeVar
from urllib.parse import urlparse

import txaio

txaio.use_asyncio()

from autobahn.asyncio.rawsocket import WampRawSocketClientFactory
from autobahn.asyncio.wamp import ApplicationSession
from autobahn.asyncio.websocket import WampWebSocketClientFactory
from autobahn.wamp.serializer import MsgPackSerializer
from autobahn.wamp.types import Challenge, CloseDetails, ComponentConfig, PublishOptions, SessionDetails

from rei.wamp.auth import Credentials

T = TypeVar("T")

#: Bytes in the socket's user-space send buffer above which the drain task pauses (and resumes below LOW).
HIGH_WATER = 256 * 1024
LOW_WATER = 64 * 1024
_YIELD_EVERY = 64  # messages written between two yields to the loop (so RPCs are answered during bursts)
_NO_ACK = PublishOptions(acknowledge=False)


class WampError(RuntimeError):
    """Connection, join, backpressure time-out or a lost connection: the stream is not intact."""


class _Session(ApplicationSession):
    """Reports join, leave and disconnect to the owning client."""

    client: WampClient

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
        self.client._on_join(self)

    def onLeave(self, details: CloseDetails) -> Any:
        self.client._on_leave(details)
        return super().onLeave(details)

    def onDisconnect(self) -> None:
        self.client._on_disconnect()
        super().onDisconnect()


class WampClient:
    """One WAMP session (msgpack serializer) in a background thread; see the module docstring."""

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
    ) -> None:
        parsed = urlparse(url)
        if parsed.scheme not in ("ws", "rs", "wss", "rss") or not parsed.hostname or not parsed.port:
            raise ValueError(f"WAMP URL must be ws[s]://host:port/path or rs[s]://host:port, got {url!r}")
        if parsed.scheme in ("wss", "rss") and ssl_context is None:
            ssl_context = ssl.create_default_context()
        if max_pending < 1:
            raise ValueError("max_pending must be >= 1")
        self.url = url
        self.realm = realm
        self._host = parsed.hostname
        self._port = parsed.port
        self._scheme = parsed.scheme
        self.auth = auth
        self._ssl = ssl_context if parsed.scheme in ("wss", "rss") else None
        self._connect_timeout = connect_timeout
        self._send_timeout = send_timeout
        self._name = name
        self._slots = threading.Semaphore(max_pending)
        self._lock = threading.Lock()
        self._outbox: collections.deque[tuple[str, Any]] = collections.deque()
        self._wake_scheduled = False
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        self._session: _Session | None = None
        self._transport: asyncio.Transport | None = None
        self._joined: concurrent.futures.Future[None] = concurrent.futures.Future()
        self._left: asyncio.Future[None] | None = None
        self._wake: asyncio.Event | None = None
        self._drain_task: asyncio.Task[None] | None = None
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
        try:
            self._submit(self._connect()).result(timeout=self._connect_timeout)
            self._joined.result(timeout=self._connect_timeout)
        except (concurrent.futures.TimeoutError, OSError, WampError) as error:
            self._stop_loop()
            detail = self._failure or str(error) or type(error).__name__
            raise WampError(f"cannot join realm {self.realm!r} at {self.url}: {detail}") from error
        return self

    def close(self, timeout: float = 10.0) -> None:
        """Flush every queued message, leave the realm, stop the thread. Raises WampError if messages were lost."""
        if self._loop is None:
            return
        self._closing = True
        try:
            if self._failure is None:
                self._submit(self._leave()).result(timeout=timeout)
        except concurrent.futures.TimeoutError as error:
            self._failure = self._failure or f"no GOODBYE from the router within {timeout} s"
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

    def publish(self, topic: str, payload: Mapping[str, Any]) -> None:
        """Queue one event (positional argument ``payload``); blocks while ``max_pending`` are queued."""
        self._check()
        if not self._slots.acquire(timeout=self._send_timeout):
            self._check()
            raise WampError(f"backpressure: the router accepted nothing for {self._send_timeout} s")
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
        """Register a procedure; ``handler`` runs on the client's thread."""
        session = self._joined_session()
        self._submit(_on_loop(lambda: session.register(handler, uri))).result(timeout=timeout)

    def subscribe(self, topic: str, handler: Callable[..., Any], timeout: float = 10.0) -> None:
        """Subscribe; ``handler(payload)`` runs on the client's thread."""
        session = self._joined_session()
        self._submit(_on_loop(lambda: session.subscribe(handler, topic))).result(timeout=timeout)

    def call(self, uri: str, *args: Any, timeout: float = 10.0) -> Any:
        """Call a procedure and return its result."""
        session = self._joined_session()
        return self._submit(_on_loop(lambda: session.call(uri, *args))).result(timeout=timeout)

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
            if self._drain_task is not None:
                self._drain_task.cancel()
            if self._transport is not None:
                self._transport.abort()

        if loop.is_running():
            try:
                asyncio.run_coroutine_threadsafe(shutdown(), loop).result(timeout=5.0)
            except (concurrent.futures.TimeoutError, RuntimeError):
                pass
            loop.call_soon_threadsafe(loop.stop)
        thread.join(timeout=5.0)
        self._loop = None
        self._thread = None

    async def _connect(self) -> None:
        def make_session() -> _Session:
            session = _Session(ComponentConfig(realm=self.realm))
            session.client = self
            return session

        factory: Any
        if self._scheme in ("rs", "rss"):
            factory = WampRawSocketClientFactory(make_session, serializer=MsgPackSerializer())
        else:
            factory = WampWebSocketClientFactory(
                make_session, url=self.url, serializers=[MsgPackSerializer()]
            )
            # No compression (CPU per message), no pings (loopback: a dead peer closes its socket).
            factory.setProtocolOptions(autoPingInterval=0, tcpNoDelay=True, perMessageCompressionOffers=[])
        self._left = asyncio.get_running_loop().create_future()
        self._wake = asyncio.Event()
        # asyncio sets TCP_NODELAY on every TCP connection it creates; the router side is rei.wamp.router's job.
        transport, _ = await asyncio.get_running_loop().create_connection(
            factory, self._host, self._port, ssl=self._ssl)
        self._transport = transport  # type: ignore[assignment]
        self._drain_task = asyncio.get_running_loop().create_task(self._drain())

    def _on_join(self, session: _Session) -> None:
        self._session = session
        if not self._joined.done():
            self._joined.set_result(None)

    def _on_leave(self, details: CloseDetails) -> None:
        if not self._closing and self._failure is None:
            self._failure = f"session ended: {details.reason} {details.message or ''}".strip()
        if not self._joined.done():
            self._joined.set_exception(WampError(self._failure or str(details.reason)))
        if self._left is not None and not self._left.done():
            self._left.set_result(None)

    def _on_disconnect(self) -> None:
        if not self._closing and self._failure is None:
            self._failure = "connection to the router lost"
        if not self._joined.done():
            self._joined.set_exception(WampError(self._failure or "disconnected"))
        if self._left is not None and not self._left.done():
            self._left.set_result(None)
        self._release_waiters()

    def _release_waiters(self) -> None:
        # Unblock a producer waiting in publish(): it then sees the failure.
        for _ in range(len(self._outbox) + 1):
            self._slots.release()

    def _wake_drain(self) -> None:
        if self._wake is not None:
            self._wake.set()

    async def _drain(self) -> None:
        assert self._wake is not None and self._transport is not None
        while True:
            await self._wake.wait()
            self._wake.clear()
            with self._lock:
                self._wake_scheduled = False
            written = 0
            while True:
                with self._lock:
                    if not self._outbox:
                        break
                    topic, payload = self._outbox.popleft()
                if self._transport.get_write_buffer_size() > HIGH_WATER:
                    while self._transport.get_write_buffer_size() > LOW_WATER:
                        if self._transport.is_closing():
                            return
                        await asyncio.sleep(0.0005)
                session = self._session
                if session is None or self._failure is not None:
                    return
                session.publish(topic, payload, options=_NO_ACK)
                self.published += 1
                self._slots.release()
                written += 1
                if written % _YIELD_EVERY == 0:
                    await asyncio.sleep(0)

    async def _flushed(self) -> None:
        assert self._transport is not None
        while True:
            with self._lock:
                empty = not self._outbox
            if empty and self._transport.get_write_buffer_size() == 0:
                return
            if self._failure is not None or self._transport.is_closing():
                return
            await asyncio.sleep(0.001)

    async def _leave(self) -> None:
        await self._flushed()
        if self._failure is not None or self._session is None:
            return
        self._session.leave()
        assert self._left is not None
        await self._left

    # -- helpers ---------------------------------------------------------------------------------------------

    def _check(self) -> None:
        if self._failure is not None:
            raise WampError(f"{self.url}: {self._failure}")
        if self._loop is None:
            raise WampError("client not started (or closed)")

    def _joined_session(self) -> _Session:
        self._check()
        if self._session is None:
            raise WampError("not joined")
        return self._session


async def _on_loop(operation: Callable[[], Any]) -> Any:
    """Run a session operation on the loop thread (autobahn is not thread-safe) and await its future."""
    return await operation()
