# SPDX-License-Identifier: EPL-2.0
"""What a router crash costs a run: outage length and messages lost, over repeated crashes.

One authenticated router (rei.wamp.Router), a publisher in the simulation role sending numbered messages at a fixed
rate (as the collector does, ``WampClient(reconnect=...)``) and a subscriber in the monitor role serving the
snapshot procedure, both reconnecting. As in ``rei run`` (``rei sim --wait-for-monitor``), the publisher holds its
queue after a reconnection until the subscriber's procedure answers again; ``--no-gate`` sends at once. Each round SIGKILLs the router's process group, restarts it on the same ports (``Router.restart``,
as ``rei run`` does) and measures:

- restart: seconds ``Router.restart()`` took (old group reaped, crossbar started, ports accepting);
- outage: seconds from the kill to the first message the subscriber received again;
- lost: messages published but never received (those inside the dying router, and - without the gate - those the
  publisher drained before the subscriber had subscribed again).

    .venv/bin/python benchmarks/router_restart.py [--rounds 5] [--rate 240] [--no-gate]
"""

from __future__ import annotations

import argparse
import os
import signal
import statistics
import tempfile
import threading
import time
from pathlib import Path

from rei.wamp import Router, Topics, WampClient

RUN_ID = "bench-restart"


class _Receiver:
    def __init__(self) -> None:
        self.seen: set[int] = set()
        self.last_arrival = 0.0
        self.lock = threading.Lock()

    def __call__(self, payload: dict) -> None:
        with self.lock:
            self.seen.add(int(payload["n"]))
            self.last_arrival = time.monotonic()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n", 1)[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--rate", type=float, default=240.0, help="messages per second (default 240)")
    parser.add_argument("--no-gate", action="store_true", help="send the queue at once after a reconnection")
    args = parser.parse_args()
    topics = Topics(RUN_ID)
    topic = topics.state
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    with tempfile.TemporaryDirectory(prefix="rei-bench-restart-") as folder, \
            Router(run_dir=Path(folder) / "router", run_id=RUN_ID) as router:
        receiver = _Receiver()
        subscriber = WampClient(router.rs_url, auth=router.credentials("monitor"), reconnect=30.0).start()
        subscriber.subscribe(topic, receiver)
        subscriber.register(topics.snapshot, lambda: "ok")  # after subscribing, as the monitor does
        publisher = WampClient(router.rs_url, auth=router.credentials("simulation"), reconnect=30.0).start()
        if not args.no_gate:
            publisher.hold_after_reconnect(lambda: publisher.call_when_registered(topics.snapshot, timeout=10.0))
        sent = 0
        rows = []
        period = 1.0 / args.rate
        for round_ in range(args.rounds):
            next_at = time.monotonic()
            phase_end = next_at + 1.0  # a second of steady stream before the crash
            killed_at: float | None = None
            restart_s: float | None = None
            restarting = threading.Thread()
            first_after = None
            while True:
                now = time.monotonic()
                if killed_at is None and now >= phase_end:
                    with receiver.lock:
                        before = set(receiver.seen)
                    assert router.pid is not None
                    os.killpg(router.pid, signal.SIGKILL)
                    killed_at = time.monotonic()
                    # restarted beside the stream: the publisher goes on queueing meanwhile, as a simulation does
                    restarting = threading.Thread(target=router.restart)
                    restarting.start()
                if restart_s is None and killed_at is not None and not restarting.is_alive():
                    restart_s = time.monotonic() - killed_at
                if killed_at is not None:
                    with receiver.lock:
                        arrived = receiver.last_arrival
                        fresh = receiver.seen - before
                    if fresh and first_after is None:
                        first_after = arrived - killed_at
                    if first_after is not None and restart_s is not None and now - killed_at > first_after + 1.0:
                        break
                    if now - killed_at > 60:
                        raise SystemExit("no message arrived within 60 s of the restart")
                publisher.publish(topic, {"n": sent})
                sent += 1
                next_at += period
                time.sleep(max(0.0, next_at - time.monotonic()))
            publisher.flush(timeout=30)
            time.sleep(0.5)
            with receiver.lock:
                lost = sent - len(receiver.seen)
            rows.append((restart_s, first_after, lost - sum(r[2] for r in rows)))
            print(f"round {round_ + 1}: restart {restart_s:.2f} s, outage {first_after:.2f} s, "
                  f"lost {rows[-1][2]} of {sent} messages so far sent")
        publisher.close()
        subscriber.close()
    restarts, outages, losses = zip(*rows, strict=True)
    print(f"median restart {statistics.median(restarts):.2f} s, median outage {statistics.median(outages):.2f} s, "
          f"lost per crash: median {statistics.median(losses):.0f}, max {max(losses)} "
          f"({max(losses) / args.rate:.2f} s of stream at {args.rate:g} Hz)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
