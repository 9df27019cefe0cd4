# SPDX-License-Identifier: EPL-2.0
"""Soak: many back-to-back `rei run` pipelines in ONE process tree, looking for leaks.

Runs the whole pipeline (router, monitor jar, simulation child, evaluator) N times from this process and compares,
at the start and after every run: this process's open file descriptors, threads and resident memory, its live
descendant processes, and the listening TCP sockets held by the process tree. A leak shows as growth.

    .venv/bin/python benchmarks/soak.py [--runs 50] [--example simple_navigation] [--humans]
"""

from __future__ import annotations

import argparse
import os
import secrets
import tempfile
import time
from pathlib import Path

from _examples import generate_example

from rei.run.pipeline import PipelineOptions, run_pipeline


def open_fds() -> int:
    return len(os.listdir("/proc/self/fd"))


def status(field: str) -> int:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith(field + ":"):
            return int(line.split()[1])
    raise KeyError(field)


def descendants() -> list[int]:
    parents: dict[int, int] = {}
    for entry in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = entry.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        parents[int(entry.parent.name)] = int(fields[1])
    mine, frontier = set(), {os.getpid()}
    while frontier:
        frontier = {pid for pid, parent in parents.items() if parent in frontier} - mine
        mine |= frontier
    return sorted(mine)


def socket_inodes(pids: list[int]) -> set[str]:
    inodes = set()
    for pid in pids:
        try:
            for fd in Path(f"/proc/{pid}/fd").iterdir():
                target = os.readlink(fd)
                if target.startswith("socket:["):
                    inodes.add(target[8:-1])
        except OSError:
            continue
    return inodes


def listening_ports(pids: list[int]) -> int:
    """Listening TCP sockets held by these processes (other jobs on the machine do not count)."""
    inodes = socket_inodes(pids)
    count = 0
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        for line in Path(table).read_text().splitlines()[1:]:
            fields = line.split()
            if fields[3] == "0A" and fields[9] in inodes:
                count += 1
    return count


def sample() -> dict[str, int]:
    tree = [os.getpid(), *descendants()]
    return {"fds": open_fds(), "threads": status("Threads"), "rss_kb": status("VmRSS"),
            "children": len(tree) - 1, "listening_ports": listening_ports(tree)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=50)
    parser.add_argument("--example", default="simple_navigation")
    parser.add_argument("--humans", action="store_true", help="keep the humans (default: left out, faster)")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory(prefix="rei-soak-") as tmp:
        case = generate_example(args.example, Path(tmp) / "case")
        sim_args = () if args.humans else ("--no-humans",)
        options = PipelineOptions(sim_args=sim_args, humans=args.humans)
        start = sample()
        print(f"start: {start}")
        statuses, walls, after_first = [], [], None
        for run in range(args.runs):
            began = time.perf_counter()
            result = run_pipeline(case, Path(tmp) / f"run{run}", options, run_id=f"soak{secrets.token_hex(4)}")
            walls.append(time.perf_counter() - began)
            statuses.append(result.status)
            now = sample()
            after_first = after_first or now
            print(f"run {run + 1:3d}/{args.runs}: {result.status:9s} exit {result.exit_code}  {walls[-1]:5.1f} s  {now}",
                  flush=True)
        end = sample()
    growth = {key: end[key] - after_first[key] for key in end}
    print(f"end:   {end}")
    print(f"{args.runs} runs, {statuses.count('COMPLETED')} completed, mean {sum(walls) / len(walls):.1f} s/run; "
          f"growth from after run 1 to the end: {growth}; {os.cpu_count()} cores, "
          f"load average {os.getloadavg()[0]:.1f}")
    leaked = end["children"] > start["children"] or end["fds"] > after_first["fds"] \
        or end["listening_ports"] > start["listening_ports"]
    print("LEAK" if leaked else "no leaked process, descriptor or listening port")


if __name__ == "__main__":
    main()
