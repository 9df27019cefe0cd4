# SPDX-License-Identifier: EPL-2.0
"""Run one task's worker process to its end, a timeout, or a stop request, and say how it went.

The worker gets its own session (process group), so stopping it also stops what it started (the monitor's JVM,
``rei run``'s router and children). ``os.wait4`` gives the CPU time of the worker and of every child it waited
for, which the campaign reports per run. Shared by the local pool (whose workers are forked by
rei.campaign.forkserver) and the Ray tasks (new processes).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Protocol

from rei.campaign.forkserver import WORKER_LOG, ForkServer, ForkServerError
from rei.campaign.plan import RunTask, write_task
from rei.run.jvm import tail

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
    attempt: int = 1  # the try this outcome is of (a Ray task lost with its node is tried again)

    @property
    def error(self) -> str | None:
        """Why the run counts as ERROR, or None when the worker finished normally."""
        if self.timed_out:
            return f"timeout: stopped after {self.wall:.0f} s"
        if self.exit_code == 0:
            return None
        if self.exit_code is None:  # no worker process ended: the log tail says why (a Ray task lost on every try)
            return self.log_tail.strip() or "the run's worker never ran"
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
              command: Sequence[str] | None = None, env: Mapping[str, str] | None = None,
              forks: ForkServer | None = None) -> Outcome:
    """Write ``task.json`` into the run folder and run the worker there: forked by ``forks`` when given (and
    answering), else ``command`` or ``worker_command`` as a new process, with ``env`` added to this process's
    environment."""
    run_dir = Path(task.run_dir)
    run_dir.mkdir(parents=True, exist_ok=True)
    for stale in ("summary.json", "result.json"):
        (run_dir / stale).unlink(missing_ok=True)
    write_task(task, run_dir)
    log = run_dir / WORKER_LOG
    started = time.perf_counter()
    timed_out = interrupted = False
    if stop is not None and stop.is_set():
        return Outcome(task.key, None, False, True, 0.0, 0.0, "", os.uname().nodename)
    worker = _start(run_dir, command, env, forks)
    try:
        while True:
            ended = worker.poll(_POLL)
            if ended is not None:
                break
            if stop is not None and stop.is_set():
                interrupted = True
            elif time.perf_counter() - started > task.timeout:
                timed_out = True
            if timed_out or interrupted:
                ended = _stop(worker)
                break
    except BaseException:  # Ctrl-C, a cancelled Ray task: the worker must not outlive us
        _stop(worker)
        raise
    status, cpu = ended
    if not (timed_out or interrupted) and status != 0:
        _signal_group(worker.pid, signal.SIGKILL)  # a crashed worker's children (a monitor JVM) go with it
    return Outcome(task.key, os.waitstatus_to_exitcode(status), timed_out, interrupted, time.perf_counter() - started,
                   cpu, tail(log, 15), os.uname().nodename)


class _Worker(Protocol):
    pid: int

    def poll(self, timeout: float = 0.0) -> tuple[int, float] | None: ...


class _Spawned:
    """A worker started as a new process (os.wait4 gives its CPU and that of every child it waited for)."""

    def __init__(self, command: Sequence[str], run_dir: Path, env: Mapping[str, str] | None) -> None:
        with open(run_dir / WORKER_LOG, "wb") as out:
            self._process = subprocess.Popen(list(command), stdout=out, stderr=subprocess.STDOUT,
                                             stdin=subprocess.DEVNULL, cwd=run_dir, start_new_session=True,
                                             env={**os.environ, **env} if env else None)
        self.pid = self._process.pid

    def poll(self, timeout: float = 0.0) -> tuple[int, float] | None:
        deadline = time.perf_counter() + timeout
        while True:
            pid, status, usage = os.wait4(self.pid, os.WNOHANG)
            if pid:
                self._process.returncode = os.waitstatus_to_exitcode(status)  # reaped here, not by Popen
                return status, usage.ru_utime + usage.ru_stime
            if time.perf_counter() >= deadline:
                return None
            time.sleep(min(_POLL, max(deadline - time.perf_counter(), 0.0)))


def _start(run_dir: Path, command: Sequence[str] | None, env: Mapping[str, str] | None,
           forks: ForkServer | None) -> _Worker:
    if forks is not None and command is None:
        try:
            return forks.fork(run_dir, env)
        except ForkServerError as error:
            print(f"campaign: {error}; this run's worker starts as a new process", flush=True)
    return _Spawned(command or worker_command(run_dir), run_dir, env)


def _stop(worker: _Worker) -> tuple[int, float]:
    """SIGTERM to the worker's process group, SIGKILL after the grace; its status and CPU once it ended."""
    _signal_group(worker.pid, signal.SIGTERM)
    ended = worker.poll(KILL_GRACE)
    _signal_group(worker.pid, signal.SIGKILL)  # it, or children that outlived it
    while ended is None:
        ended = worker.poll(_POLL)
    return ended


def _signal_group(pid: int, sig: int) -> None:
    try:
        os.killpg(pid, sig)
    except ProcessLookupError:
        pass
