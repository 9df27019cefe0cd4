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
side. Exit 1 when the goal is missed.

    .venv/bin/python benchmarks/cluster.py [--workers 2] [--rounds 1] [--keep DIR]
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
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
    args = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="rei-bench-cluster-"))
    try:
        spec = _spec(work / "spec")
        sides: dict[str, list[dict[str, float]]] = {"local": [], "ray": []}
        with _cluster(args.workers, hide=work / "spec") as address:
            for round_ in range(args.rounds):
                for side in ("local", "ray"):
                    out = work / "spec" / f"out-{side}-{round_}"
                    extra = ["--workers", str(args.workers), "--no-service"] if side == "local" else [
                        "--ray", address]
                    sides[side].append(_measure(spec, out, extra, side))
        local, ray = (_mean(sides[side]) for side in ("local", "ray"))
        ratio = ray["runs_per_hour"] / local["runs_per_hour"]
        print(f"RATIO throughput ray/local: {ray['runs_per_hour']:.0f} / {local['runs_per_hour']:.0f} runs/hour = "
              f"{ratio:.2f}x (goal >= {GOAL})")
        print(f"moved per run: {ray['sent'] / ray['runs'] / 1024:.0f} kB to the node (each case once, shared by its "
              f"runs), {ray['received'] / ray['runs'] / 1024:.0f} kB back")
        if args.keep:
            shutil.copytree(work / "spec", args.keep, dirs_exist_ok=True)
        return 0 if ratio >= GOAL else 1
    finally:
        shutil.rmtree(work, ignore_errors=True)


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


def _measure(spec: Path, out: Path, extra: list[str], side: str) -> dict[str, float]:
    load_before = os.getloadavg()
    started = time.perf_counter()
    done = subprocess.run([str(REI), "campaign", str(spec), "-o", str(out), *extra], capture_output=True, text=True,
                          check=False, env={**os.environ, "REI_SERVICE": "off"})
    wall = time.perf_counter() - started
    load_after = os.getloadavg()
    if done.returncode not in (0, 1):
        raise SystemExit(f"{side}: rei campaign failed ({done.returncode}):\n{done.stdout[-3000:]}{done.stderr[-3000:]}")
    metrics = json.loads((out / "campaign.json").read_text(encoding="utf-8"))["metrics"]
    runs = sum(1 for _ in (out / "runs").glob("*/result.json"))
    simulated = sum(json.loads(p.read_text(encoding="utf-8")).get("simulation", {}).get("cpu", 0.0)
                    for p in (out / "runs").glob("*/timing.json"))
    moved = metrics.get("transfer", {"sent": 0, "received": 0})
    result = {"wall": wall, "runs": runs, "runs_per_hour": 3600 * runs / wall, "sim_cpu": simulated,
              "cpu": metrics.get("campaign", {}).get("cpu", 0.0), "sent": moved["sent"],
              "received": moved["received"]}
    cpu = "" if side == "ray" else f", campaign CPU {result['cpu']:.0f} s"  # a node's CPU is not the driver's
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
