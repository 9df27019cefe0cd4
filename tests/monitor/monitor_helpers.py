# SPDX-License-Identifier: EPL-2.0
"""Helpers of the live-monitor tests: bounded waits and process clean-up around a real monitor jar."""

from __future__ import annotations

import os
import signal
import subprocess
import time
from collections.abc import Callable
from pathlib import Path

import pytest


def kill_group(process: subprocess.Popen) -> None:
    if process.poll() is None:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        process.wait(timeout=10)


def wait_for(predicate: Callable[[], bool], timeout: float, what: str, process: subprocess.Popen | None = None,
             log: Path | None = None) -> None:
    """Until ``predicate()``; fails the test after ``timeout`` s or when the monitor ``process`` exits."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if process is not None and process.poll() is not None:
            pytest.fail(f"{what}: the monitor exited with {process.returncode}: {log.read_text() if log else ''}")
        if time.monotonic() > deadline:
            pytest.fail(f"{what}: not within {timeout} s" + (f"; monitor stderr: {log.read_text()}" if log else ""))
        time.sleep(0.05)
