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
import signal
import subprocess
import threading
from collections.abc import Callable, Sequence
from pathlib import Path

from rei.lifetime import die_with_parent


class ManagedProcess:
    """A child process with its output in ``log`` and, optionally, each stdout line passed to ``on_line``."""

    def __init__(self, name: str, argv: Sequence[str], log: Path, *, on_line: Callable[[str], None] | None = None,
                 env: dict[str, str] | None = None, cwd: Path | None = None) -> None:
        self.name = name
        self.log = log
        self._log = open(log, "w", encoding="utf-8")  # noqa: SIM115 - closed in stop()
        self._process = subprocess.Popen(
            die_with_parent(argv), stdin=subprocess.DEVNULL, stdout=subprocess.PIPE if on_line else self._log,
            stderr=self._log, start_new_session=True, cwd=cwd,
            env={**os.environ, **(env or {})}, text=True, bufsize=1)
        self._reader: threading.Thread | None = None
        if on_line is not None:
            self._reader = threading.Thread(target=self._pump, args=(on_line,), name=f"{name}-output", daemon=True)
            self._reader.start()

    @property
    def pid(self) -> int:
        return self._process.pid

    def poll(self) -> int | None:
        """The exit code once the process has ended (negative: killed by that signal), else None."""
        return self._process.poll()

    def wait(self, timeout: float) -> int | None:
        try:
            return self._process.wait(timeout)
        except subprocess.TimeoutExpired:
            return None

    def stop(self, grace: float = 10.0) -> int:
        """SIGTERM to the process group, SIGKILL after ``grace`` seconds; returns the exit code."""
        if self._process.poll() is None:
            self._signal(signal.SIGTERM)
            if self.wait(grace) is None:
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
        self._log.flush()
        text = self.log.read_text(encoding="utf-8", errors="replace").splitlines()
        return "\n".join(text[-lines:])

    def _signal(self, sig: signal.Signals) -> None:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(self._process.pid, sig)

    def _pump(self, on_line: Callable[[str], None]) -> None:
        assert self._process.stdout is not None
        for line in self._process.stdout:
            self._log.write(line)
            self._log.flush()
            on_line(line.rstrip("\n"))
