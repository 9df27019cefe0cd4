# SPDX-License-Identifier: EPL-2.0
"""Rooms from occupancy maps beside grid rooms of the same area, measured in the same run (issue 31).

For each map, a test case in the map room and one in a grid room of the same size (``size W x H``, 1 m floors,
walls all round), each with the robot on the same floor and the same two goals, get:

- generation: wall time of ``rei-cli.jar generate`` (a cold JVM each time, what a user waits for), median of
  ``--repeat`` runs;
- mission real-time factor: simulated / wall seconds of the reference navigation's mission loop (``rei sim`` in a
  process of its own, no router: the monitor is measured on its own below; ``sim.json``), and the CPU seconds of
  the whole process (start-up included, the same for both rooms);
- monitor CPU per update: the monitor jar replaying the mission's recorded streams (``--replay``), the CPU time
  of the whole process and the time of its replay loop alone (as it reports it), per state message; and the loop
  over the first second alone (its first full frame puts every wall into the model), so that what each later
  update costs shows apart from that;
- obstacles: the map's occupied (and unknown) cells, and the rectangles they merge into (the W_map_ walls).

Each figure is printed for both rooms and as the ratio map / grid, with the load average. The maps: Nav2's depot
(``--depot FILE.yaml``, default: the depot shared beside the repository when it is there) and the synthetic
30 x 50 m building at 0.03 m (test-support/maps/synthetic_building.py, drawn into a temporary folder).

    .venv/bin/python benchmarks/map_rooms.py [--depot FILE.yaml] [--no-building] [--repeat 3]
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

# the synthetic building's drawing lives with the test support; the tests import it the same way (pytest.ini)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "test-support" / "maps"))

import synthetic_building

from rei import toolchain
from rei.maps import floor_blocks, load_map, merge_rectangles, obstacle_mask
from rei.wamp.recording import RecordingWriter, iter_recording, stream_path

REPO = Path(__file__).resolve().parents[1]
SHARED_DEPOT = REPO.parent / "shared" / "data" / "maps" / "depot.yaml"
TIMEOUT_S = 1800.0
FIRST = 20  # state messages of the first simulated second
_REPLAYED = re.compile(r"replayed (\d+) state and \d+ mission messages in ([\d.]+) s")


@dataclass(frozen=True, slots=True)
class Room:
    """One side of a comparison: its case text, and what was measured."""

    label: str
    generate_s: float
    sim_s: float
    wall_s: float
    startup_s: float  # the simulation process's wall time outside its mission loop (start, reading, loading)
    cpu_s: float
    succeeded: bool
    states: int
    monitor_cpu_s: float
    monitor_loop_s: float
    monitor_first_s: float  # the replay loop over the first FIRST states alone
    obstacles: int

    @property
    def rtf(self) -> float:
        return self.sim_s / self.wall_s

    @property
    def monitor_cpu_ms(self) -> float:
        return 1000 * self.monitor_cpu_s / self.states

    @property
    def monitor_loop_ms(self) -> float:
        return 1000 * self.monitor_loop_s / self.states

    @property
    def monitor_steady_ms(self) -> float:
        """Per update after the first second (the whole loop less the first second's, over the other states)."""
        return 1000 * (self.monitor_loop_s - self.monitor_first_s) / (self.states - FIRST)


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _run(command: list[str]) -> tuple[float, float, str]:
    """Wall seconds, CPU seconds (the process and its children) and output of one process; a failure ends the
    benchmark."""
    cpu, started = _children_cpu(), time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT_S, check=False)
    wall, cpu = time.perf_counter() - started, _children_cpu() - cpu
    if done.returncode != 0:
        sys.exit(f"benchmark: {' '.join(command)} exited {done.returncode}\n{done.stdout}{done.stderr}")
    return wall, cpu, done.stdout + done.stderr


