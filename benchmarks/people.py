# SPDX-License-Identifier: EPL-2.0
"""What reactive people cost the simulation: the same mission among 0, 10, 50 and 100 of them (issue #38).

Goals: with 100 people a simulation step costs at most twice the empty room's (RATIO <= 2.0), and a mission in
Nav2's depot among 50 people still runs at least 5 times faster than real time (real-time factor >= 5).

The rooms, each generated from a test case the script writes (``rei generate``):

- a 20 x 20 m grid room, the robot on F_1_1 and a goal across it on F_18_18; with N = 0, 10, 50 and 100
  ``avoids`` people, each on a floor of its own, walking a ``loop`` route between its floor and a floor at least
  10 m away (the first N of one list of pairs drawn with ``--seed``, so the 10 are among the 50 and the runs repeat);
- Nav2's depot (``room Depot occupancy "depot.yaml" floorSize 1.0``; ``--depot FILE.yaml``, default: the depot
  shared beside the repository), the robot on F_2_8 and a goal on F_27_8, with 50 such people on free floors of
  the generated world.json that the robot's floor reaches.

Each room with people is measured beside the same room without them (the same generated case with its HUMAN
bodies removed, ``Simulation(humans=False)``), run just before it so that both see the same machine. The robot is
driven by the reference navigation through the mission executor, as ``rei.run.run_mission`` drives it, without the
data collector (no streams are recorded or published). Measured over the mission loop alone (after the simulation,
its people server and the navigation have started):

- real-time factor: simulated seconds / wall seconds of the loop (navigation included);
- mean step time: wall time of ``Simulation.step`` (physics, lidar, animator, the crowd) per physics step;
- the people's share of a step: the time in ``Crowd.step`` (the walkers' targets, the people server's reply to
  the step asked for at the previous crowd step, read from its pipe, and the next request), in putting the
  people's bodies where the model put them and in the lidar's meeting their shapes (``Prisms.hits``), over the
  whole step time; and of it the time waiting for the server, and the server process's CPU seconds;
- the physics: the time in pybullet's ``stepSimulation`` per step (the people's bodies are fixed and meet only the
  robot and moving bodies: they cost it their bounds, and a contact when the robot touches one).

Then a short cProfile of the room with the most people (``--profile-seconds`` simulated from ``--profile-from``
on) says which functions dominate. Printed with the load average before and after; the RATIO lines give both
sides. Exit code 1 when a goal is missed.

    .venv/bin/python benchmarks/people.py [--depot FILE.yaml | --no-depot] [--counts 0,10,50,100]
        [--depot-people 50] [--seed 1] [--profile-from 30] [--profile-seconds 20]
"""

from __future__ import annotations

import argparse
import contextlib
import cProfile
import io
import json
import math
import os
import pstats
import random
import resource
import subprocess
import sys
import tempfile
import time
from collections import deque
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pybullet

from rei.artifacts import read_case
from rei.geometry import Twist2D
from rei.mission.executor import MissionExecutor
from rei.sim.lidar import Prisms
from rei.sim.people import crowd as crowd_module
from rei.sim.people import server as server_module
from rei.sim.simulation import Simulation
from rei.sut.registry import create_controller

REPO = Path(__file__).resolve().parents[1]
SHARED_DEPOT = REPO.parent / "shared" / "data" / "maps" / "depot.yaml"
PHYSICS_RATE = 240.0
CONTROL_RATE = 10.0
TIMEOUT_S = 300  # per goal, simulated
ACROSS = 10.0  # m: a person's two stops are at least this far apart
NEAR_ROBOT = 1.5  # m: no person starts or stops this near the robot's start
STEP_GOAL = 2.0
RTF_GOAL = 5.0
GENERATE_TIMEOUT_S = 600.0


@dataclass(frozen=True, slots=True)
class Room:
    """A room of the benchmark: its layout line, the robot's floor and its goal floor."""

    name: str
    layout: str
    start: str
    goal: str


