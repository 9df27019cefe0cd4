# SPDX-License-Identifier: EPL-2.0
"""The same 20-run campaign through the shared-nothing Ray path and through local workers, in one invocation.

The campaign: 10 small dense rooms (rei gen-rooms' 7 x 5 m, 10 objects, no human, two goals across the room) x 2
repetitions with the reference navigation: short missions (~20-40 simulated seconds), so it stays minutes.
Two sides, one after the other, alternating over ``--rounds`` rounds (the machine's load drifts):

- ``local``: `rei campaign --workers N --no-service` (runs forked by the fork server, replayed in one warm monitor
  JVM, written straight into OUT);
- ``ray``: `rei campaign --ray ADDRESS` on a Ray cluster started here whose head has no CPU and whose one worker
  node has N CPUs, in a mount namespace of its own where OUT and the spec's folder are hidden: every run's
  inputs go to it and its files come back through Ray (rei.campaign.transfer), as on a cluster sharing nothing.

Prints each side's wall time, runs per hour and CPU, the throughput ratio ray / local (goal >= 0.9) with both
sides, the bytes moved per run (campaign.json: metrics.transfer), and the load average before and after each
side; then whether each round's two sides gave the same results: per run its status, its verdicts (verdicts.xml
but the seconds the evaluation took), its metrics (summary.json but its wall time) and the SHA-256 of each of its
streams. Exit 1 when the goal is missed or the results differ.

``--spec SPEC``: that campaign instead (``examples/campaigns/thesis.yaml``: the thesis's 23 runs); it is read
where it is, and only OUT is hidden from the node. ``--search SPEC [--budget N]``: a search of N evaluations
(default 10, not shrunk) instead of a campaign, its candidates compared too (key, status and objective values);
TPE, CMA-ES and NSGA-II ask the same candidates on both sides only with one run at a time (``--workers 1``).

    .venv/bin/python benchmarks/cluster.py [--workers 2] [--rounds 1] [--keep DIR]
    .venv/bin/python benchmarks/cluster.py --spec examples/campaigns/thesis.yaml
    .venv/bin/python benchmarks/cluster.py --search examples/search/crossing.yaml --budget 10 --workers 1
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import hashlib
import json
import os
import re
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
REI = Path(sys.executable).parent / "rei"
RAY = Path(sys.executable).parent / "ray"
GOAL = 0.9


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--rounds", type=int, default=1, help="local and ray alternately, this many times each")
    parser.add_argument("--keep", type=Path, help="keep the campaigns' folders here (default: a temporary one)")
    parser.add_argument("--spec", type=Path, help="this campaign instead of the 20 small rooms")
    parser.add_argument("--search", type=Path, help="a search of this spec instead of a campaign")
    parser.add_argument("--budget", type=int, default=10, help="the search's evaluations (default 10)")
    args = parser.parse_args()
    if args.spec and args.search:
        parser.error("give --spec or --search, not both")
    work = Path(tempfile.mkdtemp(prefix="rei-bench-cluster-"))
    try:
        (work / "out").mkdir()
        spec = (args.search or args.spec).resolve() if args.search or args.spec else _spec(work / "out" / "spec")
        command = (["search", str(spec), "--budget", str(args.budget), "--no-shrink"] if args.search
                   else ["campaign", str(spec)])
        sides: dict[str, list[dict[str, float]]] = {"local": [], "ray": []}
        differences: list[str] = []
        with _cluster(args.workers, hide=work / "out") as address:
            for round_ in range(args.rounds):
                outs = {}
                for side in ("local", "ray"):
                    outs[side] = work / "out" / f"{side}-{round_}"
                    extra = ["--workers", str(args.workers), *(["--no-service"] if not args.search else [])] \
                        if side == "local" else ["--ray", address]
                    sides[side].append(_measure(command, outs[side], extra, side))
                found = _differences(outs["local"], outs["ray"], bool(args.search))
                differences += [f"round {round_ + 1}: {line}" for line in found]
                runs = len(_facts(outs["local"], bool(args.search)))
                print(f"SAME RESULTS round {round_ + 1}: {'yes' if not found else 'NO'}, {runs} runs compared "
                      f"(status, verdicts, metrics, streams' SHA-256{', candidates' if args.search else ''})"
                      + "".join(f"\n  {line}" for line in found[:20]), flush=True)
        local, ray = (_mean(sides[side]) for side in ("local", "ray"))
        ratio = ray["runs_per_hour"] / local["runs_per_hour"]
        print(f"RATIO throughput ray/local: {ray['runs_per_hour']:.0f} / {local['runs_per_hour']:.0f} runs/hour = "
              f"{ratio:.2f}x (goal >= {GOAL}); results {'identical' if not differences else 'DIFFERENT'} in "
              f"{args.rounds} round(s)")
        sent = "" if args.search else f"{ray['sent'] / ray['runs'] / 1024:.0f} kB to the node (each case once, " \
            "shared by its runs), "
        print(f"moved per run: {sent}{ray['received'] / ray['runs'] / 1024:.0f} kB back")
        if args.keep:
            shutil.copytree(work / "out", args.keep, dirs_exist_ok=True)
        return 0 if ratio >= GOAL and not differences else 1
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _facts(out: Path, search: bool) -> dict[str, dict[str, object]]:
    """Per run of OUT (by key): its status, verdicts, metrics and streams' SHA-256; a search's candidates also
    with their status and objective values (one that was not simulated: those alone)."""
    facts: dict[str, dict[str, object]] = {}
    if search:
        document = json.loads((out / "search.json").read_text(encoding="utf-8"))
        statuses = {e["key"]: (e["status"], e.get("values")) for e in document["evaluations"]}
    else:
        with open(out / "runs.csv", newline="", encoding="utf-8") as f:
            statuses = {row["key"]: row["status"] for row in csv.DictReader(f)}
    for key, status in statuses.items():
        run = out / "runs" / key
        fact: dict[str, object] = {"status": status}
        if (run / "summary.json").is_file():
            summary = json.loads((run / "summary.json").read_text(encoding="utf-8"))
            summary.pop("wall_time", None)
            fact["metrics"] = json.dumps(summary, sort_keys=True).replace(str(out), "OUT")
        if (run / "verdicts.xml").is_file():
            fact["verdicts"] = re.sub(r' time="[0-9.]+"', "", (run / "verdicts.xml").read_text(encoding="utf-8"))
        fact["streams"] = {p.name: hashlib.sha256(p.read_bytes()).hexdigest()
                           for p in sorted((run / "streams").glob("*")) if p.is_file()}
        facts[key] = fact
    return facts


def _differences(local: Path, ray: Path, search: bool) -> list[str]:
    """What differs between the two sides' runs, one line each ([]: the same results)."""
    here, there = _facts(local, search), _facts(ray, search)
    lines = [f"{key}: only {side}" for side, keys in (("local", here.keys() - there.keys()),
                                                    ("ray", there.keys() - here.keys())) for key in sorted(keys)]
    for key in sorted(here.keys() & there.keys()):
        lines += [f"{key}: {what} differs ({str(here[key].get(what))[:80]} / {str(there[key].get(what))[:80]})"
                  for what in ("status", "verdicts", "metrics", "streams") if here[key].get(what) != there[key].get(what)]
    if not here:
        lines.append("no run to compare")
    return lines