def _case_text(name: str, layout: str, start: str, goal: str) -> str:
    return (f"testcase {name} {{\n  room R {layout} {{\n    robot tb3 : Waffle on {start}\n  }}\n"
            f"  mission Across {{ timeout 600s goto {start} goto {goal} }}\n"
            "  monitor { close 0.25 collision 0.01 }\n}\n")


def _jars(work: Path) -> tuple[Path, Path]:
    """Copies of the CLI and monitor jars: a build while the benchmark runs would rewrite them under the JVMs."""
    copies = []
    for role in ("cli", "monitor"):
        jar = toolchain.find_jar(role)
        copies.append(Path(shutil.copy2(jar, work / jar.name)))
    return copies[0], copies[1]


def _measure(label: str, source: Path, out: Path, repeat: int, obstacles: int, jars: tuple[Path, Path]) -> Room:
    java, (cli, monitor) = toolchain.find_java(), jars
    case = out / "case"
    times = [_run(toolchain.jar_command(cli, ["generate", str(source), "-o", str(case), "--quiet"], java))[0]
             for _ in range(repeat)]
    # rei sim in a process of its own, so both rooms pay the same start-up (imports) and nothing else
    process_wall, cpu, _ = _run([sys.executable, "-m", "rei.cli", "sim", str(case), "-o", str(out / "run"), "--no-router",
                      "--progress", "none"])
    result = json.loads((out / "run" / "sim.json").read_text(encoding="utf-8"))
    _, monitor_cpu, output = _run(toolchain.jar_command(
        monitor, ["--replay", str(out / "run"), "--case", str(case), "--quiet"], java))
    replayed = _replayed(output)
    # the first second alone (the first full frame puts every wall into the model): what the rest costs per update
    first = out / "first"
    with RecordingWriter(stream_path(first, "state")) as writer:
        for message in itertools.islice(iter_recording(stream_path(out / "run", "state")), FIRST):
            writer.write(message)
    _, _, output = _run(toolchain.jar_command(monitor, ["--replay", str(first / "streams" / "state.msgpack"),
                                                        "--case", str(case), "--quiet"], java))
    first_replayed = _replayed(output)
    return Room(label, statistics.median(times), result["sim_time"], result["wall_time"],
                process_wall - result["wall_time"], cpu, result["succeeded"], replayed[0], monitor_cpu,
                replayed[1], first_replayed[1], obstacles)


def _replayed(output: str) -> tuple[int, float]:
    """State messages and seconds of the monitor's replay loop, as it reports them."""
    found = _REPLAYED.search(output)
    if found is None:
        sys.exit(f"benchmark: the monitor's replay did not report its time:\n{output}")
    return int(found[1]), float(found[2])


def _free_near(free: np.ndarray, x: float, y: float) -> str:
    """The free 1 m floor block nearest map metres ``(x, y)``."""
    ys, xs = np.nonzero(free)
    k = int(np.argmin(np.hypot(xs + 0.5 - x, ys + 0.5 - y)))
    return f"F_{xs[k]}_{ys[k]}"


def compare(name: str, yaml: Path, work: Path, repeat: int, jars: tuple[Path, Path]) -> tuple[Room, Room]:
    """The map room and the grid room of the same area, the robot crossing each along its longer side."""
    occupancy = load_map(yaml)
    mask = obstacle_mask(occupancy)
    rectangles = len(merge_rectangles(mask))
    free = floor_blocks(occupancy, 1.0).free
    width, height = free.shape[1], free.shape[0]
    along_x = width >= height
    a, b = ((1.5, height / 2), (width - 1.5, height / 2)) if along_x else ((width / 2, 1.5), (width / 2, height - 1.5))
    start, goal = _free_near(free, *a), _free_near(free, *b)
    folder = work / name
    folder.mkdir(parents=True)
    map_case = folder / "map.rei"
    map_case.write_text(_case_text(f"{name.title()}Map", f'occupancy "{yaml.resolve()}" floorSize 1.0', start, goal),
                        encoding="utf-8")
    grid_case = folder / "grid.rei"
    grid_case.write_text(_case_text(f"{name.title()}Grid", f"size {width} x {height}", start, goal), encoding="utf-8")
    print(f"{name}: {occupancy.width} x {occupancy.height} cells at {occupancy.resolution} m "
          f"({occupancy.width * occupancy.resolution:.1f} x {occupancy.height * occupancy.resolution:.1f} m), "
          f"{int(mask.sum()):,} obstacle cells merged into {rectangles:,} rectangles; {int(free.sum())} free 1 m "
          f"floors; grid room {width} x {height} ({width * height} floors, {2 * (width + height)} walls); "
          f"{start} -> {goal}", flush=True)
    mapped = _measure("map", map_case, folder / "map", repeat, rectangles, jars)
    grid = _measure("grid", grid_case, folder / "grid", repeat, 2 * (width + height), jars)
    return mapped, grid