@dataclass(frozen=True, slots=True)
class Measure:
    label: str
    people: int
    sim_s: float
    wall_s: float
    steps: int
    step_s: float  # wall seconds inside Simulation.step
    crowd_s: float  # of it in Crowd.step
    bodies_s: float  # of it putting the people's bodies in place and the lidar's meeting their shapes
    server_s: float  # of crowd_s waiting for the people server's replies
    physics_s: float  # of step_s in pybullet's stepSimulation (every body's contacts, the people's included)
    server_cpu_s: float  # the people server process's CPU seconds (start-up included)
    succeeded: bool
    outcome: str  # the mission's end: each task's reason when one failed

    @property
    def rtf(self) -> float:
        return self.sim_s / self.wall_s

    @property
    def step_ms(self) -> float:
        return 1000 * self.step_s / self.steps

    @property
    def share(self) -> float:
        return (self.crowd_s + self.bodies_s) / self.step_s


class _Timers:
    """Wall time spent in the crowd's advance, the people's bodies (put in place, met by the lidar), the people
    server's replies and pybullet's physics step, by wrapping them while a measurement runs."""

    def __init__(self) -> None:
        self.crowd = self.bodies = self.server = self.physics = 0.0

    def reset(self) -> None:
        self.crowd = self.bodies = self.server = self.physics = 0.0

    @contextlib.contextmanager
    def installed(self) -> Iterator[_Timers]:
        crowd_cls, sim_cls, server_cls = crowd_module.Crowd, Simulation, server_module.PeopleServer
        advance, place, request = crowd_cls.step, sim_cls._place_people, server_cls.receive
        meet = Prisms.hits
        step_simulation = pybullet.stepSimulation
        timers = self

        def timed_physics(*args: Any, **kwargs: Any) -> Any:
            started = time.perf_counter()
            try:
                return step_simulation(*args, **kwargs)
            finally:
                timers.physics += time.perf_counter() - started

        def timed_advance(crowd: Any, *args: Any, **kwargs: Any) -> Any:
            started = time.perf_counter()
            try:
                return advance(crowd, *args, **kwargs)
            finally:
                timers.crowd += time.perf_counter() - started

        def timed_place(sim: Any) -> Any:
            started = time.perf_counter()
            try:
                return place(sim)
            finally:
                timers.bodies += time.perf_counter() - started

        def timed_meet(prisms: Any, *args: Any) -> Any:
            started = time.perf_counter()
            try:
                return meet(prisms, *args)
            finally:
                timers.bodies += time.perf_counter() - started

        def timed_request(server: Any, *args: Any, **kwargs: Any) -> Any:
            started = time.perf_counter()
            try:
                return request(server, *args, **kwargs)
            finally:
                timers.server += time.perf_counter() - started

        crowd_cls.step, sim_cls._place_people, server_cls.receive = timed_advance, timed_place, timed_request
        Prisms.hits = timed_meet
        pybullet.stepSimulation = timed_physics  # the simulation calls it through the module, at each step
        try:
            yield self
        finally:
            crowd_cls.step, sim_cls._place_people, server_cls.receive = advance, place, request
            Prisms.hits = meet
            pybullet.stepSimulation = step_simulation


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _load() -> str:
    one, five, fifteen = os.getloadavg()
    return f"{one:.2f} {five:.2f} {fifteen:.2f}"


def _case_text(name: str, room: Room, people: list[tuple[str, str]]) -> str:
    humans = "".join(f"    human p{i} route [{a}, {b}] speed 1.2 loop avoids\n" for i, (a, b) in enumerate(people))
    return (f"testcase {name} {{\n  room R {room.layout} {{\n{humans}    robot tb3 : Waffle on {room.start}\n  }}\n"
            f"  mission Across {{ timeout {TIMEOUT_S}s goto {room.start} goto {room.goal} }}\n"
            "  monitor { close 0.25 collision 0.01 }\n}\n")


