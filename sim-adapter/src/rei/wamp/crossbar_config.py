# SPDX-License-Identifier: EPL-2.0
"""Generation of the Crossbar node configuration REI's router runs with.

Why a builder instead of a template file: the ports, the run id the permissions are scoped to and the secrets are
chosen at run time. Roles, their permissions and each transport's ``auth`` block are separate values:
``component_roles`` + ``wampcra_auth`` give one WAMP-CRA role per component with anonymous off (docs/security.md);
``anonymous_role`` is the open loopback configuration of transport tests.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Literal

TransportKind = Literal["websocket", "rawsocket"]
Serializer = Literal["msgpack", "json", "cbor"]

#: Largest WAMP message the router accepts and the Java clients read (bytes; contract/vocabulary.json). A 360-beam
#: state is ~4 KB (full frames carry no static obstacle), but two procedures answer with the whole room, which in a
#: room from an occupancy map has thousands of walls: the monitor's snapshot (the runtime model's XMI; the 30 x 50 m
#: test building's is 1.22 MB, beyond the 1 MiB of before) and the config RPC (world.json; the building's 894 KB).
MAX_MESSAGE_SIZE = 1 << 24


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
    """A WAMP authrole of the realm: ``anonymous`` (tests) or one per component (``component_roles``)."""

    name: str
    permissions: tuple[Permission, ...]

    def to_config(self) -> dict[str, Any]:
        return {"name": self.name, "permissions": [p.to_config() for p in self.permissions]}


def anonymous_role() -> Role:
    """Everything allowed under ``rei.`` - only for tests and benchmarks on loopback (``Router(auth=False)``)."""
    return Role("anonymous", (Permission("rei.", "prefix"),))


_NOTHING = {"call": False, "register": False, "publish": False, "subscribe": False}


def _allow(run_id: str | None, name: str, *actions: str) -> Permission:
    """``actions`` on the run's URI ``name`` only: ``rei.run.<run_id>.<name>`` exactly, or (no run id: a router
    shared by several runs, as in tests) every run's ``name`` via the wildcard ``rei.run..<name>``."""
    unknown = set(actions) - set(_NOTHING)
    if unknown:
        raise ValueError(f"unknown actions {sorted(unknown)}")
    flags = {**_NOTHING, **{a: True for a in actions}}
    if run_id is None:
        return Permission(f"rei.run..{name}", "wildcard", **flags)
    return Permission(f"rei.run.{run_id}.{name}", "exact", **flags)


#: What each component may do (docs/security.md). Everything not listed is denied by the router.
ROLE_GRANTS: dict[str, tuple[tuple[str, tuple[str, ...]], ...]] = {
    "collector": (("state", ("publish",)), ("config", ("register",))),
    "mission-executor": (("mission", ("publish",)), ("mission_info", ("register",))),
    # The simulator hosts the collector and the mission executor in one session: WAMP orders events per
    # publisher session only, and the monitor needs state and mission events in publication order.
    # snapshot (read-only): after a router restart it holds its queue until the monitor answers again
    "simulation": (("state", ("publish",)), ("config", ("register",)),
                   ("mission", ("publish",)), ("mission_info", ("register",)), ("snapshot", ("call",)),
                   *((f"sut.{name}", ("publish",)) for name in ("tick", "goal", "cancel", "end")),
                   ("sut.command", ("subscribe",)), ("sut.status", ("subscribe",)), ("sut.hello", ("register",))),
    # the system under test (docs/sut.md): what a robot's software sees, never the true state
    "sut": (*((f"sut.{name}", ("subscribe",)) for name in ("tick", "goal", "cancel", "end")),
            ("sut.command", ("publish",)), ("sut.status", ("publish",)), ("sut.hello", ("call",))),
    "monitor": (("state", ("subscribe",)), ("mission", ("subscribe",)), ("signal", ("publish",)),
                ("snapshot", ("register",)), ("config", ("call",))),
    # read-only: subscriptions plus the read-only procedures (snapshot: readiness probe of `rei run`)
    "evaluator": (("state", ("subscribe",)), ("mission", ("subscribe",)), ("signal", ("subscribe",)),
                  ("snapshot", ("call",)), ("config", ("call",)), ("mission_info", ("call",))),
    "viewer": (("state", ("subscribe",)), ("mission", ("subscribe",)), ("signal", ("subscribe",))),
}


def component_roles(run_id: str | None) -> tuple[Role, ...]:
    """One role per component (``ROLE_GRANTS``), scoped to run ``run_id`` (or to every run when None)."""
    return tuple(Role(name, tuple(_allow(run_id, uri, *actions) for uri, actions in grants))
                 for name, grants in ROLE_GRANTS.items())


def wampcra_auth(secrets: Mapping[str, str]) -> dict[str, Any]:
    """A transport's ``auth`` block: WAMP-CRA only (no anonymous), authid = role name, static secrets."""
    return {"wampcra": {"type": "static",
                        "users": {authid: {"secret": secret, "role": authid} for authid, secret in secrets.items()}}}


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
    tls: tuple[str, str] | None = None  # (certificate file, key file), PEM

    def endpoint(self) -> dict[str, Any]:
        if self.tls is not None:
            # Crossbar's TLS needs its own tcp endpoint (the nodelaytcp plug-in speaks plain TCP only).
            certificate, key = self.tls
            return {"type": "tcp", "interface": self.interface, "port": self.port,
                    "tls": {"certificate": certificate, "key": key}}
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
        host = f"[{self.interface}]" if ":" in self.interface else self.interface
        if self.kind == "websocket":
            return f"{'wss' if self.tls else 'ws'}://{host}:{self.port}/{self.path}"
        return f"{'rss' if self.tls else 'rs'}://{host}:{self.port}"


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
