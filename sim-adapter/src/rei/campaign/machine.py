# SPDX-License-Identifier: EPL-2.0
"""How busy this machine was during a campaign: our CPU seconds versus all cores' capacity, and everyone's.

Why both: on a shared machine a campaign's wall time depends on the other processes too; the benchmark has to
say how much of the machine the campaign used and how much was taken by others.

A campaign's CPU also counts its *helpers*: processes it did not start that worked for it (the background service
whose warm JVMs generated its cases and replayed its runs), each with all its descendants.
"""

from __future__ import annotations

import os
import resource
import time
from collections.abc import Sequence
from dataclasses import dataclass

from rei.lifetime import stat_fields


@dataclass(frozen=True, slots=True)
class Sample:
    wall: float
    own_cpu: float  # this process and its reaped children, seconds
    helpers_cpu: float  # the helpers' process trees, seconds
    busy: float  # all processes of the machine, CPU seconds (from /proc/stat), or nan
    total: float  # capacity seconds (all cores) over the same counter, or nan

    @classmethod
    def now(cls, helpers: Sequence[int] = ()) -> Sample:
        me, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
        busy, total = _proc_stat()
        return cls(time.perf_counter(), me.ru_utime + me.ru_stime + children.ru_utime + children.ru_stime,
                   sum(tree_cpu(pid) for pid in helpers), busy, total)


def tree_cpu(pid: int) -> float:
    """CPU seconds (user + system) so far of a live process and all its live descendants, from /proc; 0 without
    /proc. Descendants that have ended count through their parent's reaped-children time."""
    parents: dict[int, list[int]] = {}
    times: dict[int, float] = {}
    tick = os.sysconf("SC_CLK_TCK")
    try:
        names = os.listdir("/proc")
    except OSError:
        return 0.0
    for name in names:
        fields = stat_fields(int(name)) if name.isdigit() else None
        if fields is None:  # not a process, or ended meanwhile
            continue
        parents.setdefault(int(fields[1]), []).append(int(name))
        # utime, stime, cutime, cstime: its own and its reaped children's
        times[int(name)] = sum(int(x) for x in fields[11:15]) / tick
    total, todo = 0.0, [pid]
    while todo:
        current = todo.pop()
        total += times.get(current, 0.0)
        todo.extend(parents.get(current, ()))
    return total


def usage(start: Sample, end: Sample) -> dict[str, float]:
    """Wall seconds, our CPU seconds (with the helpers', also given alone), our share of all cores, the machine's
    busy share, cores, load average."""
    cores = os.cpu_count() or 1
    wall = max(end.wall - start.wall, 1e-9)
    helpers = max(0.0, end.helpers_cpu - start.helpers_cpu)  # a helper that ended meanwhile took its time along
    own = end.own_cpu - start.own_cpu + helpers
    span = end.total - start.total
    machine = (end.busy - start.busy) / span if span > 0 else float("nan")
    return {"wall": round(wall, 3), "cpu": round(own, 3), "helpers_cpu": round(helpers, 3), "cores": cores,
            "cpu_utilisation": round(own / (wall * cores), 4), "machine_utilisation": round(machine, 4),
            "load_average_1min": round(os.getloadavg()[0], 2)}


def _proc_stat() -> tuple[float, float]:
    try:
        with open("/proc/stat", encoding="ascii") as f:
            fields = [float(x) for x in f.readline().split()[1:]]
    except (OSError, ValueError):
        return float("nan"), float("nan")
    tick = os.sysconf("SC_CLK_TCK")
    idle = fields[3] + (fields[4] if len(fields) > 4 else 0.0)  # idle + iowait
    total = sum(fields[:8])
    return (total - idle) / tick, total / tick
