# SPDX-License-Identifier: EPL-2.0
"""Aggregating and comparing a campaign costs little next to running it (issue 29).

Runs a campaign of ``--runs`` small-room missions (default 100: rooms with a walking human, two seeds each) with
`rei campaign --workers N`, then measures, on its results, what the navigation metrics add after the runs: the
aggregation per group, room and variant (mean, median, bootstrap interval, Wilson rate: ``metric_rows`` and
``metrics.csv``) in this process, and `rei compare OUT OUT -o DIR` as a user runs it (a new process: start,
imports, pairing, paired tests, compare.html, compare.json, verdicts.xml; the campaign against itself pairs
every run). Goal: both together under 5 % of the campaign's own wall time (the RATIO line; exit 1 when missed).
The per-run metrics themselves are computed inside each run (the evaluator) and are part of the campaign's time.

    .venv/bin/python benchmarks/compare.py [--runs 100] [--workers 2] [--keep DIR | --campaign DIR]

``--campaign DIR`` measures an existing campaign folder instead of running one (its wall time from
campaign.json).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
GOAL = 0.05


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=100, help="missions in the campaign (rounded up to even)")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--keep", type=Path, help="campaign folder to keep (default: a temporary one)")
    parser.add_argument("--campaign", type=Path, help="measure this finished campaign instead of running one")
    args = parser.parse_args()

    load_before = os.getloadavg()
    if args.campaign is not None:
        out = args.campaign.resolve()
    else:
        out = (args.keep or Path(tempfile.mkdtemp(prefix="rei-compare-bench-"))).resolve()
        shutil.rmtree(out, ignore_errors=True)
        spec = out.with_name(out.name + "-spec.yaml")
        rooms = math.ceil(args.runs / 2)
        spec.write_text(f"name: compare-bench\nseed: 0\nrepetitions: 2\ntimeout: 300\ngroups:\n  - name: small\n"
                        f"    rooms: {{size: small, density: sparse, humans: 1, count: {rooms}, seed: 1}}\n",
                        encoding="utf-8")
        done = subprocess.run([sys.executable, "-m", "rei.cli", "campaign", str(spec), "-o", str(out), "--workers",
                               str(args.workers)], capture_output=True, text=True, check=False)
        spec.unlink()
        if not (out / "campaign.json").is_file():
            print(done.stdout, done.stderr, sep="\n")
            return 2
    campaign = json.loads((out / "campaign.json").read_text(encoding="utf-8"))
    campaign_wall = float(campaign["metrics"]["campaign"]["wall"])

    from rei.campaign.aggregate import metric_rows, metrics_csv
    from rei.campaign.results import RunResult

    started = time.perf_counter()
    results = [RunResult.from_dict(json.loads(p.read_text(encoding="utf-8")))
               for p in sorted((out / "runs").glob("*/result.json"))]
    rows = metric_rows(results)
    metrics_csv(rows)
    aggregate = time.perf_counter() - started

    target = out / "compare-bench"
    started = time.perf_counter()
    compared = subprocess.run([sys.executable, "-m", "rei.cli", "compare", str(out), str(out), "-o", str(target)],
                              capture_output=True, text=True, check=False)
    compare = time.perf_counter() - started
    if compared.returncode != 0:
        print(compared.stdout, compared.stderr, sep="\n")
        return 2
    shutil.rmtree(target, ignore_errors=True)

    completed = sum(r.status == "COMPLETED" for r in results)
    print(f"campaign: {len(results)}/{campaign['planned']} runs finished ({completed} COMPLETED), "
          f"{args.workers} workers; load average {load_before[0]:.1f} before, {os.getloadavg()[0]:.1f} after")
    print(f"campaign wall time          {campaign_wall:8.2f} s")
    print(f"aggregation (in process)    {aggregate:8.3f} s   ({len(rows)} metric rows)")
    print(f"rei compare OUT OUT -o DIR  {compare:8.3f} s   (a new process; {completed} pairs)")
    ratio = (aggregate + compare) / campaign_wall
    print(f"RATIO (aggregation + compare) / campaign wall  {aggregate + compare:.2f} / {campaign_wall:.1f} s = "
          f"{ratio:.4f}  (goal < {GOAL}: {'met' if ratio < GOAL else 'MISSED'}; load average {os.getloadavg()[0]:.1f})")
    if args.campaign is None and args.keep is None:
        shutil.rmtree(out, ignore_errors=True)
    return 0 if ratio < GOAL else 1


if __name__ == "__main__":
    sys.exit(main())
