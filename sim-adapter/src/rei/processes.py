# SPDX-License-Identifier: EPL-2.0
"""Child processes REI starts (the monitor, the simulation, an external system under test), supervised so none
outlives the run.

Each child gets its own process group, so stopping it stops whatever it started too. (No pre-exec hooks: the
supervisor runs a WAMP client thread, and code between fork and exec could deadlock on its locks; the
supervisor stops its children in ``finally`` blocks and on SIGTERM instead.) A supervisor killed outright
(SIGKILL, the OOM killer) runs no ``finally``: ``rei.lifetime.die_with_parent`` starts a child through util-linux's
``setpriv --pdeathsig TERM``, so the kernel sends it SIGTERM when the thread that started it dies. Output goes to
a log file in the run folder; stdout lines can also be handed to a callback as they come.
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import threading
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import IO, Any

from rei.lifetime import die_with_parent, stat_fields

_TAIL_BYTES = 64 * 1024

#: Starts a child another way: (stdin a pipe?, stdout or None for a pipe, stderr, environment, folder) -> an object
#: with Popen's pid, stdin, stdout, poll(), wait(timeout) and returncode; None: not possible here.
Launch = Callable[[bool, IO[str] | None, IO[str], dict[str, str], Path | None], Any]


class ManagedProcess:
    """A child process with its output in ``log`` and, optionally, each stdout line passed to ``on_line``."""

    def __init__(self, name: str, argv: Sequence[str], log: Path, *, on_line: Callable[[str], None] | None = None,
                 env: dict[str, str] | None = None, cwd: Path | None = None, held: bool = False,
                 launch: Launch | None = None) -> None:
        """``held``: the child's standard input is a pipe that ``release()`` writes a line to (a child that waits
        for it can start up meanwhile). ``launch``: another way to start it (``rei.service.warm``: forked from a
        warm Python), given the same streams, environment and folder; None from it: started as usual."""
        self.name = name
        self.log = log
        self._log = open(log, "w", encoding="utf-8")  # noqa: SIM115 - closed in stop()
        environment = {**os.environ, **(env or {})}
        launched = launch(held, None if on_line else self._log, self._log, environment, cwd) if launch else None
        self._process: Any = launched or subprocess.Popen(
            die_with_parent(argv), stdin=subprocess.PIPE if held else subprocess.DEVNULL,
            stdout=subprocess.PIPE if on_line else self._log,
            stderr=self._log, start_new_session=True, cwd=cwd, env=environment, text=True, bufsize=1)
        self._reader: threading.Thread | None = None
        if on_line is not None:
            self._reader = threading.Thread(target=self._pump, args=(on_line,), name=f"{name}-output", daemon=True)
            self._reader.start()

    @property
    def pid(self) -> int:
        return self._process.pid

    def release(self) -> None:
        """Tell a ``held`` child to go on: one line on its standard input, which is then closed."""
        stdin = self._process.stdin
        if stdin is not None and not stdin.closed:
            with contextlib.suppress(OSError):  # it died meanwhile: poll() says so
                stdin.write("go\n")
                stdin.close()

    def poll(self) -> int | None:
        """The exit code once the process has ended (negative: killed by that signal), else None."""
        return self._process.poll()

    def wait(self, timeout: float) -> int | None:
        try:
            return self._process.wait(timeout)
        except subprocess.TimeoutExpired:
            return None

    def stop(self, grace: float = 10.0) -> int:
        """SIGTERM to the process group, SIGKILL after ``grace`` seconds to whatever of it is left; returns the
        exit code. The group is stopped also when its leader has exited: a wrapper script's children stay behind
        in its group otherwise."""
        self._process.poll()
        if self._process.returncode is None or self._group_alive():
            self._signal(signal.SIGTERM)
            deadline = time.monotonic() + grace
            while self._group_alive() and time.monotonic() < deadline:
                time.sleep(0.05)
            if self._group_alive():
                self._signal(signal.SIGKILL)
            self._process.wait()
        if self._reader is not None:
            self._reader.join(timeout=5)
        self._log.close()
        return self._process.returncode

    def describe_exit(self) -> str:
        code = self._process.returncode
        if code is None:
            return f"{self.name} is running"
        if code < 0:
            return f"{self.name} was killed by {signal.Signals(-code).name}"
        return f"{self.name} exited with code {code}"

    def log_tail(self, lines: int = 20) -> str:
        """The last ``lines`` lines of the log (read from its end: a chatty child's log may be huge)."""
        if not self._log.closed:
            self._log.flush()
        with open(self.log, "rb") as log:
            log.seek(0, os.SEEK_END)
            log.seek(max(0, log.tell() - _TAIL_BYTES))
            text = log.read().decode("utf-8", errors="replace").splitlines()
        return "\n".join(tail_with_cause(text, lines))

    def _group_alive(self) -> bool:
        """Whether a process of the group is still running (zombies aside; the leader is reaped here)."""
        self._process.poll()
        group = self._process.pid
        for entry in Path("/proc").glob("[0-9]*"):
            fields = stat_fields(int(entry.name))
            if fields is not None and fields[0] != "Z" and int(fields[2]) == group:  # state, then ppid, then pgrp
                return True
        return False

    def _signal(self, sig: signal.Signals) -> None:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(self._process.pid, sig)

    def _pump(self, on_line: Callable[[str], None]) -> None:
        assert self._process.stdout is not None
        for line in self._process.stdout:
            self._log.write(line)
            self._log.flush()
            on_line(line.rstrip("\n"))


def close_and_reap(process: subprocess.Popen[bytes], timeout: float) -> float:
    """End a server that exits when its standard input ends (a warm JVM, the campaign's fork server): close its
    input, wait up to ``timeout`` seconds, then kill it. Returns its CPU seconds, those of the children it waited
    for included (0.0 when it was reaped already, by a ``poll()`` that saw it die)."""
    if process.stdin is not None:
        with contextlib.suppress(OSError):
            process.stdin.close()
    deadline = time.monotonic() + timeout
    while process.returncode is None:
        try:
            pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        except ChildProcessError:
            break
        if pid:
            process.returncode = os.waitstatus_to_exitcode(status)
            return usage.ru_utime + usage.ru_stime
        if time.monotonic() > deadline:
            process.kill()
        time.sleep(0.02)
    return 0.0


# The line that says why a process died, where a backtrace follows it (Rust with RUST_BACKTRACE set, the JVM): the
# log's last lines would be frames only.
_CAUSE = re.compile(r"panicked at |^Exception in thread ")


def tail_with_cause(text: list[str], lines: int) -> list[str]:
    """The last ``lines`` lines of ``text``, led by the last panic or uncaught exception line and the line after it
    when the backtrace below them is longer than the tail."""
    tail = text[-lines:]
    start = len(text) - len(tail)
    causes = [i for i, line in enumerate(text[:start]) if _CAUSE.search(line)]
    if not causes or lines < 4:
        return tail
    cause = text[causes[-1]:causes[-1] + 2]
    return [*cause, "[...]", *text[-(lines - len(cause) - 1):]]
