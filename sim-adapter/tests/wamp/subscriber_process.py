# SPDX-License-Identifier: EPL-2.0
"""A subscriber in its own process (as the Java monitor will be): python subscriber_process.py URL TOPIC N OUT.

Prints READY once subscribed, writes every received payload (re-packed) to OUT as a msgpack stream, exits 0 after
N payloads, 2 when they do not all arrive within 60 s.
"""

from __future__ import annotations

import sys
import threading

from rei.wamp import WampClient
from rei.wamp.codec import pack


def main(url: str, topic: str, count: int, out: str) -> int:
    received: list[bytes] = []
    done = threading.Event()

    def on_event(payload: dict[str, object]) -> None:
        received.append(pack(payload))
        if len(received) >= count:
            done.set()

    with WampClient(url, name="test-sub") as client:
        client.subscribe(topic, on_event)
        print("READY", flush=True)
        complete = done.wait(timeout=60)
    with open(out, "wb") as f:
        f.write(b"".join(received))
    print(f"RECEIVED {len(received)}", flush=True)
    return 0 if complete else 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]))
