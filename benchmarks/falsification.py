# SPDX-License-Identifier: EPL-2.0
"""Falsification: `rei search` (TPE) against random sampling on the same rooms, budgets and seeds, for the
reference navigation and a weakened variant of it, and the search's throughput against `rei campaign`'s.

For every room (the crossing example; the thesis's simple navigation room with its person's timing and the
table's floor free; ``doorways``, benchmarks/falsification/doorways.{rei,yaml}: two people crossing a corridor, where
failures are rare under random sampling, so a guided search can show its gain; ``crossings``,
benchmarks/falsification/crossings.{rei,yaml}: four people whose long lanes cross a longer corridor, where failures
are rarer still and come in more kinds; it is searched on the encounter margin, so the TPE searches there also refine
their near misses, docs/search.md), controller (``nav``; the weakened
``nav:moving_horizon=0``: the local planner no longer predicts where the people walk, so it meets a person it would
have let pass; in the doorways corridor, one floor wide, a smaller planner margin such as ``inflation_margin=0``
changes nothing) and seed, one search with ``--sampler tpe`` and one with ``--sampler random`` run with the same
budget (``--no-shrink``: shrinking is not part of the comparison). Printed per pair: distinct failures found (events:
what happened, with whom, where, however many requirements each violates; search.json's ``distinct_failures``) and
simulated evaluations up to the first failure (a search that found none counts its budget plus one); then for each
room and controller the median over the seeds of both sides, and RATIO lines of search to random over the sums of
these medians, with both sides.

Throughput: the evaluations per hour of the searches run in this invocation (their wall time from start to
search.json, JVM starts included) against the runs per hour of a `rei campaign` of candidates those very searches
evaluated (as many as the budget, evenly spaced over all of them, each with its search's controller and seed), on
the same number of workers. Same cases on both sides, so a search that finds more failures (longer runs: a robot
stuck by a person drives on) is not compared with a campaign of shorter runs. The load average is printed before
and after each search and at the end.

``--reuse random`` reads the random searches already finished in the ``--keep`` folder at the same budget instead of
running them again: the random sampler's candidates depend only on its seed, and every run is deterministic, so a
re-run gives the same evaluations; only its wall time would differ, and reused searches are left out of the
throughput figure. A search.json of an earlier format (``rei-search/1`` counted a failure per requirement) is written
again first, by `rei search` on the same folder with nothing left to run, so reused searches count events too.

Goals (issue 30): at a budget of 200, at least 3x the distinct failures of random sampling, the first failure in
at most a third of random's evaluations, and at least 0.9x the campaign's throughput.

    .venv/bin/python benchmarks/falsification.py [--budget 200] [--seeds 1 2 3] [--workers 2] [--keep DIR]
        [--rooms crossing crossings doorways simple_navigation] [--controllers reference weakened] [--samplers tpe random]
        [--reuse random] [--no-campaign]
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
from typing import Any

import yaml

from rei.search.outputs import (
    FORMAT,  # search.json's format: rei-search/2 counts events as distinct failures
)

REPO = Path(__file__).resolve().parents[1]
DISTINCT_GOAL = 3.0
FIRST_GOAL = 1 / 3
THROUGHPUT_GOAL = 0.9
CONTROLLERS = {"reference": "nav", "weakened": "nav:moving_horizon=0"}
SAMPLERS = ("tpe", "random")
BENCH = "bench.json"  # beside a search's outputs: its wall time and budget, for --reuse


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
    "crossings": _spec_room(REPO / "benchmarks" / "falsification" / "crossings.yaml"),
}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--budget", type=int, default=200)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--rooms", nargs="+", choices=sorted(ROOMS), default=sorted(ROOMS))
    parser.add_argument("--controllers", nargs="+", choices=list(CONTROLLERS), default=list(CONTROLLERS))
    parser.add_argument("--samplers", nargs="+", choices=SAMPLERS, default=list(SAMPLERS))
    parser.add_argument("--reuse", nargs="*", choices=SAMPLERS, default=[],
                        help="read these samplers' searches finished in --keep at this budget instead of running them")
    parser.add_argument("--keep", type=Path, help="output folder to keep (default: a temporary one)")
    parser.add_argument("--no-campaign", action="store_true", help="no throughput figure (no campaign run)")
    args = parser.parse_args()
    if args.reuse and args.keep is None:
        parser.error("--reuse needs --keep (the folder holding the finished searches)")
    print(f"load average before: {_load()}", flush=True)
    folder = args.keep or Path(tempfile.mkdtemp(prefix="rei-falsification-"))
    folder.mkdir(parents=True, exist_ok=True)
    found: dict[tuple[str, str, str], dict[int, dict[str, Any]]] = {}  # (room, controller, sampler) -> seed -> figures
    fresh: list[tuple[str, dict[str, Any]]] = []  # (controller, figures) of the searches run now
    try:
        for room in args.rooms:
            case, body = ROOMS[room]
            shutil.copy(case, folder / case.name)
            for variant in args.controllers:
                controller = CONTROLLERS[variant]
                for seed in args.seeds:
                    spec = folder / f"{room}-{variant}-{seed}.yaml"
                    spec.write_text(f"name: {room}-{variant}\ncase: {case.name}\ncontroller: \"{controller}\"\n"
                                    f"seed: {seed}\ntimeout: 300\n{body}", encoding="utf-8")
                    line = [f"{room:18} {variant:9} seed {seed}:"]
                    for sampler in args.samplers:
                        target = folder / f"{spec.stem}-{sampler}"
                        figures = _reused(spec, target, sampler, args.budget) if sampler in args.reuse else None
                        if figures is None:
                            figures = _search(spec, target, sampler, args.budget, args.workers)
                            fresh.append((controller, figures))
                        found.setdefault((room, variant, sampler), {})[seed] = figures
                        line.append(f"{sampler} {figures['distinct']} distinct, {figures['failing']} failing, first at "
                                    f"{figures['first'] or '-'}, {figures['evaluations']} evaluations in "
                                    f"{figures['wall']:.0f} s{' (reused)' if figures['reused'] else ''};")
                    print(" ".join(line) + f" load {_load()}", flush=True)
        campaign = _campaign(folder, fresh, args.budget, args.workers) if fresh and not args.no_campaign else None
    finally:
        if args.keep is None:
            shutil.rmtree(folder, ignore_errors=True)
    codes = []
    if set(args.samplers) == set(SAMPLERS):
        codes += _comparison(found, args.budget)
    if campaign is not None:
        evaluations = sum(f["evaluations"] for _, f in fresh)
        per_hour = 3600 * evaluations / max(sum(f["wall"] for _, f in fresh), 1e-9)
        print(f"searches run now: {len(fresh)}, {evaluations} evaluations, {per_hour:.0f} per hour")
        codes.append(_ratio("throughput, search evaluations per hour / campaign runs per hour", per_hour,
                            campaign, THROUGHPUT_GOAL, True))
    print(f"load average after: {_load()}")
    return max(codes, default=0)


def _comparison(found: dict[tuple[str, str, str], dict[int, dict[str, Any]]], budget: int) -> list[int]:
    """Per room and controller the median over the seeds of each side; RATIO lines over the sums of the medians."""
    sums = {sampler: {"distinct": 0.0, "first": 0.0} for sampler in SAMPLERS}
    for (room, variant, sampler), seeds in sorted(found.items()):
        distinct = statistics.median(f["distinct"] for f in seeds.values())
        first = statistics.median(f["first"] or budget + 1 for f in seeds.values())
        sums[sampler]["distinct"] += distinct
        sums[sampler]["first"] += first
        print(f"median over seeds {sorted(seeds)}: {room} {variant} {sampler}: {distinct:g} distinct "
              f"({', '.join(str(f['distinct']) for f in seeds.values())}), first failure at {first:g} "
              f"({', '.join(str(f['first'] or '-') for f in seeds.values())})")
    tpe, rnd = sums["tpe"], sums["random"]
    return [
        _ratio("distinct failures, search / random", tpe["distinct"], rnd["distinct"], DISTINCT_GOAL, True),
        _ratio("evaluations to the first failure, search / random", tpe["first"], rnd["first"], FIRST_GOAL, False),
    ]


def _search(spec: Path, target: Path, sampler: str, budget: int, workers: int) -> dict[str, Any]:
    shutil.rmtree(target, ignore_errors=True)  # a search left there would resume, and its wall time would mean nothing
    load = _load()
    started = time.perf_counter()
    _rei_search(spec, target, sampler, budget, workers)
    wall = time.perf_counter() - started
    (target / BENCH).write_text(json.dumps({"budget": budget, "wall": wall, "workers": workers, "load_before": load,
                                            "load_after": _load()}) + "\n", encoding="utf-8")
    return _figures(target, wall)


def _rei_search(spec: Path, target: Path, sampler: str, budget: int, workers: int) -> None:
    subprocess.run([sys.executable, "-m", "rei.cli", "search", str(spec), "-o", str(target), "--sampler", sampler,
                    "--budget", str(budget), "--workers", str(workers), "--no-shrink"],
                   check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=_env())


def _reused(spec: Path, target: Path, sampler: str, budget: int) -> dict[str, Any] | None:
    """A search finished in an earlier invocation at this budget, or None. Its search.json is written again when an
    earlier rei wrote it (another format: its distinct failures were per requirement, not events)."""
    try:
        bench = json.loads((target / BENCH).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if bench.get("budget") != budget:
        return None
    if _format(target) != FORMAT:
        _rei_search(spec, target, sampler, budget, 1)  # nothing left to run: it only writes its outputs
        if _format(target) != FORMAT:
            sys.exit(f"{target}: search.json could not be written again in format {FORMAT} (rei search "
                     f"{spec} -o {target} --sampler {sampler} --budget {budget} says why)")
    return {**_figures(target, float(bench["wall"])), "reused": True}


def _format(target: Path) -> str | None:
    try:
        return json.loads((target / "search.json").read_text(encoding="utf-8")).get("format")
    except (OSError, ValueError):
        return None


def _figures(target: Path, wall: float) -> dict[str, Any]:
    document = json.loads((target / "search.json").read_text(encoding="utf-8"))
    counts = document["counts"]
    return {"distinct": counts["distinct_failures"], "first": counts["first_failure_at"],
            "failing": counts["failing"], "evaluations": counts["simulated"], "wall": wall, "reused": False,
            "folder": target}


def _campaign(folder: Path, fresh: list[tuple[str, dict[str, Any]]], runs: int, workers: int) -> float:
    """Runs per hour of a campaign of ``runs`` candidates the searches in ``fresh`` evaluated, evenly spaced over
    all of them, each with its search's controller, same workers. The campaign gives every run seed 0, as the
    searches of the crossing and doorways rooms (no seed parameter) did: there its runs are the searches' runs;
    simple_navigation's candidates ran with their own seeds, so there they are alike, not identical."""
    pool = [(controller, case) for controller, figures in fresh
            for case in sorted((figures["folder"] / "candidates").glob("*.rei"))]
    chosen = [pool[i * len(pool) // runs] for i in range(min(runs, len(pool)))]
    (folder / "throughput").mkdir(exist_ok=True)
    groups: dict[str, list[str]] = {}
    for i, (controller, case) in enumerate(chosen):
        name = f"throughput/c{i:04d}.rei"
        shutil.copy(case, folder / name)
        groups.setdefault(controller, []).append(name)
    body = "".join(f"  - name: g{g}\n    cases: [{', '.join(names)}]\n    variants: [{{name: base, controller: "
                   f"\"{controller}\"}}]\n" for g, (controller, names) in enumerate(groups.items()))
    spec = folder / "throughput.yaml"
    spec.write_text(f"name: throughput\nseed: 0\ntimeout: 300\ngroups:\n{body}", encoding="utf-8")
    shutil.rmtree(folder / "campaign", ignore_errors=True)
    load = _load()
    started = time.perf_counter()
    subprocess.run([sys.executable, "-m", "rei.cli", "campaign", str(spec), "-o", str(folder / "campaign"),
                    "--workers", str(workers)], check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=_env())
    wall = time.perf_counter() - started
    per_hour = 3600 * len(chosen) / wall
    print(f"campaign: {len(chosen)} of the {len(pool)} candidates the searches ran, in {wall:.0f} s, "
          f"{per_hour:.0f} runs per hour (load {load} before, {_load()} after)", flush=True)
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
