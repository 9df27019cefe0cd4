# SPDX-License-Identifier: EPL-2.0
"""Publish-to-receive latency of state messages through REI's Crossbar router.

Two routers run side by side: Nagle on (Crossbar's plain ``tcp`` endpoint) and Nagle off (REI's ``nodelaytcp``
endpoint, see rei.wamp.crossbar_nodelay). For each router and transport (websocket, rawsocket) a subscriber runs
in its own process and a publisher (rei.wamp.WampClient, the collector's bridge) sends state messages at a fixed
wall-clock rate, after an unmeasured warm-up. By default each configuration streams continuously (as a run does);
``--rounds N`` splits the measured seconds into N interleaved rounds so that load from other jobs on a shared
machine hits every configuration alike (the idle gaps between rounds weaken the Nagle effect, though: the
receiver's delayed-ACK state is reset by idleness). Latency is CLOCK_MONOTONIC in the subscriber's
handler minus CLOCK_MONOTONIC when the simulation thread called ``publish()``: bridge, router and both sockets.

    .venv/bin/python benchmarks/wamp_latency.py [--seconds 10] [--rounds 1] [--rate 240] [--laser min|full]

Prints one row per (transport, TCP_NODELAY) with p50/p99/max, gaps and the router worker's CPU per message;
exits 1 when a TCP_NODELAY row misses p99 < 5 ms or lost a message.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from rei.geometry import Pose2D
from rei.sim.state import ObjectState, RobotState, SimState
from rei.wamp import LaserMode, Router, WampClient, encode_state
from rei.wamp.codec import pack

STATE, WARMUP, DONE = "state", "warmup", "done"


def _uri(url: str, name: str) -> str:
    """Per-transport URIs: the websocket and rawsocket pairs share a router but must not hear each other."""
    return f"rei.run.bench_{url[:2]}.{name}"


TARGET_P99_MS = 5.0


def make_state(i: int, laser: LaserMode) -> dict[str, Any]:
    """A realistic state message: robot + 4 humans + 2 dynamic boxes, laser as requested."""
    t = i / 240.0
    ranges = np.full(360, np.inf)
    ranges[:90] = 1.0 + 0.5 * np.sin(np.arange(90) * 0.1 + t)
    robot = RobotState(
        "tb3",
        (1.0 + t * 0.1, 2.0, 0.0, 0.3),
        (0.2, 0.0, 0.1),
        Pose2D(1.0, 2.0, 0.3),
        float(ranges.min()),
        ranges,
    )
    objects = tuple(
        ObjectState(f"h{k}", "HUMAN" if k < 4 else "DYNAMIC", (k + math.sin(t), 3.0, 0.85, 0.0), (0.5, 0.0, 0.0))
        for k in range(6)
    )
    return encode_state(SimState(t, robot, objects, ()), i, laser=laser, nav_state="ACTIVE")


# -- subscriber process ------------------------------------------------------------------------------------------


def run_subscriber(url: str) -> None:
    latencies: list[float] = []
    state = {"expected": 0, "gaps": 0}
    done = threading.Event()
    result: dict[str, Any] = {}

    def on_state(payload: dict[str, Any]) -> None:
        latencies.append((time.monotonic_ns() - payload["bench_ns"]) / 1e6)
        if payload["seq"] != state["expected"]:
            state["gaps"] += 1
        state["expected"] = payload["seq"] + 1

    def on_done(info: dict[str, Any]) -> None:
        result["sent"] = info["sent"]
        done.set()

    with WampClient(url, name="bench-sub") as client:
        client.subscribe(_uri(url, STATE), on_state)
        client.subscribe(_uri(url, WARMUP), lambda payload: None)
        client.subscribe(_uri(url, DONE), on_done)
        print("READY", flush=True)
        if not done.wait(timeout=600):
            raise SystemExit("subscriber: no end marker")
    lat = np.array(latencies)
    print(
        json.dumps(
            {
                "received": len(latencies),
                "sent": result["sent"],
                "gaps": state["gaps"],
                "p50": float(np.percentile(lat, 50)) if len(lat) else math.nan,
                "p99": float(np.percentile(lat, 99)) if len(lat) else math.nan,
                "max": float(lat.max()) if len(lat) else math.nan,
            }
        ),
        flush=True,
    )


# -- publisher / driver --------------------------------------------------------------------------------------


def _worker_pid(controller_pid: int) -> int | None:
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        fields = stat[stat.rindex(")") + 2 :].split()
        if int(fields[1]) == controller_pid and "crossbar-worker" in (entry / "cmdline").read_text(
            errors="ignore"
        ):
            return int(entry.name)
    return None


def _cpu_seconds(pid: int | None) -> float:
    if pid is None:
        return math.nan
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


@dataclass
class _Pair:
    """One measured configuration: a subscriber process and a publisher session on one router transport."""

    kind: str
    nodelay: str
    router: Router
    subscriber: subprocess.Popen[str]
    publisher: WampClient
    sent: int = 0
    router_cpu: float = 0.0


def _open_pair(router: Router, kind: str, nodelay: str) -> _Pair:
    url = router.url(kind)  # type: ignore[arg-type]
    sub = subprocess.Popen([sys.executable, __file__, "--subscriber", url], stdout=subprocess.PIPE, text=True)
    assert sub.stdout is not None
    if sub.stdout.readline().strip() != "READY":
        sub.kill()
        raise RuntimeError(f"subscriber on {url} did not start")
    return _Pair(kind, nodelay, router, sub, WampClient(url, name="bench-pub").start())


def _send(pair: _Pair, topic: str, templates: list[dict[str, Any]], rate: float, seconds: float) -> None:
    """Publish at ``rate`` (absolute deadlines, so no drift) for ``seconds``; stamps the time of publish()."""
    period = 1.0 / rate
    start = time.monotonic()
    for i in range(int(seconds * rate)):
        delay = start + i * period - time.monotonic()
        if delay > 0:
            time.sleep(delay)
        message = dict(templates[i % len(templates)])
        if topic == STATE:
            message["seq"] = pair.sent
            pair.sent += 1
        message["bench_ns"] = time.monotonic_ns()
        pair.publisher.publish(_uri(pair.publisher.url, topic), message)
    pair.publisher.flush()


def run(args: argparse.Namespace) -> list[tuple[_Pair, dict[str, Any]]]:
    """Both routers up, all pairs connected, then (optionally interleaved) rounds so that the load (other jobs
    on a shared 2-core box) hits every configuration alike."""
    laser = LaserMode(args.laser)
    templates = [make_state(i, laser) for i in range(64)]
    routers = {mode: Router(nodelay=mode == "on", auth=False).start() for mode in args.nodelay}
    pairs: list[_Pair] = []
    try:
        for mode, router in routers.items():
            for kind in args.transports:
                pairs.append(_open_pair(router, kind, mode))
        for pair in pairs:  # the first seconds after a router (or connection) starts are noisy: not measured
            _send(pair, WARMUP, templates, args.rate, args.warmup)
        for _ in range(args.rounds):
            for pair in pairs:
                worker = _worker_pid(pair.router.pid or -1)
                before = _cpu_seconds(worker)
                _send(pair, STATE, templates, args.rate, args.seconds / args.rounds)
                pair.router_cpu += _cpu_seconds(worker) - before
        results = []
        for pair in pairs:
            pair.publisher.publish(_uri(pair.publisher.url, DONE), {"sent": pair.sent})
            pair.publisher.close()
            out, _ = pair.subscriber.communicate(timeout=60)
            stats = json.loads(out.strip().splitlines()[-1])
            stats["router_us_per_msg"] = pair.router_cpu / max(pair.sent, 1) * 1e6
            results.append((pair, stats))
        return results
    finally:
        for pair in pairs:
            if pair.subscriber.poll() is None:
                pair.subscriber.kill()
                pair.subscriber.wait()
        for router in routers.values():
            router.stop()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=10.0, help="measured seconds per configuration")
    parser.add_argument("--rounds", type=int, default=1, help="interleaved rounds the seconds are split into")
    parser.add_argument("--rate", type=float, default=240.0)
    parser.add_argument(
        "--warmup", type=float, default=2.0, help="unmeasured seconds per configuration first"
    )
    parser.add_argument("--laser", choices=[m.value for m in LaserMode], default="min")
    parser.add_argument(
        "--transports", nargs="+", choices=["websocket", "rawsocket"], default=["websocket", "rawsocket"]
    )
    parser.add_argument("--nodelay", nargs="+", choices=["off", "on"], default=["off", "on"])
    parser.add_argument("--subscriber", metavar="URL", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.subscriber:
        run_subscriber(args.subscriber)
        return 0

    load_before = os.getloadavg()[0]
    results = run(args)
    size = len(pack({**make_state(0, LaserMode(args.laser)), "bench_ns": time.monotonic_ns()}))
    print(
        f"cores: {os.cpu_count()}  rate: {args.rate:g} Hz  measured: {args.seconds:g} s per row in "
        f"{args.rounds} round(s)  laser: {args.laser}  payload: {size} B  "
        f"load avg: {load_before:.2f} -> {os.getloadavg()[0]:.2f}"
    )
    print(
        f"{'transport':10} {'router TCP_NODELAY':18} {'sent':>6} {'recv':>6} {'gaps':>5} "
        f"{'p50 ms':>7} {'p99 ms':>7} {'max ms':>7} {'router us/msg':>13}"
    )
    ok = True
    for pair, s in results:
        print(
            f"{pair.kind:10} {pair.nodelay:18} {s['sent']:6d} {s['received']:6d} {s['gaps']:5d} "
            f"{s['p50']:7.2f} {s['p99']:7.2f} {s['max']:7.2f} {s['router_us_per_msg']:13.0f}"
        )
        if pair.nodelay == "on":
            ok = ok and s["p99"] < TARGET_P99_MS and s["gaps"] == 0 and s["received"] == s["sent"]
    print(f"target p99 < {TARGET_P99_MS} ms with TCP_NODELAY: {'met' if ok else 'NOT met'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
