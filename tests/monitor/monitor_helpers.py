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
from autobahn.wamp.exception import ApplicationError

from rei.wamp.client import WampClient


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


def call_when_registered(client: WampClient, procedure: str, timeout: float) -> str:
    """The monitor logs "monitoring" when it has asked for its subscriptions and registration; on a loaded
    machine the router may not have processed the registration yet, so retry until it answers."""
    deadline = time.monotonic() + timeout
    while True:
        try:
            return client.call(procedure, timeout=30)
        except ApplicationError as error:
            if error.error != "wamp.error.no_such_procedure" or time.monotonic() > deadline:
                raise
            time.sleep(0.25)