def _spec(folder: Path) -> Path:
    """20 runs: 10 small dense rooms, twice each."""
    folder.mkdir(parents=True)
    spec = folder / "cluster.yaml"
    spec.write_text("""name: cluster-benchmark
seed: 1
repetitions: 2
timeout: 300
groups:
  - name: small
    rooms: {size: small, density: dense, humans: 0, count: 10, seed: 7}
    variants: [{name: base, humans: false}]
""", encoding="utf-8")
    return spec


def _measure(command: list[str], out: Path, extra: list[str], side: str) -> dict[str, float]:
    load_before = os.getloadavg()
    started = time.perf_counter()
    done = subprocess.run([str(REI), *command, "-o", str(out), *extra], capture_output=True, text=True,
                          check=False, env={**os.environ, "REI_SERVICE": "off"})
    wall = time.perf_counter() - started
    load_after = os.getloadavg()
    if done.returncode not in (0, 1):
        raise SystemExit(f"{side}: rei {command[0]} failed ({done.returncode}):\n{done.stdout[-3000:]}"
                         f"{done.stderr[-3000:]}")
    search = command[0] == "search"
    document = json.loads((out / ("search.json" if search else "campaign.json")).read_text(encoding="utf-8"))
    metrics = {} if search else document["metrics"]
    runs = sum(1 for _ in (out / "runs").glob("*/result.json")) if not search else document["counts"]["simulated"]
    simulated = sum(json.loads(p.read_text(encoding="utf-8")).get("simulation", {}).get("cpu", 0.0)
                    for p in (out / "runs").glob("*/timing.json"))
    moved = metrics.get("transfer", {"sent": 0, "received": 0})
    if search and side == "ray":  # a search keeps no transfer metrics: its run folders are what came back
        moved = {"sent": 0, "received": sum(p.stat().st_size for p in (out / "runs").rglob("*") if p.is_file())}
    result = {"wall": wall, "runs": runs, "runs_per_hour": 3600 * runs / wall, "sim_cpu": simulated,
              "cpu": metrics.get("campaign", {}).get("cpu", 0.0), "sent": moved["sent"],
              "received": moved["received"]}
    cpu = "" if side == "ray" or search else f", campaign CPU {result['cpu']:.0f} s"  # a node's is not the driver's
    print(f"{side}: {runs} runs in {wall:.1f} s = {result['runs_per_hour']:.0f} runs/hour; simulation CPU "
          f"{simulated:.0f} s{cpu}; load average {load_before[0]:.1f} before, {load_after[0]:.1f} after", flush=True)
    return result


