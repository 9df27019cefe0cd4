# SPDX-License-Identifier: EPL-2.0
"""WAMP side of the sim-adapter: the private router, the wire messages, the data collector, recordings.

Wire protocol: docs/protocol.md. Importing this package selects asyncio for txaio (autobahn's framework switch),
because the client bridge runs an asyncio loop in a background thread.
"""

from rei.wamp.auth import Credentials, load_credentials
from rei.wamp.client import WampClient, WampError
from rei.wamp.codec import LaserMode, MissionEventKind, encode_mission_event, encode_state
from rei.wamp.collector import CollectorConfig, DataCollector, MissionPublisher
from rei.wamp.recording import RecordingWriter, iter_recording, read_recording, stream_path
from rei.wamp.router import Router, RouterError, find_crossbar
from rei.wamp.topics import Topics

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