def _generate(text: str, folder: Path) -> Path:
    folder.mkdir(parents=True)
    source = folder / "case.rei"
    source.write_text(text, encoding="utf-8")
    out = folder / "case"
    done = subprocess.run([sys.executable, "-m", "rei.cli", "generate", str(source), "-o", str(out)],
                          capture_output=True, text=True, timeout=GENERATE_TIMEOUT_S, check=False)
    if done.returncode != 0:
        sys.exit(f"benchmark: generating {source} failed ({done.returncode})\n{done.stdout}{done.stderr}")
    return out


def pick_routes(world: dict, room: Room, count: int, seed: int) -> list[tuple[str, str]]:
    """``count`` pairs of floors (start, far stop), every floor used once, none near the robot's start nor on its
    goal, all reachable from the robot's floor through neighbouring floors (as the language asks of a route)."""
    floors = {f["name"]: f for f in world["floors"]}
    reached, todo = {room.start}, deque([room.start])
    while todo:  # the floors the robot's floor reaches
        floor = floors[todo.popleft()]
        for side in ("top", "right", "bottom", "left"):
            other = floor.get(side)
            if other in floors and other not in reached:  # a side is a floor, a wall's name or None
                reached.add(other)
                todo.append(other)
    origin = floors[room.start]["center"]
    free = sorted(name for name in reached
                  if name != room.goal and math.dist(floors[name]["center"], origin) > NEAR_ROBOT)
    rng = random.Random(seed)
    rng.shuffle(free)
    used: set[str] = set()
    pairs = []
    for a in free:
        if len(pairs) == count:
            break
        if a in used:
            continue
        far = [b for b in free if b not in used and b != a
               and math.dist(floors[a]["center"], floors[b]["center"]) >= ACROSS]
        if not far:
            continue
        b = rng.choice(far)
        used |= {a, b}
        pairs.append((a, b))
    if len(pairs) < count:
        sys.exit(f"benchmark: only {len(pairs)} of {count} routes fit in {room.name}")
    return pairs


def measure(label: str, case_dir: Path, humans: bool, timers: _Timers, seed: int,
            max_seconds: float | None = None, profiler: cProfile.Profile | None = None,
            profile_from: float = 0.0) -> Measure:
    """The reference navigation's mission loop in the case, the simulation's step and the people's part timed;
    ``profiler`` runs from ``profile_from`` simulated seconds on."""
    case = read_case(case_dir)
    people = len(case.animation.people) if humans else 0
    time_limit = sum(goal.timeout for goal in case.mission.goals) + 30.0
    if max_seconds is not None:
        time_limit = min(time_limit, max_seconds)
    every = max(1, round(PHYSICS_RATE / CONTROL_RATE))
    cpu_before = _children_cpu()
    with Simulation(case, seed=seed, physics_rate=PHYSICS_RATE, humans=humans) as sim:
        controller = create_controller("nav")
        executor = MissionExecutor(case.mission, controller)
        controller.reset(sim.static_map(), case.mission.start)
        command = Twist2D()
        step_s = 0.0
        timers.reset()
        clock = time.perf_counter
        profiling = profiler is None
        loop_start = clock()
        while not executor.done and sim.t < time_limit:
            if not profiling and sim.t >= profile_from:
                profiler.enable()  # type: ignore[union-attr]
                profiling = True
            if sim.steps % every == 0:
                executor.tick(sim.t, sim.robot_pose())
                command = controller.step(sim.observation())
            started = clock()
            sim.step(command)
            step_s += clock() - started
        wall = clock() - loop_start
        if profiler is not None:
            profiler.disable()
        sim_s, steps = sim.t, sim.steps
        crowd_s, bodies_s, server_s, physics_s = timers.crowd, timers.bodies, timers.server, timers.physics
    results = executor.results
    succeeded = executor.done and len(results) == len(case.mission.goals) and all(r.succeeded for r in results)
    outcome = "ok" if succeeded else "; ".join(
        [f"goal {r.index}: {r.reason}" for r in results if not r.succeeded]
        or [f"cut off at {sim_s:.0f} s after {len(results)} of {len(case.mission.goals)} goals"])
    return Measure(label, people, sim_s, wall, steps, step_s, crowd_s, bodies_s, server_s, physics_s,
                   _children_cpu() - cpu_before, succeeded, outcome)


