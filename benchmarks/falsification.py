# SPDX-License-Identifier: EPL-2.0
"""Falsification: `rei search` (TPE) against random sampling on the same rooms, budgets and seeds, for the
reference navigation and a weakened variant of it, and the search's throughput against `rei campaign`'s.

For every room (the crossing example; the thesis's simple navigation room with its person's timing and the
table's floor free; ``doorways``, benchmarks/falsification/doorways.{rei,yaml}: two people crossing a corridor, where
failures are rare under random sampling, so a guided search can show its gain), controller (``nav``; ``nav:inflation_margin=0``: the planner keeps no safety margin beyond
the robot's footprint) and seed, one search with ``--sampler tpe`` and one with ``--sampler random`` run with the
same budget (``--no-shrink``: shrinking is not part of the comparison). Printed per pair and summed: distinct
failures found and simulated evaluations up to the first failure, each as a RATIO line of search to random
with both sides. Throughput: the evaluations per hour of the searches against the runs per hour of a campaign of
the crossing case repeated as many times as the budget, on the same workers (RATIO line). The load average is
printed before and after, as the other benchmarks do.

Goals (issue 30): at a budget of 200, at least 3x the distinct failures of random sampling, the first failure in
at most a third of random's evaluations, and at least 0.9x the campaign's throughput.

    .venv/bin/python benchmarks/falsification.py [--budget 200] [--seeds 1 2 3] [--workers 2] [--keep DIR]
        [--rooms crossing doorways simple_navigation]
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
from typing import Any

import yaml

REPO = Path(__file__).resolve().parents[1]
DISTINCT_GOAL = 3.0
FIRST_GOAL = 1 / 3
THROUGHPUT_GOAL = 0.9
CONTROLLERS = {"reference": "nav", "weakened": "nav:inflation_margin=0"}


def _spec_room(spec: Path) -> tuple[Path, str]:
    """A room kept as a runnable search spec: its case and the spec's parameters and objectives (the benchmark
    sets the rest)."""
    document = yaml.safe_load(spec.read_text(encoding="utf-8"))
    body = {key: document[key] for key in ("parameters", "objectives")}
    return spec.parent / document["case"], yaml.safe_dump(body, sort_keys=False, default_flow_style=None)


ROOMS: dict[str, tuple[Path, str]] = {
    "crossing": (REPO / "examples" / "search" / "crossing.rei", """\
parameters:
  - {human: walker, start: [0, 20], speed: [0.4, 1.5]}
  - {object: bin1, floor: any}
objectives:
  - {metric: clearance_humans_min}
"""),
    "simple_navigation": (REPO / "examples" / "simple_navigation.rei", """\
parameters:
  - {human: walker, start: [0, 10], speed: [0.3, 1.2]}
  - {object: table1, floor: any}
  - {seed: [0, 1000]}
objectives:
  - {metric: clearance_humans_min}
