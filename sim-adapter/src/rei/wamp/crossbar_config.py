# SPDX-License-Identifier: EPL-2.0
"""Generation of the Crossbar node configuration REI's router runs with.

Why a builder instead of a template file: the ports are chosen at run time, and the security model must be able
to grow from "anonymous on loopback" to "one authenticated role per component" (collector, mission executor,
monitor, evaluator; WAMP-CRA or ticket, anonymous off) without rewriting the rest. Roles, their permissions and
each transport's ``auth`` block are therefore separate values; adding authentication means passing other roles and
an ``auth`` mapping per transport, nothing else.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal

TransportKind = Literal["websocket", "rawsocket"]
Serializer = Literal["msgpack", "json", "cbor"]

#: Largest WAMP message the router accepts (bytes). A 360-beam full state is ~4 KB; a world is well below this.
MAX_MESSAGE_SIZE = 1 << 20


@dataclass(frozen=True, slots=True)
class Permission:
    """What a role may do on the URIs matching ``uri`` (``match`` is ``exact``, ``prefix`` or ``wildcard``)."""

    uri: str
    match: Literal["exact", "prefix", "wildcard"] = "prefix"
    call: bool = True
    register: bool = True
    publish: bool = True
    subscribe: bool = True

    def to_config(self) -> dict[str, Any]:
        return {
            "uri": self.uri,
            "match": self.match,
            "allow": {
                "call": self.call,
                "register": self.register,
                "publish": self.publish,
                "subscribe": self.subscribe,
            },
            "disclose": {"caller": False, "publisher": False},
            "cache": True,
        }


@dataclass(frozen=True, slots=True)
class Role:
    """A WAMP authrole of the realm. Today only ``anonymous``; later one per component."""

    name: str
    permissions: tuple[Permission, ...]

    def to_config(self) -> dict[str, Any]:
        return {"name": self.name, "permissions": [p.to_config() for p in self.permissions]}


def anonymous_role() -> Role:
    """Everything allowed under ``rei.`` - acceptable only because the router listens on loopback."""
    return Role("anonymous", (Permission("rei.", "prefix"),))


@dataclass(frozen=True, slots=True)
class Transport:
    """One listening transport of the router.

    ``nodelay`` selects the ``nodelaytcp:`` endpoint (see ``rei.wamp.crossbar_nodelay``) instead of Crossbar's
    plain ``tcp`` endpoint, which leaves Nagle's algorithm on. ``auth`` is Crossbar's per-transport ``auth``
    block; ``None`` means anonymous.
    """

    kind: TransportKind
    port: int
    interface: str = "127.0.0.1"
    nodelay: bool = True
    serializers: tuple[Serializer, ...] = ("msgpack",)
    path: str = "ws"
    auth: Mapping[str, Any] | None = None

    def endpoint(self) -> dict[str, Any]:
        if self.nodelay:
            return {
                "type": "twisted",
                "server_string": f"nodelaytcp:port={self.port}:interface={self.interface}",
            }
        return {"type": "tcp", "interface": self.interface, "port": self.port}

    def to_config(self) -> dict[str, Any]:
        config: dict[str, Any] = {
            "type": self.kind,
            "endpoint": self.endpoint(),
            "serializers": list(self.serializers),
        }
        if self.kind == "websocket":
            # auto_ping off: a loopback peer that dies closes its socket; pings would only cost router CPU.
            config["options"] = {"max_message_size": MAX_MESSAGE_SIZE, "auto_ping_interval": 0}
        else:
            config["options"] = {"max_message_size": MAX_MESSAGE_SIZE}
        if self.auth is not None:
            config["auth"] = dict(self.auth)
        return config

    def url(self) -> str:
        """The URL a client uses: ``ws://host:port/ws`` or ``rs://host:port``."""
        if self.kind == "websocket":
            return f"ws://{self.interface}:{self.port}/{self.path}"
        return f"rs://{self.interface}:{self.port}"


def node_config(realm: str, roles: Sequence[Role], transports: Sequence[Transport]) -> dict[str, Any]:
    """The whole Crossbar node configuration: one router worker, one realm, the given transports."""
    if not transports:
        raise ValueError("the router needs at least one transport")
    return {
        "version": 2,
        "controller": {},
        "workers": [
            {
                "type": "router",
                "realms": [{"name": realm, "roles": [r.to_config() for r in roles]}],
                "transports": [t.to_config() for t in transports],
            }
        ],
    }