def _row(m: Measure) -> None:
    print(f"{m.label:18} {m.people:>6} {m.sim_s:>7.1f} {m.wall_s:>7.2f} {m.rtf:>6.2f} {m.step_ms:>8.3f} "
          f"{1000 * (m.crowd_s + m.bodies_s) / m.steps:>9.3f} {100 * m.share:>6.1f}% "
          f"{1000 * m.server_s / m.steps:>9.3f} {1000 * m.physics_s / m.steps:>8.3f} {m.server_cpu_s:>7.2f}  "
          f"{m.outcome}"
          f"  (load {_load()})", flush=True)


def _header() -> None:
    print(f"{'room':18} {'people':>6} {'sim s':>7} {'wall s':>7} {'RTF':>6} {'step ms':>8} {'people ms':>9} "
          f"{'share':>7} {'server ms':>9} {'phys ms':>8} {'srv CPU':>7}  mission")


def _pair(label: str, case_dir: Path, timers: _Timers, seed: int) -> tuple[Measure, Measure]:
    empty = measure(f"{label}, empty", case_dir, False, timers, seed)
    _row(empty)
    full = measure(label, case_dir, True, timers, seed)
    _row(full)
    return empty, full


def profile(case_dir: Path, seed: int, start: float, seconds: float, top: int) -> None:
    """cProfile of ``seconds`` simulated seconds of the mission among the case's people, from ``start`` on."""
    timers = _Timers()  # not installed: the profile sees the code as it runs
    profiler = cProfile.Profile()
    m = measure("profiled", case_dir, True, timers, seed, max_seconds=start + seconds, profiler=profiler,
                profile_from=start)
    if m.sim_s < start:
        print(f"no cProfile: the mission among {m.people} people ended at {m.sim_s:.1f} s simulated, before "
              f"{start:g} s (--profile-from)", flush=True)
        return
    print(f"cProfile of the mission loop among {m.people} people, from {start:g} s to {m.sim_s:.1f} s simulated "
          f"(load {_load()}); by own time:")
    text = io.StringIO()
    pstats.Stats(profiler, stream=text).sort_stats("tottime").print_stats(top)
    print("\n".join(line for line in text.getvalue().splitlines() if line.strip()))
    text = io.StringIO()
    pstats.Stats(profiler, stream=text).sort_stats("cumulative").print_stats(top)
    print("by cumulative time:")
    print("\n".join(line for line in text.getvalue().splitlines() if line.strip()), flush=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--depot", type=Path, default=SHARED_DEPOT if SHARED_DEPOT.is_file() else None,
                        help="Nav2's depot map (its YAML file)")
    parser.add_argument("--counts", default="0,10,50,100", help="people in the 20 x 20 m room, comma-separated")
    parser.add_argument("--no-depot", action="store_true", help="leave out the depot")
    parser.add_argument("--depot-people", type=int, default=50)
    parser.add_argument("--seed", type=int, default=1, help="the people's placement and the simulation's seed")
    parser.add_argument("--profile-seconds", type=float, default=20.0,
                        help="simulated seconds profiled among the most people (0: no profile)")
    parser.add_argument("--profile-from", type=float, default=30.0,
                        help="simulated second the profile starts at (by then the robot is among the 100 people)")
    parser.add_argument("--top", type=int, default=25, help="functions the profile lists")
    args = parser.parse_args()
    counts = sorted({int(c) for c in args.counts.split(",")})
    print(f"REI people benchmark: {os.cpu_count()} cores, load average {_load()} (1, 5, 15 min)", flush=True)
    grid = Room("grid 20x20", "size 20 x 20", "F_1_1", "F_18_18")
    if args.depot is None and not args.no_depot:
        sys.exit("benchmark: no depot map beside the repository: --depot FILE.yaml, or --no-depot")
    depot = None if args.no_depot else Room(
        "depot", f'occupancy "{args.depot.resolve()}" floorSize 1.0', "F_2_8", "F_27_8")
    timers = _Timers()
    results: dict[str, Measure] = {}
    baselines: dict[str, Measure] = {}
    with tempfile.TemporaryDirectory(prefix="rei-bench-people-") as tmp:
        work = Path(tmp)
        # the rooms without people first: their world.json says which floors the people may use
        empty_grid = _generate(_case_text("Grid0", grid, []), work / "grid-0")
        grid_world = json.loads((empty_grid / "world.json").read_text(encoding="utf-8"))
        pairs = pick_routes(grid_world, grid, max(counts), args.seed)
        cases = {n: empty_grid if n == 0 else _generate(_case_text(f"Grid{n}", grid, pairs[:n]), work / f"grid-{n}")
                 for n in counts}
        depot_case = None
        if depot is not None:
            empty_depot = _generate(_case_text("Depot0", depot, []), work / "depot-0")
            depot_world = json.loads((empty_depot / "world.json").read_text(encoding="utf-8"))
            depot_case = _generate(_case_text(f"Depot{args.depot_people}", depot,
                                              pick_routes(depot_world, depot, args.depot_people, args.seed)),
                                   work / f"depot-{args.depot_people}")
        print(f"cases generated (load {_load()}); each room with people runs just after itself without them "
              "(same case, humans removed)", flush=True)
        _header()
        with timers.installed():
            for n in counts:
                if n == 0:
                    results["grid 0"] = measure("grid 20x20", cases[0], True, timers, args.seed)
                    _row(results["grid 0"])
                else:
                    baselines[f"grid {n}"], results[f"grid {n}"] = _pair("grid 20x20", cases[n], timers, args.seed)
            if depot_case is not None:
                baselines["depot"], results["depot"] = _pair("depot", depot_case, timers, args.seed)
        most = max(counts)
        if args.profile_seconds > 0 and most > 0:
            profile(cases[most], args.seed, args.profile_from, args.profile_seconds, args.top)
    return _report(results, baselines, counts)


