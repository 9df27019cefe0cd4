# SPDX-License-Identifier: EPL-2.0
"""Real-time factor of the simulation loop: physics + lidar + animator + odometry + contacts.

Runs a generated case (by default the sim-adapter's fixture room: 6x4 m, one walking human) headless with the
robot driving a constant command, and prints physics steps per second and the real-time factor, with the
machine's core count. The target is >= 20x real time on one core, so that a whole mission (with a navigation
stack added on top) still runs well faster than real time.

    .venv/bin/python benchmarks/sim_rtf.py [--case DIR] [--seconds 60] [--physics-rate 240] [--lidar-rate 10]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time
from pathlib import Path

from rei.geometry import Twist2D
from rei.sim.simulation import Simulation

DEFAULT_CASE = Path(__file__).resolve().parents[1] / "sim-adapter" / "tests" / "fixtures" / "room6x4"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--case", type=Path, default=DEFAULT_CASE, help="folder with the five generated files"
    )
    parser.add_argument("--seconds", type=float, default=60.0, help="simulated seconds to run")
    parser.add_argument("--physics-rate", type=float, default=240.0)
    parser.add_argument("--lidar-rate", type=float, default=10.0)
    parser.add_argument("--no-humans", action="store_true", help="remove the humans (static room)")
    parser.add_argument("--fault", default=None, help="laser fault spec, e.g. laser:10%%")
    parser.add_argument("--json", action="store_true", help="print one JSON line instead of text")
    args = parser.parse_args()

    cmd = Twist2D(0.2, 0.3)
    with Simulation(
        args.case,
        physics_rate=args.physics_rate,
        lidar_rate=args.lidar_rate,
        humans=not args.no_humans,
        fault=args.fault,
    ) as sim:
        steps = round(args.seconds * sim.physics_rate)
        start = time.perf_counter()
        for _ in range(steps):
            sim.step(cmd)
        wall = time.perf_counter() - start
        state_start = time.perf_counter()
        for _ in range(1000):
            sim.state()
        state_ms = time.perf_counter() - state_start
        result = {
            "case": args.case.name,
            "sim_seconds": sim.t,
            "steps": steps,
            "wall_seconds": round(wall, 3),
            "steps_per_second": round(steps / wall, 1),
            "real_time_factor": round(sim.t / wall, 2),
            "us_per_step": round(1e6 * wall / steps, 1),
            "state_call_us": round(1e3 * state_ms, 1),
            "physics_rate": sim.physics_rate,
            "lidar_rate": sim.lidar_rate,
            "humans": not args.no_humans,
            "cores": os.cpu_count(),
            "python": platform.python_version(),
        }
    if args.json:
        print(json.dumps(result))
        return
    print(
        f"{result['case']}: {steps} steps of {1e3 / sim.physics_rate:.2f} ms in {wall:.2f} s wall -> "
        f"{result['steps_per_second']} steps/s, real-time factor {result['real_time_factor']}x "
        f"({result['us_per_step']} us/step, state() {result['state_call_us']} us; "
        f"lidar {sim.lidar_rate:g} Hz, humans {'on' if result['humans'] else 'off'}; "
        f"{result['cores']} cores, one used)"
    )


if __name__ == "__main__":
    main()
