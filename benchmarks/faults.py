# SPDX-License-Identifier: EPL-2.0
"""What faults on a timeline cost the simulation: the same run with every fault kind active (the laser's five and
the motion's seven) against the run without faults, both in the same process, taking turns a simulated second at a
time so that the machine's other work weighs on both alike.

The run: examples/simple_navigation.rei simulated for 60 s with the robot told to turn on the spot, the lidar at
10 Hz and physics at 240 Hz, stepped by a loop shaped like the mission loop's (rei.run.mission_run): the window
clock at every step, the commands' faults at every control tick (10 Hz, as `rei run`) between the controller's
command and the robot; each run's CPU time summed over its turns. With faults: impulse noise gated 1 s in 4 s with a gain ramp, a
freeze, a blackout, an occlusion, range noise; command latency and loss; wheel slip and a stuck wheel; odometry
drift and jumps; a kidnap. Their windows overlap so that most steps see several kinds; the kidnap turns the robot
where it stands, so it stays clear of the walls as in the run without faults. Issue #39's goal: ratio <= 1.1.

    .venv/bin/python benchmarks/faults.py [--runs 3] [--seconds 60]
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import tempfile
import time
from pathlib import Path

from _examples import generate_example

from rei.artifacts import read_case
from rei.geometry import Twist2D
from rei.run import MissionRunOptions
from rei.sim.faults import FaultClock, parse_faults
from rei.sim.simulation import Simulation

GOAL = 1.1
CONTROL_RATE = MissionRunOptions().control_rate  # the mission loop's own
WANTED = Twist2D(0.0, 0.6)
LASER = ("laser:impulse,rate=0.05,width=3,gain=0.2@0/0.8@60,period=4,pulse=1;"
         "laser:freeze,period=10,pulse=0.5,from=3;laser:blackout,period=15,pulse=1,from=7;"
         "laser:occlusion,angles=-30..30,range=0.3,period=5,duty=40%;laser:noise,sigma=0.02,period=3,pulse=2")
MOTION = ("commands:latency,delay=0.2,period=6,pulse=3;commands:loss,probability=0.3,period=5,pulse=2,from=1;"
          "drive:slip,fraction=0.5,period=8,pulse=3,from=2;drive:stuck,wheel=left,period=12,pulse=1,from=4;"
          "odometry:drift,scale=1.05,bias=2,period=7,pulse=4;odometry:jump,dx=0.1,dyaw=5,period=9,pulse=1,from=3;"
          "pose:kidnap,dyaw=30,period=10,pulse=1,from=6")
EVERY_KIND = f"{LASER};{MOTION}"


class _Run:
    """One simulation stepped by a loop shaped like the mission loop's, a slice of simulated time at a time."""

    def __init__(self, case: object, fault: str | None) -> None:
        self.sim = Simulation(case, seed=1, humans=False, fault=fault)  # type: ignore[arg-type]
        faults = self.sim.faults
        self.clock = FaultClock(faults)
        self.commands = (faults.commands(self.sim.fault_generators, CONTROL_RATE) if faults.of("commands")
                         else None)
        self.control_every = round(self.sim.physics_rate / CONTROL_RATE)
        self.opened: set[int] = set()
        self.cpu = 0.0
        self.command = WANTED

    def until(self, t: float) -> None:
        sim, clock, commands, control_every = self.sim, self.clock, self.commands, self.control_every
        start = time.process_time()
        while sim.t < t:
            self.opened.update(edge.index for edge in clock.due(sim.t) if edge.begin)
            if commands is not None and sim.steps % control_every == 0:
                self.command = commands.apply(sim.t, WANTED)
            sim.step(self.command)
        self.cpu += time.process_time() - start


def _pair(case: object, seconds: float) -> tuple[float, float]:
    """CPU seconds of ``seconds`` simulated without faults and with every kind, the two runs taking turns a
    simulated second at a time (so that the load of the machine's other work falls on both alike)."""
    clean, faulty = _Run(case, None), _Run(case, EVERY_KIND)
    try:
        for k in range(1, math.ceil(seconds) + 1):
            for run in (clean, faulty) if k % 2 else (faulty, clean):
                run.until(min(float(k), seconds))
    finally:
        clean.sim.close()
        faulty.sim.close()
    assert len(faulty.opened) == len(faulty.sim.faults.faults), faulty.opened  # every fault's window did open
    return clean.cpu, faulty.cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--seconds", type=float, default=60.0)
    args = parser.parse_args()
    schedule = parse_faults(EVERY_KIND)
    kinds = {(f.sensor, f.kind) for f in schedule.faults}
    assert len(kinds) == 12, sorted(kinds)  # every kind of docs/faults.md, once
    last_open = max(next(f.timing.edges())[0] for f in schedule.faults)
    if args.seconds <= last_open:
        parser.error(f"--seconds must be over {last_open:g}: every fault's window opens by then")
    with tempfile.TemporaryDirectory() as tmp:
        case = read_case(generate_example("simple_navigation", Path(tmp) / "case"))
        pairs = [_pair(case, args.seconds) for _ in range(args.runs)]
    clean, faulty = [c for c, _ in pairs], [f for _, f in pairs]
    c, f = statistics.median(clean), statistics.median(faulty)
    print(f"without faults: {c:.3f} s CPU for {args.seconds:g} s simulated (median of {args.runs}: "
          f"{', '.join(f'{x:.3f}' for x in clean)})")
    print(f"every kind ({len(kinds)}): {f:.3f} s CPU ({', '.join(f'{x:.3f}' for x in faulty)})")
    load = os.getloadavg()
    ratios = ", ".join(f"{y / x:.3f}" for x, y in pairs)
    print(f"RATIO faults/none {f / c:.3f} (goal <= {GOAL}; each pair: {ratios}) load {load[0]:.1f} {load[1]:.1f} "
          f"{load[2]:.1f}")


if __name__ == "__main__":
    main()
