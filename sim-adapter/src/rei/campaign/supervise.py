# SPDX-License-Identifier: EPL-2.0
"""Run one task's worker process to its end, a timeout, or a stop request, and say how it went.

The worker gets its own session (process group), so stopping it also stops what it started (the monitor's JVM,
``rei run``'s router and children). ``os.wait4`` gives the CPU time of the worker and of every child it waited
for, which the campaign reports per run. Shared by the local pool and the Ray tasks.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from rei.campaign.plan import RunTask
from rei.run.jvm import tail

WORKER_LOG = "worker.log"
#: Seconds a stopped worker gets for SIGTERM before SIGKILL.
KILL_GRACE = 3.0
_POLL = 0.05


@dataclass(frozen=True, slots=True)
class Outcome:
    """How a worker process ended. ``interrupted``: stopped on request (the run is not finished)."""

    key: str
    exit_code: int | None
    timed_out: bool
    interrupted: bool
    wall: float
    cpu: float
    log_tail: str
    host: str

    @property
    def error(self) -> str | None:
        """Why the run counts as ERROR, or None when the worker finished normally."""
        if self.timed_out:
            return f"timeout: stopped after {self.wall:.0f} s"
        if self.exit_code == 0:
            return None
        if self.exit_code is not None and self.exit_code < 0:
            how = f"killed by {signal.Signals(-self.exit_code).name}"
        else:
            how = f"exited with {self.exit_code}"
        last = self.log_tail.strip().splitlines()[-1:] or ["(no output)"]
        return f"crashed: the worker {how}: {last[0]}"

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def worker_command(run_dir: Path) -> list[str]:
    return [sys.executable, "-m", "rei.campaign.worker", str(run_dir)]


def supervise(task: RunTask, stop: threading.Event | None = None,
              command: Sequence[str] | None = None, env: Mapping[str, str] | None = None) -> Outcome:
    """Write ``task.json`` into the run folder and run the worker (or ``command``) there, with ``env`` added to
    this process's environment."""
    run_dir = Path(task.run_dir)
    run_dir.mkdir(parents=True, exist_ok=True)
    for stale in ("summary.json", "result.json"):
        (run_dir / stale).unlink(missing_ok=True)
    (run_dir / "task.json").write_text(json.dumps(task.to_dict(), indent=2) + "\n", encoding="utf-8")
    log = run_dir / WORKER_LOG
    started = time.perf_counter()
    timed_out = interrupted = False
    if stop is not None and stop.is_set():
        return Outcome(task.key, None, False, True, 0.0, 0.0, "", os.uname().nodename)
    with open(log, "wb") as out:
        process = subprocess.Popen(list(command or worker_command(run_dir)), stdout=out, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, cwd=run_dir, start_new_session=True,
                                   env={**os.environ, **env} if env else None)
        try:
            while True:
                pid, status, usage = os.wait4(process.pid, os.WNOHANG)
                if pid:
                    break
                if stop is not None and stop.is_set():
                    interrupted = True
                elif time.perf_counter() - started > task.timeout:
                    timed_out = True
                if timed_out or interrupted:
                    status, usage = _stop(process.pid)
                    break
                time.sleep(_POLL)
        except BaseException:  # Ctrl-C, a cancelled Ray task: the worker must not outlive us
            _stop(process.pid)
            process.returncode = -1
            raise
    if not (timed_out or interrupted) and status != 0:
        _signal_group(process.pid, signal.SIGKILL)  # a crashed worker's children (a monitor JVM) go with it
    process.returncode = code = os.waitstatus_to_exitcode(status)
    return Outcome(task.key, code, timed_out, interrupted, time.perf_counter() - started,
                   usage.ru_utime + usage.ru_stime, tail(log, 15), os.uname().nodename)


def _stop(pid: int) -> tuple[int, Any]:
    """SIGTERM to the worker's process group, SIGKILL after the grace; reap the worker."""
    _signal_group(pid, signal.SIGTERM)
    deadline = time.perf_counter() + KILL_GRACE
    while time.perf_counter() < deadline:
        found, status, usage = os.wait4(pid, os.WNOHANG)
        if found:
            _signal_group(pid, signal.SIGKILL)  # children that outlived it
            return status, usage
        time.sleep(_POLL)
    _signal_group(pid, signal.SIGKILL)
    _, status, usage = os.wait4(pid, 0)
    return status, usage


def _signal_group(pid: int, sig: int) -> None:
    try:
        os.killpg(pid, sig)
    except ProcessLookupError:
        pass
