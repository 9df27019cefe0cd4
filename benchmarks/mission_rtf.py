# SPDX-License-Identifier: EPL-2.0
"""Real-time factor of a whole mission: simulation, reference navigation, mission executor and data collector
publishing state at 20 Hz through a real Crossbar router.

The example case is generated from examples/simple_navigation.rei (6 x 4 m, a table, a shelf, one walking
human; 360-beam lidar at 10 Hz, physics at 240 Hz, control at 10 Hz). The mission runs pinned to one core; the
router is started before pinning, so it runs on the other. Target: >= 20x real time.

    .venv/bin/python benchmarks/mission_rtf.py [--runs 3] [--example simple_navigation] [--no-router]
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path

from _examples import generate_example

from rei.run import MissionRunOptions, run_mission
from rei.wamp.client import WampClient
from rei.wamp.router import Router


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--example", default="simple_navigation")
    parser.add_argument("--no-router", action="store_true", help="record only, publish nothing")
    parser.add_argument("--no-humans", action="store_true")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory(prefix="rei-bench-") as tmp:
        case = generate_example(args.example, Path(tmp) / "case")
        router = None if args.no_router else Router(run_dir=Path(tmp) / "router", auth=False).start()
        try:
            if hasattr(os, "sched_setaffinity"):
                os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
            rows = []
            for run in range(args.runs):
                client = None if router is None else WampClient(router.rs_url).start()
                cpu = time.process_time()
                try:
                    result = run_mission(case, Path(tmp) / f"run{run}",
                                         MissionRunOptions(seed=run, humans=not args.no_humans),
                                         run_id=f"bench{run}", client=client)
                finally:
                    if client is not None:
                        client.close()
                cpu = time.process_time() - cpu
                rows.append((result, cpu))
                print(f"run {run}: {'ok  ' if result.succeeded else 'FAIL'} sim {result.sim_time:6.1f} s  "
                      f"wall {result.wall_time:5.2f} s  {result.real_time_factor:5.1f}x wall  "
                      f"{result.sim_time / cpu:5.1f}x CPU  {result.state_messages} state messages")
        finally:
            if router is not None:
                router.stop()
    wall = statistics.median(r.real_time_factor for r, _ in rows)
    cpu = statistics.median(r.sim_time / c for r, c in rows)
    print(f"median real-time factor: {wall:.1f}x (wall), {cpu:.1f}x (CPU of the mission process); "
          f"target >= 20x; {os.cpu_count()} cores, mission pinned to one, "
          f"load average {os.getloadavg()[0]:.1f}; {'no router' if args.no_router else 'publishing via Crossbar'}")


if __name__ == "__main__":
    main()
