# SPDX-License-Identifier: EPL-2.0
"""Children that do not outlive their parent, even one killed outright (SIGKILL, the OOM killer).

A supervisor stops its children in ``finally`` blocks and on SIGTERM; a SIGKILL runs neither. On Linux the kernel
can signal a child when its parent dies (``PR_SET_PDEATHSIG``); setting it between fork and exec would need a
pre-exec hook, which can deadlock a process that runs threads, so the child is started through util-linux's
``setpriv --pdeathsig TERM`` instead (part of every Debian system), which sets it and execs the command.
"""

from __future__ import annotations

import atexit
import contextlib
import gc
import os
import shutil
import signal
import sys
import threading
from collections.abc import Iterator, Sequence


def stat_fields(pid: int) -> list[str] | None:
    """The fields of ``/proc/PID/stat`` after the command name (state, ppid, pgrp, ...: proc(5)'s fields 3 on, so
    index ``i`` is field ``i + 3``); None when the process is gone or there is no /proc. The name is cut at its
    last ``)``: it may hold spaces and parentheses."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as f:
            stat = f.read()
    except OSError:
        return None
    _, paren, fields = stat.rpartition(")")
    return fields.split() if paren else None


def alive(pid: int) -> bool:
    """Whether process ``pid`` exists (one of another user counts; a zombie too, until its parent reaps it)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def die_with_parent(argv: Sequence[str]) -> list[str]:
    """``argv`` started so that it gets SIGTERM when the starting thread dies (Linux with setpriv; else as is).

    The signal follows the *thread* that forked, not the process: start such children from a thread that lives
    as long as they should (the pipeline's main thread).
    """
    setpriv = shutil.which("setpriv")
    if setpriv is None or not sys.platform.startswith("linux"):
        return list(argv)
    return [setpriv, "--pdeathsig", "TERM", "--", *argv]


def skip_exit_collection() -> None:
    """At this process's exit, skip the full garbage collection the interpreter runs as it shuts down.

    That collection walks every object the process still holds (numpy, pybullet, a run's data): 0.12-0.33 s between
    a simulation's last file and its exit, which ``rei run`` waits for (0.01-0.05 s without it). What it would free
    goes with the process; REI closes its files itself, none relies on a collection to be flushed."""
    atexit.register(gc.freeze)  # exit functions run before the interpreter's last collections, which skip frozen objects


@contextlib.contextmanager
def sigterm_unwinds() -> Iterator[None]:
    """SIGTERM raises ``SystemExit(143)`` in the main thread while inside, so ``finally`` blocks and context
    managers run (stopping the children they started) instead of the process dying on the spot."""

    def unwind(signum: int, frame: object) -> None:
        raise SystemExit(128 + signum)

    previous = signal.signal(signal.SIGTERM, unwind)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


#: Seconds between the wake-ups of a main thread that waits for a stop (``wait_for_stop``).
SIGNAL_POLL_S = 0.2


def wait_for_stop(stop: threading.Event) -> None:
    """Wait in the main thread until ``stop`` is set, or a signal handler raises (Ctrl-C's KeyboardInterrupt).

    A wait without a timeout can miss a signal for good: the kernel delivers a process's signal to any of its
    threads, and when that is not the main thread, the main thread's blocked wait is not interrupted, while Python
    runs handlers only in the main thread. Waking every ``SIGNAL_POLL_S`` lets them run."""
    while not stop.wait(SIGNAL_POLL_S):
        pass
