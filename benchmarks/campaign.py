# SPDX-License-Identifier: EPL-2.0
"""A campaign of the thesis's size (7.4): 14 small-room runs, 8 medium-room runs with a human, 1 large room.

Runs examples/campaigns/thesis.yaml cold (fresh output folder: every case generated, every run executed) with
`rei campaign --workers N` and reports the wall time, runs per hour, the campaign's CPU seconds and its share of
the machine's cores, how busy the machine was overall (other processes included) and the load average, and
where the runs' time went (simulation, monitor replay, evaluation). Targets: all 23 runs in under 2 minutes on
2 cores; the campaign's CPU <= 1.25x its simulations' CPU and its wall time <= 1.1x that CPU spread over the cores
(both sides printed as RATIO lines; exit 1 when one is missed).

Two settings (``--jvms``, default both, one after the other):

- ``own``: no background service (``REI_SERVICE=off``): the campaign starts its generator and monitor JVMs and
  pays their warm-up (JIT, the rules' build), as on a machine where nothing ran before;
- ``service``: a background service of its own (a private ``REI_SERVICE_DIR``), started and warmed by one
  ``rei run`` of the example, as after a user's earlier run; the campaign generates and replays in its warm JVMs.
  The service's CPU during the campaign counts as the campaign's (``helpers_cpu`` in campaign.json).

    .venv/bin/python benchmarks/campaign.py [--jvms own|service|both] [--workers 2]
                                            [--spec examples/campaigns/thesis.yaml] [--keep DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
#: The campaign's CPU at most this times its simulations' CPU (the rest: generation, replays, workers' start).
CPU_GOAL = 1.25
#: Its wall time at most this times the simulations' CPU spread over the cores.
WALL_GOAL = 1.1


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--spec", type=Path, default=REPO / "examples" / "campaigns" / "thesis.yaml")
    parser.add_argument("--keep", type=Path, help="output folder to keep (default: a temporary one; with both "
                        "settings, DIR-own and DIR-service)")
    parser.add_argument("--jvms", choices=("own", "service", "both"), default="both")
    args = parser.parse_args()

    codes = []
    for setting in ("own", "service") if args.jvms == "both" else (args.jvms,):
        keep = args.keep.with_name(f"{args.keep.name}-{setting}") if args.keep and args.jvms == "both" else args.keep
        if setting == "own":
            codes.append(_measure(args, keep, {**os.environ, "REI_SERVICE": "off"}, "own JVMs, no service"))
            continue
        with tempfile.TemporaryDirectory(prefix="rei-svc-") as folder:  # short: a socket path has 107 bytes
            env = {**os.environ, "REI_SERVICE": "on", "REI_SERVICE_DIR": folder}
            try:
                subprocess.run([sys.executable, "-m", "rei.cli", "run", str(REPO / "examples" / "simple_navigation.rei"),
                                "-o", str(Path(folder) / "warm-up")], env=env, capture_output=True, check=True)
                _await_spare(Path(folder))  # the next spare router's start (~4 s of CPU) is not the campaign's
                codes.append(_measure(args, keep, env, "the warm JVMs of a background service (warmed by one rei run)"))
            finally:
                subprocess.run([sys.executable, "-m", "rei.cli", "service", "stop"], env=env, capture_output=True,
                               check=False)
    return max(codes)


def _await_spare(folder: Path, timeout: float = 60.0) -> None:
    from rei.service.client import request

    deadline = time.monotonic() + timeout
    while request(folder, {"op": "status"}).get("spare") is None and time.monotonic() < deadline:
        time.sleep(0.2)


def _measure(args: argparse.Namespace, keep: Path | None, env: dict[str, str], setting: str) -> int:
    out = keep or Path(tempfile.mkdtemp(prefix="rei-campaign-bench-"))
    shutil.rmtree(out, ignore_errors=True)
    load_before = os.getloadavg()
    started = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "rei.cli", "campaign", str(args.spec), "-o", str(out),
                           "--workers", str(args.workers)], capture_output=True, text=True, check=False, env=env)
    wall = time.perf_counter() - started
    if not (out / "campaign.json").is_file():
        print(done.stdout, done.stderr, sep="\n")
        return 2
    campaign = json.loads((out / "campaign.json").read_text(encoding="utf-8"))
    metrics = campaign["metrics"]
    usage, runs, prepare = metrics["campaign"], metrics["runs"], metrics["prepare"]
    finished = campaign["finished"]
    print(f"campaign {campaign['name']} with {setting}: {finished}/{campaign['planned']} runs, "
          f"{campaign['errors']} in ERROR, {args.workers} workers on {usage['cores']} cores")
    print(f"wall time       {wall:7.1f} s   (target < 120 s: {'met' if wall < 120 and finished == 23 else 'MISSED'})")
    print(f"runs per hour   {3600 * finished / wall:7.0f}")
    print(f"campaign CPU    {usage['cpu']:7.1f} s   = {100 * usage['cpu_utilisation']:.0f} % of {usage['cores']} cores "
          f"over the wall time; of it the service's {usage.get('helpers_cpu', 0.0):.1f} s")
    print(f"machine busy    {100 * usage['machine_utilisation']:7.0f} %   (all processes; load average "
          f"{load_before[0]:.1f} before, {usage['load_average_1min']:.1f} after)")
    print(f"case generation {prepare['cpu']:7.1f} s CPU for {prepare['generated']} cases ({prepare['wall']:.1f} s wall)")
    for name, t in runs["phases"].items():
        print(f"  {name:<13} {t['cpu']:7.1f} s CPU  {t['wall']:7.1f} s wall (summed over runs)")
    overhead = runs["cpu"] - sum(t["cpu"] for t in runs["phases"].values())
    print(f"  {'worker start':<13} {overhead:7.1f} s CPU  (Python start, imports, files)")
    # the floor, measured in the same run: the simulations' own CPU (issue #17's goals are ratios to it)
    sim_cpu = runs["phases"].get("simulation", {}).get("cpu", 0.0)
    cpu_ratio = usage["cpu"] / sim_cpu if sim_cpu else float("inf")
    ideal_wall = sim_cpu / usage["cores"]
    wall_ratio = wall / ideal_wall if ideal_wall else float("inf")
    print(f"RATIO campaign CPU / simulation CPU          {usage['cpu']:7.1f} / {sim_cpu:7.1f} s = {cpu_ratio:.2f}  "
          f"(goal <= {CPU_GOAL}: {'met' if cpu_ratio <= CPU_GOAL else 'MISSED'})")
    print(f"RATIO wall / (simulation CPU / {usage['cores']} cores)     {wall:7.1f} / {ideal_wall:7.1f} s = "
          f"{wall_ratio:.2f}  (goal <= {WALL_GOAL}: {'met' if wall_ratio <= WALL_GOAL else 'MISSED'}; load average "
          f"{usage['load_average_1min']:.1f})")
    if keep is None:
        shutil.rmtree(out, ignore_errors=True)
    else:
        print(f"report: {out / 'report.html'}")
    if done.returncode not in (0, 1):
        return done.returncode
    return 0 if cpu_ratio <= CPU_GOAL and wall_ratio <= WALL_GOAL else 1


if __name__ == "__main__":
    sys.exit(main())
