# SPDX-License-Identifier: EPL-2.0
"""What the process boundary costs: the mission's real-time factor with the reference navigation as an external
SUT (`rei nav-sut`, lockstep over the router) beside the same mission with the in-process controller, measured in
the same run, interleaved, same seeds. Also the per-tick round trip (tick published -> command taken), whose
p50 includes the navigation's own step. Target: external >= 0.7 x in-process.

Both variants publish state at 20 Hz through the same authenticated Crossbar router, as `rei run` does.
`--sut` measures another external SUT the same way, e.g. the reference navigation as a ROS 1 node through the
bridge (docs/ros.md; no target: the ratio is reported); given more than once, each is measured in the same run,
interleaved with the in-process runs (e.g. the ROS 2 bridge with the ros2-client node and with REI's own node).

    .venv/bin/python benchmarks/sut_rtf.py [--runs 3] [--example simple_navigation]
    .venv/bin/python benchmarks/sut_rtf.py --sut "ros1:python3 examples/sut/ros1/reference_nav_node.py"
    .venv/bin/python benchmarks/sut_rtf.py --sut "ros2:$(bash scripts/setup-ros2-node.sh)" \
        --sut "ros2:python3 examples/sut/ros2/reference_nav_node.py"
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
from pathlib import Path

from _examples import REPO, generate_example

from rei.run import MissionRunOptions, MissionRunResult, run_mission
from rei.sut.external.options import SutOptions
from rei.wamp.client import WampClient
from rei.wamp.router import Router

TARGET = 0.7


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--example", default="simple_navigation")
    parser.add_argument("--sut", action="append", metavar="COMMAND",
                        help="an external SUT's command (default rei nav-sut; repeat to measure several)")
    args = parser.parse_args()
    suts: list[str] = args.sut or ["rei nav-sut"]

    with tempfile.TemporaryDirectory(prefix="rei-bench-") as tmp:
        case = generate_example(args.example, Path(tmp) / "case")
        with Router(run_dir=Path(tmp) / "router", run_id="bench") as router:  # the runs follow one another
            variants: dict[str, SutOptions | None] = {"in-process": None}
            for number, command in enumerate(suts):
                variants[f"external {number + 1}" if len(suts) > 1 else "external"] = SutOptions(
                    command=command, offer_map=True, router_url=router.ws_url, auth_file=router.auth_file("sut"),
                    cwd=REPO)
            rows: dict[str, list[MissionRunResult]] = {variant: [] for variant in variants}
            for run in range(args.runs):
                for variant, sut in variants.items():
                    with WampClient(router.rs_url, auth=router.credentials("simulation")) as client:
                        result = run_mission(case, Path(tmp) / f"{variant}{run}", MissionRunOptions(seed=run, sut=sut),
                                             run_id="bench", client=client)
                    rows[variant].append(result)
                    trip = result.sut["round_trip_ms"] if result.sut else None
                    print(f"run {run} {variant:10s}: {'ok  ' if result.succeeded else 'FAIL'} sim {result.sim_time:6.1f} s  "
                          f"wall {result.wall_time:5.2f} s  {result.real_time_factor:5.1f}x real time"
                          + (f"  round trip p50 {trip['p50']:.2f} ms p99 {trip['p99']:.2f} ms" if trip else ""))
    inproc = statistics.median(r.real_time_factor for r in rows["in-process"])
    target = TARGET if suts == ["rei nav-sut"] else None
    met = True
    for (variant, results), command in zip(list(rows.items())[1:], suts, strict=True):
        ext = statistics.median(r.real_time_factor for r in results)
        p50 = statistics.median(r.sut["round_trip_ms"]["p50"] for r in results if r.sut)
        p99 = statistics.median(r.sut["round_trip_ms"]["p99"] for r in results if r.sut)
        ratio = ext / inproc
        met = met and (target is None or ratio >= target)
        print(f"median real-time factor: {variant} SUT ({command}) {ext:.1f}x, in-process {inproc:.1f}x: ratio "
              f"{ratio:.2f}" + (f" (target >= {target})" if target else "") + f"; per-tick round trip p50 "
              f"{p50:.2f} ms, p99 {p99:.2f} ms; {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
    raise SystemExit(0 if met else 1)


if __name__ == "__main__":
    main()
