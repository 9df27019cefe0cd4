# SPDX-License-Identifier: EPL-2.0
"""What a robot read from a URDF description costs the simulation step, against a box robot (issue #41).

Goal: a described robot's mean simulation step costs at most 1.2 times the box robot's (RATIO <= 1.2).

The same mission, the simple navigation example (examples/simple_navigation.rei: the 6 x 4 m lab, a table, a
shelf, a walking person, two goals), generated three times with ``rei generate``: with its box robot (the default
catalogue's Waffle), with a robot type read from a description (``--urdf``, default the round robot of
examples/robots, ``--lidar`` its lidar's link, ``--arg NAME:=VALUE`` its xacro arguments), and with the Waffle's box
on a holonomic drive (figures only: its drive pushes the body each step instead of turning two wheel motors).

Each is driven by the reference navigation through the mission executor, as ``rei.run.run_mission`` drives it,
without the data collector. Measured over the mission loop: the wall time of ``Simulation.step`` (physics, lidar,
animator, odometry, contacts) per physics step. The three missions run at once in one process, in turn a control
period (24 physics steps) each, so that every side sees the same machine from moment to moment (on a shared
machine whole runs one after the other differed by 1.5x); that ``--rounds`` times. The RATIO line compares the
medians of the rounds' mean steps and prints both sides, with the load average before and after. Exit code 1 when
the goal is missed.

    .venv/bin/python benchmarks/robot_step.py [--urdf FILE --lidar LINK [--arg NAME:=VALUE ...]] [--rounds 5]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from rei.artifacts.case import read_case
from rei.mission.executor import MissionExecutor
from rei.sim.simulation import Simulation
from rei.sut.registry import create_controller

REPO = Path(__file__).resolve().parents[1]
EXAMPLE = REPO / "examples" / "simple_navigation.rei"
PHYSICS_RATE = 240.0
CONTROL_RATE = 10.0
GOAL = 1.2
GENERATE_TIMEOUT_S = 300


class Run:
    """One room's mission, advanced a control period at a time: the reference navigation's command, then the
    physics steps of the period, whose wall time is summed."""

    def __init__(self, label: str, case_dir: Path) -> None:
        self.label = label
        self.case = read_case(case_dir)
        self.time_limit = sum(goal.timeout for goal in self.case.mission.goals) + 30.0
        self.sim = Simulation(self.case, physics_rate=PHYSICS_RATE)
        self.controller = create_controller("nav")
        self.executor = MissionExecutor(self.case.mission, self.controller)
        self.controller.reset(self.sim.static_map(), self.case.mission.start)
        self.step_s = 0.0

    @property
    def done(self) -> bool:
        return self.executor.done or self.sim.t >= self.time_limit

    def period(self, every: int) -> None:
        sim = self.sim
        self.executor.tick(sim.t, sim.robot_pose())
        command = self.controller.step(sim.observation())
        clock = time.perf_counter
        started = clock()
        for _ in range(every):
            sim.step(command)
        self.step_s += clock() - started

    @property
    def step_us(self) -> float:
        return 1e6 * self.step_s / self.sim.steps

    @property
    def succeeded(self) -> bool:
        results = self.executor.results
        return self.executor.done and all(r.succeeded for r in results) and len(results) == len(
            self.case.mission.goals)


def _load() -> str:
    one, five, fifteen = os.getloadavg()
    return f"{one:.2f} {five:.2f} {fifteen:.2f}"


def _generate(text: str, folder: Path, catalogue: str | None = None) -> Path:
    folder.mkdir(parents=True)
    if catalogue is not None:
        (folder / "robots.rei").write_text(catalogue, encoding="utf-8")
        text = 'import "robots.rei"\n' + text
    source = folder / "case.rei"
    source.write_text(text, encoding="utf-8")
    out = folder / "case"
    done = subprocess.run([sys.executable, "-m", "rei.cli", "generate", str(source), "-o", str(out), "--quiet"],
                          capture_output=True, text=True, timeout=GENERATE_TIMEOUT_S, check=False)
    if done.returncode != 0:
        sys.exit(f"benchmark: generating {source} failed ({done.returncode})\n{done.stdout}{done.stderr}")
    return out


def measure(cases: dict[str, Path]) -> dict[str, Run]:
    """Every room's mission at once, in turn a control period each (so a change of the machine's load falls on
    all of them alike), until each has ended."""
    every = max(1, round(PHYSICS_RATE / CONTROL_RATE))
    runs = {label: Run(label, case_dir) for label, case_dir in cases.items()}
    try:
        while not all(run.done for run in runs.values()):
            for run in runs.values():
                if not run.done:
                    run.period(every)
    finally:
        for run in runs.values():
            run.sim.close()
    return runs


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--urdf", type=Path, default=REPO / "examples" / "robots" / "round_bot.urdf",
                        help="the described robot's URDF or xacro file (default: examples/robots/round_bot.urdf)")
    parser.add_argument("--lidar", default="laser", help="its lidar's link (default: laser, the round robot's)")
    parser.add_argument("--arg", action="append", default=[], metavar="NAME:=VALUE", help="a xacro argument")
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    xacro = ""
    for item in args.arg:
        name, sep, value = item.partition(":=")
        if not sep:
            parser.error(f"--arg {item!r}: expected NAME:=VALUE")
        xacro += f' arg {name} "{value}"'
    text = EXAMPLE.read_text(encoding="utf-8")
    if "robot tb3 : Waffle" not in text:
        sys.exit(f"benchmark: {EXAMPLE} no longer has 'robot tb3 : Waffle'")
    # the Waffle's speeds, so that the navigation drives all three alike
    described = (f'catalogue Robots {{\n  robot type Described : urdf "{args.urdf.resolve()}"{xacro} mass 1.8 '
                 f'speed 0.26 turn 1.82\n    lidar link "{args.lidar}"\n}}\n')
    holonomic = ("catalogue Robots {\n  robot type Omni : box 0.281 x 0.306 x 0.141 mass 1.8 drive holonomic\n"
                 "    lidar height 0.17\n}\n")
    with tempfile.TemporaryDirectory(prefix="rei-robot-step-") as tmp:
        folder = Path(tmp)
        cases = {
            "box": _generate(text, folder / "box"),
            "described": _generate(text.replace("robot tb3 : Waffle", "robot tb3 : Described"), folder / "described",
                                   described),
            "holonomic box": _generate(text.replace("robot tb3 : Waffle", "robot tb3 : Omni"), folder / "holonomic",
                                       holonomic),
        }
        load_before = _load()
        print(f"load average before: {load_before}; {os.cpu_count()} cores; described robot: {args.urdf.name}")
        print(f"{'round':>5} {'robot':14} {'sim s':>7} {'steps':>7} {'step us':>9}  mission")
        rounds: dict[str, list[float]] = {label: [] for label in cases}
        succeeded = True
        for k in range(args.rounds):
            runs = measure(cases)
            for label, run in runs.items():
                rounds[label].append(run.step_us)
                succeeded &= run.succeeded
                print(f"{k + 1:>5} {label:14} {run.sim.t:>7.1f} {run.sim.steps:>7} {run.step_us:>9.1f}  "
                      f"{'ok' if run.succeeded else 'FAILED'}", flush=True)
        load_after = _load()
    medians = {label: statistics.median(values) for label, values in rounds.items()}
    ratio = medians["described"] / medians["box"]
    print(f"load average after: {load_after}")
    print(f"RATIO described/box step: {medians['described']:.1f} us / {medians['box']:.1f} us = {ratio:.3f} "
          f"(goal <= {GOAL}; medians of {args.rounds} rounds)")
    print(f"holonomic box/box step: {medians['holonomic box']:.1f} us / {medians['box']:.1f} us = "
          f"{medians['holonomic box'] / medians['box']:.3f} (figures only)")
    if not succeeded:
        print("benchmark: a mission failed (its step times are still printed)", file=sys.stderr)
    return 0 if ratio <= GOAL else 1


if __name__ == "__main__":
    sys.exit(main())
