# SPDX-License-Identifier: EPL-2.0
"""What faults on a timeline cost the simulation: the same run with every laser fault kind active against the run
without faults, measured in the same process, one after the other, alternating.

The run: examples/simple_navigation.rei simulated for 60 s with the robot turning on the spot (a fixed command, so
both runs do the same physics), the lidar at 10 Hz and physics at 240 Hz, stepped by the simulation loop alone
(the mission loop's per-step work for faults, the window clock, is included: it runs here as there). With
faults: impulse noise gated 1 s in 4 s with a gain ramp, a freeze, a blackout, an occlusion and range noise,
their windows overlapping so that most scans see two or more kinds. Issue #39's goal: ratio <= 1.1.

    .venv/bin/python benchmarks/faults.py [--runs 3] [--seconds 60]
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path

from _examples import generate_example

from rei.artifacts import read_case
from rei.geometry import Twist2D
from rei.sim.faults import FaultClock
from rei.sim.simulation import Simulation

GOAL = 1.1
EVERY_KIND = ("laser:impulse,rate=0.05,width=3,gain=0.2@0/0.8@60,period=4,pulse=1;"
              "laser:freeze,period=10,pulse=0.5,from=3;laser:blackout,period=15,pulse=1,from=7;"
              "laser:occlusion,angles=-30..30,range=0.3,period=5,duty=40%;laser:noise,sigma=0.02,period=3,pulse=2")


def _run(case: object, fault: str | None, seconds: float) -> float:
    """CPU seconds of ``seconds`` simulated."""
    with Simulation(case, seed=1, humans=False, fault=fault) as sim:  # type: ignore[arg-type]
        clock = FaultClock(sim.faults)
        command = Twist2D(0.0, 0.6)
        edges = 0
        start = time.process_time()
        while sim.t < seconds:
            edges += len(clock.due(sim.t))
            sim.step(command)
        spent = time.process_time() - start
    if fault is not None:
        assert edges > 20, edges  # the windows did open and close
    return spent


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=60.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        case = read_case(generate_example("simple_navigation", Path(tmp) / "case"))
        clean, faulty = [], []
        for _ in range(args.runs):
            clean.append(_run(case, None, args.seconds))
            faulty.append(_run(case, EVERY_KIND, args.seconds))
    c, f = statistics.median(clean), statistics.median(faulty)
    print(f"without faults: {c:.3f} s CPU for {args.seconds:g} s simulated (median of {args.runs}: "
          f"{', '.join(f'{x:.3f}' for x in clean)})")
    print(f"every kind:     {f:.3f} s CPU ({', '.join(f'{x:.3f}' for x in faulty)})")
    print(f"RATIO faults/none {f / c:.3f} (goal <= {GOAL}) load {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