def report(name: str, mapped: Room, grid: Room) -> None:
    load = os.getloadavg()[0]
    rows = [
        ("generation (s, cold JVM, median)", mapped.generate_s, grid.generate_s),
        ("mission real-time factor (sim/wall)", mapped.rtf, grid.rtf),
        ("simulation start-up and exit (s, wall)", mapped.startup_s, grid.startup_s),
        ("simulation process CPU (s)", mapped.cpu_s, grid.cpu_s),
        ("monitor CPU per update (ms, whole JVM)", mapped.monitor_cpu_ms, grid.monitor_cpu_ms),
        ("monitor replay loop per update (ms)", mapped.monitor_loop_ms, grid.monitor_loop_ms),
        ("monitor replay, the first second (s)", mapped.monitor_first_s, grid.monitor_first_s),
        ("monitor replay per update after it (ms)", mapped.monitor_steady_ms, grid.monitor_steady_ms),
        ("static obstacles (walls)", mapped.obstacles, grid.obstacles),
    ]
    print(f"{name}: map room {mapped.sim_s:.1f} s simulated ({'ok' if mapped.succeeded else 'FAILED'}, "
          f"{mapped.states} states), grid room {grid.sim_s:.1f} s ({'ok' if grid.succeeded else 'FAILED'}, "
          f"{grid.states} states)")
    print(f"{'':40} {'map':>10} {'grid':>10} {'map/grid':>9}")
    for label, m, g in rows:
        ratio = m / g if g else math.inf
        print(f"{label:40} {m:>10.3f} {g:>10.3f} {ratio:>9.2f}")
    print(f"RATIO {name} map/grid: generation {mapped.generate_s / grid.generate_s:.2f}, real-time factor "
          f"{mapped.rtf / grid.rtf:.2f}, monitor CPU per update {mapped.monitor_cpu_ms / grid.monitor_cpu_ms:.2f} "
          f"(replay loop after the first second {mapped.monitor_steady_ms / grid.monitor_steady_ms:.2f}) "
          f"(load average {load:.2f})", flush=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--depot", type=Path, default=SHARED_DEPOT if SHARED_DEPOT.is_file() else None,
                        help="Nav2's depot map (its YAML file)")
    parser.add_argument("--no-building", action="store_true", help="leave out the synthetic 30 x 50 m building")
    parser.add_argument("--repeat", type=int, default=3, help="generations per room (median)")
    args = parser.parse_args()
    print(f"REI map-room benchmark: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
    with tempfile.TemporaryDirectory(prefix="rei-bench-maps-") as tmp:
        work = Path(tmp)
        maps = []
        if args.depot is not None:
            maps.append(("depot", args.depot))
        if not args.no_building:
            maps.append(("building", synthetic_building.write(work / "building-map")))
        if not maps:
            sys.exit("benchmark: no map to measure (--depot FILE.yaml, or leave the building in)")
        failed, jars = False, _jars(work)
        for name, yaml in maps:
            mapped, grid = compare(name, yaml, work, args.repeat, jars)
            report(name, mapped, grid)
            failed |= not (mapped.succeeded and grid.succeeded)
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
