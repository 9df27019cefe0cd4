# SPDX-License-Identifier: EPL-2.0
"""WAMP side of the sim-adapter: the private router, the wire messages, the data collector, recordings.

Wire protocol: docs/protocol.md. Importing ``rei.wamp.client`` selects asyncio for txaio (autobahn's framework
switch), because the client bridge runs an asyncio loop in a background thread.
"""

import importlib
from typing import Any

_EXPORTS = {
    "Credentials": "rei.wamp.auth",
    "load_credentials": "rei.wamp.auth",
    "WampClient": "rei.wamp.client",
    "WampError": "rei.wamp.client",
    "LaserMode": "rei.wamp.codec",
    "MissionEventKind": "rei.wamp.codec",
    "encode_mission_event": "rei.wamp.codec",
    "encode_state": "rei.wamp.codec",
    "CollectorConfig": "rei.wamp.collector",
    "DataCollector": "rei.wamp.collector",
    "MissionPublisher": "rei.wamp.collector",
    "RecordingWriter": "rei.wamp.recording",
    "iter_recording": "rei.wamp.recording",
    "read_recording": "rei.wamp.recording",
    "stream_path": "rei.wamp.recording",
    "Router": "rei.wamp.router",
    "RouterError": "rei.wamp.router",
    "find_crossbar": "rei.wamp.router",
    "Topics": "rei.wamp.topics",
}


def __getattr__(name: str) -> Any:
    """Re-exports, imported on first use: the WAMP client pulls in autobahn (~0.3 s), which recording-only
    runs (campaign workers, ``rei sim --no-router``) never need."""
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'rei.wamp' has no attribute {name!r}")
    return getattr(importlib.import_module(module), name)


__all__ = [
    "CollectorConfig",
    "Credentials",
    "DataCollector",
    "LaserMode",
    "MissionEventKind",
    "MissionPublisher",
    "RecordingWriter",
    "Router",
    "RouterError",
    "Topics",
    "WampClient",
    "WampError",
    "encode_mission_event",
    "encode_state",
    "find_crossbar",
    "iter_recording",
    "load_credentials",
    "read_recording",
    "stream_path",
]
