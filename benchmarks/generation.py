# SPDX-License-Identifier: EPL-2.0
"""How long does generation take as rooms grow? Target: a 10,000-floor room in under 5 s.

Rooms are written in the explicit floor-graph form (every floor names its right and top neighbour, walls all
around), since that is what the layout code has to traverse and what a procedural room generator emits; a
`size` grid would hide the parse and link cost of the floor references.

Two figures per size:
- cold: one `rei-cli.jar generate` process, wall time including the JVM start -- what a user waits for;
- warm: `--repeat N` in one process; the CLI prints one timing per iteration -- the generator's own cost once
  the JIT has warmed up.

Usage: .venv/bin/python benchmarks/generation.py [--sizes 100 1000 10000] [--repeat 5] [--keep DIR] [--check]
"""

from __future__ import annotations

import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from rei import toolchain

TARGET_FLOORS = 10_000
TARGET_SECONDS = 5.0
TIMEOUT_S = 900.0

# One timing per iteration, e.g. "iteration 2/5: 812 ms", "repeat 3: 0.81 s", "#4 generate 812.5ms".
_TIMING = re.compile(r"(?i)(?:iteration|repeat|run|#)\s*(\d+)\D[^\n]*?(\d+(?:\.\d+)?)\s*(ms|s)\b")


@dataclass(frozen=True, slots=True)
class Measurement:
    floors: int
    grid: tuple[int, int]
    file_kib: float
    cold_s: float
    warm_s: list[float]


def grid_for(floors: int) -> tuple[int, int]:
    """Columns x rows with exactly `floors` cells, as square as possible (100 -> 10 x 10, 1000 -> 40 x 25)."""
    rows = max(r for r in range(1, math.isqrt(floors) + 1) if floors % r == 0)
    return floors // rows, rows


def room_text(floors: int) -> str:
    """A test case with a `floors`-floor room in the explicit graph form, a robot, four objects and two goals."""
    columns, rows = grid_for(floors)
    lines = [f"testcase Bench{floors} {{", f"  room Grid{floors} floorSize 1.0 {{"]
    walls: list[str] = []
    for y in range(rows):
        for x in range(columns):
            sides = []
            for side, (nx, ny) in (("right", (x + 1, y)), ("top", (x, y + 1))):
                if nx < columns and ny < rows:
                    sides.append(f"{side} F_{nx}_{ny}")
                else:
                    walls.append(f"W_{x}_{y}_{side}")
                    sides.append(f"{side} {walls[-1]}")
            for side, border in (("left", x == 0), ("bottom", y == 0)):
                if border:
                    walls.append(f"W_{x}_{y}_{side}")
                    sides.append(f"{side} {walls[-1]}")
            lines.append(f"    floor F_{x}_{y} {' '.join(sides)}")
    lines += [f"    wall {name}" for name in walls]
    spots = [
        (columns // 4, rows // 4),
        (columns // 2, rows // 2),
        (3 * columns // 4, rows // 4),
        (columns // 4, 3 * rows // 4),
    ]
    lines += [f"    object table{i} : Table on F_{x}_{y}" for i, (x, y) in enumerate(spots, 1)]
    lines += [
        "    robot tb3 : Waffle on F_0_0",
        "  }",
        f"  mission Cross {{ goto F_{columns - 1}_{rows - 1} goto F_0_0 }}",
        "  monitor { close 0.25 collision 0.01 }",
        "}",
        "",
    ]
    return "\n".join(lines)


def run(command: list[str]) -> tuple[float, str]:
    """Wall time and combined output of one process; a failure ends the benchmark with its output."""
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT_S, check=False)
    elapsed = time.perf_counter() - started
    if done.returncode != 0:
        sys.exit(f"benchmark: {' '.join(command)} exited {done.returncode}\n{done.stdout}{done.stderr}")
    return elapsed, done.stdout + done.stderr


def parse_timings(output: str, expected: int) -> list[float]:
    """Per-iteration seconds from the `--repeat` output, in iteration order."""
    timings: dict[int, float] = {}
    for index, value, unit in _TIMING.findall(output):
        timings[int(index)] = float(value) / (1000.0 if unit.lower() == "ms" else 1.0)
    if len(timings) != expected:
        sys.exit(f"benchmark: expected {expected} per-iteration timings, found {len(timings)} in:\n{output}")
    return [timings[i] for i in sorted(timings)]


def measure(floors: int, workdir: Path, jar: Path, java: toolchain.Java, repeat: int) -> Measurement:
    source = workdir / f"room{floors}.rei"
    source.write_text(room_text(floors), encoding="utf-8")
    out = workdir / f"out{floors}"
    cold_s, _ = run(toolchain.jar_command(jar, ["generate", str(source), "-o", str(out), "--quiet"], java))
    if not (out / "world.json").is_file():
        sys.exit(f"benchmark: generate of {floors} floors wrote no world.json")
    _, output = run(
        toolchain.jar_command(jar, ["generate", str(source), "-o", str(out), "--repeat", str(repeat)], java)
    )
    return Measurement(
        floors, grid_for(floors), source.stat().st_size / 1024, cold_s, parse_timings(output, repeat)
    )


def report(results: list[Measurement], repeat: int) -> bool:
    """Print the table; True when the 10,000-floor room (if measured) meets the target, cold."""
    print(
        f"REI generation benchmark: {os.cpu_count()} cores, {sys.platform}, "
        f"target {TARGET_FLOORS:,} floors < {TARGET_SECONDS:.0f} s (cold, incl. JVM start)"
    )
    header = (
        f"{'floors':>8} {'grid':>9} {'.rei KiB':>9} {'cold s':>8} {'warm 1st s':>11} "
        f"{'warm best s':>12} {'warm median s':>14}"
    )
    print(header)
    print("-" * len(header))
    met = True
    for m in results:
        print(
            f"{m.floors:>8,} {f'{m.grid[0]}x{m.grid[1]}':>9} {m.file_kib:>9.0f} {m.cold_s:>8.2f} "
            f"{m.warm_s[0]:>11.3f} {min(m.warm_s):>12.3f} {statistics.median(m.warm_s):>14.3f}"
        )
        if m.floors == TARGET_FLOORS:
            met = m.cold_s < TARGET_SECONDS
            print(
                f"{'':>8} target {'met' if met else 'MISSED'}: {m.cold_s:.2f} s cold vs {TARGET_SECONDS:.0f} s"
            )
    print(f"(warm: {repeat} iterations in one JVM, as printed by rei-cli --repeat)")
    return met


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100, 1_000, 10_000], metavar="FLOORS")
    parser.add_argument("--repeat", type=int, default=5, help="warm iterations (default 5)")
    parser.add_argument("--keep", type=Path, metavar="DIR", help="write rooms and outputs here and keep them")
    parser.add_argument("--check", action="store_true", help="exit 1 when the 10,000-floor target is missed")
    args = parser.parse_args(argv)
    if args.repeat < 1 or any(size < 1 for size in args.sizes):
        parser.error("sizes and --repeat must be positive")
    try:
        java, jar = toolchain.find_java(), toolchain.find_jar("cli")
    except toolchain.ToolchainError as error:
        print(f"benchmark: {error}", file=sys.stderr)
        return 3
    with tempfile.TemporaryDirectory(prefix="rei-bench-") as scratch:
        workdir = args.keep or Path(scratch)
        workdir.mkdir(parents=True, exist_ok=True)
        results = [measure(size, workdir, jar, java, args.repeat) for size in args.sizes]
    met = report(results, args.repeat)
    return 1 if args.check and not met else 0


if __name__ == "__main__":
    sys.exit(main())