def _report(results: dict[str, Measure], baselines: dict[str, Measure], counts: list[int]) -> int:
    load = _load()
    met = True
    for n in counts:
        if n == 0:
            continue
        full, empty = results[f"grid {n}"], baselines[f"grid {n}"]
        ratio = full.step_ms / empty.step_ms
        goal = ""
        if n == 100:
            met &= ratio <= STEP_GOAL
            goal = f"goal <= {STEP_GOAL}: {'met' if ratio <= STEP_GOAL else 'MISSED'}; "
        print(f"RATIO grid 20x20, {n} people / empty room, mean step time: {full.step_ms:.3f} ms / "
              f"{empty.step_ms:.3f} ms = {ratio:.2f}  ({goal}real-time factor {full.rtf:.2f} vs {empty.rtf:.2f}; "
              f"the people's share of a step {100 * full.share:.1f} %; physics {1000 * full.physics_s / full.steps:.3f}"
              f" vs {1000 * empty.physics_s / empty.steps:.3f} ms a step; load average {load})")
    if "depot" in results:
        full, empty = results["depot"], baselines["depot"]
        met &= full.rtf >= RTF_GOAL
        print(f"RATIO depot, {full.people} people, real-time factor: {full.sim_s:.1f} s simulated / {full.wall_s:.2f} s "
              f"wall = {full.rtf:.2f}  (goal >= {RTF_GOAL:g}: {'met' if full.rtf >= RTF_GOAL else 'MISSED'}; "
              f"empty depot {empty.sim_s:.1f} s / {empty.wall_s:.2f} s = {empty.rtf:.2f}; mean step time "
              f"{full.step_ms:.3f} ms vs {empty.step_ms:.3f} ms = {full.step_ms / empty.step_ms:.2f}; the people's "
              f"share of a step {100 * full.share:.1f} %; physics {1000 * full.physics_s / full.steps:.3f} vs "
              f"{1000 * empty.physics_s / empty.steps:.3f} ms a step; load average {load})")
    print(f"load average after: {load}")
    return 0 if met else 1


if __name__ == "__main__":
    raise SystemExit(main())