"""),
    "doorways": _spec_room(REPO / "benchmarks" / "falsification" / "doorways.yaml"),
}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--budget", type=int, default=200)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--rooms", nargs="+", choices=sorted(ROOMS), default=sorted(ROOMS))
    parser.add_argument("--keep", type=Path, help="output folder to keep (default: a temporary one)")
    args = parser.parse_args()
    print(f"load average before: {_load()}", flush=True)
    folder = args.keep or Path(tempfile.mkdtemp(prefix="rei-falsification-"))
    folder.mkdir(parents=True, exist_ok=True)
    totals = {"tpe": {"distinct": 0, "first": 0, "unfound": 0, "evaluations": 0, "wall": 0.0},
              "random": {"distinct": 0, "first": 0, "unfound": 0, "evaluations": 0, "wall": 0.0}}
    try:
        for room in args.rooms:
            case, body = ROOMS[room]
            shutil.copy(case, folder / case.name)
            for variant, controller in CONTROLLERS.items():
                for seed in args.seeds:
                    spec = folder / f"{room}-{variant}-{seed}.yaml"
                    spec.write_text(f"name: {room}-{variant}\ncase: {case.name}\ncontroller: \"{controller}\"\n"
                                    f"seed: {seed}\ntimeout: 300\n{body}", encoding="utf-8")
                    line = [f"{room:18} {variant:9} seed {seed}:"]
                    for sampler in ("tpe", "random"):
                        found = _search(spec, folder / spec.stem, sampler, args.budget, args.workers)
                        t = totals[sampler]
                        t["distinct"] += found["distinct"]
                        t["evaluations"] += found["evaluations"]
                        t["wall"] += found["wall"]
                        # a search that found nothing counts its whole budget (and one more) as its first failure
                        t["first"] += found["first"] or args.budget + 1
                        t["unfound"] += found["first"] is None
                        line.append(f"{sampler} {found['distinct']} distinct, first at {found['first'] or '-'}, "
                                    f"{found['evaluations']} evaluations in {found['wall']:.0f} s;")
                    print(" ".join(line), flush=True)
        campaign = _campaign(folder, args.workers)
    finally:
        if args.keep is None:
            shutil.rmtree(folder, ignore_errors=True)
    tpe, rnd = totals["tpe"], totals["random"]
    codes = [
        _ratio("distinct failures, search / random", tpe["distinct"], rnd["distinct"], DISTINCT_GOAL, True),
        _ratio("evaluations to the first failure, search / random", tpe["first"], rnd["first"], FIRST_GOAL, False),
    ]
    per_hour = 3600 * (tpe["evaluations"] + rnd["evaluations"]) / max(tpe["wall"] + rnd["wall"], 1e-9)
    codes.append(_ratio("throughput, search evaluations per hour / campaign runs per hour", per_hour,
                        campaign, THROUGHPUT_GOAL, True))
    print(f"searches without any failure: tpe {tpe['unfound']}, random {rnd['unfound']} (each counted as budget + 1)")
    print(f"load average after: {_load()}")
    return max(codes)


def _search(spec: Path, out: Path, sampler: str, budget: int, workers: int) -> dict[str, Any]:
    target = out.with_name(f"{out.name}-{sampler}")
    started = time.perf_counter()
    subprocess.run([sys.executable, "-m", "rei.cli", "search", str(spec), "-o", str(target), "--sampler", sampler,
                    "--budget", str(budget), "--workers", str(workers), "--no-shrink"],
                   check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=_env())
    wall = time.perf_counter() - started
    document = json.loads((target / "search.json").read_text(encoding="utf-8"))
    counts = document["counts"]
    return {"distinct": counts["distinct_failures"], "first": counts["first_failure_at"],
            "evaluations": counts["simulated"], "wall": wall}


def _campaign(folder: Path, workers: int) -> float:
    """Runs per hour of a campaign of the cases the random searches simulated (comparable rooms: the same
    candidates; a campaign gives each run the spec's seed, so the runs are alike, not identical), same workers."""
    cases = sorted(folder.glob("*-random/candidates/*.rei"))
    (folder / "throughput").mkdir(exist_ok=True)
    names = []
    for i, case in enumerate(cases):
        names.append(f"throughput/c{i:04d}.rei")
        shutil.copy(case, folder / names[-1])
    spec = folder / "throughput.yaml"
    spec.write_text(f"name: throughput\ntimeout: 300\ngroups:\n  - name: candidates\n    cases: [{', '.join(names)}]\n",
                    encoding="utf-8")
    started = time.perf_counter()
    subprocess.run([sys.executable, "-m", "rei.cli", "campaign", str(spec), "-o", str(folder / "campaign"),
                    "--workers", str(workers)], check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=_env())
    wall = time.perf_counter() - started
    per_hour = 3600 * len(cases) / wall
    print(f"campaign: the {len(cases)} cases the random searches ran, in {wall:.0f} s, {per_hour:.0f} runs per hour",
          flush=True)
    return per_hour


def _env() -> dict[str, str]:
    return {**os.environ, "REI_SERVICE": "off"}  # both sides start their own JVMs


def _ratio(what: str, ours: float, theirs: float, goal: float, higher: bool) -> int:
    # both real sides are printed: over a zero the ratio is infinite (nothing over nothing is no ratio: missed)
    ratio = ours / theirs if theirs else float("inf") if ours else float("nan")
    met = ratio >= goal if higher else ratio <= goal
    print(f"RATIO {what}: {ours:g} / {theirs:g} = {ratio:.2f} (goal {'>=' if higher else '<='} {goal:.2f}) "
          f"{'met' if met else 'MISSED'}")
    return 0 if met else 1


def _load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


if __name__ == "__main__":
    sys.exit(main())
