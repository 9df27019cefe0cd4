# SPDX-License-Identifier: EPL-2.0
"""Twisted endpoint plug-in that runs INSIDE the Crossbar router process, never in the simulation.

Why it exists: with autobahn 26.10.2, Crossbar's server-side WebSocket connections never get TCP_NODELAY
(``WebSocketAdapterProtocol.connectionMade`` reads ``self.tcpNoDelay`` before the factory options are copied and
swallows the AttributeError), and its RawSocket protocol never asks for it at all. Nagle's algorithm then holds
each small EVENT frame until the subscriber's delayed ACK arrives: 15-17 ms median, ~42 ms p99 at 240 Hz instead
of ~1 ms.

The fix belongs to the transport, where socket options live: this module provides the ``nodelaytcp:`` server
endpoint string (Twisted's documented ``IStreamServerEndpointStringParser`` plug-in point, used by Crossbar's
documented ``{"type": "twisted", "server_string": ...}`` listening endpoint). It is a plain TCP listening port
whose accepted connections get TCP_NODELAY before any protocol (WebSocket or RawSocket) sees them. No installed
package is modified: ``rei.wamp.router`` copies this file to ``<run>/plugins/twisted/plugins/`` and puts
``<run>/plugins`` on the router's PYTHONPATH, where Twisted's plug-in loader finds it.

Usage in a Crossbar transport: ``"endpoint": {"type": "twisted",
"server_string": "nodelaytcp:port=8080:interface=127.0.0.1"}``.

Only Twisted and zope.interface are imported (both in the router's venv, neither in the simulation's).
"""

from __future__ import annotations

import socket
from typing import Any

from twisted.internet import tcp
from twisted.internet.interfaces import IStreamServerEndpoint, IStreamServerEndpointStringParser
from twisted.plugin import IPlugin
from zope.interface import implementer


class NoDelayServer(tcp.Server):
    """An accepted TCP connection with Nagle's algorithm off from its first byte."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # Before makeConnection(): the protocol's first write (handshake reply) is already unbuffered.
        self.socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)


class NoDelayPort(tcp.Port):
    """A TCP listening port that builds :class:`NoDelayServer` transports for accepted connections."""

    transport = NoDelayServer


@implementer(IStreamServerEndpoint)
class NoDelayTCP4ServerEndpoint:
    """IPv4 TCP server endpoint whose connections have TCP_NODELAY set."""

    def __init__(self, reactor: Any, port: int, backlog: int = 50, interface: str = "127.0.0.1") -> None:
        self._reactor = reactor
        self._port = port
        self._backlog = backlog
        self._interface = interface

    def listen(self, protocol_factory: Any) -> Any:
        from twisted.internet import defer

        def start() -> NoDelayPort:
            # What reactor.listenTCP() does, with our Port class.
            port = NoDelayPort(self._port, protocol_factory, self._backlog, self._interface, self._reactor)
            port.startListening()
            return port

        return defer.execute(start)


@implementer(IPlugin, IStreamServerEndpointStringParser)
class NoDelayTCPParser:
    """Parses ``nodelaytcp:port=N[:interface=ADDR][:backlog=N]``; the interface defaults to loopback."""

    prefix = "nodelaytcp"

    def parseStreamServer(self, reactor: Any, *args: str, **kwargs: str) -> NoDelayTCP4ServerEndpoint:
        port = int(kwargs.pop("port", args[0] if args else "0"))
        interface = kwargs.pop("interface", "127.0.0.1")
        backlog = int(kwargs.pop("backlog", "50"))
        if kwargs:
            raise ValueError(f"nodelaytcp: unknown options {sorted(kwargs)}")
        return NoDelayTCP4ServerEndpoint(reactor, port, backlog=backlog, interface=interface)


nodelaytcp = NoDelayTCPParser()
