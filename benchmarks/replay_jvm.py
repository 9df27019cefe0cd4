# SPDX-License-Identifier: EPL-2.0
"""Cost of one monitor replay JVM (a campaign's per-run judgement, `rei evaluate`), with and without class-data
sharing (rei.run.jvm).

Records the example's mission once (``rei sim --no-router``), then replays it ``--repeat`` times per setting
through ``rei.run.jvm.run_jar`` and prints median wall and CPU seconds of the JVM. The archive is dumped by an
unmeasured first run into a temporary folder.

    .venv/bin/python benchmarks/replay_jvm.py [--repeat 7] [--example simple_navigation]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from rei.run.jvm import CDS_ENV, run_jar

REPO = Path(__file__).resolve().parents[1]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n", 1)[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--example", default="simple_navigation")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="rei-bench-replay-") as folder:
        run = Path(folder) / "run"
        subprocess.run([sys.executable, "-m", "rei.cli", "sim", str(REPO / "examples" / f"{args.example}.rei"),
                        "-o", str(run), "--no-router", "--progress", "none"], check=True, capture_output=True)
        replay = ["--replay", str(run), "--case", str(run / "case"), "--quiet"]
        rows = {}
        for setting, cds in (("without sharing", "off"), ("with sharing", str(Path(folder) / "cds"))):
            os.environ[CDS_ENV] = cds
            run_jar("monitor", replay, Path(folder) / "warm-up.log")  # page cache warm; dumps the archive
            results = [run_jar("monitor", replay, Path(folder) / "replay.log") for _ in range(args.repeat)]
            if any(r.code != 0 for r in results):
                raise SystemExit(f"a replay failed: {results[-1].log_tail}")
            rows[setting] = (statistics.median(r.wall for r in results), statistics.median(r.cpu for r in results))
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}; {args.repeat} replays each")
    for setting, (wall, cpu) in rows.items():
        print(f"{setting:16} median wall {wall:.2f} s, CPU {cpu:.2f} s")
    (wall0, cpu0), (wall1, cpu1) = rows.values()
    print(f"sharing saves {1 - wall1 / wall0:.0%} wall, {1 - cpu1 / cpu0:.0%} CPU per replay")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