def _mean(rounds: list[dict[str, float]]) -> dict[str, float]:
    total = {key: sum(r[key] for r in rounds) for key in rounds[0]}
    return {**total, "runs_per_hour": 3600 * total["runs"] / total["wall"]}


@contextlib.contextmanager
def _cluster(cpus: int, hide: Path) -> Iterator[str]:
    """A head of no CPU and one worker node of ``cpus`` CPUs in a mount namespace of its own where ``hide`` is an
    empty tmpfs; its address; every process stopped afterwards."""
    root = Path(tempfile.mkdtemp(prefix="rei-bc-"))  # short: Ray's unix sockets live below it
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    token = root / "auth_token"
    token.write_text(secrets.token_hex(32), encoding="ascii")
    env = {**os.environ, "RAY_TMPDIR": str(root), "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN_PATH": str(token)}
    common = ["--block", "--node-ip-address=127.0.0.1", "--disable-usage-stats", "--object-store-memory=200000000"]
    processes = []
    log = open(root / "ray.log", "ab")  # noqa: SIM115 - closed below
    try:
        processes.append(subprocess.Popen([str(RAY), "start", "--head", f"--port={port}", "--num-cpus=0",
                                           "--include-dashboard=false", f"--temp-dir={root / 'ray'}", *common],
                                          stdout=log, stderr=subprocess.STDOUT, start_new_session=True, env=env))
        (root / "node").mkdir()
        node = [str(RAY), "start", f"--address=127.0.0.1:{port}", f"--num-cpus={cpus}",
                f'--resources={{"rei": {cpus}}}', *common]
        processes.append(subprocess.Popen(
            ["unshare", "-m", "sh", "-c", 'mount -t tmpfs tmpfs "$0" && exec "$@"', str(hide), *node],
            stdout=log, stderr=subprocess.STDOUT, start_new_session=True, env={**env, "TMPDIR": str(root / "node")}))
        probe = "import ray; ray.init(logging_level='ERROR'); print(int(ray.cluster_resources().get('CPU', 0)))"
        deadline = time.monotonic() + 180
        while time.monotonic() < deadline:
            answer = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=False,
                                    env={**env, "RAY_ADDRESS": f"127.0.0.1:{port}"})
            if answer.stdout.strip().splitlines()[-1:] == [str(cpus)]:
                break
            time.sleep(2)
        else:
            raise SystemExit(f"the cluster never had {cpus} CPUs")
        os.environ.update({k: env[k] for k in ("RAY_TMPDIR", "RAY_AUTH_MODE", "RAY_AUTH_TOKEN_PATH")})
        yield f"127.0.0.1:{port}"
    finally:
        for process in reversed(processes):  # the node first
            with contextlib.suppress(ProcessLookupError):
                process.send_signal(signal.SIGTERM)
            with contextlib.suppress(subprocess.TimeoutExpired):
                process.wait(60)
            with contextlib.suppress(ProcessLookupError):
                os.killpg(process.pid, signal.SIGKILL)
            process.wait()
        log.close()
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
