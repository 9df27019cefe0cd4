# SPDX-License-Identifier: EPL-2.0
"""What `rei run` costs beyond its simulation: the README's example, run as a user runs it.

In a fresh service folder (so the first run starts the background service, rei.service), runs
``rei run examples/simple_navigation.rei`` once ("first run after set-up"), then ``--runs`` more times back to back
("warm"), then once with ``--no-service`` (everything started by the run itself, as before the service). For each
it prints the command's wall time beside the simulation's own wall time from the same run (``sim.json``), and the
load average. Goals of issue #17: warm wall <= 1.5x the simulation's wall; first run <= 2x a warm run.

    .venv/bin/python benchmarks/run_overhead.py [--runs 5] [--example simple_navigation] [--rei COMMAND]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from rei.service.client import stop

REPO = Path(__file__).resolve().parents[1]
WARM_GOAL = 1.5
FIRST_GOAL = 2.0


def _run(rei: str, example: Path, out: Path, env: dict[str, str], *options: str) -> tuple[float, float]:
    """The command's wall time and the simulation's (sim.json: the mission loop alone)."""
    shutil.rmtree(out, ignore_errors=True)
    started = time.perf_counter()
    done = subprocess.run([rei, "run", str(example), "-o", str(out), *options], env=env,
                          capture_output=True, text=True, check=False)
    wall = time.perf_counter() - started
    if done.returncode not in (0, 1):
        sys.exit(f"rei run failed ({done.returncode}):\n{done.stdout}\n{done.stderr}")
    return wall, float(json.loads((out / "sim.json").read_text(encoding="utf-8"))["wall_time"])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="warm runs after the first")
    parser.add_argument("--example", default="simple_navigation")
    parser.add_argument("--rei", default=str(REPO / "rei"),
                        help="the command to time (default ./rei, as a user runs it; .venv/bin/rei leaves out the "
                        "wrapper's check for a stale build, e.g. while Java sources are being edited)")
    args = parser.parse_args()
    example = REPO / "examples" / f"{args.example}.rei"
    work = Path(tempfile.mkdtemp(prefix="rei-run-bench-"))
    env = {**os.environ, "REI_SERVICE_DIR": str(work / "service")}
    env.pop("REI_SERVICE", None)
    try:
        first = _run(args.rei, example, work / "out", env)
        load_first = os.getloadavg()[0]
        warm = [_run(args.rei, example, work / "out", env) for _ in range(args.runs)]
        load_warm = os.getloadavg()[0]
        alone = _run(args.rei, example, work / "out", env, "--no-service")
        load_alone = os.getloadavg()[0]
    finally:
        stop(work / "service")
        shutil.rmtree(work, ignore_errors=True)

    def line(name: str, wall: float, sim: float, load: float) -> str:
        return f"{name:<22} {wall:6.2f} s wall, simulation {sim:5.2f} s: {wall / sim:4.2f}x  (load average {load:.2f})"

    print(line("first run (service)", *first, load_first))
    for i, (wall, sim) in enumerate(warm, 1):
        print(line(f"warm run {i}", wall, sim, load_warm))
    print(line("own router and JVMs", *alone, load_alone))
    ratios = [wall / sim for wall, sim in warm]
    warm_ratio = statistics.median(ratios)
    warm_wall = statistics.median(wall for wall, _ in warm)
    warm_sim = statistics.median(sim for _, sim in warm)
    first_ratio = first[0] / warm_wall
    print(f"RATIO warm rei run / its simulation (median of {len(warm)}): {warm_wall:.2f} s / {warm_sim:.2f} s; "
          f"median of the ratios {warm_ratio:.2f}  (goal <= {WARM_GOAL}: {'met' if warm_ratio <= WARM_GOAL else 'MISSED'};"
          f" load average {load_warm:.2f})")
    print(f"RATIO first run / warm run: {first[0]:.2f} s / {warm_wall:.2f} s = {first_ratio:.2f}  "
          f"(goal <= {FIRST_GOAL}: {'met' if first_ratio <= FIRST_GOAL else 'MISSED'}; load average {load_first:.2f})")
    print(f"RATIO own router and JVMs / its simulation: {alone[0]:.2f} s / {alone[1]:.2f} s = {alone[0] / alone[1]:.2f}"
          f"  (before the service; load average {load_alone:.2f})")
    return 0 if warm_ratio <= WARM_GOAL and first_ratio <= FIRST_GOAL else 1


if __name__ == "__main__":
    sys.exit(main())
